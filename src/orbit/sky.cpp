// The Sun and the Moon from a station: look angles, echo Doppler, refraction (orbit/sky.h).
#include "orbit/sky.h"

#include <algorithm>
#include <cmath>

#include "orbit/constants.h"
#include "orbit/geometry.h"
#include "orbit/moon.h"
#include "util/text.h"

namespace tb::orbit {

std::string_view body_name(Body b) { return b == Body::sun ? "SUN" : "MOON"; }

std::optional<Body> parse_body(std::string_view name) {
  if (text::iequals(name, "SUN")) return Body::sun;
  if (text::iequals(name, "MOON")) return Body::moon;
  return std::nullopt;
}

namespace {
StateVector sun_state_teme(UtcTime t) {
  constexpr double kHalfStepS = 30.0;
  const Vec3 before = sun_position_km(add_seconds(t, -kHalfStepS));
  const Vec3 after = sun_position_km(add_seconds(t, kHalfStepS));
  StateVector s;
  s.r_km = sun_position_km(t);
  for (int i = 0; i < 3; ++i) s.v_km_s[i] = (after[i] - before[i]) / (2.0 * kHalfStepS);
  return s;
}

// Saemundsson's and Bennett's formulas give arcminutes; both scale with the air's density.
double density_scale(double pressure_hpa, double temperature_c) {
  return (pressure_hpa / 1010.0) * (283.0 / (273.0 + temperature_c));
}
constexpr double kRefractionFloorDeg = -1.0;
}  // namespace

StateVector body_state_teme(Body b, UtcTime t) {
  return b == Body::sun ? sun_state_teme(t) : moon_state_teme(t);
}

LookAngles body_look(Body b, const Observer& o, UtcTime t, const EarthOrientation& eo) {
  return look_angles(teme_to_ecef(body_state_teme(b, t), t, eo), o);
}

double eme_echo_doppler_hz(double freq_hz, double range_rate_km_s) {
  return -2.0 * freq_hz * range_rate_km_s / kSpeedOfLightKmS;
}

double refraction_deg(double true_el_deg, double pressure_hpa, double temperature_c) {
  const double h = std::max(true_el_deg, kRefractionFloorDeg);
  const double arcmin = 1.02 / std::tan((h + 10.3 / (h + 5.11)) * kDegToRad);
  return arcmin / 60.0 * density_scale(pressure_hpa, temperature_c);
}

double refraction_from_apparent_deg(double apparent_el_deg, double pressure_hpa, double temperature_c) {
  const double h = std::max(apparent_el_deg, kRefractionFloorDeg);
  const double arcmin = 1.0 / std::tan((h + 7.31 / (h + 4.4)) * kDegToRad);
  return arcmin / 60.0 * density_scale(pressure_hpa, temperature_c);
}

}  // namespace tb::orbit
