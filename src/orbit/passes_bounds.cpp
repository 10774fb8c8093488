// The pass search's safe steps: bounds on the orbit and the station geometry, and from them how long
// F = sin(el) - sin(horizon) provably keeps its sign (bounds (a) to (d) of passes.cpp's opening comment).
#include <algorithm>
#include <cmath>

#include "orbit/passes_internal.h"

namespace tb::orbit::detail {

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
  inv_h_min_ = 1.0 / h_min_;
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
  // What along_track and the local bounds compute for a span long enough that the distance may take
  // any value in [r_min_, r_max_]: the same arithmetic, done once.
  glob_.pert = pert;
  const double inv_r = 1.0 / r_min_;
  glob_.lc = 2.0 * kMu * inv_r * inv_r * inv_r + kOmega * kOmega;
  glob_.omega_w = r_max_ * pert / h_min_;
  glob_.w_sat_lo = h_min_ / (r_max_ * r_max_);
  glob_.w_sat_hi = h_max_ / (r_min_ * r_min_);
  glob_.cos_lam_low = cos_lambda(r_max_, true, kAngleMargin);
  glob_.cos_lam_high = cos_lambda(r_min_, false, -kAngleMargin);
  glob_.floor_below = sb;
}

Searcher::Local Searcher::local(const Sample& s, double span) const {
  Local L;
  L.r_lo = std::max(r_min_, s.r - rdot_max_ * span);
  L.r_hi = std::min(r_max_, s.r + rdot_max_ * span);
  // Earth-fixed acceleration = gravity + centrifugal (c, |c(t) - c0| <= lc |r(t) - r0|) + perturbations
  // + Coriolis (2 omega |v|, but perpendicular to v: it turns v without changing |v|). So
  // |v(t)| <= |v0| + span (c0 + pert + lc V span): a Gronwall bound when span is short.
  double lc, pert;
  if (L.r_lo == r_min_) {  // derive() did this arithmetic
    lc = glob_.lc;
    pert = L.r_hi == r_max_ ? glob_.pert : perturbation(L.r_lo, L.r_hi);
  } else {
    const double inv_r = 1.0 / L.r_lo;
    lc = 2.0 * kMu * inv_r * inv_r * inv_r + kOmega * kOmega;
    pert = perturbation_inv(inv_r, L.r_hi);
  }
  L.pert = pert;
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
  const double d0 = std::abs(s.Fdot) + s.fdot_err;
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
  const bool glob = G.r_lo == r_min_ && G.r_hi == r_max_;  // then derive() did the arithmetic below
  // Reciprocals of the distances (multiplications stand in for divisions below: an ulp, far inside
  // the margins).
  const double ir_lo = glob ? 0.0 : 1.0 / G.r_lo, ir_hi = glob ? 0.0 : 1.0 / G.r_hi;
  // A satellite slower than the Earth's rotation may fall behind its foot (geostationary, a high
  // apogee): nothing to rely on.
  const double w_sat_lo = glob ? glob_.w_sat_lo : h_min_ * ir_hi * ir_hi;
  if (w_sat_lo <= kOmega) return 0.0;
  const double omega_w = glob ? glob_.omega_w : G.r_hi * perturbation_inv(ir_lo, G.r_hi) * inv_h_min_;
  const double du = g.du;
  const double beta_rate = kOmega * cos_phi_ + omega_w;
  const double db = beta_rate * span;
  // Nothing when beta + db may reach 1.4 rad: then sin(beta) >= sin(1.4 - db) >=
  // sin(1.4) (1 - db^2 / 2) - cos(1.4) db (beta itself, an asin, is not needed).
  if (g.sin_b >= 0.9854497299884601 * (1.0 - 0.5 * db * db) - 0.16996714290024104 * db) return 0.0;
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
  const double inv_hi = 1.0 / cos_beta_hi, inv_lo = 1.0 / cos_beta_lo;
  const double inv_hi2 = inv_hi * inv_hi, inv_lo2 = inv_lo * inv_lo;
  auto over_cos2 = [&](double n) { return n >= 0.0 ? n * inv_hi2 : n * inv_lo2; };
  const double turn = 2.0 * omega_w * inv_hi;  // the plane's turning moves the foot too
  const double foot_hi = kOmega * over_cos2(n0 + dn) + turn;
  const double foot_lo = kOmega * -over_cos2(-(n0 - dn)) - turn;
  const double w_lo = w_sat_lo - foot_hi, w_hi = (glob ? glob_.w_sat_hi : h_max_ * ir_lo * ir_lo) - foot_lo;
  if (w_lo <= 0.0) return 0.0;
  double x = 0.0;
  if (below) {
    // Up needs theta <= lam <= 90 deg, so |du| <= u with cos(u) = cos(lam) / cos(beta_lo).
    const double cos_lam = glob ? glob_.cos_lam_low : cos_lambda(G.r_hi, true, kAngleMargin);
    if (cos_lam <= 0.0) return 0.0;
    const double c = cos_lam * inv_lo;
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
    const double cos_lam = glob ? glob_.cos_lam_high : cos_lambda(G.r_lo, false, -kAngleMargin);
    if (cos_lam <= 0.0 || cos_lam >= 1.0) return 0.0;
    const double c = cos_lam * inv_hi;
    if (c >= 1.0) return 0.0;
    // du > u: nothing certain (sqrt in place of hypot: du_x, du_y are of the order of 1e4 km).
    if (du > 0.0 && s.du_x < c * std::sqrt(s.du_x * s.du_x + s.du_y * s.du_y)) return 0.0;
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
  const Angles& g = angles(s, kDu | kBeta | kTheta);
  const double theta = g.theta, beta = g.beta;
  const double d = s.Fdot + s.fdot_err;
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
      const double lam = L.r_hi == r_max_ ? lambda_glob_ : lambda(L.r_hi, true) + kAngleMargin;
      const double s_lo = std::max(floor_below(L.r_lo), s.s - L.V * span);
      // The envelope's root is positive (F < 0): the angle bounds count only when they are too.
      double loc = envelope_root(s.F, d, curvature(s, L, span, s_lo));
      if (theta > lam) loc = std::max(loc, (theta - lam) * L.r_lo / L.V);
      if (beta > lam) loc = std::max(loc, (beta - lam) / (kOmega * cos_phi_ + L.r_hi * L.pert / h_min_));
      return std::min(loc, span);
    };
    best = fitted_span(local_step, best);
    // Along track again, over a span fitted to the result (tighter).
    if (x > 0.0) best = std::max(best, along_track(s, g, std::max(1.5 * x, 60.0), true, best));
  }
  return kStepSafety * best;
}

