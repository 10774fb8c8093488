// Pass search: AOS, TCA, LOS without stepping through the day.
//
// The search works on F(t) = sin(el(t)) - sin(horizon): the satellite is up when F >= 0. Each
// propagation gives F, its rate Fdot (from the SGP4 velocity) and a few geometric quantities; from them
// the search takes the longest step that provably cannot skip a change of sign of F. Four bounds, each a
// lower bound on the time until the sign of F can change:
//
//   (a) theta, the geocentric angle between station and satellite. Up needs theta <= lambda(r), the
//       horizon half-angle for the satellite's distance r; in the Earth-fixed frame (where the station
//       stands still) theta changes at most at |v_ecef| / r.
//   (b) beta, the station's angular distance from the osculating orbit plane: theta >= |beta| always,
//       and beta changes only at the Earth's rate times cos(latitude) plus the slow turning of the
//       plane. A station far from the plane is skipped in jumps of hours.
//   (c) a second-order envelope of F. |F''| <= B over the step, B from bounds on the satellite's
//       Earth-fixed speed and acceleration and on its range; then F cannot reach 0 before the first
//       root of F + F' x + B x^2 / 2 (or, inside a pass, of F + F' x - B x^2 / 2). Near a crossing this
//       is a Newton step from the safe side: the same rule walks onto AOS and LOS.
//   (d) along track: with the station's foot point on the orbit plane, cos(theta) = cos(beta) cos(du),
//       du the satellite's angle ahead of the foot. When the satellite always runs ahead of the foot
//       (LEO and MEO), a satellite that has just passed must go round the orbit before the next pass,
//       and a satellite in the middle of a pass stays up until du reaches the far edge. The first jumps
//       from one pass to the next, the second from AOS to just before LOS.
//
// Every bound is evaluated with constants valid along the whole orbit (perigee speed, apogee distance)
// and again with constants valid only for a span of time from the present state (the distance can only
// change at the radial speed bound, the speed only by the acceleration bound), which is what makes slow
// elliptical and geostationary orbits cheap. AOS and LOS are polished by a bracketed Newton iteration
// on F, each maximum by a bracketed secant on F' and, where the SGP4 velocity is not exact enough for
// that, by parabolic interpolation of F. docs/passes.md has the derivations and the measurements.
#include "orbit/passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "orbit/constants.h"

namespace tb::orbit {
namespace {

using wgs72::kJ2;
using wgs72::kMu;                           // SGP4's own, km^3/s^2
constexpr double kReSgp4 = wgs72::kRadiusKm;  // SGP4's equatorial radius, km
constexpr double kOmega = kEarthRotationRadS * 1.000001;  // Earth rate with a hair of margin, rad/s

// Margins. The geometry is exact; these cover what the state at the window start and the mean elements
// cannot promise about the osculating orbit later (measured over the gpredict catalogue in the tests,
// and widened at run time whenever a state falls outside them).
constexpr double kRadiusMarginRel = 0.003;
constexpr double kRadiusMarginKm = 20.0;
constexpr double kMomentumMargin = 0.01;     // on |r x v|
constexpr double kSpeedFactor = 1.02;        // on vis-viva speeds and on gravity
constexpr double kVelocityErrKmS = 3e-4;     // |SGP4 velocity - d/dt SGP4 position|: measured up to
constexpr double kVelocityErrPerEcc = 0.015; //   1.4e-4 km/s on circular orbits, 0.008 e on elliptic ones
constexpr double kStepSafety = 0.97;         // every safe step is shortened by this factor
constexpr double kAngleMargin = 2e-4;        // rad, on horizon angles
constexpr double kMaxElTolerance = 2e-5;     // sin(el): hidden maxima below this are not chased
constexpr double kTaylorAngle = 5e-7;        // rad: error allowed to the model step onto a maximum
constexpr double kFlatTopShift = 10.0;       // s: flatter maxima are found from F alone
constexpr double kModelStep = 2.0;           // s: a crossing this close is taken from the quadratic model

void sin_cos(double x, double& s, double& c) {
#if defined(__GNUC__) && !defined(__clang__)  // clang has no __builtin_sincos (it fuses sin+cos itself)
  __builtin_sincos(x, &s, &c);
#else
  s = std::sin(x);
  c = std::cos(x);
#endif
}

// atan2 from a minimax polynomial: |error| < 6e-9 rad (2e7 + 5e7 points against std::atan2, asin and
// acos), a few times faster. Used only inside the bounds, which carry kFastAtanErr on the safe side.
constexpr double kFastAtanErr = 2e-8;
double fast_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double mx = std::max(ax, ay), mn = std::min(ax, ay);
  if (mx == 0.0) return 0.0;
  const double a = mn / mx, s = a * a;
  double r = a * (0.9999998863824159 +
                  s * (-0.33332597025546035 +
                       s * (0.19985906731337763 +
                            s * (-0.14161228977057888 +
                                 s * (0.1049894535543198 +
                                      s * (-0.07234855996589841 +
                                           s * (0.03978120868453937 +
                                                s * (-0.014401349336020525 + s * 0.0024567225469432352))))))));
  if (ay > ax) r = 0.5 * kPi - r;
  if (x < 0.0) r = kPi - r;
  return y < 0.0 ? -r : r;
}
double fast_asin(double x) { return fast_atan2(x, std::sqrt(std::max(0.0, 1.0 - x * x))); }
double fast_acos(double x) { return fast_atan2(std::sqrt(std::max(0.0, 1.0 - x * x)), x); }

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// One propagation, reduced to what the search needs.
struct Sample {
  double t = 0.0;          // s from the window start
  double F = 0.0;          // sin(el) - sin(horizon)
  double Fdot = 0.0;       // 1/s, from the SGP4 velocity
  double Fddot = 0.0;      // 1/s^2, with point-mass gravity (for Newton steps, never for bounds)
  double r = 0.0;          // geocentric distance, km
  double v = 0.0;          // Earth-fixed speed, km/s
  double s = 0.0;          // range, km
  double sdot = 0.0;       // range rate, km/s
  double c0 = 0.0;         // |point-mass gravity + centrifugal| at r, km/s^2
  double h = 0.0;          // |r x v| (inertial), km^2/s
  double cos_theta = 0.0;  // station direction . satellite direction
  double sin_beta = 0.0;   // station direction . orbit normal
  double w_z = 0.0;        // z component of the orbit normal (cos of the osculating inclination)
  double du_y = 0.0, du_x = 0.0;  // atan2(du_y, du_x): angle of the satellite ahead of the station's foot
                                  // on the orbit plane
  StateVector ecef;
};

Vec3 accel(const StateVector& e);

// The state dt seconds on, by a second-order Taylor step (dt of a few seconds: metres).
StateVector taylor(const StateVector& e, double dt) {
  if (dt == 0.0) return e;
  const Vec3 a = accel(e);
  StateVector out = e;
  for (int k = 0; k < 3; ++k) {
    out.r_km[k] += (e.v_km_s[k] + 0.5 * a[k] * dt) * dt;
    out.v_km_s[k] += a[k] * dt;
  }
  return out;
}

// Earth-fixed acceleration with point-mass gravity: gravity + centrifugal + Coriolis, km/s^2 (for
// Newton and Taylor steps, never for bounds).
Vec3 accel(const StateVector& e) {
  const double r2 = dot(e.r_km, e.r_km);
  const double k = kEarthRotationRadS * kEarthRotationRadS - kMu / (r2 * std::sqrt(r2));
  return {k * e.r_km[0] + 2.0 * kEarthRotationRadS * e.v_km_s[1],
          k * e.r_km[1] - 2.0 * kEarthRotationRadS * e.v_km_s[0],
          (k - kEarthRotationRadS * kEarthRotationRadS) * e.r_km[2]};
}

// The angles of a sample that the geometric bounds use (computed only where a step is planned).
struct Angles {
  double theta = 0.0;    // geocentric angle station - satellite (only when asked for), at most this
  double beta, du;       // beta at most this; du in (-pi, pi] to kFastAtanErr (along_track allows)
  double sin_b, cos_b;   // of beta
  Angles(const Sample& s, bool with_theta)
      : beta(std::max(0.0, fast_asin(std::min(std::abs(s.sin_beta), 1.0)) - kFastAtanErr)),
        du(fast_atan2(s.du_y, s.du_x)),
        sin_b(std::min(std::abs(s.sin_beta), 1.0)),
        cos_b(std::sqrt(1.0 - sin_b * sin_b)) {
    if (with_theta) theta = std::max(0.0, fast_acos(std::clamp(s.cos_theta, -1.0, 1.0)) - kFastAtanErr);
  }
};

// The first x > 0 where F + d x + (b / 2) x^2 reaches 0 for F < 0 (an upper envelope), or where
// F + d x - (b / 2) x^2 reaches 0 for F >= 0 (a lower envelope). b > 0.
double envelope_root(double F, double d, double b) {
  if (F < 0.0) return (-d + std::sqrt(d * d - 2.0 * b * F)) / b;
  return (d + std::sqrt(d * d + 2.0 * b * F)) / b;
}

// Perturbing acceleration bound (J2 with room for the higher zonals, Sun and Moon, drag), km/s^2.
double perturbation(double r_lo, double r_hi) {
  const double q = kReSgp4 / r_lo;
  const double q2 = q * q;
  return (4.5 * kJ2 * kMu / (kReSgp4 * kReSgp4)) * q2 * q2 + 3e-13 * r_hi + 1e-8;
}

class Searcher {
 public:
  Searcher(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop, const PassOptions& opt,
           const EarthOrientation& eo);

