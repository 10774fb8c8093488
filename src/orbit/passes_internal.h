// The pass search's internals, shared by passes.cpp (the search: stepping from crossing to crossing),
// passes_bounds.cpp (how far a step may safely go) and passes_refine.cpp (AOS, LOS and the maximum to
// the precision asked). Private to src/orbit. passes.cpp's opening comment explains the method.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "orbit/constants.h"
#include "orbit/geometry.h"
#include "orbit/passes.h"
#include "orbit/sgp4_common.h"  // poly_sin_cos

namespace tb::orbit::detail {

using wgs72::kJ2;
using wgs72::kMu;                                    // SGP4's own, km^3/s^2
inline constexpr double kReSgp4 = wgs72::kRadiusKm;  // SGP4's equatorial radius, km
inline constexpr double kOmega = kEarthRotationRadS * 1.000001;  // Earth rate with a hair of margin, rad/s

// Margins. The geometry is exact; these cover what the state at the window start and the mean elements
// cannot promise about the osculating orbit later (measured over the gpredict catalogue in the tests,
// and widened at run time whenever a state falls outside them).
inline constexpr double kRadiusMarginRel = 0.003;
inline constexpr double kRadiusMarginKm = 20.0;
inline constexpr double kMomentumMargin = 0.01;     // on |r x v|
inline constexpr double kSpeedFactor = 1.02;        // on vis-viva speeds and on gravity
inline constexpr double kVelocityErrKmS = 3e-4;     // |SGP4 velocity - d/dt SGP4 position|: measured up to
inline constexpr double kVelocityErrPerEcc = 0.015; //   1.4e-4 km/s on circular orbits, 0.008 e on elliptic ones
inline constexpr double kStepSafety = 0.97;         // every safe step is shortened by this factor
inline constexpr double kAngleMargin = 2e-4;        // rad, on horizon angles
inline constexpr double kMaxElTolerance = 2e-5;     // sin(el): hidden maxima below this are not chased
inline constexpr double kTaylorAngle = 5e-7;        // rad: error allowed to the model step onto a maximum
inline constexpr double kFlatTopShift = 10.0;       // s: flatter maxima are found from F alone
inline constexpr double kModelStep = 2.0;           // s: a crossing this close is taken from the quadratic model

// atan2 from a minimax polynomial: |error| < 6e-9 rad (2e7 + 5e7 points against std::atan2, asin and
// acos), a few times faster. Used only inside the bounds, which carry kFastAtanErr on the safe side.
inline constexpr double kFastAtanErr = 2e-8;
inline double fast_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double mx = std::max(ax, ay), mn = std::min(ax, ay);
  if (mx == 0.0) return 0.0;
  const double a = mn / mx, s = a * a;
  // The polynomial in s by Estrin's scheme (pairs, then pairs of pairs): a third shorter a dependency
  // chain than Horner's rule, the same coefficients.
  const double s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
  const double p01 = 0.9999998863824159 + s * -0.33332597025546035;
  const double p23 = 0.19985906731337763 + s * -0.14161228977057888;
  const double p45 = 0.1049894535543198 + s * -0.07234855996589841;
  const double p67 = 0.03978120868453937 + s * -0.014401349336020525;
  const double p07 = (p01 + s2 * p23) + s4 * (p45 + s2 * p67);
  double r = a * (p07 + s8 * 0.0024567225469432352);
  if (ay > ax) r = 0.5 * kPi - r;
  if (x < 0.0) r = kPi - r;
  return y < 0.0 ? -r : r;
}
inline double fast_asin(double x) { return fast_atan2(x, std::sqrt(std::max(0.0, 1.0 - x * x))); }
inline double fast_acos(double x) { return fast_atan2(std::sqrt(std::max(0.0, 1.0 - x * x)), x); }


// The angles of a sample that the geometric bounds use (computed only where a step is planned, once per
// sample: see angles()).
struct Angles {
  double theta = 0.0;    // geocentric angle station - satellite, at most this
  double beta = 0.0;     // at most this
  double du = 0.0;       // in (-pi, pi] to kFastAtanErr (along_track allows)
  double sin_b = 0.0, cos_b = 1.0;  // of beta
};

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
  double fdot_err = 0.0;   // bound on the error of Fdot from that of the SGP4 velocity: vel_err / s
  double c0 = 0.0;         // |point-mass gravity + centrifugal| at r, km/s^2
  double h = 0.0;          // |r x v| (inertial), km^2/s
  double cos_theta = 0.0;  // station direction . satellite direction
  double sin_beta = 0.0;   // station direction . orbit normal
  double w_z = 0.0;        // z component of the orbit normal (cos of the osculating inclination)
  double du_y = 0.0, du_x = 0.0;  // atan2(du_y, du_x): angle of the satellite ahead of the station's foot
                                  // on the orbit plane
  StateVector ecef;
  // angles(): which of them are computed (kDu, kBeta, kTheta bits).
  mutable int angles_have = 0;
  mutable Angles angles_cache;
};

