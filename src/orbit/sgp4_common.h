// Arithmetic that the scalar propagator (sgp4.cpp) and the batch kernel (sgp4_batch.cpp) share,
// written once (private to src/orbit). Always inline: the kernel's loops over lanes must stay simple
// loops the compiler vectorises, and the scalar code keeps its results to the bit.
#pragma once
#include <cmath>
#include <cstdint>

namespace tb::orbit::detail {

struct SinCos {
  double s, c;
};

// sin and cos without a branch or a library call: Cody-Waite reduction to [-pi/4, pi/4] with pi/2 in
// two parts (fdlibm's pio2_1, pio2_1t; the first has 33 bits, so n * it is exact for |n| < 2^20, i.e.
// |x| < 1.6e6 rad) and fdlibm's kernel polynomials (below 1 ulp there), the quadrant by selects. A
// loop over lanes of it vectorises; in scalar code it is a few times cheaper than libm's sincos.
inline constexpr double kReducibleAngle = 1.6e6;  // rad: |x| up to this is reduced exactly enough
[[gnu::always_inline]] inline SinCos poly_sin_cos(double x) {
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kPio2Hi = 1.57079632673412561417e+00;
  constexpr double kPio2Lo = 6.07710050650619224932e-11;
  constexpr double kRoundMagic = 0x1.8p52;  // (x + magic) - magic rounds to an integer, |x| < 2^51
  const double n = (x * kTwoOverPi + kRoundMagic) - kRoundMagic;
  const double r = (x - n * kPio2Hi) - n * kPio2Lo;
  const double z = r * r;
  const double s = r + r * z *
                           (-1.66666666666666324348e-01 +
                            z * (8.33333333332248946124e-03 +
                                 z * (-1.98412698298579493134e-04 +
                                      z * (2.75573137070700676789e-06 +
                                           z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)))));
  const double c = 1.0 - 0.5 * z +
                   z * z *
                       (4.16666666666666019037e-02 +
                        z * (-1.38888888888741095749e-03 +
                             z * (2.48015872894767294178e-05 +
                                  z * (-2.75573143513906633035e-07 +
                                       z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
  const double q = n - 4.0 * std::floor(n * 0.25);  // quadrant 0..3
  const bool odd = q == 1.0 || q == 3.0;
  const double sin_abs = odd ? c : s;
  const double cos_abs = odd ? s : c;
  return {q >= 2.0 ? -sin_abs : sin_abs, (q == 1.0 || q == 2.0) ? -cos_abs : cos_abs};
}

// sin d and cos d for |d| < 2e-3 (kSmallAngle) by a short series, exact to rounding there: the
// propagator's corrections to angles whose sine and cosine are known are mostly that small. The
// coefficients multiply (a division by 6, 12 or 20 would not be replaced by one, and its latency
// sits on the propagator's longest chain).
inline constexpr double kSmallAngle = 2e-3;
[[gnu::always_inline]] inline SinCos small_angle_sin_cos(double d) {
  const double d2 = d * d;
  return {d * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0))), 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0))};
}

// Remainder of x / 2pi with the sign of x, exactly C's fmod(x, 2pi), which the reference uses
// throughout. fmod is exact, so it returns x itself when |x| < 2pi. Below 2^26 turns the remainder
// is x - k 2pi with k = trunc(x / 2pi), computed exactly without a call: 2pi split in a 26-bit and a
// 27-bit part makes both products exact, x - k hi is exact (Sterbenz), and the result, being
// representable, is what the last subtraction gives; a k one off (x / 2pi rounded across an integer)
// shows as a remainder outside [0, 2pi) and is corrected. unit_orbit compares it with fmod.
[[gnu::always_inline]] inline double fmod_two_pi(double x) {
  constexpr double kTwoPiDouble = 6.28318530717958647693;  // the double nearest 2pi
  constexpr double kHi = 0x1.921fb5p+2;      // 2pi's leading 26 bits
  constexpr double kLo = 0x1.110b46p-24;     // the rest: kHi + kLo == 2pi exactly
  static_assert(kHi + kLo == kTwoPiDouble);
  constexpr double kMaxTurns = 67108864.0;   // 2^26
  const double ax = std::fabs(x);
  if (ax < kTwoPiDouble) return x;
  if (!(ax < kMaxTurns * kTwoPiDouble)) return std::fmod(x, kTwoPiDouble);  // also NaN
  double k = static_cast<double>(static_cast<std::int64_t>(ax * (1.0 / kTwoPiDouble)));
  double r = (ax - k * kHi) - k * kLo;
  if (r < 0.0) {
    k -= 1.0;
    r = (ax - k * kHi) - k * kLo;
  } else if (r >= kTwoPiDouble) {
    k += 1.0;
    r = (ax - k * kHi) - k * kLo;
  }
  return x < 0.0 ? -r : r;
}

// The unit position vector u and the unit vector v along the track (the paper's ux, uy, uz and
// vx, vy, vz) from the argument of latitude, the node and the inclination (sines and cosines).
struct Orientation {
  double ux, uy, uz, vx, vy, vz;
};
[[gnu::always_inline]] inline Orientation orientation(SinCos s, SinCos node, SinCos inc) {
  const double xmx = -node.s * inc.c;
  const double xmy = node.c * inc.c;
  const double ux = xmx * s.s + node.c * s.c;
  const double uy = xmy * s.s + node.s * s.c;
  const double uz = inc.s * s.s;
  const double vx = xmx * s.c - node.c * s.s;
  const double vy = xmy * s.c - node.s * s.s;
  const double vz = inc.s * s.c;
  return {ux, uy, uz, vx, vy, vz};
}

}  // namespace tb::orbit::detail
