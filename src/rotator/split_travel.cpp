#include "rotator/split_travel.h"

#include <cstdio>
#include <vector>

namespace tb::rotator {

namespace {
std::string deg1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}
}  // namespace

std::string compass_sector_text(station::RotorStart start, const Range& travel) {
  if (travel.empty()) return "nothing";
  // A whole turn or more ("180.0-180.0" read as nothing to an operator; issue 30), or one azimuth.
  if (travel.width() >= 360.0 - 1e-9) return "all azimuths";
  if (travel.width() <= 0.0) return deg1(wrap360(travel.lo + rotor_start_deg(start))) + " only";
  const double lo = wrap360(travel.lo + rotor_start_deg(start));
  double hi = wrap360(travel.hi + rotor_start_deg(start));
  if (hi == 0.0 && travel.width() > 0.0) hi = 360.0;
  return deg1(lo) + "-" + deg1(hi);
}

std::optional<std::string> split_travel_warning(const RotatorConfig& c, station::RotorStart start) {
  const AdcModel m(c, start);
  if (!m.travel_split()) return std::nullopt;
  std::vector<std::string> reach;
  for (const Range& p : m.az_pieces())
    if (!p.empty()) reach.push_back(compass_sector_text(start, p));
  std::string text = "Limits split the travel: with the rotor stop at " + deg1(m.start_deg()) + " (" +
                     (start == station::RotorStart::north ? "North" : "South") + " start) the antenna can reach " +
                     reach[0] + " or " + reach[1];
  if (c.cross_limit_sector)
    return text + ", and may cross between passes (never during one), as the limits are pointing limits only. " +
           "A pass is followed in the piece that covers the most of it; the realtime display says how much.";
  return text + ", and keeps to the one it is in, as the limits bar the excluded " + deg1(c.az_limit_max) + "-" +
         deg1(c.az_limit_min) +
         " between them. A pass is followed as far as that piece allows; the realtime display says how much "
         "(--cross-limit-sector yes lets it cross between passes).";
}

}  // namespace tb::rotator
