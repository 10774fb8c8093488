// The deep-space (SDP4) part of the SGP4 model, built once per element set: the lunar-solar
// terms at epoch, the secular rates, the geopotential resonance and its integrator's checkpoints.
// Names follow Vallado's dscom, dsinit and dspace; sgp4_internal.h has the structures.
#include <cmath>
#include <cstddef>
#include <vector>

#include "orbit/sgp4_internal.h"

namespace tb::orbit::sgp4_internal {

double gstime(double jdut1) {
  const double tut1 = (jdut1 - 2451545.0) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;  // seconds
  temp = std::fmod(temp * kDegToRad / 240.0, kTwoPi);
  if (temp < 0.0) temp += kTwoPi;
  return temp;
}

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

void resonance_step(const DeepSpace& ds, double& xli, double& xni, double& atime, DeepSpace::Rates& r,
                    double delt, double argpo, double argpdot) {
  xli = xli + r.xldot * delt + r.xndt * kResonanceStepSquaredHalf;
  xni = xni + r.xndt * delt + r.xnddt * kResonanceStepSquaredHalf;
  atime = atime + delt;
  r = resonance_rates(ds, xli, xni, atime, argpo, argpdot);
}

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

}  // namespace tb::orbit::sgp4_internal