  // The next pass overlapping the window whose maximum reaches the minimum, or nothing.
  std::optional<Pass> next() {
    while (auto p = next_any()) {
      if (p->max_el_deg >= opt_.min_max_elevation_deg) return p;
    }
    return std::nullopt;
  }
  long evaluations() const { return evals_; }

 private:
  struct Local { double r_lo, r_hi, V, A; };  // bounds valid over a span from a sample

  std::optional<Pass> next_any();
  // Steps from cur_ (down) to the next AOS: its time, the first sample of the pass and the sample
  // nearest to AOS. False when the window or the propagation ends first.
  bool find_aos(double& aos_t, Sample& aos_s, Sample& aos_near);
  bool eval(double t, Sample& out);
  void init_bounds(const Sample& s0);
  void widen(const Sample& s);
  void derive();
  Local local(const Sample& s, double span) const;
  // Largest geocentric angle between station and satellite at distance r with geocentric elevation
  // at least e_low_ (low) or e_high_ (the horizon half-angle), pi when any angle will do; and the
  // cosine of that angle plus a margin.
  double lambda(double r, bool low) const;
  double cos_lambda(double r, bool low, double margin) const;
  double range_floor_below(double r) const;  // least range of a satellite at >= r below the horizon
  double curvature(const Sample& s, const Local& L, double span, double s_lo) const;
  double fdot_err(const Sample& s) const { return vel_err_ / s.s; }
  // (d): the time, at most span, for which the satellite provably stays down (below) or up, given
  // that it provably does for `covered` seconds anyway; 0 if the bound says nothing.
  // mode kAhead: as above; kBack: the same looking back from s; kGuess: where a forward jump would
  // land if the satellite had already cleared the window's edge (to be proven afterwards).
  enum Mode { kAhead, kBack, kGuess };
  double along_track(const Sample& s, const Angles& g, double span, bool below, double covered,
                     Mode mode = kAhead) const;
  double step_below(const Sample& s);
  double step_above(const Sample& s);
  // The best of step(span) (a bound valid over span, capped by it) for two spans: about twice the
  // last step, then one fitted to what that gave.
  template <class Step>
  double fitted_span(const Step& step) const {
    const double span0 = std::clamp(2.0 * last_step_, 20.0, 86400.0);
    const double x0 = step(span0);
    const double span1 = x0 < span0 ? std::max(1.5 * x0, 20.0) : 4.0 * span0;
    const double x1 = std::max(x0, step(span1));
    // A step that fell well short of the last one: try the last one's span too.
    return x1 < 0.5 * last_step_ ? std::max(x1, step(std::max(last_step_, 20.0))) : x1;
  }
  // How long after (dir = 1) or before (dir = -1) s, at most span, F provably keeps its sign.
  double reach(const Sample& s, double span, int dir) const;
  // Whether F provably keeps its sign from a (where it does for `fwd` seconds) to b.
  bool keeps_sign(const Sample& a, double fwd, const Sample& b) const {
    const double gap = b.t - a.t - fwd;  // what b has to cover looking back
    return gap <= 0.0 || reach(b, gap, -1) >= gap || monotone(a, b);
  }
  // Whether F is provably monotonic from a to b: F' has the same sign at both ends and cannot turn
  // in between, |F'a| + |F'b| > B (b - a).
  bool monotone(const Sample& a, const Sample& b) const;

  // Refines the crossing between a and b (exactly one of them up; `single`: F is monotonic between
  // them). Sets its time t, the final bracket (up, down) and the evaluated sample nearest to it.
  // False if the propagator failed inside.
  bool refine_crossing(const Sample& a, const Sample& b, bool single, double& t, Sample& up, Sample& down,
                       Sample& near);
  // Fills tca and max_el_deg from the samples of a pass, propagating more where a maximum hides.
  // guess: a first guess for the time of the maximum (negative: none).
  void finish_pass(std::vector<Sample>& samples, Pass& p, double guess);
  Sample refine_max(const Sample& a, const Sample& b, double guess);
  Sample polish_max(const Sample& best, double h);
  UtcTime at(double t) const { return add_seconds(start_, t); }
  // look_angles(ecef, obs_) with the station's frame computed once (the same arithmetic); only the
  // azimuth unless `all`.
  LookAngles look(const StateVector& ecef, bool all = true) const;

  const Sgp4& sat_;
  Observer obs_;
  UtcTime start_;
  double span_ = 0.0;        // window length, s
  PassOptions opt_;
  double tol_ = 0.1;         // precision, s
  double tol_top_ = 0.1;     // precision of a maximum: at most 0.1 s, so that its elevation
                             // stays within 1e-4 deg whatever the precision asked of AOS and LOS
  double min_step_ = 0.05;
  double tsince0_ = 0.0;     // minutes from epoch at the window start
  double gmst0_ = 0.0;       // GMST at the window start, rad
  double gmst_rate_ = 0.0;   // rad/s

  // Station.
  Vec3 site_{};              // Earth-fixed position, km
  Vec3 up_{};                // geodetic zenith
  double sl_ = 0.0, cl_ = 1.0, so_ = 0.0, co_ = 1.0;  // sin, cos of geodetic latitude and longitude
  Vec3 us_{};                // geocentric direction
  double rs_ = 0.0;          // geocentric distance, km
  double cos_phi_ = 1.0;     // cos(geocentric latitude)
  double sin_h_ = 0.0;
  double e_low_ = 0.0;       // up needs at least this geocentric elevation (rad)
  double e_high_ = 0.0;      // down has at most this geocentric elevation (rad)
  double cos_e_low_ = 1.0, sin_e_low_ = 0.0, cos_e_high_ = 1.0, sin_e_high_ = 0.0;

  // Orbit bounds (km, km/s, km/s^2, km^2/s) and what follows from them.
  double r_min_ = 0.0, r_max_ = 0.0, h_min_ = 0.0, h_max_ = 0.0;
  double rdot_max_ = 0.0, v_glob_ = 0.0, a_glob_ = 0.0, lambda_glob_ = 0.0;
  double omega_a_glob_ = 0.0, omega_b_glob_ = 0.0, b_below_glob_ = 0.0, b_above_glob_ = 0.0;
  double vel_err_ = 0.0;     // bound on |SGP4 velocity - d/dt SGP4 position|, km/s
  bool eccentric_ = false;   // a pass may have several maxima: prove there is no higher one
  double last_step_ = 60.0;

