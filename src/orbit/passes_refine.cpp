// The pass search's refinement: AOS and LOS by a bracketed Newton iteration on F, each maximum by a
// bracketed secant on F' and, where the SGP4 velocity is not exact enough for that, by parabolic
// interpolation of F (passes.cpp's opening comment; docs/passes.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "orbit/passes_internal.h"

namespace tb::orbit::detail {

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
        m.fdot_err < -0.25 * tol_top_ * m.Fddot) {
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
  const double shift_bound = m.fdot_err / std::max(-m.Fddot, 1e-300);
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

double Searcher::tca_guess(double aos_t, const Sample& aos_near, double los_t, const Sample& los_near) const {
  // The top of the cubic through (0, F') at AOS and LOS (the middle for a symmetric pass).
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
  return aos_t + u * D;
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
  std::vector<std::pair<std::size_t, std::size_t>>& work = work_;
  work.clear();
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
      const double da = a.Fdot + a.fdot_err, db = b.Fdot - b.fdot_err;
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

}  // namespace tb::orbit::detail
