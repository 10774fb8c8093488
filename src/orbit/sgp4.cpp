// SGP4/SDP4 after Vallado, Crawford, Hujsak, Kelso, "Revisiting Spacetrack Report #3"
// (AIAA 2006-6753), WGS-72 constants, improved operation mode. See docs/sgp4.md.
//
// Variable names follow the paper's code (ecco, nodeo, cc1, xlcof, d2201, ...) so that every line can
// be checked against it; the structure is ours: everything that depends only on the element set is
// computed once in the constructor and held in an immutable Model, and propagate_minutes() is a pure
// function of that model and the time. The deep-space resonance integrator restarts from epoch on
// every call; with its fixed 720-minute steps that produces the same numbers as the paper's cached
// integrator, without mutable state.
#include "orbit/sgp4.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "orbit/constants.h"
#include "orbit/sgp4_common.h"

namespace tb::orbit {
namespace {

using wgs72::kJ2;
using wgs72::kJ3;
using wgs72::kJ4;
using wgs72::kKmPerSecPerErPerMin;  // velocity unit
using wgs72::kXke;
constexpr double kEarthRadiusKm = wgs72::kRadiusKm;
constexpr double kTwoThirds = 2.0 / 3.0;
constexpr double kMinutesPerTimeUnit = 1.0 / kXke;  // tumin
constexpr double kJ3OverJ2 = kJ3 / kJ2;

// Element-set units: rev/day -> rad/min.
constexpr double kRevPerDayPerRadPerMin = 1440.0 / kTwoPi;  // xpdotp

// Below this |1 + cos i| the J3 long-period terms use a fixed divisor (i = 180 deg guard).
constexpr double kRetrogradeGuard = 1.5e-12;
// Orbits with a period of 225 minutes or more get the deep-space (SDP4) treatment.
constexpr double kDeepSpacePeriodMinutes = 225.0;
// Julian date of 1949 Dec 31 00:00 UT, the origin of SGP4's "epoch" day count.
constexpr double kSgp4EpochJd = 2433281.5;

// Lunar and solar constants.
constexpr double kSolarMeanMotion = 1.19459e-5;   // zns, rad/min
constexpr double kSolarEccentricity = 0.01675;    // zes
constexpr double kLunarMeanMotion = 1.5835218e-4; // znl, rad/min
constexpr double kLunarEccentricity = 0.05490;    // zel

// Earth rotation rate, rad/min (7.29211514668855e-5 rad/s).
constexpr double kEarthRotationRadPerMin = 4.37526908801129966e-3;  // rptim

// Resonance integrator step (minutes) and its half-square (step^2 / 2).
constexpr double kResonanceStep = 720.0;
constexpr double kResonanceStepSquaredHalf = 259200.0;
// Integrator checkpoints (DeepSpace::ahead/behind): one every step (12 hours), over 366 days each
// way (about 58 kB and 1,464 integrator steps per resonant set, once). Inside that span a
// propagation integrates no step at all (the state at the checkpoint is the loop's at that step);
// beyond it, the integration goes on from the last.
constexpr std::size_t kCheckpointStride = 1;
constexpr std::size_t kCheckpointSteps = 732;

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
// sidereal angle at epoch. Kept separate from gmst82() so that the SDP4 resonance phase uses the
// very same arithmetic as the published code.
double gstime(double jdut1) {
  const double tut1 = (jdut1 - 2451545.0) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;  // seconds
  temp = std::fmod(temp * kDegToRad / 240.0, kTwoPi);
  if (temp < 0.0) temp += kTwoPi;
  return temp;
}

// The epoch as the reference's TLE reader computes it: day of year -> month, day, h, m, s, then a
// Julian date split into a day boundary and a fraction.
JulianDate element_epoch(int year, double day_of_year) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  if (!(day_of_year >= 0.0 && day_of_year < 1000.0)) return {kNan, kNan};  // not a day of a year
  int month_days[13] = {0, 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const int day_number = static_cast<int>(std::floor(day_of_year));
  if (year % 4 == 0) month_days[2] = 29;
  int month = 1;
  int days_before = 0;
  while (day_number > days_before + month_days[month] && month < 12) {
    days_before += month_days[month];
    ++month;
  }
  const int day = day_number - days_before;
  double temp = (day_of_year - day_number) * 24.0;
  const int hour = static_cast<int>(std::floor(temp));
  temp = (temp - hour) * 60.0;
  const int minute = static_cast<int>(std::floor(temp));
  const double second = (temp - minute) * 60.0;

  JulianDate jd;
  jd.whole = 367.0 * year - std::floor((7 * (year + std::floor((month + 9) / 12.0))) * 0.25) +
             std::floor(275 * month / 9.0) + day + 1721013.5;
  jd.fraction = (second + minute * 60.0 + hour * 3600.0) / 86400.0;
  if (std::fabs(jd.fraction) > 1.0) {
    const double whole_days = std::floor(jd.fraction);
    jd.whole += whole_days;
    jd.fraction -= whole_days;
  }
  return jd;
}

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
BodyPeriodics body_periodics(const BodyTerms& b, double emsq, double eccentricity) {
  BodyPeriodics p;
  p.e2 = 2.0 * b.s1 * b.s6;
  p.e3 = 2.0 * b.s1 * b.s7;
  p.i2 = 2.0 * b.s2 * b.z12;
  p.i3 = 2.0 * b.s2 * (b.z13 - b.z11);
  p.l2 = -2.0 * b.s3 * b.z2;
  p.l3 = -2.0 * b.s3 * (b.z3 - b.z1);
  p.l4 = -2.0 * b.s3 * (-21.0 - 9.0 * emsq) * eccentricity;
  p.gh2 = 2.0 * b.s4 * b.z32;
  p.gh3 = 2.0 * b.s4 * (b.z33 - b.z31);
  p.gh4 = -18.0 * b.s4 * eccentricity;
  p.h2 = -2.0 * b.s2 * b.z22;
  p.h3 = -2.0 * b.s2 * (b.z23 - b.z21);
  return p;
}

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
                                  double np, LunarSolarPeriodics& out) {
  constexpr double c1ss = 2.9864797e-6;
  constexpr double c1l = 4.7968065e-7;
  constexpr double zsinis = 0.39785416;
  constexpr double zcosis = 0.91744867;
  constexpr double zcosgs = 0.1945905;
  constexpr double zsings = -0.98088458;

  DeepSpaceCommon c{};
  const double snodm = std::sin(nodep);
  const double cnodm = std::cos(nodep);
  const double sinomm = std::sin(argpp);
  const double cosomm = std::cos(argpp);
  c.sinim = std::sin(inclp);
  c.cosim = std::cos(inclp);
  const double em = ep;
  c.emsq = em * em;
  const double betasq = 1.0 - c.emsq;
  const double rtemsq = std::sqrt(betasq);

  const double day = epoch + 18261.5;  // days since 1900 Jan 0.5
  const double xnodce = std::fmod(4.5236020 - 9.2422029e-4 * day, kTwoPi);
  const double stem = std::sin(xnodce);
  const double ctem = std::cos(xnodce);
  const double zcosil = 0.91375164 - 0.03568096 * ctem;
  const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
  const double zsinhl = 0.089683511 * stem / zsinil;
  const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
  const double gam = 5.8351514 + 0.0019443680 * day;
  double zx = 0.39785416 * stem / zsinil;
  const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
  zx = std::atan2(zx, zy);
  zx = gam + zx - xnodce;
  const double zcosgl = std::cos(zx);
  const double zsingl = std::sin(zx);

  // Two passes: the Sun (third body with the ecliptic orientation), then the Moon.
  double zcosg = zcosgs, zsing = zsings, zcosi = zcosis, zsini = zsinis;
  double zcosh = cnodm, zsinh = snodm;
  double cc = c1ss;
  const double xnoi = 1.0 / np;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
  double z1 = 0, z2 = 0, z3 = 0, z11 = 0, z12 = 0, z13 = 0, z21 = 0, z22 = 0, z23 = 0;
  double z31 = 0, z32 = 0, z33 = 0;
  for (int body = 0; body < 2; ++body) {
    const double a1 = zcosg * zcosh + zsing * zcosi * zsinh;
    const double a3 = -zsing * zcosh + zcosg * zcosi * zsinh;
    const double a7 = -zcosg * zsinh + zsing * zcosi * zcosh;
    const double a8 = zsing * zsini;
    const double a9 = zsing * zsinh + zcosg * zcosi * zcosh;
    const double a10 = zcosg * zsini;
    const double a2 = c.cosim * a7 + c.sinim * a8;
    const double a4 = c.cosim * a9 + c.sinim * a10;
    const double a5 = -c.sinim * a7 + c.cosim * a8;
    const double a6 = -c.sinim * a9 + c.cosim * a10;

    const double x1 = a1 * cosomm + a2 * sinomm;
    const double x2 = a3 * cosomm + a4 * sinomm;
    const double x3 = -a1 * sinomm + a2 * cosomm;
    const double x4 = -a3 * sinomm + a4 * cosomm;
    const double x5 = a5 * sinomm;
    const double x6 = a6 * sinomm;
    const double x7 = a5 * cosomm;
    const double x8 = a6 * cosomm;

    z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
    z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
    z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
    z1 = 3.0 * (a1 * a1 + a2 * a2) + z31 * c.emsq;
    z2 = 6.0 * (a1 * a3 + a2 * a4) + z32 * c.emsq;
    z3 = 3.0 * (a3 * a3 + a4 * a4) + z33 * c.emsq;
    z11 = -6.0 * a1 * a5 + c.emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
    z12 = -6.0 * (a1 * a6 + a3 * a5) +
          c.emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
    z13 = -6.0 * a3 * a6 + c.emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
    z21 = 6.0 * a2 * a5 + c.emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
    z22 = 6.0 * (a4 * a5 + a2 * a6) +
          c.emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
    z23 = 6.0 * a4 * a6 + c.emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
    z1 = z1 + z1 + betasq * z31;
    z2 = z2 + z2 + betasq * z32;
    z3 = z3 + z3 + betasq * z33;
    s3 = cc * xnoi;
    s2 = -0.5 * s3 / rtemsq;
    s4 = s3 * rtemsq;
    s1 = -15.0 * em * s4;
    s5 = x1 * x3 + x2 * x4;
    s6 = x2 * x3 + x1 * x4;
    s7 = x2 * x4 - x1 * x3;

    if (body == 0) {  // keep the solar terms, set up the lunar pass
      c.sun = {s1, s2, s3, s4, s5, s6, s7, z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33};
      zcosg = zcosgl;
      zsing = zsingl;
      zcosi = zcosil;
      zsini = zsinil;
      zcosh = zcoshl * cnodm + zsinhl * snodm;
      zsinh = snodm * zcoshl - cnodm * zsinhl;
      cc = c1l;
    }
  }

  LunarSolarPeriodics& p = out;
  p.zmol = std::fmod(4.7199672 + 0.22997150 * day - gam, kTwoPi);
  p.zmos = std::fmod(6.2565837 + 0.017201977 * day, kTwoPi);

  c.moon = {s1, s2, s3, s4, s5, s6, s7, z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33};
  p.solar = body_periodics(c.sun, c.emsq, kSolarEccentricity);
  p.lunar = body_periodics(c.moon, c.emsq, kLunarEccentricity);
  return c;
}

// Epoch quantities the deep-space set-up takes from the near-earth initialisation.
struct DeepSpaceInputs {
  double ecco, eccsq, inclo, argpo, mo, nodeo, no;  // mean elements (no un-Kozai'd)
  double mdot, nodedot, xpidot;                     // secular rates
};

// Secular lunar-solar rates and the geopotential resonance terms (half-day and one-day orbits).
void deep_space_secular(const DeepSpaceInputs& in, const DeepSpaceCommon& c, DeepSpace& ds) {
  constexpr double q22 = 1.7891679e-6;
  constexpr double q31 = 2.1460748e-6;
  constexpr double q33 = 2.2123015e-7;
  constexpr double root22 = 1.7891679e-6;
  constexpr double root44 = 7.3636953e-9;
  constexpr double root54 = 2.1765803e-9;
  constexpr double root32 = 3.7393792e-7;
  constexpr double root52 = 1.1428639e-7;
  constexpr double kNearEquatorial = 5.2359877e-2;  // 3 deg: no node rate from the Sun/Moon

  const double nm = in.no;
  const double em = in.ecco;
  const double sinim = c.sinim;
  const double cosim = c.cosim;
  const double emsq = c.emsq;

  ds.resonance = Resonance::none;
  if (nm < 0.0052359877 && nm > 0.0034906585) ds.resonance = Resonance::one_day;
  if (nm >= 8.26e-3 && nm <= 9.24e-3 && em >= 0.5) ds.resonance = Resonance::half_day;

  const bool near_equatorial = in.inclo < kNearEquatorial || in.inclo > kPi - kNearEquatorial;

  // Solar.
  const double ses = c.sun.s1 * kSolarMeanMotion * c.sun.s5;
  const double sis = c.sun.s2 * kSolarMeanMotion * (c.sun.z11 + c.sun.z13);
  const double sls = -kSolarMeanMotion * c.sun.s3 * (c.sun.z1 + c.sun.z3 - 14.0 - 6.0 * emsq);
  const double sghs = c.sun.s4 * kSolarMeanMotion * (c.sun.z31 + c.sun.z33 - 6.0);
  double shs = -kSolarMeanMotion * c.sun.s2 * (c.sun.z21 + c.sun.z23);
  if (near_equatorial) shs = 0.0;
  if (sinim != 0.0) shs = shs / sinim;
  const double sgs = sghs - cosim * shs;

  // Lunar.
  ds.dedt = ses + c.moon.s1 * kLunarMeanMotion * c.moon.s5;
  ds.didt = sis + c.moon.s2 * kLunarMeanMotion * (c.moon.z11 + c.moon.z13);
  ds.dmdt = sls - kLunarMeanMotion * c.moon.s3 * (c.moon.z1 + c.moon.z3 - 14.0 - 6.0 * emsq);
  const double sghl = c.moon.s4 * kLunarMeanMotion * (c.moon.z31 + c.moon.z33 - 6.0);
  double shll = -kLunarMeanMotion * c.moon.s2 * (c.moon.z21 + c.moon.z23);
  if (near_equatorial) shll = 0.0;
  ds.domdt = sgs + sghl;
  ds.dnodt = shs;
  if (sinim != 0.0) {
    ds.domdt = ds.domdt - cosim / sinim * shll;
    ds.dnodt = ds.dnodt + shll / sinim;
  }

  if (ds.resonance == Resonance::none) return;

  const double theta = std::fmod(ds.gsto, kTwoPi);
  const double aonv = std::pow(nm / kXke, kTwoThirds);

  if (ds.resonance == Resonance::half_day) {
    const double cosisq = cosim * cosim;
    // The eccentricity polynomials use the epoch eccentricity.
    const double e = in.ecco;
    const double esq = in.eccsq;
    const double eoc = e * esq;
    const double g201 = -0.306 - (e - 0.64) * 0.440;
    double g211, g310, g322, g410, g422, g520, g521, g532, g533;
    if (e <= 0.65) {
      g211 = 3.616 - 13.2470 * e + 16.2900 * esq;
      g310 = -19.302 + 117.3900 * e - 228.4190 * esq + 156.5910 * eoc;
      g322 = -18.9068 + 109.7927 * e - 214.6334 * esq + 146.5816 * eoc;
      g410 = -41.122 + 242.6940 * e - 471.0940 * esq + 313.9530 * eoc;
      g422 = -146.407 + 841.8800 * e - 1629.014 * esq + 1083.4350 * eoc;
      g520 = -532.114 + 3017.977 * e - 5740.032 * esq + 3708.2760 * eoc;
    } else {
      g211 = -72.099 + 331.819 * e - 508.738 * esq + 266.724 * eoc;
      g310 = -346.844 + 1582.851 * e - 2415.925 * esq + 1246.113 * eoc;
      g322 = -342.585 + 1554.908 * e - 2366.899 * esq + 1215.972 * eoc;
      g410 = -1052.797 + 4758.686 * e - 7193.992 * esq + 3651.957 * eoc;
      g422 = -3581.690 + 16178.110 * e - 24462.770 * esq + 12422.520 * eoc;
      if (e > 0.715)
        g520 = -5149.66 + 29936.92 * e - 54087.36 * esq + 31324.56 * eoc;
      else
        g520 = 1464.74 - 4664.75 * e + 3763.64 * esq;
    }
    if (e < 0.7) {
      g533 = -919.22770 + 4988.6100 * e - 9064.7700 * esq + 5542.21 * eoc;
      g521 = -822.71072 + 4568.6173 * e - 8491.4146 * esq + 5337.524 * eoc;
      g532 = -853.66600 + 4690.2500 * e - 8624.7700 * esq + 5341.4 * eoc;
    } else {
      g533 = -37995.780 + 161616.52 * e - 229838.20 * esq + 109377.94 * eoc;
      g521 = -51752.104 + 218913.95 * e - 309468.16 * esq + 146349.42 * eoc;
      g532 = -40023.880 + 170470.89 * e - 242699.48 * esq + 115605.82 * eoc;
    }

    const double sini2 = sinim * sinim;
    const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
    const double f221 = 1.5 * sini2;
    const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
    const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
    const double f441 = 35.0 * sini2 * f220;
    const double f442 = 39.3750 * sini2 * sini2;
    const double f522 = 9.84375 * sinim *
                        (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                         0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
    const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                                 6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
    const double f542 = 29.53125 * sinim *
                        (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
    const double f543 = 29.53125 * sinim *
                        (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));
    const double xno2 = nm * nm;
    const double ainv2 = aonv * aonv;
    double temp1 = 3.0 * xno2 * ainv2;
    double temp = temp1 * root22;
    ds.d2201 = temp * f220 * g201;
    ds.d2211 = temp * f221 * g211;
    temp1 = temp1 * aonv;
    temp = temp1 * root32;
    ds.d3210 = temp * f321 * g310;
    ds.d3222 = temp * f322 * g322;
    temp1 = temp1 * aonv;
    temp = 2.0 * temp1 * root44;
    ds.d4410 = temp * f441 * g410;
    ds.d4422 = temp * f442 * g422;
    temp1 = temp1 * aonv;
    temp = temp1 * root52;
    ds.d5220 = temp * f522 * g520;
    ds.d5232 = temp * f523 * g532;
    temp = 2.0 * temp1 * root54;
    ds.d5421 = temp * f542 * g521;
    ds.d5433 = temp * f543 * g533;
    ds.xlamo = std::fmod(in.mo + in.nodeo + in.nodeo - theta - theta, kTwoPi);
    ds.xfact = in.mdot + ds.dmdt + 2.0 * (in.nodedot + ds.dnodt - kEarthRotationRadPerMin) - in.no;
  } else {  // one-day (geosynchronous) resonance
    const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
    const double g310 = 1.0 + 2.0 * emsq;
    const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
    const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
    const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
    double f330 = 1.0 + cosim;
    f330 = 1.875 * f330 * f330 * f330;
    double del1 = 3.0 * nm * nm * aonv * aonv;
    ds.del2 = 2.0 * del1 * f220 * g200 * q22;
    ds.del3 = 3.0 * del1 * f330 * g300 * q33 * aonv;
    del1 = del1 * f311 * g310 * q31 * aonv;
    ds.del1 = del1;
    ds.xlamo = std::fmod(in.mo + in.nodeo + in.argpo - theta, kTwoPi);
    ds.xfact = in.mdot + in.xpidot - kEarthRotationRadPerMin + ds.dmdt + ds.domdt + ds.dnodt - in.no;
  }
}

// Mean elements as they evolve between the secular update and the periodics.
struct MeanElements {
  double em, argpm, inclm, mm, nodem, nm;
};

// Derivatives of the resonance integrator's state: mean motion xni and mean longitude xli at
// atime minutes from epoch.
DeepSpace::Rates resonance_rates(const DeepSpace& ds, double xli, double xni, double atime,
                                 double argpo, double argpdot) {
  constexpr double fasx2 = 0.13130908;
  constexpr double fasx4 = 2.8843198;
  constexpr double fasx6 = 0.37448087;
  constexpr double g22 = 5.7686396;
  constexpr double g32 = 0.95240898;
  constexpr double g44 = 1.8014998;
  constexpr double g52 = 1.0508330;
  constexpr double g54 = 4.4108898;

  DeepSpace::Rates r;
  r.xldot = xni + ds.xfact;
  if (ds.resonance == Resonance::one_day) {
    const SinCos a = sin_cos(xli - fasx2);
    const SinCos b = sin_cos(2.0 * (xli - fasx4));
    const SinCos c = sin_cos(3.0 * (xli - fasx6));
    r.xndt = ds.del1 * a.s + ds.del2 * b.s + ds.del3 * c.s;
    r.xnddt = ds.del1 * a.c + 2.0 * ds.del2 * b.c + 3.0 * ds.del3 * c.c;
  } else {
    const double xomi = argpo + argpdot * atime;
    const double x2omi = xomi + xomi;
    const double x2li = xli + xli;
    const SinCos a = sin_cos(x2omi + xli - g22);
    const SinCos b = sin_cos(xli - g22);
    const SinCos c = sin_cos(xomi + xli - g32);
    const SinCos d = sin_cos(-xomi + xli - g32);
    const SinCos e = sin_cos(x2omi + x2li - g44);
    const SinCos f = sin_cos(x2li - g44);
    const SinCos g = sin_cos(xomi + xli - g52);
    const SinCos h = sin_cos(-xomi + xli - g52);
    const SinCos i = sin_cos(xomi + x2li - g54);
    const SinCos j = sin_cos(-xomi + x2li - g54);
    r.xndt = ds.d2201 * a.s + ds.d2211 * b.s + ds.d3210 * c.s + ds.d3222 * d.s + ds.d4410 * e.s +
             ds.d4422 * f.s + ds.d5220 * g.s + ds.d5232 * h.s + ds.d5421 * i.s + ds.d5433 * j.s;
    r.xnddt = ds.d2201 * a.c + ds.d2211 * b.c + ds.d3210 * c.c + ds.d3222 * d.c + ds.d5220 * g.c +
              ds.d5232 * h.c +
              2.0 * (ds.d4410 * e.c + ds.d4422 * f.c + ds.d5421 * i.c + ds.d5433 * j.c);
  }
  r.xnddt = r.xnddt * r.xldot;
  return r;
}

// The integrator's state after n steps of delt from epoch (n = 0, 1, 2, ...; atime = n * delt).
void resonance_step(const DeepSpace& ds, double& xli, double& xni, double& atime, DeepSpace::Rates& r,
                    double delt, double argpo, double argpdot) {
  xli = xli + r.xldot * delt + r.xndt * kResonanceStepSquaredHalf;
  xni = xni + r.xndt * delt + r.xnddt * kResonanceStepSquaredHalf;
  atime = atime + delt;
  r = resonance_rates(ds, xli, xni, atime, argpo, argpdot);
}

// The checkpoints (DeepSpace::ahead/behind) for t, computed once per model.
void build_checkpoints(DeepSpace& ds, double no, double argpo, double argpdot) {
  for (const double delt : {kResonanceStep, -kResonanceStep}) {
    auto& out = delt > 0.0 ? ds.ahead : ds.behind;
    out.reserve(kCheckpointSteps / kCheckpointStride);
    double atime = 0.0, xni = no, xli = ds.xlamo;
    DeepSpace::Rates r = ds.rates_at_epoch;
    for (std::size_t n = 1; n <= kCheckpointSteps; ++n) {
      resonance_step(ds, xli, xni, atime, r, delt, argpo, argpdot);
      if (n % kCheckpointStride == 0) out.push_back({xli, xni, r});
    }
  }
}

// How many steps the integration from epoch towards t takes from a checkpoint: the largest
// multiple of the stride, within the checkpoints, such that the loop's condition
// |t - atime| >= step still held one step before it (so the loop from epoch passes it). 0: none.
[[gnu::always_inline]] inline std::size_t checkpoint_steps(const DeepSpace& ds, double t, double delt) {
  const double whole = std::floor(std::fabs(t) / kResonanceStep);
  if (!(whole >= static_cast<double>(kCheckpointStride))) return 0;  // also NaN
  const auto& cps = delt > 0.0 ? ds.ahead : ds.behind;
  std::size_t j = whole >= static_cast<double>(cps.size() * kCheckpointStride)
                      ? cps.size()
                      : static_cast<std::size_t>(whole) / kCheckpointStride;
  while (j > 0 && !(std::fabs(t - static_cast<double>(j * kCheckpointStride - 1) * delt) >= kResonanceStep)) --j;
  return j * kCheckpointStride;
}

// Secular lunar-solar drift plus, for resonant orbits, the numerically integrated mean longitude
// and mean motion. The integrator steps 720 minutes from epoch towards t (from the last checkpoint
// on that way).
[[gnu::always_inline]] inline void deep_space_drift(const DeepSpace& ds, double no, double argpo, double argpdot, double t,
                      MeanElements& m) {
  m.em = m.em + ds.dedt * t;
  m.inclm = m.inclm + ds.didt * t;
  m.argpm = m.argpm + ds.domdt * t;
  m.nodem = m.nodem + ds.dnodt * t;
  m.mm = m.mm + ds.dmdt * t;
  if (ds.resonance == Resonance::none) return;

  const double theta = std::fmod(ds.gsto + t * kEarthRotationRadPerMin, kTwoPi);
  double atime = 0.0;
  double xni = no;
  double xli = ds.xlamo;
  DeepSpace::Rates r = ds.rates_at_epoch;
  const double delt = t > 0.0 ? kResonanceStep : -kResonanceStep;
  if (const std::size_t steps = checkpoint_steps(ds, t, delt)) {
    const DeepSpace::IntegratorState& c = (t > 0.0 ? ds.ahead : ds.behind)[steps / kCheckpointStride - 1];
    xli = c.xli;
    xni = c.xni;
    r = c.r;
    atime = static_cast<double>(steps) * delt;  // exact: what `steps` additions of delt give
  }
  while (std::fabs(t - atime) >= kResonanceStep) resonance_step(ds, xli, xni, atime, r, delt, argpo, argpdot);
  const double ft = t - atime;

  const double nm = xni + r.xndt * ft + r.xnddt * ft * ft * 0.5;
  const double xl = xli + r.xldot * ft + r.xndt * ft * ft * 0.5;
  if (ds.resonance == Resonance::half_day)
    m.mm = xl - 2.0 * m.nodem + 2.0 * theta;
  else
    m.mm = xl - m.nodem - m.argpm + theta;
  const double dndt = nm - no;
  m.nm = no + dndt;
}

// Osculating elements after the lunar-solar periodics.
struct PerturbedElements {
  double ep, inclp, nodep, argpp, mp;
  double sinip, cosip;  // of inclp
};

// One body's share of the periodics at t: offsets of e, i, l, gh (argument of perigee + node) and h.
struct BodyOffsets {
  double e, i, l, gh, h;
};
[[gnu::always_inline]] inline BodyOffsets body_offsets(const BodyPeriodics& b, double zm, double eccentricity) {
  const double zf = zm + 2.0 * eccentricity * sin_cos(zm).s;
  const SinCos z = sin_cos(zf);
  const double f2 = 0.5 * z.s * z.s - 0.25;
  const double f3 = -0.5 * z.s * z.c;
  return {b.e2 * f2 + b.e3 * f3, b.i2 * f2 + b.i3 * f3, b.l2 * f2 + b.l3 * f3 + b.l4 * z.s,
          b.gh2 * f2 + b.gh3 * f3 + b.gh4 * z.s, b.h2 * f2 + b.h3 * f3};
}

[[gnu::always_inline]] inline void lunar_solar_periodics(const LunarSolarPeriodics& p, double t, PerturbedElements& x) {
  const BodyOffsets sun = body_offsets(p.solar, p.zmos + kSolarMeanMotion * t, kSolarEccentricity);  // ses ... shs
  const BodyOffsets moon = body_offsets(p.lunar, p.zmol + kLunarMeanMotion * t, kLunarEccentricity);  // sel ... shll
  const double pe = sun.e + moon.e;
  const double pinc = sun.i + moon.i;
  const double pl = sun.l + moon.l;
  double pgh = sun.gh + moon.gh;
  double ph = sun.h + moon.h;

  x.inclp = x.inclp + pinc;
  x.ep = x.ep + pe;
  const SinCos inc = sin_cos(x.inclp);
  x.sinip = inc.s;
  x.cosip = inc.c;

  // Periodics applied directly above 0.2 rad of (perturbed) inclination, with Lyddane's
  // modification below it.
  if (x.inclp >= 0.2) {
    ph = ph / x.sinip;
    pgh = pgh - x.cosip * ph;
    x.argpp = x.argpp + pgh;
    x.nodep = x.nodep + ph;
    x.mp = x.mp + pl;
  } else {
    const SinCos node = sin_cos(x.nodep);
    double alfdp = x.sinip * node.s;
    double betdp = x.sinip * node.c;
    const double dalf = ph * node.c + pinc * x.cosip * node.s;
    const double dbet = -ph * node.s + pinc * x.cosip * node.c;
    alfdp = alfdp + dalf;
    betdp = betdp + dbet;
    x.nodep = wrap_two_pi(x.nodep);
    double xls = x.mp + x.argpp + x.cosip * x.nodep;
    const double dls = pl + pgh - pinc * x.nodep * x.sinip;
    xls = xls + dls;
    const double xnoh = x.nodep;
    x.nodep = std::atan2(alfdp, betdp);
    if (std::fabs(xnoh - x.nodep) > kPi) {
      if (x.nodep < xnoh)
        x.nodep = x.nodep + kTwoPi;
      else
        x.nodep = x.nodep - kTwoPi;
    }
    x.mp = x.mp + pl;
    x.argpp = xls - x.mp - x.cosip * x.nodep;
  }
}

[[gnu::always_inline]] inline Propagation failure(Sgp4Error e) {
  Propagation p;
  p.error = e;
  return p;
}
[[gnu::always_inline]] inline bool fail(PerturbedTerms& out, Sgp4Error e) {
  out.error = e;
  return false;
}

}  // namespace

// Every coefficient of the paper's satrec that depends only on the element set.
struct Sgp4::Model {
  // Mean elements at epoch: radians, un-Kozai'd mean motion in rad/min, bstar in 1/earth radii.
  double ecco = 0, inclo = 0, nodeo = 0, argpo = 0, mo = 0, no_unkozai = 0, bstar = 0;
  double sinio = 0, cosio = 0;
  double ao = 0;          // (xke / no_unkozai)^(2/3), earth radii
  double a = 0;           // semi-major axis reported to users, (no_unkozai * tumin)^(-2/3)
  // Secular rates.
  double mdot = 0, argpdot = 0, nodedot = 0;
  // Drag.
  double cc1 = 0, cc4 = 0, cc5 = 0, d2 = 0, d3 = 0, d4 = 0, delmo = 0, eta = 0, omgcof = 0;
  double sinmao = 0, t2cof = 0, t3cof = 0, t4cof = 0, t5cof = 0, xmcof = 0, nodecf = 0;
  // Long- and short-period gravity terms (near-earth; recomputed per call for deep space).
  double aycof = 0, xlcof = 0, con41 = 0, x1mth2 = 0, x7thm1 = 0;
  bool simplified_drag = false;  // isimp: perigee below 220 km, or deep space
  bool deep_space = false;
  DeepSpace ds;

