// The Sun and the Moon as targets: where they are from a station (topocentric azimuth, elevation,
// range and range rate), the Moon's self-echo Doppler, atmospheric refraction, and their rise,
// culmination and set. Pure functions: values in, values out. How accurate: docs/calibration.md.
//
// Use:
//   const auto body = parse_body("moon");                        // Body::moon
//   LookAngles la = body_look(*body, observer, now);              // where to point (geometric)
//   double el = la.el_deg + refraction_deg(la.el_deg);           // optical elevation, if wanted
//   double shift = eme_echo_doppler_hz(144.1e6, la.range_rate_km_s);  // EME echo offset
//   auto p = next_body_pass(*body, observer, now);                // rise (aos), culmination (tca), set (los)
#pragma once
#include <optional>
#include <string_view>
#include <vector>

#include "orbit/observe.h"
#include "orbit/passes.h"

namespace tb::orbit {

enum class Body { sun, moon };

// "SUN" or "MOON": the names the command line and the menus use.
std::string_view body_name(Body b);
// SUN or MOON in any case, nothing else (surrounding blanks not trimmed).
std::optional<Body> parse_body(std::string_view name);

// Geocentric position (km) and velocity (km/s) in the frame of SGP4's states (TEME), so that
// teme_to_ecef and look_angles apply as for a satellite. The Sun: sun_position_km (Vallado's
// Algorithm 29); the Moon: moon_state_teme (Meeus chapter 47, orbit/moon.h). Velocities are central
// differences over +-30 s.
StateVector body_state_teme(Body b, UtcTime t);

// Topocentric look angles of the body's centre from the station: azimuth and elevation as seen from
// the station itself (the Moon's parallax, up to about 1 deg, included), geometric (no
// refraction), range from the station and range rate (+ receding) in the Earth-fixed frame.
LookAngles body_look(Body b, const Observer& o, UtcTime t, const EarthOrientation& eo = {});

// Self-echo Doppler of a signal sent at freq_hz and reflected by a body whose range from the
// station changes at range_rate_km_s (+ receding): -2 f rdot / c (the first-order round trip; EME).
double eme_echo_doppler_hz(double freq_hz, double range_rate_km_s);

// Atmospheric refraction, degrees, for optical pointing near the horizon (radio refraction is
// larger and weather-dependent; trakbox points at geometric positions unless asked).
// refraction_deg: how much the air lifts a body at geometric (true) elevation true_el_deg
// (Saemundsson 1986, as in Meeus eq. 16.4), scaled by pressure/1010 hPa and 283 K/(273 + temperature).
// Elevations below -1 deg take the value at -1 deg (the formula's pole is at -5.1 deg).
double refraction_deg(double true_el_deg, double pressure_hpa = 1010.0, double temperature_c = 10.0);
// The inverse direction (Bennett 1982, Meeus eq. 16.3): the lift to remove from an apparent
// (observed) elevation to get the geometric one. Same scaling and floor.
double refraction_from_apparent_deg(double apparent_el_deg, double pressure_hpa = 1010.0,
                                    double temperature_c = 10.0);

// Rises, culminations and sets of the body's centre overlapping [start, stop), as satellite passes
// are reported: aos = rise (the crossing of options.horizon_deg upward), tca = culmination (the
// highest elevation of that stretch), los = set; up_at_start / up_at_end as for satellites.
// Geometric elevations (no refraction), so the Sun's "rise" at 0 deg is its centre on the
// geometric horizon, not the almanac's sunrise (-0.833 deg). The search samples every 10 minutes,
// also catches a stretch above the horizon shorter than that (a grazing Moon near the poles) by
// refining every local maximum, and refines crossings to options.precision_s.
std::vector<Pass> find_body_passes(Body b, const Observer& o, UtcTime start, UtcTime stop,
                                   const PassOptions& options = {}, const EarthOrientation& eo = {});
// The next stretch above the horizon reaching options.min_max_elevation_deg, within max_days; one in
// progress at `from` counts (up_at_start, aos = from).
std::optional<Pass> next_body_pass(Body b, const Observer& o, UtcTime from, double max_days = 3.0,
                                   const PassOptions& options = {}, const EarthOrientation& eo = {});

}  // namespace tb::orbit
