#include "rotator/config.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "rotator/adc_model.h"
#include "util/exact_number.h"

namespace tb::rotator {

namespace {
using limits::kMinSpanWidth;

std::string num(double v) { return text::exact_number(v); }

void check_span(std::vector<std::string>& out, const char* axis, const AxisSpan& s) {
  std::string name = std::string(axis) + " ADC span";
  if (!limits::kSpan.contains(s.min) || !limits::kSpan.contains(s.max))
    out.push_back(name + " " + std::to_string(s.min) + "-" + std::to_string(s.max) +
                  ": counts must lie in 0..1023 (10-bit ADC)");
  else if (s.max - s.min < kMinSpanWidth)
    out.push_back(name + " " + std::to_string(s.min) + "-" + std::to_string(s.max) +
                  ": maximum must exceed minimum by at least " + std::to_string(kMinSpanWidth) +
                  " counts (if the reading falls as the rotator turns CW/UP, swap the potentiometer ends)");
}
}  // namespace

std::vector<std::string> validate(const RotatorConfig& c) {
  std::vector<std::string> out;
  check_span(out, "azimuth", c.az_span);
  check_span(out, "elevation", c.el_span);
  if (!(c.az_travel_deg >= limits::kTravelMinDeg && c.az_travel_deg <= limits::kTravelMaxDeg))
    out.push_back("azimuth travel " + num(c.az_travel_deg) + " deg: expected " + num(limits::kTravelMinDeg) + " to " +
                  num(limits::kTravelMaxDeg));
  auto check_counts = [&out](const char* what, int v, limits::Counts r) {
    if (!r.contains(v))
      out.push_back(std::string(what) + " " + std::to_string(v) + ": expected " + std::to_string(r.lo) + ".." +
                    std::to_string(r.hi) + " counts");
  };
  check_counts("azimuth dead band", c.az_dead_band, limits::kDeadBand);
  check_counts("elevation dead band", c.el_dead_band, limits::kDeadBand);
  check_counts("azimuth skew", c.az_skew, limits::kSkew);
  check_counts("elevation skew", c.el_skew, limits::kSkew);
  for (const auto& [what, v] : {std::pair{"azimuth offset", c.az_offset_deg}, std::pair{"elevation offset", c.el_offset_deg}})
    if (!(std::abs(v) <= limits::kSkyOffsetMaxDeg))
      out.push_back(std::string(what) + " " + num(v) + " deg: expected " + num(-limits::kSkyOffsetMaxDeg) + " to " +
                    num(limits::kSkyOffsetMaxDeg));
  const double el_top = c.el_top_deg();
  auto az_ok = [](double a) { return std::isfinite(a) && a >= 0.0 && a <= 360.0; };
  auto el_ok = [&](double e) { return std::isfinite(e) && e >= 0.0 && e <= el_top; };
  const std::string el_expect = c.el_flip_allowed ? "0..180" : "0..90";
  if (!az_ok(c.parking.az)) out.push_back("azimuth parking value " + num(c.parking.az) + ": expected 0..360");
  if (!el_ok(c.parking.el))
    out.push_back("elevation parking value " + num(c.parking.el) + ": expected " + el_expect);
  if (!az_ok(c.az_limit_min)) out.push_back("azimuth minimum value " + num(c.az_limit_min) + ": expected 0..360");
  if (!az_ok(c.az_limit_max)) out.push_back("azimuth maximum value " + num(c.az_limit_max) + ": expected 0..360");
  if (az_ok(c.az_limit_min) && az_ok(c.az_limit_max) && c.az_limit_max - c.az_limit_min < 360.0 &&
      wrap360(c.az_limit_max - c.az_limit_min) == 0.0)
    out.push_back("azimuth limits " + num(c.az_limit_min) + " and " + num(c.az_limit_max) +
                  ": the same azimuth leaves no room to turn (use 0 and 360 for no limit)");
  if (!el_ok(c.el_limit_min)) out.push_back("elevation minimum value " + num(c.el_limit_min) + ": expected " + el_expect);
  if (!el_ok(c.el_limit_max)) out.push_back("elevation maximum value " + num(c.el_limit_max) + ": expected " + el_expect);
  if (el_ok(c.el_limit_min) && el_ok(c.el_limit_max) && c.el_limit_max < c.el_limit_min)
    out.push_back("elevation limits " + num(c.el_limit_min) + ".." + num(c.el_limit_max) +
                  ": maximum must not be below minimum");
  for (std::size_t i = 0; i < c.presets.size(); ++i) {
    const AzEl& p = c.presets[i];
    if (!az_ok(p.az) || !el_ok(p.el))
      out.push_back("preset " + std::to_string(i + 1) + " " + num(p.az) + "/" + num(p.el) +
                    ": expected azimuth 0..360 and elevation " + el_expect);
  }
  if (!(c.az_rate_deg_s > 0.0) || !(c.el_rate_deg_s > 0.0))
    out.push_back("motor rates must be positive (deg/s)");
  if (!(c.coast_s >= 0.0 && c.coast_s <= limits::kCoastMaxS))
    out.push_back("coast time " + num(c.coast_s) + " s: expected 0.." + num(limits::kCoastMaxS));
  if (!(c.stall_s > 0.0)) out.push_back("stall time " + num(c.stall_s) + " s: expected > 0");
  if (out.empty()) {
    AdcModel m(c, station::RotorStart::north);
    if (m.az_travel_range().empty() || m.el_range().empty())
      out.push_back("limits, span and skew together leave no position the antenna may be moved to");
  }
  return out;
}

}  // namespace tb::rotator
