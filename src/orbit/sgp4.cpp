// SGP4/SDP4 after Vallado, Crawford, Hujsak, Kelso, "Revisiting Spacetrack Report #3"
// (AIAA 2006-6753), WGS-72 constants, improved operation mode. See docs/sgp4.md.
//
// Variable names follow the paper's code (ecco, nodeo, cc1, xlcof, d2201, ...) so that every line can
// be checked against it; the structure is ours: everything that depends only on the element set is
// computed once in the constructor and held in an immutable Model, and propagate_minutes() is a pure
// function of that model and the time. The deep-space resonance integrator restarts on every call
// from the checkpoint its integration from epoch would pass (sgp4_deep.cpp builds them); with its
// fixed 720-minute steps that produces the same numbers as the paper's cached integrator, without
// mutable state. The deep-space set-up is in sgp4_deep.cpp, what both share in sgp4_internal.h.
#include "orbit/sgp4.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "orbit/constants.h"
#include "orbit/sgp4_common.h"
#include "orbit/sgp4_internal.h"

namespace tb::orbit {

using namespace sgp4_internal;

namespace {

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
  // The node's sine and cosine do not wait for Kepler's equation: the short-period correction is
  // added to them at the end (see xnode), off the longest chain of the propagation.
  const SinCos node0 = sin_cos(p.nodep);
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
  const double dnode = 1.5 * temp2 * p.cosip * sin2u;  // xnode = nodep + dnode
  const double mvt = rdotl - nm * temp1 * x1mth2_t * sin2u / kXke;
  const double rvdot = rvdotl + nm * temp1 * (x1mth2_t * cos2u + 1.5 * con41_t) / kXke;

  // Orientation vectors.
  // (sinu, cosu) is a unit vector up to rounding; normalised, it is the (sin, cos) of the
  // reference's atan2(sinu, cosu), to which the short-period terms add small corrections.
  const double unit = 1.0 / std::sqrt(sinu * sinu + cosu * cosu);
  const SinCos s = add_angle({sinu * unit, cosu * unit}, -0.25 * temp2 * x7thm1_t * sin2u);
  const SinCos node = add_angle(node0, dnode);
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
