// The Moon's geocentric position: Meeus, Astronomical Algorithms (2nd ed. 1998), chapter 47, the
// truncated ELP-2000/82 series (all of tables 47.A and 47.B), with the low-accuracy nutation of
// chapter 22. Meeus gives about 10" in longitude and 4" in latitude. Pure functions.
//
// Time: the series runs in Terrestrial Time (Meeus's TD). UtcTime is POSIX UTC, so
// terrestrial_jd() adds TT - UTC = 32.184 s + TAI - UTC (the leap seconds since 1972; the table
// ends with the one of 2017-01-01). Skipping the 69 s would put the Moon 0.01 deg off.
#pragma once
#include "orbit/observe.h"
#include "orbit/time.h"

namespace tb::orbit {

// TAI - UTC in seconds at t (10 before 1972; the last leap second in the table is 2017-01-01).
double tai_minus_utc_s(UtcTime t);
// Julian Ephemeris Day (TT) of a UTC time.
JulianDate terrestrial_jd(UtcTime t);

// Nutation in longitude and obliquity (Meeus 22, low accuracy: 0.5" and 0.1"), the mean and
// true obliquity, all in degrees, at Julian centuries T from J2000.0 (TT).
struct Nutation {
  double dpsi_deg = 0.0;
  double deps_deg = 0.0;
  double mean_obliquity_deg = 0.0;
  double true_obliquity_deg = 0.0;
};
Nutation nutation(double centuries_tt);

struct MoonPosition {
  double longitude_deg = 0.0;           // geometric ecliptic longitude, mean equinox of date, [0, 360)
  double latitude_deg = 0.0;            // ecliptic latitude
  double distance_km = 0.0;             // centre of the Earth to centre of the Moon
  double apparent_longitude_deg = 0.0;  // longitude + nutation in longitude, [0, 360)
  double ra_deg = 0.0;                  // apparent right ascension (true equator and equinox), [0, 360)
  double dec_deg = 0.0;                 // apparent declination
  double equation_of_equinoxes_deg = 0.0;  // dpsi cos(eps): apparent minus mean sidereal time
};

// The Moon at a Julian Ephemeris Day (TT), as Meeus's example 47.a computes it.
MoonPosition moon_position(JulianDate jde);
// The Moon at a UTC time.
MoonPosition moon_position(UtcTime t);

// The Moon's geocentric position, km, in TEME (below); position only, for searches.
Vec3 moon_position_teme_km(UtcTime t);

// The Moon's geocentric position in km in the frame trakbox's look angles start from (TEME: true
// equator, mean equinox; what teme_to_ecef rotates by GMST), with its velocity in km/s (a central
// difference over +-30 s).
StateVector moon_state_teme(UtcTime t);

}  // namespace tb::orbit