double Searcher::step_above(const Sample& s) {
  const double d = s.Fdot - s.fdot_err;
  double best = envelope_root(s.F, d, b_above_glob_);
  // Along track: a pass lasts at most about 2 lam / w; from a quarter revolution to fitted spans.
  const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
  const Angles& g = angles(s, kDu);
  double x = along_track(s, g, 0.25 * rev, false, best);
  if (x > 0.0) {  // a span fitted to the result is tighter
    best = std::max(best, x);
    x = along_track(s, g, std::max(1.2 * x, 30.0), false, best);
  }
  best = std::max(best, x);
  // Local constants over a span, about twice the last step, then one fitted to the result.
  auto local_step = [&](double span) {
    const Local L = local(s, span);
    const double s_lo = std::max({L.r_lo - rs_, s.s - L.V * span, 1.0});
    return std::min(envelope_root(s.F, d, curvature(s, L, span, s_lo)), span);
  };
  best = fitted_span(local_step, best);
  return kStepSafety * best;
}

double Searcher::reach(const Sample& s, double span, int dir) const {
  // The envelope first; the angles only when it falls short.
  const Local L = local(s, span);
  const bool below = s.F < 0.0;
  const double d = dir * s.Fdot + (below ? s.fdot_err : -s.fdot_err);
  const double s_lo = below ? std::max(floor_below(L.r_lo), s.s - L.V * span)
                            : std::max({L.r_lo - rs_, s.s - L.V * span, 1.0});
  double x = envelope_root(s.F, d, curvature(s, L, span, s_lo));
  if (x >= span) return span;
  const Angles& g = angles(s, below ? kDu | kTheta : kDu);
  if (below) {
    const double lam = L.r_hi == r_max_ ? lambda_glob_ : lambda(L.r_hi, true) + kAngleMargin;
    x = std::max(x, (g.theta - lam) * L.r_lo / L.V);
  }
  if (x < span && dir < 0) x = std::max(x, along_track(s, g, span, below, 0.0, kBack));
  return std::min(span, x);
}

bool Searcher::monotone(const Sample& a, const Sample& b) const {
  const double e = std::max(a.fdot_err, b.fdot_err);
  const double da = std::abs(a.Fdot) - e, db = std::abs(b.Fdot) - e;
  if (da <= 0.0 || db <= 0.0 || (a.Fdot > 0.0) != (b.Fdot > 0.0)) return false;
  const double D = b.t - a.t;
  const Local L = local(a, D);
  const double s_lo = std::max({L.r_lo - rs_, 0.5 * (a.s + b.s - L.V * D), 1.0});
  return da + db > curvature(a, L, D, s_lo) * D;
}

}  // namespace tb::orbit::detail
