// What sgp4.cpp (the model and the propagator) and sgp4_deep.cpp (the deep-space set-up) share:
// the WGS-72 and lunar-solar constants, the sine, cosine, angle addition and fmod the propagator
// uses, and the deep-space (SDP4) part of the model with the functions that build it. Private to
// src/orbit.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "orbit/constants.h"
#include "orbit/sgp4_common.h"

namespace tb::orbit::sgp4_internal {

using wgs72::kJ2;
using wgs72::kJ3;
using wgs72::kJ4;
using wgs72::kKmPerSecPerErPerMin;  // velocity unit
using wgs72::kXke;
inline constexpr double kEarthRadiusKm = wgs72::kRadiusKm;
inline constexpr double kTwoThirds = 2.0 / 3.0;
inline constexpr double kMinutesPerTimeUnit = 1.0 / kXke;  // tumin
inline constexpr double kJ3OverJ2 = kJ3 / kJ2;

// Element-set units: rev/day -> rad/min.
inline constexpr double kRevPerDayPerRadPerMin = 1440.0 / kTwoPi;  // xpdotp

// Below this |1 + cos i| the J3 long-period terms use a fixed divisor (i = 180 deg guard).
inline constexpr double kRetrogradeGuard = 1.5e-12;
// Orbits with a period of 225 minutes or more get the deep-space (SDP4) treatment.
inline constexpr double kDeepSpacePeriodMinutes = 225.0;
// Julian date of 1949 Dec 31 00:00 UT, the origin of SGP4's "epoch" day count.
inline constexpr double kSgp4EpochJd = 2433281.5;

// Lunar and solar constants.
inline constexpr double kSolarMeanMotion = 1.19459e-5;   // zns, rad/min
inline constexpr double kSolarEccentricity = 0.01675;    // zes
inline constexpr double kLunarMeanMotion = 1.5835218e-4; // znl, rad/min
inline constexpr double kLunarEccentricity = 0.05490;    // zel

// Earth rotation rate, rad/min (7.29211514668855e-5 rad/s).
inline constexpr double kEarthRotationRadPerMin = 4.37526908801129966e-3;  // rptim

// Resonance integrator step (minutes) and its half-square (step^2 / 2).
inline constexpr double kResonanceStep = 720.0;
inline constexpr double kResonanceStepSquaredHalf = 259200.0;
// Integrator checkpoints (DeepSpace::ahead/behind): one every step (12 hours), over 366 days each
// way (about 58 kB and 1,464 integrator steps per resonant set, once). Inside that span a
// propagation integrates no step at all (the state at the checkpoint is the loop's at that step);
// beyond it, the integration goes on from the last.
inline constexpr std::size_t kCheckpointStride = 1;
inline constexpr std::size_t kCheckpointSteps = 732;

// fmod(x, 2pi), exactly, as the reference computes it throughout (detail::fmod_two_pi).
[[gnu::always_inline]] inline double wrap_two_pi(double x) { return detail::fmod_two_pi(x); }

using detail::SinCos;
// sin and cos by detail::poly_sin_cos (inline, a few times cheaper than libm's sincos, within an ulp
// of it), by libm beyond the angles it reduces exactly enough (times decades from epoch).
[[gnu::always_inline]] inline SinCos sin_cos(double x) {
  if (std::fabs(x) < detail::kReducibleAngle) [[likely]]
    return detail::poly_sin_cos(x);
  return {std::sin(x), std::cos(x)};
}

// sin and cos of (a + d) from those of a. The propagator's corrections are mostly tiny, and then a
// short series for sin d and cos d (exact to rounding for |d| < 2e-3) saves a libm call.
[[gnu::always_inline]] inline SinCos add_angle(SinCos a, double d) {
  const SinCos e = std::fabs(d) < detail::kSmallAngle ? detail::small_angle_sin_cos(d) : sin_cos(d);
  return {a.s * e.c + a.c * e.s, a.c * e.c - a.s * e.s};
}

// Greenwich mean sidereal time (IAU-82) from a single Julian date, as the reference computes the
// sidereal angle at epoch (sgp4_deep.cpp).
double gstime(double jdut1);

enum class Resonance { none, one_day, half_day };

// One third body's terms at epoch: the paper's s1 ... s7 and z1 ... z33 for the Moon, the same
// quantities for the Sun under the names ss1 ... ss7 and sz1 ... sz33.
struct BodyTerms {
  double s1, s2, s3, s4, s5, s6, s7;
  double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

// Coefficients of one body's long-period periodics: the paper's se2, se3, si2, si3, sl2, sl3, sl4,
// sgh2, sgh3, sgh4, sh2, sh3 for the Sun and ee2, e3, xi2, xi3, xl2, xl3, xl4, xgh2, xgh3, xgh4, xh2,
// xh3 for the Moon (zero at epoch by construction).
struct BodyPeriodics {
  double e2 = 0, e3 = 0, i2 = 0, i3 = 0, l2 = 0, l3 = 0, l4 = 0, gh2 = 0, gh3 = 0, gh4 = 0, h2 = 0, h3 = 0;
};

// The same formulas for either body, from its terms and its eccentricity (zes, zel).
BodyPeriodics body_periodics(const BodyTerms& b, double emsq, double eccentricity);

struct LunarSolarPeriodics {
  BodyPeriodics solar, lunar;
  double zmol = 0, zmos = 0;  // lunar and solar mean anomalies at epoch
};

// Everything of the deep-space common terms that the secular-rate and resonance set-up needs.
struct DeepSpaceCommon {
  double sinim, cosim, emsq;
  BodyTerms moon, sun;  // the paper's s*, z* and ss*, sz*
};

// The deep-space (SDP4) part of the model.
struct DeepSpace {
  LunarSolarPeriodics periodics;
  // Secular lunar-solar rates of e, i, M, node, argument of perigee (per minute).
  double dedt = 0, didt = 0, dmdt = 0, dnodt = 0, domdt = 0;
  double gsto = 0;  // Greenwich sidereal angle at epoch, rad
  Resonance resonance = Resonance::none;
  // Half-day resonance coefficients.
  double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0, d4422 = 0;
  double d5220 = 0, d5232 = 0, d5421 = 0, d5433 = 0;
  // One-day (synchronous) resonance coefficients.
  double del1 = 0, del2 = 0, del3 = 0;
  double xfact = 0, xlamo = 0;
  // Rates of the resonance integrator's state (mean motion xni and mean longitude xli).
  struct Rates {
    double xndt = 0, xldot = 0, xnddt = 0;
  };
  Rates rates_at_epoch;  // the integrator's first evaluation, the same for every call
  // The integrator's state after every kCheckpointStride steps ahead of epoch (ahead[j]: after
  // (j + 1) * stride steps) and behind it, computed once with the model. A propagation starts from
  // the last checkpoint the integration from epoch would pass and takes the same steps from there,
  // so its result is bit-identical to integrating from epoch, at a cost that no longer grows with the
  // age of the elements (within the checkpoints' span).
  struct IntegratorState {
    double xli = 0, xni = 0;
    Rates r;
  };
  std::vector<IntegratorState> ahead, behind;
};

// Lunar-solar terms common to the secular and periodic deep-space effects, at epoch.
DeepSpaceCommon deep_space_common(double epoch, double ep, double argpp, double inclp, double nodep,
                                  double np, LunarSolarPeriodics& out);

// Epoch quantities the deep-space set-up takes from the near-earth initialisation.
struct DeepSpaceInputs {
  double ecco, eccsq, inclo, argpo, mo, nodeo, no;  // mean elements (no un-Kozai'd)
  double mdot, nodedot, xpidot;                     // secular rates
};

// Secular lunar-solar rates and the geopotential resonance terms (half-day and one-day orbits).
void deep_space_secular(const DeepSpaceInputs& in, const DeepSpaceCommon& c, DeepSpace& ds);

// Mean elements as they evolve between the secular update and the periodics.
struct MeanElements {
  double em, argpm, inclm, mm, nodem, nm;
};

// Derivatives of the resonance integrator's state: mean motion xni and mean longitude xli at
// atime minutes from epoch.
DeepSpace::Rates resonance_rates(const DeepSpace& ds, double xli, double xni, double atime,
                                 double argpo, double argpdot);

// The integrator's state after n steps of delt from epoch (n = 0, 1, 2, ...; atime = n * delt).
void resonance_step(const DeepSpace& ds, double& xli, double& xni, double& atime, DeepSpace::Rates& r,
                    double delt, double argpo, double argpdot);

// The checkpoints (DeepSpace::ahead/behind) for t, computed once per model.
void build_checkpoints(DeepSpace& ds, double no, double argpo, double argpdot);

}  // namespace tb::orbit::sgp4_internal