  // epoch: days since 1949 Dec 31 00:00 UT; no_kozai: mean motion from the element set, rad/min.
  void initialise(double epoch, double no_kozai);
  // The propagator, inlined into each of the variants below: the perturbed elements (false: the
  // propagation fails with out.error), then finish() below.
  [[gnu::always_inline]] inline bool perturbed(double tsince, PerturbedTerms& out) const;
  [[gnu::always_inline]] inline Propagation propagate_inline(double tsince) const;
  // The propagator compiled for the baseline instruction set and, on x86-64, for x86-64-v3 (AVX2 and
  // FMA); propagate() runs the best this processor has (chosen once).
  static Propagation propagate_baseline(const Model& m, double tsince);
  static Propagation propagate_v3(const Model& m, double tsince);
  static bool perturbed_baseline(const Model& m, double tsince, PerturbedTerms& out);
  static bool perturbed_v3(const Model& m, double tsince, PerturbedTerms& out);
  Propagation propagate(double tsince) const;
  void perturbed_terms(double tsince, PerturbedTerms& out) const;
};

void Sgp4::Model::initialise(double epoch, double no_kozai) {
  // Un-Kozai the mean motion and the epoch auxiliaries.
  const double eccsq = ecco * ecco;
  const double omeosq = 1.0 - eccsq;
  const double rteosq = std::sqrt(omeosq);
  cosio = std::cos(inclo);
  const double cosio2 = cosio * cosio;
  const double ak = std::pow(kXke / no_kozai, kTwoThirds);
  const double d1 = 0.75 * kJ2 * (3.0 * cosio2 - 1.0) / (rteosq * omeosq);
  double del = d1 / (ak * ak);
  const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
  del = d1 / (adel * adel);
  no_unkozai = no_kozai / (1.0 + del);

  ao = std::pow(kXke / no_unkozai, kTwoThirds);
  sinio = std::sin(inclo);
  const double po = ao * omeosq;
  const double con42 = 1.0 - 5.0 * cosio2;
  con41 = -con42 - cosio2 - cosio2;
  const double posq = po * po;
  const double rp = ao * (1.0 - ecco);
  const double gsto = gstime(epoch + kSgp4EpochJd);

  a = std::pow(no_unkozai * kMinutesPerTimeUnit, -kTwoThirds);

  // Atmospheric density parameters: s and (q0 - s)^4, lowered for perigees under 156 km.
  const double ss = 78.0 / kEarthRadiusKm + 1.0;
  const double qzms2ttemp = (120.0 - 78.0) / kEarthRadiusKm;
  const double qzms2t = qzms2ttemp * qzms2ttemp * qzms2ttemp * qzms2ttemp;

  simplified_drag = rp < (220.0 / kEarthRadiusKm + 1.0);
  double sfour = ss;
  double qzms24 = qzms2t;
  const double perige = (rp - 1.0) * kEarthRadiusKm;
  if (perige < 156.0) {
    sfour = perige - 78.0;
    if (perige < 98.0) sfour = 20.0;
    const double qzms24temp = (120.0 - sfour) / kEarthRadiusKm;
    qzms24 = qzms24temp * qzms24temp * qzms24temp * qzms24temp;
    sfour = sfour / kEarthRadiusKm + 1.0;
  }
  const double pinvsq = 1.0 / posq;

  const double tsi = 1.0 / (ao - sfour);
  eta = ao * ecco * tsi;
  const double etasq = eta * eta;
  const double eeta = ecco * eta;
  const double psisq = std::fabs(1.0 - etasq);
  const double coef = qzms24 * std::pow(tsi, 4.0);
  const double coef1 = coef / std::pow(psisq, 3.5);
  const double cc2 = coef1 * no_unkozai *
                     (ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                      0.375 * kJ2 * tsi / psisq * con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
  cc1 = bstar * cc2;
  double cc3 = 0.0;
  if (ecco > 1.0e-4) cc3 = -2.0 * coef * tsi * kJ3OverJ2 * no_unkozai * sinio / ecco;
  x1mth2 = 1.0 - cosio2;
  cc4 = 2.0 * no_unkozai * coef1 * ao * omeosq *
        (eta * (2.0 + 0.5 * etasq) + ecco * (0.5 + 2.0 * etasq) -
         kJ2 * tsi / (ao * psisq) *
             (-3.0 * con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
              0.75 * x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) * std::cos(2.0 * argpo)));
  cc5 = 2.0 * coef1 * ao * omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);