  bool started_ = false;
  bool done_ = false;
  Sample cur_{};             // the latest sample, down (except at the very start)
  long evals_ = 0;
};

Searcher::Searcher(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop, const PassOptions& opt,
                   const EarthOrientation& eo)
    : sat_(sat), obs_(o), start_(start), opt_(opt) {
  span_ = static_cast<double>((stop - start).count()) * 1e-6;
  tol_ = std::max(opt_.precision_s, 1e-3);
  tol_top_ = std::min(tol_, 0.1);
  min_step_ = 0.5 * tol_;
  tsince0_ = minutes_between(sat.epoch(), start);
  // GMST-82 is a cubic in time; over the days a search spans it is linear to 1e-11 rad.
  const JulianDate jd0 = julian_date(start, eo.dut1_s);
  gmst0_ = gmst82(jd0);
  const double tut1 = ((jd0.whole - kJdJ2000) + jd0.fraction) / 36525.0;
  const double sec_per_century = 876600.0 * 3600.0 + 8640184.812866 + 2.0 * 0.093104 * tut1 -
                                 3.0 * 6.2e-6 * tut1 * tut1;
  gmst_rate_ = sec_per_century / (36525.0 * kSecondsPerDay) * (kPi / 43200.0);

  site_ = observer_ecef_km(o);
  const double lat = o.lat_deg * kDegToRad, lon = o.lon_deg * kDegToRad;
  sl_ = std::sin(lat);
  cl_ = std::cos(lat);
  so_ = std::sin(lon);
  co_ = std::cos(lon);
  up_ = {cl_ * co_, cl_ * so_, sl_};
  rs_ = norm(site_);
  us_ = {site_[0] / rs_, site_[1] / rs_, site_[2] / rs_};
  cos_phi_ = std::hypot(us_[0], us_[1]);
  // Elevations above planes whose normals differ by delta differ by at most delta.
  const double delta = std::acos(std::clamp(dot(up_, us_), -1.0, 1.0));
  const double h = std::clamp(opt_.horizon_deg, -89.0, 89.0) * kDegToRad;
  sin_h_ = std::sin(h);
  e_low_ = h - delta - kAngleMargin;
  e_high_ = std::min(h + delta + kAngleMargin, 0.5 * kPi);
  cos_e_low_ = std::cos(e_low_);
  sin_e_low_ = std::sin(e_low_);
  cos_e_high_ = std::cos(e_high_);
  sin_e_high_ = std::sin(e_high_);
  if (span_ <= 0.0 || sat.init_error() != Sgp4Error::none) done_ = true;
}

bool Searcher::eval(double t, Sample& out) {
  ++evals_;
  const Propagation p = sat_.propagate_minutes(tsince0_ + t / 60.0);
  if (!p.ok()) return false;
  // TEME -> pseudo-Earth-fixed as teme_to_ecef does it.
  double c, sn;
  sin_cos(gmst0_ + gmst_rate_ * t, sn, c);
  const Vec3& rt = p.state.r_km;
  const Vec3& vt = p.state.v_km_s;
  StateVector& e = out.ecef;
  e.r_km = {c * rt[0] + sn * rt[1], -sn * rt[0] + c * rt[1], rt[2]};
  e.v_km_s = {c * vt[0] + sn * vt[1] + kEarthRotationRadS * e.r_km[1],
              -sn * vt[0] + c * vt[1] - kEarthRotationRadS * e.r_km[0], vt[2]};
  const Vec3 rho = {e.r_km[0] - site_[0], e.r_km[1] - site_[1], e.r_km[2] - site_[2]};
  out.t = t;
  out.s = norm(rho);
  const double inv_s = 1.0 / out.s;
  const double f = dot(rho, up_) * inv_s;
  out.sdot = dot(rho, e.v_km_s) * inv_s;
  out.F = f - sin_h_;
  out.Fdot = (dot(e.v_km_s, up_) - f * out.sdot) * inv_s;
  const double r2 = dot(e.r_km, e.r_km), v2 = dot(e.v_km_s, e.v_km_s);
  out.r = std::sqrt(r2);
  out.v = std::sqrt(v2);
  const double ir3 = kMu / (r2 * out.r);
  const double w2 = kEarthRotationRadS * kEarthRotationRadS;
  const double cxy = w2 - ir3, cz = ir3 * e.r_km[2];
  out.c0 = std::sqrt(cxy * cxy * (e.r_km[0] * e.r_km[0] + e.r_km[1] * e.r_km[1]) + cz * cz);
  // f'' = a.(z - f u) / s - |u'|^2 f - 2 (s'/s) f', a = gravity + centrifugal + Coriolis.
  const Vec3 a = accel(e);
  const double u2 = std::max(0.0, v2 - out.sdot * out.sdot) * inv_s * inv_s;
  out.Fddot = (dot(a, up_) - f * dot(a, rho) * inv_s) * inv_s - u2 * f - 2.0 * out.sdot * inv_s * out.Fdot;
  out.cos_theta = dot(e.r_km, us_) / out.r;
  const Vec3 hv = cross(rt, vt);  // inertial angular momentum, TEME
  out.h = norm(hv);
  const double inv_h = 1.0 / out.h;
  const Vec3 w = {(c * hv[0] + sn * hv[1]) * inv_h, (-sn * hv[0] + c * hv[1]) * inv_h, hv[2] * inv_h};
  out.sin_beta = dot(w, us_);
  out.w_z = w[2];
  // The satellite moves along W x r; ahead of the foot p of the station: cos(du) ~ us.r, sin ~ us.(r x W).
  out.du_y = dot(us_, cross(e.r_km, w));
  out.du_x = dot(us_, e.r_km);
  return true;
}

LookAngles Searcher::look(const StateVector& ecef, bool all) const {
  const Vec3 rho = {ecef.r_km[0] - site_[0], ecef.r_km[1] - site_[1], ecef.r_km[2] - site_[2]};
  const double south = sl_ * co_ * rho[0] + sl_ * so_ * rho[1] - cl_ * rho[2];
  const double east = -so_ * rho[0] + co_ * rho[1];
  const double zen = cl_ * co_ * rho[0] + cl_ * so_ * rho[1] + sl_ * rho[2];
  LookAngles la;
  la.range_km = norm(rho);
  if (la.range_km <= 0.0) return la;
  double az = (east == 0.0 && south == 0.0) ? 0.0 : std::atan2(east, -south) / kDegToRad;
  az = std::fmod(az, 360.0);
  if (az < 0.0) az += 360.0;
  if (az >= 360.0) az = 0.0;
  la.az_deg = az;
  if (!all) return la;
  la.el_deg = std::atan2(zen, std::hypot(south, east)) / kDegToRad;
  la.range_rate_km_s = dot(rho, ecef.v_km_s) / la.range_km;
  return la;
}

double Searcher::lambda(double r, bool low) const {
  const double x = rs_ * (low ? cos_e_low_ : cos_e_high_) / r;
  if (x >= 1.0) return kPi;
  return std::min(kPi, 0.5 * kPi - (low ? e_low_ : e_high_) - fast_asin(x) + kFastAtanErr);
}

double Searcher::cos_lambda(double r, bool low, double margin) const {
  // lambda = pi/2 - e - a with sin(a) = x: cos(lambda) = sin(e + a), sin(lambda) = cos(e + a); then
  // cos(lambda + margin) by the sum formula.
  const double ce = low ? cos_e_low_ : cos_e_high_, se = low ? sin_e_low_ : sin_e_high_;
  const double x = rs_ * ce / r;
  if (x >= 1.0) return -1.0;
  const double cx = std::sqrt(1.0 - x * x);
  const double cl = se * cx + ce * x, sl = ce * cx - se * x;
  return cl * (1.0 - 0.5 * margin * margin) - sl * margin;  // |margin| is tiny: to 1e-16
}

double Searcher::range_floor_below(double r) const {
  // Range to a point at distance r seen at geocentric elevation e: sqrt(r^2 - R^2 cos^2 e) - R sin e,
  // falling as e rises; below the horizon e <= e_high_.
  const double q = r * r - rs_ * rs_ * cos_e_high_ * cos_e_high_;
  const double s = (q > 0.0 ? std::sqrt(q) : 0.0) - rs_ * sin_e_high_;
  return std::max({s, r - rs_, 1.0});
}

void Searcher::init_bounds(const Sample& s0) {
  // Mean perigee and apogee from the elements, osculating ones at the window start, and margins.
  const double rp_mean = sat_.perigee_km() + kReSgp4, ra_mean = sat_.apogee_km() + kReSgp4;
  const Vec3& re = s0.ecef.r_km;
  const Vec3& ve = s0.ecef.v_km_s;
  const Vec3 vi = {ve[0] - kEarthRotationRadS * re[1], ve[1] + kEarthRotationRadS * re[0], ve[2]};
  const double energy = 0.5 * dot(vi, vi) - kMu / s0.r;
  double rp_osc = s0.r, ra_osc = s0.r;
  if (energy < 0.0) {
    const double a = -kMu / (2.0 * energy);
    const double e = std::sqrt(std::max(0.0, 1.0 - s0.h * s0.h / (kMu * a)));
    rp_osc = a * (1.0 - e);
    ra_osc = a * (1.0 + e);
  } else {
    ra_osc = 1e7;
  }
  const double lo = std::min({rp_mean, rp_osc, s0.r});
  const double hi = std::max({ra_mean, ra_osc, s0.r});
  r_min_ = std::max(lo * (1.0 - kRadiusMarginRel) - kRadiusMarginKm, 0.5 * kReSgp4);
  r_max_ = hi * (1.0 + kRadiusMarginRel) + kRadiusMarginKm;
  h_min_ = (1.0 - kMomentumMargin) * s0.h;
  h_max_ = (1.0 + kMomentumMargin) * s0.h;
  derive();
  eccentric_ = sat_.elements().eccentricity > 0.05;
  vel_err_ = kVelocityErrKmS + kVelocityErrPerEcc * sat_.elements().eccentricity;
}

void Searcher::widen(const Sample& s) {
  // Every sample checks the bounds; one outside them widens them (a decaying orbit does this).
  bool changed = false;
  if (s.r < r_min_) {
    r_min_ = std::max(s.r * (1.0 - kRadiusMarginRel) - kRadiusMarginKm, 0.5 * kReSgp4);
    changed = true;
  }
  if (s.r > r_max_) {
    r_max_ = s.r * (1.0 + kRadiusMarginRel) + kRadiusMarginKm;
    changed = true;
  }
  if (s.h < h_min_) {
    h_min_ = (1.0 - kMomentumMargin) * s.h;
    changed = true;
  }
  if (s.h > h_max_) {
    h_max_ = (1.0 + kMomentumMargin) * s.h;
    changed = true;
  }
  if (changed) derive();
}

void Searcher::derive() {
  const double e_max = (r_max_ - r_min_) / (r_max_ + r_min_);
  const double v_in = kSpeedFactor * std::sqrt(kMu * (2.0 / r_min_ - 1.0 / r_max_));  // vis-viva, a <= r_max
  v_glob_ = v_in + kOmega * r_max_;
  rdot_max_ = std::min(v_in, 1.1 * kMu * e_max / h_min_ + 0.01);  // |r'| = (mu / h) e |sin(nu)|
  const double pert = perturbation(r_min_, r_max_);
  a_glob_ = kSpeedFactor * kMu / (r_min_ * r_min_) + kOmega * kOmega * r_max_ + pert + 2.0 * kOmega * v_glob_;
  lambda_glob_ = lambda(r_max_, true) + kAngleMargin;
  omega_a_glob_ = v_glob_ / r_min_;
  omega_b_glob_ = kOmega * cos_phi_ + r_max_ * pert / h_min_;
  const double sb = range_floor_below(r_min_);
  b_below_glob_ = a_glob_ / sb + 2.0 * v_glob_ * v_glob_ / (sb * sb);
  const double sa = std::max(r_min_ - rs_, 1.0);
  b_above_glob_ = a_glob_ / sa + 2.0 * v_glob_ * v_glob_ / (sa * sa);
}

Searcher::Local Searcher::local(const Sample& s, double span) const {
  Local L;
  L.r_lo = std::max(r_min_, s.r - rdot_max_ * span);
  L.r_hi = std::min(r_max_, s.r + rdot_max_ * span);
  // Earth-fixed acceleration = gravity + centrifugal (c, |c(t) - c0| <= lc |r(t) - r0|) + perturbations
  // + Coriolis (2 omega |v|, but perpendicular to v: it turns v without changing |v|). So
  // |v(t)| <= |v0| + span (c0 + pert + lc V span): a Gronwall bound when span is short.
  const double inv_r = 1.0 / L.r_lo;
  const double lc = 2.0 * kMu * inv_r * inv_r * inv_r + kOmega * kOmega;
  const double pert = perturbation(L.r_lo, L.r_hi);
  const double den = 1.0 - lc * span * span;
  L.V = v_glob_;
  if (den > 0.25) L.V = std::min(v_glob_, (s.v + (s.c0 + pert) * span) / den);
  L.A = std::min(a_glob_, s.c0 + pert + lc * L.V * span + 2.0 * kOmega * L.V);
  return L;
}

double Searcher::curvature(const Sample& s, const Local& L, double span, double s_lo) const {
  // f = sin(el) = u.z with u the unit line of sight, rho = s u. Differentiating twice:
  //   f'' = rho''.(z - f u) / s - |u'|^2 f - 2 (s'/s) f',
  // with |z - f u| = cos(el) <= 1, |u'| <= V / s, |rho''| <= A. Over the span |f'| <= |f'0| + B t and
  // |f| <= |f0| + |f'0| t + B t^2 / 2, so B bounds |f''| when
  //   B >= A / s + K (|f0| + |f'0| span) + C |f'0| + B (C span + K span^2 / 2),  K = V^2/s^2, C = 2 S / s,
  // S bounding |s'| (|s''| = |s |u'|^2 + rho''.u| <= V^2 / s + A). The crude bound A/s + 2 V^2/s^2 (from
  // |f| <= 1 and |f'| <= V/s) holds regardless.
  const double inv_s = 1.0 / s_lo;
  const double K = L.V * L.V * inv_s * inv_s;
  const double crude = L.A * inv_s + 2.0 * K;
  const double f0 = std::abs(s.F + sin_h_);
  const double d0 = std::abs(s.Fdot) + vel_err_ / s.s;
  const double S = std::min(L.V, std::abs(s.sdot) + (L.V * L.V * inv_s + L.A) * span);
  const double C = 2.0 * S * inv_s;
  const double den = 1.0 - C * span - 0.5 * K * span * span;
  if (den <= 0.1) return crude;
  return std::min(crude, (L.A * inv_s + K * std::min(1.0, f0 + d0 * span) + C * d0) / den);
}

double Searcher::along_track(const Sample& s, const Angles& g, double span, bool below, double covered,
                             Mode mode) const {
  // Station u = cos(beta) p + sin(beta) W, satellite r^ = cos(du) p + sin(du) W x p, so
  // cos(theta) = cos(beta) cos(du) exactly. The foot p moves at most at the station's inertial speed
  // over cos(beta) plus the plane's turning; the satellite runs at h / r^2 along the plane. When it is
  // always faster than the foot, du only grows, at a rate in [w_lo, w_hi].
  struct {
    double r_lo, r_hi;
  } G = {std::max(r_min_, s.r - rdot_max_ * span), std::min(r_max_, s.r + rdot_max_ * span)};
  // A satellite slower than the Earth's rotation may fall behind its foot (geostationary, a high
  // apogee): nothing to rely on.
  if (h_min_ / (G.r_hi * G.r_hi) <= kOmega) return 0.0;
  const double omega_w = G.r_hi * perturbation(G.r_lo, G.r_hi) / h_min_;
  const double beta = g.beta, du = g.du;
  const double beta_rate = kOmega * cos_phi_ + omega_w;
  const double db = beta_rate * span;
  if (beta + db >= 1.4) return 0.0;
  // cos(beta + db) >= cos(beta) (1 - db^2/2) - sin(beta) db, cos(beta - db) <= cos(beta) + sin(beta) db:
  // bounds on the smallest and largest cos(beta) over the span, each on the safe side where used.
  const double cos_beta_hi = g.cos_b * (1.0 - 0.5 * db * db) - g.sin_b * db;
  const double cos_beta_lo = std::min(1.0, g.cos_b + g.sin_b * db);
  if (cos_beta_hi <= 0.1) return 0.0;
  // The foot's own speed along the plane: the station moves at omega z x u, and
  // (z x u).(W x p) = (W_z - u_z sin(beta)) / cos(beta), so foot = omega (W_z - u_z sin(beta)) / cos^2(beta).
  // W_z changes only as the plane turns, sin(beta) at most at beta_rate.
  const double n0 = s.w_z - us_[2] * s.sin_beta;
  const double dn = (omega_w + std::abs(us_[2]) * beta_rate) * span;
  const double inv_hi2 = 1.0 / (cos_beta_hi * cos_beta_hi), inv_lo2 = 1.0 / (cos_beta_lo * cos_beta_lo);
  auto over_cos2 = [&](double n) { return n >= 0.0 ? n * inv_hi2 : n * inv_lo2; };
  const double turn = 2.0 * omega_w / cos_beta_hi;  // the plane's turning moves the foot too
  const double foot_hi = kOmega * over_cos2(n0 + dn) + turn;
  const double foot_lo = kOmega * -over_cos2(-(n0 - dn)) - turn;
  const double w_lo = h_min_ / (G.r_hi * G.r_hi) - foot_hi, w_hi = h_max_ / (G.r_lo * G.r_lo) - foot_lo;
  if (w_lo <= 0.0) return 0.0;
  double x = 0.0;
  if (below) {
    // Up needs theta <= lam <= 90 deg, so |du| <= u with cos(u) = cos(lam) / cos(beta_lo).
    const double cos_lam = cos_lambda(G.r_hi, true, kAngleMargin);
    if (cos_lam <= 0.0) return 0.0;
    const double c = cos_lam / cos_beta_lo;
    if (c >= 1.0) return span;
    const double u = fast_acos(c) + 2.0 * kFastAtanErr;  // wider by the errors of u and du
    if (mode == kBack) {
      if (du > u) x = (du - u) / w_hi;                  // came from the window's far edge
      else if (du < -u) x = (du + kTwoPi - u) / w_hi;   // came round the orbit
    } else if (du < -u) {
      x = (-u - du) / w_hi;                 // still approaching
    } else if (du > u || covered >= (u - du) / w_lo || (mode == kGuess && du >= 0.0)) {
      x = (kTwoPi - u - du) / w_hi;         // passed (or surely past before `covered` runs out)
    }
  } else {
    // Up is certain while theta <= lam_in: while |du| <= u with cos(u) = cos(lam_in) / cos(beta_hi).
    const double cos_lam = cos_lambda(G.r_lo, false, -kAngleMargin);
    if (cos_lam <= 0.0 || cos_lam >= 1.0) return 0.0;
    const double c = cos_lam / cos_beta_hi;
    if (c >= 1.0) return 0.0;
    if (du > 0.0 && s.du_x < c * std::hypot(s.du_x, s.du_y)) return 0.0;  // du > u: nothing certain
    const double u = fast_acos(c) - 2.0 * kFastAtanErr;  // narrower by the errors of u and du
    if (mode == kBack) {
      if (std::abs(du) <= u) x = (du + u) / w_hi;
    } else if (du <= u && (du >= -u || covered >= (-u - du) / w_lo || mode == kGuess)) {
      x = (u - du) / w_hi;
    }
  }
  return std::min(span, x);
}

double Searcher::step_below(const Sample& s) {
  const Angles g(s, true);
  const double theta = g.theta, beta = g.beta;
  const double d = s.Fdot + fdot_err(s);
  // Global constants: valid for any step.
  double best = std::max({(theta - lambda_glob_) / omega_a_glob_, (beta - lambda_glob_) / omega_b_glob_,
                          envelope_root(s.F, d, b_below_glob_)});
  // Along track, over one revolution (unless the station stays far from the plane for longer).
  const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
  const double x = best < rev ? along_track(s, g, rev, true, best) : 0.0;
  best = std::max(best, x);
  if (best < 0.4 * rev) {
    // Close: local constants over a span, about twice the last step, then one fitted to the result.
    auto local_step = [&](double span) {
      const Local L = local(s, span);
      const double lam = lambda(L.r_hi, true) + kAngleMargin;
      const double omega_w = L.r_hi * perturbation(L.r_lo, L.r_hi) / h_min_;
      const double s_lo = std::max(range_floor_below(L.r_lo), s.s - L.V * span);
      const double loc = std::max({(theta - lam) * L.r_lo / L.V, (beta - lam) / (kOmega * cos_phi_ + omega_w),
                                   envelope_root(s.F, d, curvature(s, L, span, s_lo))});
      return std::min(loc, span);
    };
    best = std::max(best, fitted_span(local_step));
    // Along track again, over a span fitted to the result (tighter).
    if (x > 0.0) best = std::max(best, along_track(s, g, std::max(1.5 * x, 60.0), true, best));
  }
  return kStepSafety * best;
}

double Searcher::step_above(const Sample& s) {
  const double d = s.Fdot - fdot_err(s);
  double best = envelope_root(s.F, d, b_above_glob_);
  // Along track: a pass lasts at most about 2 lam / w; from a quarter revolution to fitted spans.
  const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
  const Angles g(s, false);
  double x = along_track(s, g, 0.25 * rev, false, best);
  for (int k = 0; k < 1 && x > 0.0; ++k) {  // a span fitted to the result is tighter
    best = std::max(best, x);
    x = along_track(s, g, std::max(1.2 * x, 30.0), false, best);
  }
  best = std::max(best, x);
  if (true) {
    auto local_step = [&](double span) {
      const Local L = local(s, span);
      const double s_lo = std::max({L.r_lo - rs_, s.s - L.V * span, 1.0});
      return std::min(envelope_root(s.F, d, curvature(s, L, span, s_lo)), span);
    };
    best = std::max(best, fitted_span(local_step));
  }
  return kStepSafety * best;
}

double Searcher::reach(const Sample& s, double span, int dir) const {
  // The envelope first; the angles only when it falls short.
  const Local L = local(s, span);
  const bool below = s.F < 0.0;
  const double d = dir * s.Fdot + (below ? fdot_err(s) : -fdot_err(s));
  const double s_lo = below ? std::max(range_floor_below(L.r_lo), s.s - L.V * span)
                            : std::max({L.r_lo - rs_, s.s - L.V * span, 1.0});
  double x = envelope_root(s.F, d, curvature(s, L, span, s_lo));
  if (x >= span) return span;
  const Angles g(s, below);
  if (below) x = std::max(x, (g.theta - lambda(L.r_hi, true) - kAngleMargin) * L.r_lo / L.V);
  if (x < span && dir < 0) x = std::max(x, along_track(s, g, span, below, 0.0, kBack));
  return std::min(span, x);
}

bool Searcher::monotone(const Sample& a, const Sample& b) const {
  const double e = std::max(fdot_err(a), fdot_err(b));
  const double da = std::abs(a.Fdot) - e, db = std::abs(b.Fdot) - e;
  if (da <= 0.0 || db <= 0.0 || (a.Fdot > 0.0) != (b.Fdot > 0.0)) return false;
  const double D = b.t - a.t;
  const Local L = local(a, D);
  const double s_lo = std::max({L.r_lo - rs_, 0.5 * (a.s + b.s - L.V * D), 1.0});
  return da + db > curvature(a, L, D, s_lo) * D;
}

// The first x > 0 where the quadratic model F + F' x + F'' x^2 / 2 crosses zero; infinity if none.
double predict_crossing(const Sample& s) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (std::abs(s.Fddot) < 1e-300) return s.Fdot * s.F < 0.0 ? -s.F / s.Fdot : inf;
  const double disc = s.Fdot * s.Fdot - 2.0 * s.Fddot * s.F;
  if (disc < 0.0) return inf;
  const double sq = std::sqrt(disc);
  double best = inf;
  for (double x : {(-s.Fdot - sq) / s.Fddot, (-s.Fdot + sq) / s.Fddot})
    if (x > 0.0 && x < best) best = x;
  return best;
}

