#include "radio/link_common.h"

#include <spdlog/fmt/fmt.h>

namespace tb::radio::link {

std::string band_name(Hz hz) {
  struct Band {
    double from_mhz, to_mhz;
    const char* name;
  };
  // The ITU regions' amateur allocations, widest edges.
  static constexpr Band kBands[] = {
      {1.8, 2.0, "160 m"},       {3.5, 4.0, "80 m"},         {5.3, 5.45, "60 m"},        {7.0, 7.3, "40 m"},
      {10.1, 10.15, "30 m"},     {14.0, 14.35, "20 m"},      {18.068, 18.168, "17 m"},   {21.0, 21.45, "15 m"},
      {24.89, 24.99, "12 m"},    {28.0, 29.7, "10 m"},       {50.0, 54.0, "6 m"},        {70.0, 71.0, "4 m"},
      {144.0, 148.0, "2 m"},     {219.0, 225.0, "1.25 m"},   {420.0, 450.0, "70 cm"},    {902.0, 928.0, "33 cm"},
      {1240.0, 1300.0, "23 cm"}, {2300.0, 2450.0, "13 cm"},  {3300.0, 3500.0, "9 cm"},   {5650.0, 5925.0, "5.7 GHz"},
      {10000.0, 10500.0, "10 GHz"}, {24000.0, 24250.0, "24 GHz"},
  };
  const double mhz = static_cast<double>(hz) / 1e6;
  for (const Band& b : kBands)
    if (mhz >= b.from_mhz && mhz <= b.to_mhz) return b.name;
  return fmt::format("{:.3f} MHz", mhz);
}

void require_band(const std::string& radio, std::span<const HzRange> bands, Link l, Hz hz) {
  if (bands.empty()) return;
  for (const HzRange& b : bands)
    if (b.contains(hz)) return;
  throw LinkError("no " + band_name(hz),
                  fmt::format("{} has no {} band: the {} at {} Hz is not sent", radio, band_name(hz), to_string(l), hz));
}

}  // namespace tb::radio::link