  // Secular gravity rates (J2 to second order, J4).
  const double cosio4 = cosio2 * cosio2;
  const double temp1 = 1.5 * kJ2 * pinvsq * no_unkozai;
  const double temp2 = 0.5 * temp1 * kJ2 * pinvsq;
  const double temp3 = -0.46875 * kJ4 * pinvsq * pinvsq * no_unkozai;
  mdot = no_unkozai + 0.5 * temp1 * rteosq * con41 +
         0.0625 * temp2 * rteosq * (13.0 - 78.0 * cosio2 + 137.0 * cosio4);
  argpdot = -0.5 * temp1 * con42 + 0.0625 * temp2 * (7.0 - 114.0 * cosio2 + 395.0 * cosio4) +
            temp3 * (3.0 - 36.0 * cosio2 + 49.0 * cosio4);
  const double xhdot1 = -temp1 * cosio;
  nodedot = xhdot1 + (0.5 * temp2 * (4.0 - 19.0 * cosio2) + 2.0 * temp3 * (3.0 - 7.0 * cosio2)) * cosio;
  const double xpidot = argpdot + nodedot;
  omgcof = bstar * cc3 * std::cos(argpo);
  xmcof = 0.0;
  if (ecco > 1.0e-4) xmcof = -kTwoThirds * coef * bstar / eeta;
  nodecf = 3.5 * omeosq * xhdot1 * cc1;
  t2cof = 1.5 * cc1;
  if (std::fabs(cosio + 1.0) > kRetrogradeGuard)
    xlcof = -0.25 * kJ3OverJ2 * sinio * (3.0 + 5.0 * cosio) / (1.0 + cosio);
  else
    xlcof = -0.25 * kJ3OverJ2 * sinio * (3.0 + 5.0 * cosio) / kRetrogradeGuard;
  aycof = -0.5 * kJ3OverJ2 * sinio;
  const double delmotemp = 1.0 + eta * std::cos(mo);
  delmo = delmotemp * delmotemp * delmotemp;
  sinmao = std::sin(mo);
  x7thm1 = 7.0 * cosio2 - 1.0;