bool Searcher::refine_crossing(const Sample& a, const Sample& b, bool single, double& t, Sample& up,
                               Sample& down, Sample& near) {
  // From the sample nearest the crossing the quadratic model predicts it. When F is known to be
  // monotonic between a and b the crossing is unique, and a predicted step shorter than half the
  // precision ends the search. Otherwise the bracket itself must close to the precision (to prove
  // where F first changes sign): each evaluation then goes a quarter of the precision beyond the
  // prediction, so that an accurate prediction closes it with one more. Regula falsi when the model
  // points outside the bracket, bisection when two steps fail to halve it.
  up = a.F >= 0.0 ? a : b;
  down = a.F >= 0.0 ? b : a;
  near = std::abs(up.F * down.Fdot) < std::abs(down.F * up.Fdot) ? up : down;
  int slow = 0;
  double prev_width = std::abs(up.t - down.t);
  for (int it = 0; it < 100 && std::abs(up.t - down.t) > tol_; ++it) {
    const double lo = std::min(up.t, down.t), hi = std::max(up.t, down.t);
    // Root of the model nearest to `near`, towards the other end of the bracket.
    const double dir = (near.F >= 0.0) == (up.t < down.t) ? 1.0 : -1.0;
    double dx = std::numeric_limits<double>::quiet_NaN();
    {
      const double A = 0.5 * near.Fddot, B = near.Fdot * dir, C = near.F;  // in y = dir dx > 0
      const double disc = B * B - 4.0 * A * C;
      if (std::abs(A) > 1e-300 && disc >= 0.0) {
        const double sq = std::sqrt(disc);
        double y = std::numeric_limits<double>::infinity();
        for (double cand : {(-B - sq) / (2.0 * A), (-B + sq) / (2.0 * A)})
          if (cand >= 0.0 && cand < y) y = cand;
        if (std::isfinite(y)) dx = dir * y;
      }
      if (!std::isfinite(dx) && near.Fdot != 0.0) dx = -near.F / near.Fdot;
    }
    // Unique crossing: the model's root is good to far below the precision within kModelStep.
    if (single && std::abs(dx) < std::max(0.5 * tol_, kModelStep)) {
      t = near.t + dx;
      return true;
    }
    double x;
    if (slow >= 2) {
      x = 0.5 * (lo + hi);
      slow = 0;
    } else {
      x = near.t + dx + (single ? 0.0 : (dx >= 0.0 ? 0.25 : -0.25) * tol_);
      if (!(x > lo && x < hi)) x = down.t + (up.t - down.t) * (down.F / (down.F - up.F));  // regula falsi
      x = std::clamp(x, lo + 0.01 * tol_, hi - 0.01 * tol_);
    }
    Sample m;
    if (!eval(x, m)) return false;
    widen(m);
    (m.F >= 0.0 ? up : down) = m;
    near = m;
    // A bracket that has shrunk may now be provably monotonic: its crossing is then unique.
    if (!single) single = up.t < down.t ? monotone(up, down) : monotone(down, up);
    const double width = std::abs(up.t - down.t);
    slow = width > 0.5 * prev_width ? slow + 1 : 0;
    prev_width = width;
  }
  const double den = down.F - up.F;
  t = den != 0.0 ? down.t + (up.t - down.t) * (down.F / den) : up.t;
  return true;
}

