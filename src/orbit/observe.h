// From a TEME state to what a ground station sees: Earth-fixed frame, WGS-84 station, look angles,
// range rate, sub-satellite point, orbital phase, Doppler, Sun, eclipse and visibility.
// Pure functions: values in, values out.
#pragma once
#include "orbit/sgp4.h"

namespace tb::orbit {

inline constexpr double kAosThresholdDeg = -2.0;          // the manual's AOS rule
inline constexpr double kSpeedOfLightKmS = 299792.458;
inline constexpr double kWgs84A_km = 6378.137;                 // WGS-84 equatorial radius
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;
inline constexpr double kEarthRotationRadS = 7.292115146706979e-5;  // as Vallado's teme2ecef
inline constexpr double kAstronomicalUnitKm = 149597870.7;
inline constexpr double kVisibleSunMaxElevationDeg = -12.0;   // nautical twilight

// A station on the WGS-84 ellipsoid. Height in metres (the manual's "above sea level"; the
// ellipsoid stands in for sea level, see docs/orbit.md).
struct Observer {
  double lat_deg = 0.0;   // + north
  double lon_deg = 0.0;   // + east
  double height_m = 0.0;
};

struct Geodetic {
  double lat_deg = 0.0;
  double lon_deg = 0.0;   // (-180, 180]
  double alt_km = 0.0;    // above the WGS-84 ellipsoid
};

struct LookAngles {
  double az_deg = 0.0;            // [0, 360), from north through east
  double el_deg = 0.0;
  double range_km = 0.0;
  double range_rate_km_s = 0.0;   // + receding
};

// Earth orientation: UT1 - UTC in seconds (DUT1, |DUT1| < 0.9 s). Default 0.
struct EarthOrientation {
  double dut1_s = 0.0;
};

// TEME -> Earth-fixed (pseudo-Earth-fixed: GMST-82 rotation, no polar motion), with velocity.
StateVector teme_to_ecef(const StateVector& teme, UtcTime t, const EarthOrientation& eo = {});
Vec3 observer_ecef_km(const Observer& o);
Geodetic ecef_to_geodetic(const Vec3& r_km);
LookAngles look_angles(const StateVector& ecef, const Observer& o);

// Mean anomaly at t in 256ths of an orbit (AMSAT "phase"), [0, 256).
double phase256(const Elements& e, UtcTime t);

// Shift heard on the ground for a signal sent at freq_hz by a source moving at range_rate (+ away).
double doppler_shift_hz(double freq_hz, double range_rate_km_s);

struct Observation {
  UtcTime time{};
  Sgp4Error error = Sgp4Error::none;  // when not none, nothing below is valid
  StateVector teme;
  LookAngles look;
  Geodetic sub_point;
  double phase256 = 0.0;
  bool ok() const { return error == Sgp4Error::none; }
};

Observation observe(const Sgp4& sat, const Observer& o, UtcTime t, const EarthOrientation& eo = {});
// observe() for a propagation already made at t (by the batch propagator, orbit/sgp4_batch.h).
Observation observe(const Sgp4& sat, const Observer& o, UtcTime t, const Propagation& p,
                    const EarthOrientation& eo = {});

// The Sun: low-precision solar coordinates (Astronomical Almanac, as in Vallado Algorithm 29),
// position in TEME-aligned equatorial km (the difference to TEME is far below this model's error).
Vec3 sun_position_km(UtcTime t);
// Sun elevation at the observer, degrees.
double sun_elevation_deg(const Observer& o, UtcTime t, const EarthOrientation& eo = {});
// True when the Earth hides the Sun's centre, seen from the satellite (cylindrical-free conical test).
bool in_eclipse(const Vec3& sat_teme_km, UtcTime t);
// Optically visible: satellite above the horizon and sunlit, Sun below -12 deg at the station.
bool visible(const Observation& obs, const Observer& o, const EarthOrientation& eo = {});

}  // namespace tb::orbit
