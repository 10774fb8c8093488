// Observation geometry: TEME -> Earth-fixed, WGS-84 station, look angles, sub-point, phase, Sun.
// Conventions and the measured agreement with Skyfield are in docs/orbit.md.
#include "orbit/observe.h"

#include <algorithm>
#include <cmath>

#include "orbit/constants.h"
#include "orbit/geometry.h"

namespace tb::orbit {
namespace {

using detail::dot;
using detail::norm;
using detail::sub;
using detail::wrap360;

constexpr double kE2 = kWgs84Flattening * (2.0 - kWgs84Flattening);  // first eccentricity squared

}  // namespace

StateVector teme_to_ecef(const StateVector& teme, UtcTime t, const EarthOrientation& eo) {
  // Vallado's teme2ecef without polar motion: r_pef = R3(gmst) r_teme,
  // v_pef = R3(gmst) v_teme - omega x r_pef.
  const double g = gmst82(julian_date(t, eo.dut1_s));
  const double c = std::cos(g), s = std::sin(g);
  StateVector out;
  out.r_km = {c * teme.r_km[0] + s * teme.r_km[1], -s * teme.r_km[0] + c * teme.r_km[1], teme.r_km[2]};
  const double vx = c * teme.v_km_s[0] + s * teme.v_km_s[1];
  const double vy = -s * teme.v_km_s[0] + c * teme.v_km_s[1];
  out.v_km_s = {vx + kEarthRotationRadS * out.r_km[1], vy - kEarthRotationRadS * out.r_km[0], teme.v_km_s[2]};
  return out;
}

Vec3 observer_ecef_km(const Observer& o) {
  const double lat = o.lat_deg * kDegToRad, lon = o.lon_deg * kDegToRad;
  const double h = o.height_m / 1000.0;
  const double sl = std::sin(lat), cl = std::cos(lat);
  const double n = kWgs84A_km / std::sqrt(1.0 - kE2 * sl * sl);  // prime-vertical radius of curvature
  return {(n + h) * cl * std::cos(lon), (n + h) * cl * std::sin(lon), (n * (1.0 - kE2) + h) * sl};
}

Geodetic ecef_to_geodetic(const Vec3& r) {
  // Fixed-point iteration on the geodetic latitude (Vallado Algorithm 12 in spirit), to 1e-12 rad.
  const double p = std::hypot(r[0], r[1]);
  Geodetic g;
  double lon = std::atan2(r[1], r[0]);
  if (lon <= -kPi) lon += kTwoPi;  // keep (-180, 180]
  double lat = std::atan2(r[2], p * (1.0 - kE2));
  for (int i = 0; i < 50; ++i) {
    const double sl = std::sin(lat);
    const double n = kWgs84A_km / std::sqrt(1.0 - kE2 * sl * sl);
    const double next = std::atan2(r[2] + n * kE2 * sl, p);
    const bool done = std::abs(next - lat) < 1e-12;
    lat = next;
    if (done) break;
  }
  const double sl = std::sin(lat), cl = std::cos(lat);
  // Height along the normal; valid at every latitude, the poles included.
  g.alt_km = p * cl + r[2] * sl - kWgs84A_km * std::sqrt(1.0 - kE2 * sl * sl);
  g.lat_deg = lat / kDegToRad;
  g.lon_deg = lon / kDegToRad;
  if (g.lon_deg <= -180.0) g.lon_deg += 360.0;
  return g;
}

LookAngles look_angles(const StateVector& ecef, const Observer& o) {
  const Vec3 site = observer_ecef_km(o);
  // The station is fixed in this frame: the line of sight changes at the satellite's velocity.
  return detail::look_from(sub(ecef.r_km, site), ecef.v_km_s, detail::station_frame(o));
}

double phase256(const Elements& e, UtcTime t) {
  // AMSAT "MA": mean anomaly advanced by the mean motion and its first derivative, as the
  // element set states them (rev/day, rev/day^2), in 256ths of an orbit.
  const double dt_days = minutes_between(e.epoch(), t) / kMinutesPerDay;
  const double revs = e.mean_motion_rev_per_day * dt_days + e.ndot_over_2 * dt_days * dt_days;
  // Keep the whole revolutions out of the sum so that the fraction stays exact far from epoch.
  const double frac_revs = revs - std::floor(revs);
  const double ma_deg = wrap360(e.mean_anomaly_deg + 360.0 * frac_revs);
  double p = ma_deg * (256.0 / 360.0);
  if (p >= 256.0) p = 0.0;
  return p;
}

double doppler_shift_hz(double freq_hz, double range_rate_km_s) {
  return -freq_hz * range_rate_km_s / kSpeedOfLightKmS;
}

Observation observe(const Sgp4& sat, const Observer& o, UtcTime t, const EarthOrientation& eo) {
  return observe(sat, o, t, sat.propagate(t), eo);
}

Observation observe(const Sgp4& sat, const Observer& o, UtcTime t, const Propagation& p, const EarthOrientation& eo) {
  Observation obs;
  obs.time = t;
  obs.error = p.error;
  if (!p.ok()) return obs;
  obs.teme = p.state;
  const StateVector ecef = teme_to_ecef(p.state, t, eo);
  obs.look = look_angles(ecef, o);
  obs.sub_point = ecef_to_geodetic(ecef.r_km);
  obs.phase256 = phase256(sat.elements(), t);
  return obs;
}

Vec3 sun_position_km(UtcTime t) {
  // Vallado, Fundamentals of Astrodynamics and Applications, Algorithm 29 ("sun"), from the
  // Astronomical Almanac's low-precision formulae; about 0.01 deg, valid 1950-2050. The book uses
  // T_UT1 for the mean longitude and T_TDB ~ T_UT1 for the rest; UTC stands in for both here
  // (the Sun moves 0.04"/s, far below the model's error).
  const JulianDate jd = julian_date(t);
  const double tut1 = ((jd.whole - kJdJ2000) + jd.fraction) / 36525.0;
  const double mean_long = wrap360(280.460 + 36000.77 * tut1);
  const double mean_anomaly = wrap360(357.5291092 + 35999.05034 * tut1) * kDegToRad;
  const double ecl_long = wrap360(mean_long + 1.914666471 * std::sin(mean_anomaly) +
                                  0.019994643 * std::sin(2.0 * mean_anomaly)) * kDegToRad;
  const double obliquity = (23.439291 - 0.0130042 * tut1) * kDegToRad;
  const double r_au = 1.000140612 - 0.016708617 * std::cos(mean_anomaly) -
                      0.000139589 * std::cos(2.0 * mean_anomaly);
  const double r_km = r_au * kAstronomicalUnitKm;
  return {r_km * std::cos(ecl_long), r_km * std::cos(obliquity) * std::sin(ecl_long),
          r_km * std::sin(obliquity) * std::sin(ecl_long)};
}

double sun_elevation_deg(const Observer& o, UtcTime t, const EarthOrientation& eo) {
  StateVector sun;
  sun.r_km = sun_position_km(t);
  return look_angles(teme_to_ecef(sun, t, eo), o).el_deg;
}

bool in_eclipse(const Vec3& sat_teme_km, UtcTime t) {
  // Seen from the satellite, the Earth (a sphere of the WGS-84 equatorial radius) is a disc of
  // angular radius asin(R / |r|) around the direction -r. The Sun's centre is hidden when the angle
  // between -r and the direction to the Sun is smaller than that.
  const double r = norm(sat_teme_km);
  if (r <= kWgs84A_km) return true;  // inside the Earth: no sunlight
  const Vec3 to_sun = sub(sun_position_km(t), sat_teme_km);
  const Vec3 to_earth = {-sat_teme_km[0], -sat_teme_km[1], -sat_teme_km[2]};
  const double cos_sep = dot(to_sun, to_earth) / (norm(to_sun) * r);
  const double sep = std::acos(std::clamp(cos_sep, -1.0, 1.0));
  return sep < std::asin(kWgs84A_km / r);
}

bool visible(const Observation& obs, const Observer& o, const EarthOrientation& eo) {
  if (!obs.ok() || obs.look.el_deg < 0.0) return false;
  if (in_eclipse(obs.teme.r_km, obs.time)) return false;
  return sun_elevation_deg(o, obs.time, eo) < kVisibleSunMaxElevationDeg;
}

}  // namespace tb::orbit