Sample Searcher::refine_max(const Sample& a, const Sample& b, double guess) {
  // a.Fdot > 0 >= b.Fdot. The first guess is the top of the cubic through (F, Fdot) at both ends, then
  // bracketed Newton on Fdot with the point-mass F'' (regula falsi or bisection when Newton leaves the
  // bracket or stalls), until a Newton step is below a quarter of the precision.
  Sample lo = a, hi = b;
  Sample best = a.F >= b.F ? a : b;
  double x = -1.0;
  {
    const double D = hi.t - lo.t;
    const double p0 = lo.F, p1 = hi.F, m0 = lo.Fdot * D, m1 = hi.Fdot * D;
    const double qa = 3.0 * (2.0 * p0 + m0 - 2.0 * p1 + m1);  // p'(u) = qa u^2 + qb u + m0 on [0, 1]
    const double qb = 2.0 * (-3.0 * p0 - 2.0 * m0 + 3.0 * p1 - m1);
    double u = -1.0;
    if (std::abs(qa) > 1e-300) {
      const double disc = qb * qb - 4.0 * qa * m0;
      if (disc >= 0.0) {
        const double sq = std::sqrt(disc);
        for (double cand : {(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)})
          if (cand > 0.0 && cand < 1.0 && 2.0 * qa * cand + qb <= 0.0) u = cand;
      }
    } else if (qb != 0.0) {
      u = -m0 / qb;
    }
    if (!(u > 0.0 && u < 1.0)) u = lo.Fdot / (lo.Fdot - hi.Fdot);
    x = guess > lo.t && guess < hi.t ? guess : lo.t + u * D;
  }
  Sample m, prev;
  bool have_prev = false, have_m = false;
  double width = hi.t - lo.t;
  for (int it = 0; it < 60 && hi.t - lo.t > tol_top_; ++it) {
    x = std::clamp(x, lo.t + 0.125 * tol_top_, hi.t - 0.125 * tol_top_);
    if (have_m) {
      prev = m;
      have_prev = true;
    }
    if (!eval(x, m)) {
      have_m = false;
      break;  // keep what we have
    }
    have_m = true;
    widen(m);
    if (m.F > best.F) best = m;
    (m.Fdot > 0.0 ? lo : hi) = m;
    double nx = m.Fddot < 0.0 ? m.t - m.Fdot / m.Fddot : -1.0;
    if (std::abs(nx - m.t) < 0.25 * tol_top_) break;
    // A short Newton step needs no propagation: the quadratic model gives the maximum, a Taylor step
    // of the state its direction.
    const double dx = nx - m.t;
    // The step is short enough when the velocity error, extrapolated over it, moves the line of sight by
    // less than kTaylorAngle, and can move the zero of Fdot by less than a quarter of the precision.
    if (nx > lo.t && nx < hi.t && vel_err_ * std::abs(dx) < kTaylorAngle * m.s &&
        fdot_err(m) < -0.25 * tol_top_ * m.Fddot) {
      Sample top = m;
      top.t = nx;
      top.F = m.F + 0.5 * m.Fdot * dx;  // F + F' dx + F'' dx^2 / 2 with dx = -F'/F''
      const Vec3 a = accel(m.ecef);
      for (int k = 0; k < 3; ++k) {
        top.ecef.r_km[k] += (m.ecef.v_km_s[k] + 0.5 * a[k] * dx) * dx;
        top.ecef.v_km_s[k] += a[k] * dx;
      }
      return top.F >= best.F ? top : best;
    }
    const bool slow = hi.t - lo.t > 0.5 * width;
    width = hi.t - lo.t;
    if (!(nx > lo.t && nx < hi.t)) nx = slow ? 0.5 * (lo.t + hi.t) : lo.t + width * lo.Fdot / (lo.Fdot - hi.Fdot);
    x = nx;
  }
  if (!have_m) return best;
  // Where the top is so flat that the velocity error could move the zero of Fdot by more than a few
  // seconds (geostationary orbits, high apogees), the point-mass F'' is not good enough either: find
  // the top from F alone.
  const double shift_bound = fdot_err(m) / std::max(-m.Fddot, 1e-300);
  if (shift_bound > kFlatTopShift) return polish_max(best, std::min(shift_bound, 3600.0));
  if (!(m.Fddot < 0.0) || shift_bound < 0.25 * tol_top_) return best;
  // The SGP4 velocity is not exactly the derivative of the SGP4 position, so the zero of Fdot may sit
  // off the top of F where the top is flat. Measure the bias b of Fdot between two samples (trapezoid
  // rule: F(q) - F(m) = D (Fdot(m) + Fdot(q)) / 2 - b D, up to D^3 F'''/12) and go to the zero of
  // Fdot - b.
  const Sample* q = nullptr;
  for (const Sample* c : {&prev, &lo, &hi}) {
    if (c == &prev && !have_prev) continue;
    const double d = std::abs(c->t - m.t);
    if (d >= 0.01 && d <= 20.0 && (!q || d < std::abs(q->t - m.t))) q = c;
  }
  if (!q) return best;
  const double D = q->t - m.t;
  const double bias = 0.5 * (m.Fdot + q->Fdot) - (q->F - m.F) / D;
  Sample cur = m;
  for (int k = 0; k < 3; ++k) {
    const double tx = cur.t - (cur.Fdot - bias) / cur.Fddot;
    if (std::abs(tx - cur.t) < 0.25 * tol_top_) break;
    Sample n;
    if (!eval(tx, n) || !(n.Fddot < 0.0)) break;
    widen(n);
    if (n.F > best.F) best = n;
    cur = n;
  }
  return best;
}