  if (kTwoPi / no_unkozai >= kDeepSpacePeriodMinutes) {
    deep_space = true;
    simplified_drag = true;
    ds.gsto = gsto;
    const DeepSpaceCommon common =
        deep_space_common(epoch, ecco, argpo, inclo, nodeo, no_unkozai, ds.periodics);
    // (The periodics are zero at epoch, so the elements need no correction here.)
    const DeepSpaceInputs in{ecco, eccsq, inclo, argpo, mo, nodeo, no_unkozai, mdot, nodedot, xpidot};
    deep_space_secular(in, common, ds);
    if (ds.resonance != Resonance::none) {
      ds.rates_at_epoch = resonance_rates(ds, ds.xlamo, no_unkozai, 0.0, argpo, argpdot);
      build_checkpoints(ds, no_unkozai, argpo, argpdot);
    }
  }

  if (!simplified_drag) {
    const double cc1sq = cc1 * cc1;
    d2 = 4.0 * ao * tsi * cc1sq;
    const double temp = d2 * tsi * cc1 / 3.0;
    d3 = (17.0 * ao + sfour) * temp;
    d4 = 0.5 * temp * ao * tsi * (221.0 * ao + 31.0 * sfour) * cc1;
    t3cof = d2 + 2.0 * cc1sq;
    t4cof = 0.25 * (3.0 * d3 + cc1 * (12.0 * d2 + 10.0 * cc1sq));
    t5cof = 0.2 * (3.0 * d4 + 12.0 * cc1 * d3 + 6.0 * d2 * d2 + 15.0 * cc1sq * (2.0 * d2 + cc1sq));
  }
}

