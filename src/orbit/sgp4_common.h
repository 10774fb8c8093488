// Arithmetic that the scalar propagator (sgp4.cpp) and the batch kernel (sgp4_batch.cpp) share,
// written once (private to src/orbit). Always inline: the kernel's loops over lanes must stay simple
// loops the compiler vectorises, and the scalar code keeps its results to the bit.
#pragma once
#include <cmath>

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
