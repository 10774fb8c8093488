// Vector arithmetic and the topocentric frame, shared by observe.cpp and the pass search (private
// to src/orbit). look_from is the one place where a line of sight becomes azimuth, elevation and
// range: look_angles() and the pass search's look() both call it, so they agree to the bit.
#pragma once
#include <cmath>

#include "orbit/constants.h"
#include "orbit/observe.h"

namespace tb::orbit::detail {

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Angle in degrees reduced to [0, 360).
inline double wrap360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r = 0.0;  // fmod of a tiny negative can round up to exactly 360
  return r;
}

// A station's topocentric frame: sines and cosines of its geodetic latitude and longitude.
struct StationFrame {
  double sl = 0.0, cl = 1.0, so = 0.0, co = 1.0;
};
inline StationFrame station_frame(const Observer& o) {
  const double lat = o.lat_deg * kDegToRad, lon = o.lon_deg * kDegToRad;
  return {std::sin(lat), std::cos(lat), std::sin(lon), std::cos(lon)};
}

// Look angles along the Earth-fixed line of sight rho (km) changing at rho_dot (km/s), from a station
// with frame f. Only range and azimuth unless `all`.
inline LookAngles look_from(const Vec3& rho, const Vec3& rho_dot, const StationFrame& f, bool all = true) {
  // Topocentric south-east-zenith components.
  const double s = f.sl * f.co * rho[0] + f.sl * f.so * rho[1] - f.cl * rho[2];
  const double e = -f.so * rho[0] + f.co * rho[1];
  const double z = f.cl * f.co * rho[0] + f.cl * f.so * rho[1] + f.sl * rho[2];
  LookAngles la;
  la.range_km = norm(rho);
  if (la.range_km <= 0.0) return la;
  la.az_deg = (e == 0.0 && s == 0.0) ? 0.0 : wrap360(std::atan2(e, -s) / kDegToRad);
  if (!all) return la;
  // asin(Z / range) written as atan2: the same angle, without asin's loss of precision near the
  // zenith (asin(1 - 1e-16) is 8e-7 deg short of 90).
  la.el_deg = std::atan2(z, std::hypot(s, e)) / kDegToRad;
  la.range_rate_km_s = dot(rho, rho_dot) / la.range_km;
  return la;
}

}  // namespace tb::orbit::detail