[[gnu::always_inline]] inline bool Sgp4::Model::perturbed(double t, PerturbedTerms& out) const {
  // Secular gravity and atmospheric drag.
  const double xmdf = mo + mdot * t;
  const double argpdf = argpo + argpdot * t;
  const double nodedf = nodeo + nodedot * t;
  const double t2 = t * t;
  MeanElements m;
  m.argpm = argpdf;
  m.mm = xmdf;
  m.nodem = nodedf + nodecf * t2;
  double tempa = 1.0 - cc1 * t;
  double tempe = bstar * cc4 * t;
  double templ = t2cof * t2;

  if (!simplified_drag) {
    const double delomg = omgcof * t;
    const SinCos xm = sin_cos(xmdf);
    const double delmtemp = 1.0 + eta * xm.c;
    const double delm = xmcof * (delmtemp * delmtemp * delmtemp - delmo);
    const double temp = delomg + delm;
    m.mm = xmdf + temp;
    m.argpm = argpdf - temp;
    const double t3 = t2 * t;
    const double t4 = t3 * t;
    tempa = tempa - d2 * t2 - d3 * t3 - d4 * t4;
    tempe = tempe + bstar * cc5 * (add_angle(xm, temp).s - sinmao);
    templ = templ + t3cof * t3 + t4 * (t4cof + t * t5cof);
  }

  m.nm = no_unkozai;
  m.em = ecco;
  m.inclm = inclo;
  double am;
  if (deep_space) {
    deep_space_drift(ds, no_unkozai, argpo, argpdot, t, m);
    if (m.nm <= 0.0) return fail(out, Sgp4Error::mean_motion);
    // Only the resonance integrator changes the mean motion.
    // (xke / n)^(2/3) as cbrt squared: within an ulp of pow, at a third of its cost.
    const double cube_root = ds.resonance == Resonance::none ? 0.0 : std::cbrt(kXke / m.nm);
    const double a_mean = ds.resonance == Resonance::none ? ao : cube_root * cube_root;
    am = a_mean * tempa * tempa;
  } else {
    am = ao * tempa * tempa;
  }
  const double nm = kXke / (am * std::sqrt(am));
  double em = m.em - tempe;

  if (em >= 1.0 || em < -0.001) return fail(out, Sgp4Error::mean_eccentricity);
  if (em < 1.0e-6) em = 1.0e-6;
  double mm = m.mm + no_unkozai * templ;
  double xlm = mm + m.argpm + m.nodem;
  const double nodem = wrap_two_pi(m.nodem);
  const double argpm = wrap_two_pi(m.argpm);
  xlm = wrap_two_pi(xlm);
  mm = wrap_two_pi(xlm - argpm - nodem);

  PerturbedElements p{em, m.inclm, nodem, argpm, mm, sinio, cosio};
  double aycof_t = aycof, xlcof_t = xlcof, con41_t = con41, x1mth2_t = x1mth2, x7thm1_t = x7thm1;
  if (deep_space) {
    lunar_solar_periodics(ds.periodics, t, p);
    if (p.inclp < 0.0) {
      p.inclp = -p.inclp;
      p.nodep = p.nodep + kPi;
      p.argpp = p.argpp - kPi;
      const SinCos inc = sin_cos(p.inclp);
      p.sinip = inc.s;
      p.cosip = inc.c;
    }
    if (p.ep < 0.0 || p.ep > 1.0) return fail(out, Sgp4Error::perturbed_eccentricity);
    // Long-period coefficients with the perturbed inclination.
    aycof_t = -0.5 * kJ3OverJ2 * p.sinip;
    if (std::fabs(p.cosip + 1.0) > kRetrogradeGuard)
      xlcof_t = -0.25 * kJ3OverJ2 * p.sinip * (3.0 + 5.0 * p.cosip) / (1.0 + p.cosip);
    else
      xlcof_t = -0.25 * kJ3OverJ2 * p.sinip * (3.0 + 5.0 * p.cosip) / kRetrogradeGuard;
    const double cosisq = p.cosip * p.cosip;
    con41_t = 3.0 * cosisq - 1.0;
    x1mth2_t = 1.0 - cosisq;
    x7thm1_t = 7.0 * cosisq - 1.0;
  }

  out = {am, nm, p.ep, p.nodep, p.argpp, p.mp, p.sinip, p.cosip, aycof_t, xlcof_t, con41_t, x1mth2_t, x7thm1_t,
         Sgp4Error::none};
  return true;
}