Sample Searcher::polish_max(const Sample& best, double h) {
  // Successive parabolic interpolation on F alone, through a triple with the highest in the middle.
  h = std::max(h, tol_top_);
  Sample a, b, c = best;
  if (!eval(c.t - h, a) || !eval(c.t + h, b)) return best;
  for (int k = 0; k < 8 && (a.F > c.F || b.F > c.F); ++k) {  // walk until c is the highest
    if (a.F > c.F) {
      b = c;
      c = a;
      if (!eval(c.t - h, a)) return c.F > best.F ? c : best;
    } else {
      a = c;
      c = b;
      if (!eval(c.t + h, b)) return c.F > best.F ? c : best;
    }
  }
  for (int it = 0; it < 12; ++it) {
    const double p = c.t - a.t, q = c.t - b.t;
    const double num = p * p * (c.F - b.F) - q * q * (c.F - a.F);
    const double den = p * (c.F - b.F) - q * (c.F - a.F);
    if (den == 0.0) break;
    const double x = c.t - 0.5 * num / den;
    if (!(x > a.t && x < b.t) || std::abs(x - c.t) < 0.5 * tol_top_) break;
    Sample m;
    if (!eval(x, m)) break;
    if (m.F > c.F) {
      (x < c.t ? b : a) = c;
      c = m;
    } else {
      (x < c.t ? a : b) = m;
    }
  }
  return c.F > best.F ? c : best;
}

