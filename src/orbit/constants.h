// The numbers the orbit code shares: pi and its multiples, and the WGS-72 Earth model that SGP4 is
// defined with (Vallado's "wgs72", improved mode). Private to src/orbit: one definition, bit for bit
// what sgp4.cpp, sgp4_batch.cpp, passes.cpp and observe.cpp each used to spell out.
#pragma once
#include <numbers>

namespace tb::orbit {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDegToRad = kPi / 180.0;

// WGS-72 as used by SGP4 ("wgs72", not the older "wgs72old" with a rounded xke):
// mu = 398600.8 km^3/s^2, equatorial radius 6378.135 km.
namespace wgs72 {
inline constexpr double kMu = 398600.8;            // km^3/s^2
inline constexpr double kRadiusKm = 6378.135;      // equatorial radius
// xke = 60 / sqrt(R^3 / mu), sqrt(earth radii^3 / mu) per minute. std::sqrt is not constexpr in
// C++20, so this is the value that expression gives in double arithmetic (as the reference computes
// it at run time): 60.0 / std::sqrt(6378.135 * 6378.135 * 6378.135 / 398600.8).
inline constexpr double kXke = 0x1.309b5d0b2444cp-4;  // 0.07436691613317342
inline constexpr double kJ2 = 0.001082616;
inline constexpr double kJ3 = -0.00000253881;
inline constexpr double kJ4 = -0.00000165597;
// SGP4's velocity unit (earth radii per minute) in km/s.
inline constexpr double kKmPerSecPerErPerMin = kRadiusKm * kXke / 60.0;
}  // namespace wgs72

}  // namespace tb::orbit
