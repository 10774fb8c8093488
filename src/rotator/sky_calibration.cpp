// "This is the Sun / Moon" (rotator/sky_calibration.h).
#include "rotator/sky_calibration.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "util/format.h"

namespace tb::rotator {

namespace {
double axis_counts_per_deg(const RotatorConfig& c, bool az) {
  const double width = az ? c.az_span.width() : c.el_span.width();
  return width / (az ? c.az_travel_deg : c.el_top_deg());
}
}  // namespace

BodyFix body_fix(orbit::Body body, orbit::UtcTime t, AzEl reading, const orbit::LookAngles& computed) {
  BodyFix fix;
  fix.body = body;
  fix.time = t;
  fix.reading = reading;
  fix.computed = {computed.az_deg, computed.el_deg};
  const std::string name(orbit::body_name(body));
  if (!std::isfinite(reading.az) || !std::isfinite(reading.el) || !std::isfinite(computed.az_deg) ||
      !std::isfinite(computed.el_deg)) {
    fix.error = "the reading or the computed position is not a number";
  } else if (computed.el_deg < kMinCalibrationElevationDeg) {
    fix.error = text::printf_string("the %s is at %.1f deg elevation, below the %.0f deg a calibration needs",
                             name.c_str(), computed.el_deg, kMinCalibrationElevationDeg);
  } else if (reading.el < 0.0 || reading.el > 90.0) {
    fix.error = text::printf_string("the rotator reads %.1f deg elevation, outside 0..90: point the antenna "
                             "at the %s without flipping it over the top",
                             reading.el, name.c_str());
  } else {
    fix.correction.az_deg = -std::remainder(reading.az - computed.az_deg, 360.0);
    if (fix.correction.az_deg <= -180.0) fix.correction.az_deg += 360.0;
    fix.correction.el_deg = computed.el_deg - reading.el;
  }
  return fix;
}

SkewChange skew_for(const RotatorConfig& c, const PointingCorrection& correction) {
  SkewChange s;
  s.az_skew_before = s.az_skew_after = c.az_skew;
  s.el_skew_before = s.el_skew_after = c.el_skew;
  if (!std::isfinite(correction.az_deg) || !std::isfinite(correction.el_deg)) {
    s.error = "the correction is not a number";
    return s;
  }
  const double az_cpd = axis_counts_per_deg(c, true), el_cpd = axis_counts_per_deg(c, false);
  const double az_counts = std::round(correction.az_deg * az_cpd);
  const double el_counts = std::round(correction.el_deg * el_cpd);
  const double az_new = c.az_skew + az_counts, el_new = c.el_skew + el_counts;
  if (!limits::kSkew.contains(static_cast<int>(std::clamp(az_new, -1e6, 1e6)))) {
    s.error = text::printf_string("azimuth skew %.0f counts (%+.2f deg) would leave %d..%d", az_new,
                           correction.az_deg, limits::kSkew.lo, limits::kSkew.hi);
    return s;
  }
  if (!limits::kSkew.contains(static_cast<int>(std::clamp(el_new, -1e6, 1e6)))) {
    s.error = text::printf_string("elevation skew %.0f counts (%+.2f deg) would leave %d..%d", el_new,
                           correction.el_deg, limits::kSkew.lo, limits::kSkew.hi);
    return s;
  }
  s.az_skew_after = static_cast<int>(az_new);
  s.el_skew_after = static_cast<int>(el_new);
  s.az_residual_deg = correction.az_deg - az_counts / az_cpd;
  s.el_residual_deg = correction.el_deg - el_counts / el_cpd;
  return s;
}

RotatorConfig SkewChange::apply(RotatorConfig c) const {
  if (!ok()) return c;
  c.az_skew = az_skew_after;
  c.el_skew = el_skew_after;
  return c;
}

RotatorConfig SkewChange::undo(RotatorConfig c) const {
  if (!ok()) return c;
  c.az_skew = az_skew_before;
  c.el_skew = el_skew_before;
  return c;
}

OffsetChange offsets_for(const RotatorConfig& c, const PointingCorrection& correction, const std::string& source,
                         const std::string& time_iso) {
  OffsetChange o;
  o.after = c;
  const double az = c.az_offset_deg + correction.az_deg, el = c.el_offset_deg + correction.el_deg;
  for (const auto& [axis, v] : {std::pair{"azimuth", az}, std::pair{"elevation", el}})
    if (!(std::abs(v) <= limits::kSkyOffsetMaxDeg)) {
      o.error = fmt::format("the {} offset would be {:+.2f} deg, beyond {:.0f} either way: check the station's "
                            "position, the clock and that the antenna is on the body",
                            axis, v, limits::kSkyOffsetMaxDeg);
      return o;
    }
  o.after.az_offset_deg = az;
  o.after.el_offset_deg = el;
  SkyCalibration& k = o.after.sky;
  k.previous_az_offset_deg = c.az_offset_deg;
  k.previous_el_offset_deg = c.el_offset_deg;
  k.previous_source = c.sky.source;
  k.previous_time = c.sky.time;
  k.source = source;
  k.time = time_iso;
  return o;
}

OffsetChange undo_offsets(const RotatorConfig& c) {
  OffsetChange o;
  o.after = c;
  if (c.sky.source.empty() && c.sky.previous_source.empty()) {
    o.error = "no sky calibration to undo";
    return o;
  }
  SkyCalibration& k = o.after.sky;
  o.after.az_offset_deg = c.sky.previous_az_offset_deg;
  o.after.el_offset_deg = c.sky.previous_el_offset_deg;
  k.source = c.sky.previous_source;
  k.time = c.sky.previous_time;
  k.previous_az_offset_deg = c.az_offset_deg;
  k.previous_el_offset_deg = c.el_offset_deg;
  k.previous_source = c.sky.source;
  k.previous_time = c.sky.time;
  return o;
}

}  // namespace tb::rotator