void Searcher::finish_pass(std::vector<Sample>& samples, Pass& p, double guess) {
  std::sort(samples.begin(), samples.end(), [](const Sample& x, const Sample& y) { return x.t < y.t; });
  std::size_t best = 0;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].F > samples[best].F) best = i;
  Sample top = samples[best];
  // Every local maximum: a change of sign of Fdot between two samples, or one hidden between samples
  // where Fdot keeps its sign (a turn of the cubic through both ends; for orbits where a pass may have
  // several maxima also wherever the second-order envelope leaves room above the best maximum).
  std::vector<std::pair<std::size_t, std::size_t>> work;
  work.reserve(samples.size() + 8);
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) work.emplace_back(i, i + 1);
  int budget = 400;
  while (!work.empty() && budget-- > 0) {
    const auto [ia, ib] = work.back();
    work.pop_back();
    const Sample a = samples[ia], b = samples[ib];
    const double D = b.t - a.t;
    if (D <= tol_top_) continue;
    if (a.Fdot > 0.0 && b.Fdot <= 0.0) {
      const Sample m = refine_max(a, b, guess);
      if (m.F > top.F) top = m;
      continue;
    }
    const double p0 = a.F, p1 = b.F, m0 = a.Fdot * D, m1 = b.Fdot * D;
    const double qa = 3.0 * (2.0 * p0 + m0 - 2.0 * p1 + m1);
    const double qb = 2.0 * (-3.0 * p0 - 2.0 * m0 + 3.0 * p1 - m1);
    double split = -1.0;
    if (std::abs(qa) > 1e-300) {
      const double disc = qb * qb - 4.0 * qa * m0;
      if (disc > 0.0) {
        const double sq = std::sqrt(disc);
        for (double u : {(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)})
          if (u > 0.0 && u < 1.0 && 2.0 * qa * u + qb < 0.0) split = u;
      }
    }
    if (split < 0.0 && eccentric_) {
      // Upper envelope on [a, b]: min of F_a + d_a x + B x^2/2 and F_b - d_b (D - x) + B (D - x)^2/2.
      const Local L = local(a, D);
      const double s_lo = std::max({L.r_lo - rs_, a.s - L.V * D, 1.0});
      const double B = curvature(a, L, D, s_lo);
      const double da = a.Fdot + fdot_err(a), db = b.Fdot - fdot_err(b);
      const double k0 = a.F - b.F + db * D - 0.5 * B * D * D;  // their difference is k0 + k1 x
      const double k1 = da - db + B * D;
      if (k1 != 0.0) {
        const double xs = -k0 / k1;
        if (xs > 0.0 && xs < D && a.F + da * xs + 0.5 * B * xs * xs > top.F + kMaxElTolerance) split = xs / D;
      }
    }
    if (split > 0.0) {
      Sample m;
      if (!eval(std::clamp(a.t + split * D, a.t + 0.25 * tol_top_, b.t - 0.25 * tol_top_), m)) continue;
      widen(m);
      if (m.F > top.F) top = m;
      samples.push_back(m);
      work.emplace_back(ia, samples.size() - 1);
      work.emplace_back(samples.size() - 1, ib);
    }
  }
  p.tca = at(top.t);
  const LookAngles la = look(top.ecef);
  p.max_el_deg = la.el_deg;
  p.tca_az_deg = la.az_deg;
}