// The rest of a propagation from the perturbed elements: long-period periodics, Kepler's equation,
// short-period periodics, position and velocity.
[[gnu::always_inline]] inline Propagation finish(const PerturbedTerms& p) {
  const double am = p.am, nm = p.nm;
  const double aycof_t = p.aycof, xlcof_t = p.xlcof, con41_t = p.con41, x1mth2_t = p.x1mth2, x7thm1_t = p.x7thm1;
  // Long-period periodics.
  const SinCos argp = sin_cos(p.argpp);
  const double axnl = p.ep * argp.c;
  double temp = 1.0 / (am * (1.0 - p.ep * p.ep));
  const double aynl = p.ep * argp.s + temp * aycof_t;
  const double xl = p.mp + p.argpp + p.nodep + temp * xlcof_t * axnl;

  // Kepler's equation in the (axnl, aynl) form, Newton steps limited to 0.95 rad.
  const double u = wrap_two_pi(xl - p.nodep);
  // As in the reference, the sine and cosine used afterwards are those of the last iterate
  // evaluated, not of the final (at most 1e-12 rad different) update.
  double eo1 = u;
  SinCos eo = sin_cos(eo1);
  for (int iteration = 1;; ++iteration) {
    double tem5 = 1.0 - eo.c * axnl - eo.s * aynl;
    tem5 = (u - aynl * eo.c + axnl * eo.s - eo1) / tem5;
    if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
    eo1 = eo1 + tem5;
    if (std::fabs(tem5) < 1.0e-12 || iteration == 10) break;
    eo = add_angle(eo, tem5);
  }

  // Short-period preliminaries.
  const double ecose = axnl * eo.c + aynl * eo.s;
  const double esine = axnl * eo.s - aynl * eo.c;
  const double el2 = axnl * axnl + aynl * aynl;
  const double pl = am * (1.0 - el2);
  if (pl < 0.0) return failure(Sgp4Error::semi_latus_rectum);

  const double rl = am * (1.0 - ecose);
  const double rdotl = std::sqrt(am) * esine / rl;
  const double rvdotl = std::sqrt(pl) / rl;
  const double betal = std::sqrt(1.0 - el2);
  temp = esine / (1.0 + betal);
  const double sinu = am / rl * (eo.s - aynl - axnl * temp);
  const double cosu = am / rl * (eo.c - axnl + aynl * temp);
  const double sin2u = (cosu + cosu) * sinu;
  const double cos2u = 1.0 - 2.0 * sinu * sinu;
  temp = 1.0 / pl;
  const double temp1 = 0.5 * kJ2 * temp;
  const double temp2 = temp1 * temp;

  // Short-period periodics.
  const double mrt = rl * (1.0 - 1.5 * temp2 * betal * con41_t) + 0.5 * temp1 * x1mth2_t * cos2u;
  const double xnode = p.nodep + 1.5 * temp2 * p.cosip * sin2u;
  const double mvt = rdotl - nm * temp1 * x1mth2_t * sin2u / kXke;
  const double rvdot = rvdotl + nm * temp1 * (x1mth2_t * cos2u + 1.5 * con41_t) / kXke;

  // Orientation vectors.
  // (sinu, cosu) is a unit vector up to rounding; normalised, it is the (sin, cos) of the
  // reference's atan2(sinu, cosu), to which the short-period terms add small corrections.
  const double unit = 1.0 / std::sqrt(sinu * sinu + cosu * cosu);
  const SinCos s = add_angle({sinu * unit, cosu * unit}, -0.25 * temp2 * x7thm1_t * sin2u);
  const SinCos node = sin_cos(xnode);
  const SinCos inc = add_angle({p.sinip, p.cosip}, 1.5 * temp2 * p.cosip * p.sinip * cos2u);
  const detail::Orientation o = detail::orientation(s, node, inc);

  if (mrt < 1.0) return failure(Sgp4Error::decayed);

  Propagation out;
  out.state.r_km = {(mrt * o.ux) * kEarthRadiusKm, (mrt * o.uy) * kEarthRadiusKm, (mrt * o.uz) * kEarthRadiusKm};
  out.state.v_km_s = {(mvt * o.ux + rvdot * o.vx) * kKmPerSecPerErPerMin,
                      (mvt * o.uy + rvdot * o.vy) * kKmPerSecPerErPerMin,
                      (mvt * o.uz + rvdot * o.vz) * kKmPerSecPerErPerMin};
  return out;
}

