// Meeus chapter 47 (the Moon) and chapter 22 (nutation, low accuracy). The periodic terms are
// Meeus's tables 47.A and 47.B in full; each row is the multiples of D, M, M', F and the
// coefficient(s). Checked against Meeus's worked example 47.a in tests/unit/orbit/test_moon.cpp.
#include "orbit/moon.h"

#include <array>
#include <cmath>
#include <cstdlib>

#include "orbit/constants.h"
#include "orbit/geometry.h"

namespace tb::orbit {
namespace {

using detail::wrap360;

// TAI - UTC from each leap second on (IERS Bulletin C; none announced after 2017-01-01).
struct LeapStep {
  int year, month;
  double tai_minus_utc_s;
};
constexpr std::array<LeapStep, 28> kLeapSteps{{
    {1972, 1, 10}, {1972, 7, 11}, {1973, 1, 12}, {1974, 1, 13}, {1975, 1, 14}, {1976, 1, 15},
    {1977, 1, 16}, {1978, 1, 17}, {1979, 1, 18}, {1980, 1, 19}, {1981, 7, 20}, {1982, 7, 21},
    {1983, 7, 22}, {1985, 7, 23}, {1988, 1, 24}, {1990, 1, 25}, {1991, 1, 26}, {1992, 7, 27},
    {1993, 7, 28}, {1994, 7, 29}, {1996, 1, 30}, {1997, 7, 31}, {1999, 1, 32}, {2006, 1, 33},
    {2009, 1, 34}, {2012, 7, 35}, {2015, 7, 36}, {2017, 1, 37},
}};

constexpr double kTtMinusTaiS = 32.184;

// Table 47.A: D, M, M', F, coefficient of sin in the sum for longitude (1e-6 deg), coefficient of
// cos in the sum for distance (1e-3 km).
struct LrTerm {
  signed char d, m, mp, f;
  int l, r;
};
constexpr std::array<LrTerm, 60> kLr{{
    {0, 0, 1, 0, 6288774, -20905355}, {2, 0, -1, 0, 1274027, -3699111}, {2, 0, 0, 0, 658314, -2955968},
    {0, 0, 2, 0, 213618, -569925},    {0, 1, 0, 0, -185116, 48888},     {0, 0, 0, 2, -114332, -3149},
    {2, 0, -2, 0, 58793, 246158},     {2, -1, -1, 0, 57066, -152138},   {2, 0, 1, 0, 53322, -170733},
    {2, -1, 0, 0, 45758, -204586},    {0, 1, -1, 0, -40923, -129620},   {1, 0, 0, 0, -34720, 108743},
    {0, 1, 1, 0, -30383, 104755},     {2, 0, 0, -2, 15327, 10321},      {0, 0, 1, 2, -12528, 0},
    {0, 0, 1, -2, 10980, 79661},      {4, 0, -1, 0, 10675, -34782},     {0, 0, 3, 0, 10034, -23210},
    {4, 0, -2, 0, 8548, -21636},      {2, 1, -1, 0, -7888, 24208},      {2, 1, 0, 0, -6766, 30824},
    {1, 0, -1, 0, -5163, -8379},      {1, 1, 0, 0, 4987, -16675},       {2, -1, 1, 0, 4036, -12831},
    {2, 0, 2, 0, 3994, -10445},       {4, 0, 0, 0, 3861, -11650},       {2, 0, -3, 0, 3665, 14403},
    {0, 1, -2, 0, -2689, -7003},      {2, 0, -1, 2, -2602, 0},          {2, -1, -2, 0, 2390, 10056},
    {1, 0, 1, 0, -2348, 6322},        {2, -2, 0, 0, 2236, -9884},       {0, 1, 2, 0, -2120, 5751},
    {0, 2, 0, 0, -2069, 0},           {2, -2, -1, 0, 2048, -4950},      {2, 0, 1, -2, -1773, 4130},
    {2, 0, 0, 2, -1595, 0},           {4, -1, -1, 0, 1215, -3958},      {0, 0, 2, 2, -1110, 0},
    {3, 0, -1, 0, -892, 3258},        {2, 1, 1, 0, -810, 2616},         {4, -1, -2, 0, 759, -1897},
    {0, 2, -1, 0, -713, -2117},       {2, 2, -1, 0, -700, 2354},        {2, 1, -2, 0, 691, 0},
    {2, -1, 0, -2, 596, 0},           {4, 0, 1, 0, 549, -1423},         {0, 0, 4, 0, 537, -1117},
    {4, -1, 0, 0, 520, -1571},        {1, 0, -2, 0, -487, -1739},       {2, 1, 0, -2, -399, 0},
    {0, 0, 2, -2, -381, -4421},       {1, 1, 1, 0, 351, 0},             {3, 0, -2, 0, -340, 0},
    {4, 0, -3, 0, 330, 0},            {2, -1, 2, 0, 327, 0},            {0, 2, 1, 0, -323, 1165},
    {1, 1, -1, 0, 299, 0},            {2, 0, 3, 0, 294, 0},             {2, 0, -1, -2, 0, 8752},
}};

// Table 47.B: D, M, M', F, coefficient of sin in the sum for latitude (1e-6 deg).
struct BTerm {
  signed char d, m, mp, f;
  int b;
};
constexpr std::array<BTerm, 60> kB{{
    {0, 0, 0, 1, 5128122}, {0, 0, 1, 1, 280602}, {0, 0, 1, -1, 277693}, {2, 0, 0, -1, 173237},
    {2, 0, -1, 1, 55413},  {2, 0, -1, -1, 46271}, {2, 0, 0, 1, 32573},  {0, 0, 2, 1, 17198},
    {2, 0, 1, -1, 9266},   {0, 0, 2, -1, 8822},   {2, -1, 0, -1, 8216}, {2, 0, -2, -1, 4324},
    {2, 0, 1, 1, 4200},    {2, 1, 0, -1, -3359},  {2, -1, -1, 1, 2463}, {2, -1, 0, 1, 2211},
    {2, -1, -1, -1, 2065}, {0, 1, -1, -1, -1870}, {4, 0, -1, -1, 1828}, {0, 1, 0, 1, -1794},
    {0, 0, 0, 3, -1749},   {0, 1, -1, 1, -1565},  {1, 0, 0, 1, -1491},  {0, 1, 1, 1, -1475},
    {0, 1, 1, -1, -1410},  {0, 1, 0, -1, -1344},  {1, 0, 0, -1, -1335}, {0, 0, 3, 1, 1107},
    {4, 0, 0, -1, 1021},   {4, 0, -1, 1, 833},    {0, 0, 1, -3, 777},   {4, 0, -2, 1, 671},
    {2, 0, 0, -3, 607},    {2, 0, 2, -1, 596},    {2, -1, 1, -1, 491},  {2, 0, -2, 1, -451},
    {0, 0, 3, -1, 439},    {2, 0, 2, 1, 422},     {2, 0, -3, -1, 421},  {2, 1, -1, 1, -366},
    {2, 1, 0, 1, -351},    {4, 0, 0, 1, 331},     {2, -1, 1, 1, 315},   {2, -2, 0, -1, 302},
    {0, 0, 1, 3, -283},    {2, 1, 1, -1, -229},   {1, 1, 0, -1, 223},   {1, 1, 0, 1, 223},
    {0, 1, -2, -1, -220},  {2, 1, -1, -1, -220},  {1, 0, 1, 1, -185},   {2, -1, -2, -1, 181},
    {0, 1, 2, 1, -177},    {4, 0, -2, -1, 176},   {4, -1, -1, -1, 166}, {1, 0, 1, -1, -164},
    {4, 0, 1, -1, 132},    {1, 0, -1, -1, -119},  {4, -1, 0, -1, 115},  {2, -2, 0, 1, 107},
}};

double sin_deg(double deg) { return std::sin(deg * kDegToRad); }
double cos_deg(double deg) { return std::cos(deg * kDegToRad); }

// The terms with M are multiplied by E (|M| = 1) or E^2 (|M| = 2): the Earth's orbit's eccentricity
// decreasing.
double eccentricity_factor(int m, double e) {
  const int k = std::abs(m);
  return k == 1 ? e : (k == 2 ? e * e : 1.0);
}

// The fundamental arguments, degrees (Meeus 47.1 to 47.5).
struct LunarArguments {
  double lp, d, m, mp, f;
};
LunarArguments lunar_arguments(double t) {
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  return {
      wrap360(218.3164477 + 481267.88123421 * t - 0.0015786 * t2 + t3 / 538841.0 - t4 / 65194000.0),
      wrap360(297.8501921 + 445267.1114034 * t - 0.0018819 * t2 + t3 / 545868.0 - t4 / 113065000.0),
      wrap360(357.5291092 + 35999.0502909 * t - 0.0001536 * t2 + t3 / 24490000.0),
      wrap360(134.9633964 + 477198.8675055 * t + 0.0087414 * t2 + t3 / 69699.0 - t4 / 14712000.0),
      wrap360(93.2720950 + 483202.0175233 * t - 0.0036539 * t2 - t3 / 3526000.0 + t4 / 863310000.0),
  };
}

}  // namespace

double tai_minus_utc_s(UtcTime t) {
  double value = 10.0;
  for (const LeapStep& s : kLeapSteps) {
    if (t < from_civil(s.year, s.month, 1)) break;
    value = s.tai_minus_utc_s;
  }
  return value;
}

JulianDate terrestrial_jd(UtcTime t) { return julian_date(t, tai_minus_utc_s(t) + kTtMinusTaiS); }

Nutation nutation(double t) {
  const double omega = 125.04452 - 1934.136261 * t + 0.0020708 * t * t + t * t * t / 450000.0;
  const double l_sun = 280.4665 + 36000.7698 * t;
  const double l_moon = 218.3165 + 481267.8813 * t;
  Nutation n;
  n.dpsi_deg = (-17.20 * sin_deg(omega) - 1.32 * sin_deg(2 * l_sun) - 0.23 * sin_deg(2 * l_moon) +
                0.21 * sin_deg(2 * omega)) / 3600.0;
  n.deps_deg = (9.20 * cos_deg(omega) + 0.57 * cos_deg(2 * l_sun) + 0.10 * cos_deg(2 * l_moon) -
                0.09 * cos_deg(2 * omega)) / 3600.0;
  // Meeus 22.2: 23 deg 26' 21.448" - 46.8150" T - 0.00059" T^2 + 0.001813" T^3.
  n.mean_obliquity_deg = 23.0 + 26.0 / 60.0 +
                         (21.448 - 46.8150 * t - 0.00059 * t * t + 0.001813 * t * t * t) / 3600.0;
  n.true_obliquity_deg = n.mean_obliquity_deg + n.deps_deg;
  return n;
}

MoonPosition moon_position(JulianDate jde) {
  const double t = ((jde.whole - kJdJ2000) + jde.fraction) / 36525.0;
  const LunarArguments a = lunar_arguments(t);
  const double e = 1.0 - 0.002516 * t - 0.0000074 * t * t;
  double sum_l = 0.0, sum_r = 0.0, sum_b = 0.0;
  for (const LrTerm& k : kLr) {
    const double arg = k.d * a.d + k.m * a.m + k.mp * a.mp + k.f * a.f;
    const double ef = eccentricity_factor(k.m, e);
    sum_l += k.l * ef * sin_deg(arg);
    sum_r += k.r * ef * cos_deg(arg);
  }
  for (const BTerm& k : kB) {
    const double arg = k.d * a.d + k.m * a.m + k.mp * a.mp + k.f * a.f;
    sum_b += k.b * eccentricity_factor(k.m, e) * sin_deg(arg);
  }
  // Venus (A1), Jupiter (A2) and the Earth's flattening (A3).
  const double a1 = 119.75 + 131.849 * t, a2 = 53.09 + 479264.290 * t, a3 = 313.45 + 481266.484 * t;
  sum_l += 3958.0 * sin_deg(a1) + 1962.0 * sin_deg(a.lp - a.f) + 318.0 * sin_deg(a2);
  sum_b += -2235.0 * sin_deg(a.lp) + 382.0 * sin_deg(a3) + 175.0 * sin_deg(a1 - a.f) +
           175.0 * sin_deg(a1 + a.f) + 127.0 * sin_deg(a.lp - a.mp) - 115.0 * sin_deg(a.lp + a.mp);

  MoonPosition p;
  p.longitude_deg = wrap360(a.lp + sum_l / 1e6);
  p.latitude_deg = sum_b / 1e6;
  p.distance_km = 385000.56 + sum_r / 1000.0;
  const Nutation n = nutation(t);
  p.apparent_longitude_deg = wrap360(p.longitude_deg + n.dpsi_deg);
  // Ecliptic to equatorial (Meeus 13.3, 13.4) with the true obliquity.
  const double lam = p.apparent_longitude_deg * kDegToRad, beta = p.latitude_deg * kDegToRad;
  const double eps = n.true_obliquity_deg * kDegToRad;
  p.ra_deg = wrap360(std::atan2(std::sin(lam) * std::cos(eps) - std::tan(beta) * std::sin(eps),
                                std::cos(lam)) / kDegToRad);
  p.dec_deg = std::asin(std::sin(beta) * std::cos(eps) + std::cos(beta) * std::sin(eps) * std::sin(lam)) /
              kDegToRad;
  p.equation_of_equinoxes_deg = n.dpsi_deg * std::cos(eps);
  return p;
}

MoonPosition moon_position(UtcTime t) { return moon_position(terrestrial_jd(t)); }

// Geocentric TEME position: the apparent right ascension less the equation of the equinoxes is the
// right ascension from the mean equinox along the true equator, TEME's x axis.
Vec3 moon_position_teme_km(UtcTime t) {
  const MoonPosition p = moon_position(t);
  const double ra = (p.ra_deg - p.equation_of_equinoxes_deg) * kDegToRad;
  const double dec = p.dec_deg * kDegToRad;
  return {p.distance_km * std::cos(dec) * std::cos(ra), p.distance_km * std::cos(dec) * std::sin(ra),
          p.distance_km * std::sin(dec)};
}

StateVector moon_state_teme(UtcTime t) {
  constexpr double kHalfStepS = 30.0;
  const Vec3 before = moon_position_teme_km(add_seconds(t, -kHalfStepS));
  const Vec3 after = moon_position_teme_km(add_seconds(t, kHalfStepS));
  StateVector s;
  s.r_km = moon_position_teme_km(t);
  for (int i = 0; i < 3; ++i) s.v_km_s[i] = (after[i] - before[i]) / (2.0 * kHalfStepS);
  return s;
}

}  // namespace tb::orbit