std::optional<Pass> Searcher::next_any() {
  if (done_) return std::nullopt;
  if (!started_) {
    started_ = true;
    if (!eval(0.0, cur_)) {
      done_ = true;
      return std::nullopt;
    }
    init_bounds(cur_);
  }
  Pass pass;
  double aos_t = 0.0;
  Sample aos_s, aos_near;  // the first sample of the pass, and the one nearest to AOS
  if (cur_.t == 0.0 && cur_.F >= 0.0) {
    pass.up_at_start = true;
    aos_s = aos_near = cur_;
  } else if (!find_aos(aos_t, aos_s, aos_near)) {
    done_ = true;
    return std::nullopt;
  }
  // Up: step to LOS (or the window end, or the end of the propagation).
  last_step_ = 30.0;  // the spans of the local bounds start afresh at each crossing
  std::vector<Sample> samples;
  samples.reserve(24);
  samples.push_back(aos_s);
  Sample up = aos_s;
  double los_t = span_;
  Sample los_near = up;
  // As in find_aos: a speculative sample not proven yet (still up), or a refined LOS with its up side.
  std::optional<Sample> ahead;
  bool cross = false;
  double cross_t = 0.0;
  Sample cross_down, cross_near;
  for (;;) {
    if (up.t >= span_) {
      pass.up_at_end = true;
      los_t = span_;
      los_near = up;
      done_ = true;
      break;
    }
    const double safe = step_above(up);
    if (ahead && keeps_sign(up, safe, *ahead)) {
      if (cross) {
        los_t = cross_t;
        los_near = cross_near;
        samples.push_back(*ahead);
        cur_ = cross_down;
        break;
      }
      last_step_ = ahead->t - up.t;
      samples.push_back(*ahead);
      up = *ahead;
      ahead.reset();
      continue;
    }
    Sample n, in, out;
    double t = 0.0;
    // A step onto the predicted LOS, or the along-track jump across the pass taken before the
    // satellite is proven inside it: kept only when proven not to have jumped a crossing.
    double target = -1.0;
    if (!ahead) {
      const double xp = predict_crossing(up);
      if (xp > safe && xp < 3.0 * safe + 30.0) {
        target = up.t + xp + 0.125 * tol_ + 0.002 * xp;
      } else if (safe < 300.0 && up.du_y < 0.0) {  // still approaching the station's foot
        const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
        const Angles g(up, false);
        double xg = along_track(up, g, 0.25 * rev, false, 0.0, kGuess);
        if (xg > 0.0) xg = std::max(xg, along_track(up, g, std::max(1.2 * xg, 30.0), false, 0.0, kGuess));
        if (xg > 2.0 * safe) target = up.t + 0.99 * xg;
      }
    }
    if (target > 0.0 && target < span_) {
      if (eval(target, n)) {
        widen(n);
        if (n.F < 0.0) {
          const bool single = monotone(up, n);
          if (refine_crossing(up, n, single, t, in, out, los_near)) {
            if (single || keeps_sign(up, safe, in)) {
              los_t = t;
              samples.push_back(in);
              cur_ = out;
              break;
            }
            ahead = in;
            cross = true;
            cross_t = t;
            cross_down = out;
            cross_near = los_near;
          }
        } else if (keeps_sign(up, safe, n)) {
          last_step_ = n.t - up.t;
          samples.push_back(n);
          up = n;
          continue;
        } else {
          ahead = n;
        }
      }
    }
    const double step = std::max(safe, min_step_);
    last_step_ = step;
    const double tn = std::min(up.t + step, span_);
    if (!eval(tn, n)) {
      // The propagation ends inside the pass, and with it the search: find where, or a LOS before it.
      done_ = true;
      double good = up.t, bad = tn;
      bool set = false;
      while (bad - good > tol_) {
        const double mid = 0.5 * (good + bad);
        Sample m;
        if (!eval(mid, m)) {
          bad = mid;
        } else if (m.F < 0.0) {
          n = m;
          set = true;
          break;
        } else {
          good = mid;
          up = m;
          samples.push_back(m);
        }
      }
      if (set && refine_crossing(up, n, false, t, in, out, los_near)) {
        los_t = t;
        samples.push_back(in);
      } else {
        pass.up_at_end = true;
        los_t = up.t;
        los_near = up;
      }
      break;
    }
    widen(n);
    if (n.F < 0.0) {
      if (refine_crossing(up, n, monotone(up, n), t, in, out, los_near)) {
        los_t = t;
        cur_ = out;
      } else {
        pass.up_at_end = true;
        los_t = in.t;
        los_near = in;
        done_ = true;
      }
      samples.push_back(in);
      break;
    }
    samples.push_back(n);
    up = n;
    if (ahead && up.t >= ahead->t) {
      ahead.reset();
      cross = false;
    }
  }
  // For a whole pass, the top of the cubic through (0, F') at AOS and LOS is a good first guess for
  // the maximum (the middle for a symmetric pass).
  double guess = -1.0;
  if (!pass.up_at_start && !pass.up_at_end) {
    const double D = los_t - aos_t, m0 = aos_near.Fdot * D, m1 = los_near.Fdot * D;
    const double qa = 3.0 * (m0 + m1), qb = -2.0 * (2.0 * m0 + m1);  // p'(u) = qa u^2 + qb u + m0
    double u = 0.5;
    if (std::abs(qa) > 1e-12 * std::abs(qb)) {
      const double disc = qb * qb - 4.0 * qa * m0;
      if (disc >= 0.0) {
        const double sq = std::sqrt(disc);
        for (double cand : {(-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)})
          if (cand > 0.0 && cand < 1.0 && 2.0 * qa * cand + qb < 0.0) u = cand;
      }
    } else if (qb != 0.0) {
      u = std::clamp(-m0 / qb, 0.0, 1.0);
    }
    guess = aos_t + u * D;
  }
  finish_pass(samples, pass, guess);
  last_step_ = 30.0;
  pass.aos = at(aos_t);
  pass.los = at(los_t);
  pass.aos_az_deg = look(taylor(aos_near.ecef, aos_t - aos_near.t), false).az_deg;
  pass.los_az_deg = look(taylor(los_near.ecef, los_t - los_near.t), false).az_deg;
  return pass;
}

bool Searcher::find_aos(double& aos_t, Sample& aos_s, Sample& aos_near) {
  // A speculative sample that could not be proven yet is kept: `ahead` (still down) or a refined
  // crossing `cross` whose down side is `ahead`. Safe steps go on until the proof reaches it.
  std::optional<Sample> ahead;
  bool cross = false;
  double cross_t = 0.0;
  Sample cross_up, cross_near;
  for (;;) {
    const double safe = step_below(cur_);
    if (cur_.t + safe >= span_) return false;
    if (ahead && keeps_sign(cur_, safe, *ahead)) {
      if (cross) {
        aos_t = cross_t;
        aos_s = cross_up;
        aos_near = cross_near;
        return aos_t < span_;
      }
      last_step_ = ahead->t - cur_.t;
      cur_ = *ahead;
      ahead.reset();
      continue;
    }
    Sample n, down;
    // A step onto the predicted AOS, or the along-track jump to the next approach taken before the
    // satellite is proven clear of this one: kept only when proven not to have jumped a crossing.
    double target = -1.0;
    if (!ahead) {
      const double xp = predict_crossing(cur_);
      if (xp > safe && xp < 3.0 * safe + 30.0) {
        target = cur_.t + xp + 0.125 * tol_ + 0.002 * xp;
      } else if (safe < 300.0 && cur_.du_y > 0.0) {  // receding from the station's foot
        const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
        const double xg = along_track(cur_, Angles(cur_, false), rev, true, 0.0, kGuess);
        if (xg > 2.0 * safe) target = cur_.t + 0.99 * xg;
      }
    }
    if (target > 0.0) {
      if (eval(std::min(target, span_), n)) {
        widen(n);
        if (n.F >= 0.0) {
          const bool single = monotone(cur_, n);
          if (refine_crossing(cur_, n, single, aos_t, aos_s, down, aos_near)) {
            if (single || keeps_sign(cur_, safe, down)) {
              return aos_t < span_;
            }
            ahead = down;
            cross = true;
            cross_t = aos_t;
            cross_up = aos_s;
            cross_near = aos_near;
          }
        } else if (keeps_sign(cur_, safe, n)) {
          last_step_ = n.t - cur_.t;
          cur_ = n;
          continue;
        } else {
          ahead = n;
        }
      }
    }
    const double step = std::max(safe, min_step_);
    last_step_ = step;
    const double tn = std::min(cur_.t + step, span_);
    if (!eval(tn, n)) return false;  // decayed (or another propagation error): no more passes
    widen(n);
    if (n.F >= 0.0) {
      // The safe step proved F < 0 up to cur_ + safe, so any crossing is in the last min_step.
      return refine_crossing(cur_, n, monotone(cur_, n), aos_t, aos_s, down, aos_near) && aos_t < span_;
    }
    cur_ = n;
    if (ahead && cur_.t >= ahead->t) {  // stepped past it (a min_step): forget it
      ahead.reset();
      cross = false;
    }
    if (tn >= span_) return false;
  }
}

}  // namespace

std::vector<Pass> find_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                              const PassOptions& options, const EarthOrientation& eo, PassSearchStats& stats) {
  std::vector<Pass> out;
  Searcher s(sat, o, start, stop, options, eo);
  while (auto p = s.next()) out.push_back(*p);
  stats.propagations += s.evaluations();
  return out;
}

std::vector<Pass> find_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                              const PassOptions& options, const EarthOrientation& eo) {
  PassSearchStats unused;
  return find_passes(sat, o, start, stop, options, eo, unused);
}

std::optional<Pass> next_pass(const Sgp4& sat, const Observer& o, UtcTime from, double max_days,
                              const PassOptions& options, const EarthOrientation& eo) {
  Searcher s(sat, o, from, add_seconds(from, max_days * kSecondsPerDay), options, eo);
  return s.next();
}

}  // namespace tb::orbit