[[gnu::always_inline]] inline Propagation Sgp4::Model::propagate_inline(double t) const {
  PerturbedTerms p;
  if (!perturbed(t, p)) return failure(p.error);
  return finish(p);
}

Propagation Sgp4::Model::propagate_baseline(const Model& m, double t) { return m.propagate_inline(t); }
bool Sgp4::Model::perturbed_baseline(const Model& m, double t, PerturbedTerms& out) { return m.perturbed(t, out); }

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// With FMA the polynomial sine and cosine and the long dependency chains of the propagator take about
// two thirds of the time. Results differ from the baseline build's at the level of rounding
// (contracted multiply-adds), far below the comparisons of docs/sgp4.md.
[[gnu::target("arch=x86-64-v3")]] Propagation Sgp4::Model::propagate_v3(const Model& m, double t) {
  return m.propagate_inline(t);
}
[[gnu::target("arch=x86-64-v3")]] bool Sgp4::Model::perturbed_v3(const Model& m, double t, PerturbedTerms& out) {
  return m.perturbed(t, out);
}
namespace {
bool has_v3() {
  static const bool v3 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return v3;
}
}  // namespace
#else
Propagation Sgp4::Model::propagate_v3(const Model& m, double t) { return m.propagate_inline(t); }
bool Sgp4::Model::perturbed_v3(const Model& m, double t, PerturbedTerms& out) { return m.perturbed(t, out); }
namespace {
bool has_v3() { return false; }
}  // namespace
#endif

