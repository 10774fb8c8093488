#include <doctest/doctest.h>

#include <cmath>

#include "orbit/moon.h"

using namespace tb::orbit;

TEST_CASE("Moon: Meeus example 47.a, 1992 April 12 0h TD") {
  // Meeus, Astronomical Algorithms (2nd ed., 1998), example 47.a: JDE 2448724.5 gives
  // lambda = 133.162655 deg, beta = -3.229126 deg, Delta = 368409.7 km; with dpsi = +0.004610 deg
  // the apparent lambda = 133.167265 deg, and with eps = 23.440636 deg the apparent
  // alpha = 134.688470 deg, delta = 13.768368 deg.
  const MoonPosition p = moon_position(JulianDate{2448724.5, 0.0});
  CHECK(std::abs(p.longitude_deg - 133.162655) < 2e-6);
  CHECK(std::abs(p.latitude_deg - -3.229126) < 2e-6);
  CHECK(std::abs(p.distance_km - 368409.7) < 0.1);
  // The apparent place uses chapter 22's low-accuracy nutation (0.5" in dpsi, 0.1" in deps): within
  // 0.0002 deg of Meeus's full-series figures.
  CHECK(std::abs(p.apparent_longitude_deg - 133.167265) < 2e-4);
  CHECK(std::abs(p.ra_deg - 134.688470) < 2e-4);
  CHECK(std::abs(p.dec_deg - 13.768368) < 2e-4);
}

TEST_CASE("Nutation: Meeus example 22.a, 1987 April 10 0h TD") {
  // Meeus example 22.a (full series): dpsi = -3.788", deps = +9.443", eps0 = 23 deg 26' 27.407",
  // eps = 23 deg 26' 36.850". The low-accuracy terms are within 0.5" and 0.1"; eps0 is exact.
  const double t = (2446895.5 - 2451545.0) / 36525.0;
  const Nutation n = nutation(t);
  CHECK(std::abs(n.dpsi_deg * 3600.0 - -3.788) < 0.5);
  CHECK(std::abs(n.deps_deg * 3600.0 - 9.443) < 0.1);
  CHECK(std::abs(n.mean_obliquity_deg - (23.0 + 26.0 / 60.0 + 27.407 / 3600.0)) < 0.001 / 3600.0);
  CHECK(std::abs(n.true_obliquity_deg - (23.0 + 26.0 / 60.0 + 36.850 / 3600.0)) < 0.1 / 3600.0);
}

TEST_CASE("TAI - UTC steps at the leap seconds (IERS Bulletin C)") {
  CHECK(tai_minus_utc_s(from_civil(1970, 1, 1)) == 10.0);
  CHECK(tai_minus_utc_s(from_civil(1998, 12, 31, 23, 59, 59.0)) == 31.0);
  CHECK(tai_minus_utc_s(from_civil(1999, 1, 1)) == 32.0);
  CHECK(tai_minus_utc_s(from_civil(2016, 12, 31, 23, 59, 59.0)) == 36.0);
  CHECK(tai_minus_utc_s(from_civil(2017, 1, 1)) == 37.0);
  CHECK(tai_minus_utc_s(from_civil(2026, 12, 7)) == 37.0);
  // TT = UTC + 37 s + 32.184 s in 2026.
  const JulianDate tt = terrestrial_jd(from_civil(2026, 1, 1));
  const JulianDate utc = julian_date(from_civil(2026, 1, 1));
  CHECK(std::abs((tt.value() - utc.value()) * 86400.0 - 69.184) < 1e-4);
}

TEST_CASE("Moon: TEME state is the apparent place turned by the equation of the equinoxes") {
  const UtcTime t = from_civil(2026, 5, 21, 18, 0);
  const MoonPosition p = moon_position(t);
  const StateVector s = moon_state_teme(t);
  const double r = std::sqrt(s.r_km[0] * s.r_km[0] + s.r_km[1] * s.r_km[1] + s.r_km[2] * s.r_km[2]);
  CHECK(std::abs(r - p.distance_km) < 1e-6);
  const double ra = std::atan2(s.r_km[1], s.r_km[0]) * 180.0 / 3.141592653589793;
  const double expected = p.ra_deg - p.equation_of_equinoxes_deg;
  CHECK(std::abs(std::remainder(ra - expected, 360.0)) < 1e-9);
  // The Moon moves about 1 km/s around the Earth.
  const double v = std::sqrt(s.v_km_s[0] * s.v_km_s[0] + s.v_km_s[1] * s.v_km_s[1] + s.v_km_s[2] * s.v_km_s[2]);
  CHECK(v > 0.95);
  CHECK(v < 1.1);
}