// The sample's angles, each computed on first use: du, sin_b and cos_b always, beta and theta when asked.
enum AngleNeed : int { kDu = 1, kBeta = 2, kTheta = 4 };
inline const Angles& angles(const Sample& s, int need) {
  Angles& g = s.angles_cache;
  const int missing = (need | kDu) & ~s.angles_have;
  if (missing == 0) return g;
  if (missing & kDu) {
    g.sin_b = std::min(std::abs(s.sin_beta), 1.0);
    g.du = fast_atan2(s.du_y, s.du_x);
    g.cos_b = std::sqrt(1.0 - g.sin_b * g.sin_b);
  }
  if (missing & kBeta) g.beta = std::max(0.0, fast_asin(g.sin_b) - kFastAtanErr);
  if (missing & kTheta) g.theta = std::max(0.0, fast_acos(std::clamp(s.cos_theta, -1.0, 1.0)) - kFastAtanErr);
  s.angles_have |= missing;
  return g;
}

inline Vec3 accel(const StateVector& e);

// The state dt seconds on, by a second-order Taylor step (dt of a few seconds: metres).
inline StateVector taylor(const StateVector& e, double dt) {
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
// k = w^2 - mu / r^3, for a caller that has it already.
inline Vec3 accel(const StateVector& e, double k) {
  return {k * e.r_km[0] + 2.0 * kEarthRotationRadS * e.v_km_s[1],
          k * e.r_km[1] - 2.0 * kEarthRotationRadS * e.v_km_s[0],
          (k - kEarthRotationRadS * kEarthRotationRadS) * e.r_km[2]};
}
inline Vec3 accel(const StateVector& e) {
  const double r2 = dot(e.r_km, e.r_km);
  return accel(e, kEarthRotationRadS * kEarthRotationRadS - kMu / (r2 * std::sqrt(r2)));
}

// The first x > 0 where F + d x + (b / 2) x^2 reaches 0 for F < 0 (an upper envelope), or where
// F + d x - (b / 2) x^2 reaches 0 for F >= 0 (a lower envelope). b > 0.
inline double envelope_root(double F, double d, double b) {
  if (F < 0.0) return (-d + std::sqrt(d * d - 2.0 * b * F)) / b;
  return (d + std::sqrt(d * d + 2.0 * b * F)) / b;
}

// Perturbing acceleration bound (J2 with room for the higher zonals, Sun and Moon, drag), km/s^2,
// for q = R / r_lo. Callers give r_lo or, where they have it, its reciprocal (each q rounded as
// before, so that the bounds keep their values to the bit).
inline double perturbation_q(double q, double r_hi) {
  const double q2 = q * q;
  return (4.5 * kJ2 * kMu / (kReSgp4 * kReSgp4)) * q2 * q2 + 3e-13 * r_hi + 1e-8;
}
inline double perturbation(double r_lo, double r_hi) { return perturbation_q(kReSgp4 / r_lo, r_hi); }
inline double perturbation_inv(double inv_r_lo, double r_hi) { return perturbation_q(kReSgp4 * inv_r_lo, r_hi); }

// The first x > 0 where the quadratic model F + F' x + F'' x^2 / 2 crosses zero; infinity if none.
double predict_crossing(const Sample& s);

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
  void record_tsince(std::vector<double>* into) { trace_ = into; }

 private:
  struct Local { double r_lo, r_hi, V, A, pert; };  // bounds valid over a span from a sample (pert:
                                                     // perturbation(r_lo, r_hi))

  std::optional<Pass> next_any();
  // How a walk (below) ended.
  struct Walk {
    enum End { kCrossed, kWindowEnd, kRefineFailed, kPropagationFailed } end = kWindowEnd;
    double t = 0.0;      // kCrossed: the time of the crossing
    Sample same, other;  // kCrossed: the final bracket, `same` on the side the walk started on;
                         // kRefineFailed: `same` the last sample on that side
    Sample near;         // kCrossed: the evaluated sample nearest to the crossing
    Sample last;         // kWindowEnd, kPropagationFailed: the last sample on the starting side
    double bad_t = 0.0;  // kPropagationFailed: the time at which the propagation failed
  };
  // Steps from `from` (down when `below`, else up) to the next change of sign of F, by safe steps and
  // speculative ones (see speculative_target) kept only when proven not to have jumped a crossing.
  // The samples on the starting side that it steps onto go to *keep when keep is not null.
  // Down, it stops when the safe step reaches the window end; up, when a sample does.
  Walk walk(const Sample& from, bool below, std::vector<Sample>* keep);
  // Where to try a step that the bounds cannot prove yet, or -1: onto the crossing the quadratic model
  // predicts a little beyond the safe step, else (safe steps short, the satellite receding from the
  // station's foot when below, approaching it when up) the along-track jump to the next approach or
  // across the pass.
  double speculative_target(const Sample& s, double safe, bool below) const;
  // The propagation failed at bad_t inside a pass last seen up at `up`: the search ends there, at a
  // LOS found before it or with up_at_end.
  void end_inside_pass(Sample up, double bad_t, std::vector<Sample>& samples, Pass& pass, double& los_t,
                       Sample& los_near);
  // For a whole pass, a first guess of the time of the maximum from the rates at AOS and LOS.
  double tca_guess(double aos_t, const Sample& aos_near, double los_t, const Sample& los_near) const;
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
  double floor_below(double r) const { return r == r_min_ ? glob_.floor_below : range_floor_below(r); }
  double curvature(const Sample& s, const Local& L, double span, double s_lo) const;
  // (d): the time, at most span, for which the satellite provably stays down (below) or up, given
  // that it provably does for `covered` seconds anyway; 0 if the bound says nothing.
  // mode kAhead: as above; kBack: the same looking back from s; kGuess: where a forward jump would
  // land if the satellite had already cleared the window's edge (to be proven afterwards).
  enum Mode { kAhead, kBack, kGuess };
  double along_track(const Sample& s, const Angles& g, double span, bool below, double covered,
                     Mode mode = kAhead) const;
  double step_below(const Sample& s);
  double step_above(const Sample& s);
  // The best of `known` and step(span) (a bound valid over span, capped by it) for two spans: about
  // twice the last step, then one fitted to what that gave. A span no longer than `known` cannot beat
  // it and is not tried (the same result, without the work).
  template <class Step>
  double fitted_span(const Step& step, double known) const {
    const double span0 = std::clamp(2.0 * last_step_, 20.0, 86400.0);
    if (known >= 4.0 * span0) return known;  // every span below is at most 4 span0
    const double x0 = step(span0);
    const double span1 = x0 < span0 ? std::max(1.5 * x0, 20.0) : 4.0 * span0;
    const bool try1 = span1 > known;
    const double y1 = try1 ? step(span1) : 0.0;
    const double x1 = std::max(x0, y1);
    // A step that fell well short of the last one: try the last one's span too. The bounds only
    // loosen as the span grows, so a longer span can do better than span1 only when span1 itself
    // capped the step.
    const double span2 = std::max(last_step_, 20.0);
    const bool try2 = x1 < 0.5 * last_step_ && span2 > known && (!try1 || y1 >= span1 || span2 < span1);
    const double x2 = try2 ? std::max(x1, step(span2)) : x1;
    return std::max(known, x2);
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
  StationFrame frame_{};     // sin, cos of geodetic latitude and longitude
  Vec3 us_{};                // geocentric direction
  double rs_ = 0.0;          // geocentric distance, km
  double cos_phi_ = 1.0;     // cos(geocentric latitude)
  double sin_h_ = 0.0;
  double e_low_ = 0.0;       // up needs at least this geocentric elevation (rad)
  double e_high_ = 0.0;      // down has at most this geocentric elevation (rad)
  double cos_e_low_ = 1.0, sin_e_low_ = 0.0, cos_e_high_ = 1.0, sin_e_high_ = 0.0;

  // Orbit bounds (km, km/s, km/s^2, km^2/s) and what follows from them.
  double r_min_ = 0.0, r_max_ = 0.0, h_min_ = 0.0, h_max_ = 0.0, inv_h_min_ = 0.0;
  double rdot_max_ = 0.0, v_glob_ = 0.0, a_glob_ = 0.0, lambda_glob_ = 0.0;
  double omega_a_glob_ = 0.0, omega_b_glob_ = 0.0, b_below_glob_ = 0.0, b_above_glob_ = 0.0;
  struct {                   // derive()'s values of what the bounds compute from [r_min_, r_max_]
    double pert, lc, omega_w, w_sat_lo, w_sat_hi, cos_lam_low, cos_lam_high, floor_below;
  } glob_{};
  double vel_err_ = 0.0;     // bound on |SGP4 velocity - d/dt SGP4 position|, km/s
  bool eccentric_ = false;   // a pass may have several maxima: prove there is no higher one
  double last_step_ = 60.0;

  bool started_ = false;
  bool done_ = false;
  Sample cur_{};             // the latest sample, down (except at the very start)
  std::vector<Sample> samples_;                              // next_any's samples of a pass
  std::vector<std::pair<std::size_t, std::size_t>> work_;  // finish_pass's intervals to examine
  long evals_ = 0;
  std::vector<double>* trace_ = nullptr;  // PassSearchStats::tsince_minutes
};

// The masked searches (passes_mask.cpp): find_passes and next_pass with options.mask set.
std::vector<Pass> masked_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                                const PassOptions& options, const EarthOrientation& eo, PassSearchStats& stats);
std::optional<Pass> masked_next_pass(const Sgp4& sat, const Observer& o, UtcTime from, double max_days,
                                     const PassOptions& options, const EarthOrientation& eo);

}  // namespace tb::orbit::detail