Propagation Sgp4::Model::propagate(double t) const {
  using Fn = Propagation (*)(const Model&, double);
  static const Fn fn = has_v3() ? &propagate_v3 : &propagate_baseline;
  return fn(*this, t);
}

void Sgp4::Model::perturbed_terms(double t, PerturbedTerms& out) const {
  using Fn = bool (*)(const Model&, double, PerturbedTerms&);
  static const Fn fn = has_v3() ? &perturbed_v3 : &perturbed_baseline;
  fn(*this, t, out);
}

const char* describe(Sgp4Error e) {
  switch (e) {
    case Sgp4Error::none: return "no error";
    case Sgp4Error::mean_eccentricity: return "mean eccentricity is outside the range 0 to 1";
    case Sgp4Error::mean_motion: return "mean motion is not positive";
    case Sgp4Error::perturbed_eccentricity:
      return "perturbed eccentricity is outside the range 0 to 1";
    case Sgp4Error::semi_latus_rectum: return "semi-latus rectum is negative";
    case Sgp4Error::decayed: return "orbit has decayed (radius below one earth radius)";
  }
  return "unknown SGP4 error";
}

Sgp4::Sgp4(const Elements& elements)
    : elements_(elements),
      epoch_jd_(element_epoch(elements.epoch_year, elements.epoch_day)),
      epoch_(from_year_day(elements.epoch_year, elements.epoch_day)) {
  const double n = elements.mean_motion_rev_per_day;
  const double e = elements.eccentricity;
  // The reference would run on with NaNs here; refuse such sets up front.
  if (!(e >= 0.0 && e < 1.0)) {
    init_error_ = Sgp4Error::mean_eccentricity;
    return;
  }
  if (!(n > 0.0) || !std::isfinite(n)) {
    init_error_ = Sgp4Error::mean_motion;
    return;
  }

  auto model = std::make_shared<Model>();
  model->ecco = e;
  model->inclo = elements.inclination_deg * kDegToRad;
  model->nodeo = elements.raan_deg * kDegToRad;
  model->argpo = elements.arg_perigee_deg * kDegToRad;
  model->mo = elements.mean_anomaly_deg * kDegToRad;
  model->bstar = elements.bstar;
  model->initialise((epoch_jd_.whole + epoch_jd_.fraction) - kSgp4EpochJd, n / kRevPerDayPerRadPerMin);
  deep_space_ = model->deep_space;
  init_error_ = model->propagate(0.0).error;
  model_ = std::move(model);
}

PerturbedTerms Sgp4::perturbed_terms(double tsince) const {
  PerturbedTerms p{};
  p.error = init_error_;
  if (init_error_ == Sgp4Error::none) model_->perturbed_terms(tsince, p);
  return p;
}

Propagation Sgp4::propagate_minutes(double tsince) const {
  if (init_error_ != Sgp4Error::none) return failure(init_error_);
  return model_->propagate(tsince);
}

namespace detail {
class Sgp4Access {
 public:
  static Sgp4 without_checkpoints(const Sgp4& sat) {
    Sgp4 copy = sat;
    if (copy.model_) {
      auto model = std::make_shared<Sgp4::Model>(*copy.model_);
      model->ds.ahead.clear();
      model->ds.behind.clear();
      copy.model_ = std::move(model);
    }
    return copy;
  }
};
Sgp4 without_resonance_checkpoints(const Sgp4& sat) { return Sgp4Access::without_checkpoints(sat); }
}  // namespace detail

double Sgp4::mean_motion_rad_per_min() const {
  return model_ ? model_->no_unkozai : std::numeric_limits<double>::quiet_NaN();
}

double Sgp4::semi_major_axis_er() const {
  return model_ ? model_->a : std::numeric_limits<double>::quiet_NaN();
}

std::optional<NearEarthTerms> Sgp4::near_earth_terms() const {
  if (deep_space_ || init_error_ != Sgp4Error::none) return std::nullopt;
  const Model& m = *model_;
  return NearEarthTerms{m.ecco,   m.inclo,  m.nodeo,  m.argpo,  m.mo,     m.no_unkozai, m.bstar,  m.sinio,
                        m.cosio,  m.ao,     m.mdot,   m.argpdot, m.nodedot, m.cc1,      m.cc4,    m.cc5,
                        m.d2,     m.d3,     m.d4,     m.delmo,  m.eta,    m.omgcof,     m.sinmao, m.t2cof,
                        m.t3cof,  m.t4cof,  m.t5cof,  m.xmcof,  m.nodecf, m.aycof,      m.xlcof,  m.con41,
                        m.x1mth2, m.x7thm1, m.simplified_drag};
}

double Sgp4::period_minutes() const { return kTwoPi / mean_motion_rad_per_min(); }

double Sgp4::perigee_km() const {
  if (!model_) return std::numeric_limits<double>::quiet_NaN();
  return (model_->a * (1.0 - model_->ecco) - 1.0) * kEarthRadiusKm;
}

double Sgp4::apogee_km() const {
  if (!model_) return std::numeric_limits<double>::quiet_NaN();
  return (model_->a * (1.0 + model_->ecco) - 1.0) * kEarthRadiusKm;
}

}  // namespace tb::orbit
