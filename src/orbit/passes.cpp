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
#include <utility>

#include "orbit/passes_internal.h"

namespace tb::orbit {
namespace detail {

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
  frame_ = station_frame(o);
  up_ = {frame_.cl * frame_.co, frame_.cl * frame_.so, frame_.sl};
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
  vel_err_ = kVelocityErrKmS + kVelocityErrPerEcc * sat.elements().eccentricity;
  if (span_ <= 0.0 || sat.init_error() != Sgp4Error::none) done_ = true;
}

bool Searcher::eval(double t, Sample& out) {
  ++evals_;
  const double tsince = tsince0_ + t / 60.0;
  if (trace_ != nullptr) trace_->push_back(tsince);
  const Propagation p = sat_.propagate_minutes(tsince);
  if (!p.ok()) return false;
  // TEME -> pseudo-Earth-fixed as teme_to_ecef does it.
  // SGP4's own inlined sine and cosine (1 ulp), a fraction of libm's sincos.
  const SinCos rot = poly_sin_cos(gmst0_ + gmst_rate_ * t);
  const double c = rot.c, sn = rot.s;
  const Vec3& rt = p.state.r_km;
  const Vec3& vt = p.state.v_km_s;
  StateVector& e = out.ecef;
  e.r_km = {c * rt[0] + sn * rt[1], -sn * rt[0] + c * rt[1], rt[2]};
  e.v_km_s = {c * vt[0] + sn * vt[1] + kEarthRotationRadS * e.r_km[1],
              -sn * vt[0] + c * vt[1] - kEarthRotationRadS * e.r_km[0], vt[2]};
  const Vec3 rho = sub(e.r_km, site_);
  out.t = t;
  out.angles_have = 0;
  out.s = norm(rho);
  const double inv_s = 1.0 / out.s;
  out.fdot_err = vel_err_ / out.s;
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
  // f'' = a.(z - f u) / s - |u'|^2 f - 2 (s'/s) f', a = gravity + centrifugal + Coriolis, with
  // cxy = w2 - mu / r^3 already at hand.
  const Vec3 a = accel(e, cxy);
  const double u2 = std::max(0.0, v2 - out.sdot * out.sdot) * inv_s * inv_s;
  out.Fddot = (dot(a, up_) - f * dot(a, rho) * inv_s) * inv_s - u2 * f - 2.0 * out.sdot * inv_s * out.Fdot;
  out.du_x = dot(us_, e.r_km);
  out.cos_theta = out.du_x / out.r;
  const Vec3 hv = cross(rt, vt);  // inertial angular momentum, TEME
  out.h = norm(hv);
  const double inv_h = 1.0 / out.h;
  const Vec3 w = {(c * hv[0] + sn * hv[1]) * inv_h, (-sn * hv[0] + c * hv[1]) * inv_h, hv[2] * inv_h};
  out.sin_beta = dot(w, us_);
  out.w_z = w[2];
  // The satellite moves along W x r; ahead of the foot p of the station: cos(du) ~ us.r, sin ~ us.(r x W).
  out.du_y = dot(us_, cross(e.r_km, w));
  return true;
}

LookAngles Searcher::look(const StateVector& ecef, bool all) const {
  return look_from(sub(ecef.r_km, site_), ecef.v_km_s, frame_, all);
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
  } else {
    // Down: step to the next AOS. No AOS in the window, or a propagation error (decayed): no more passes.
    const Walk down = walk(cur_, true, nullptr);
    if (down.end != Walk::kCrossed || down.t >= span_) {
      done_ = true;
      return std::nullopt;
    }
    aos_t = down.t;
    aos_s = down.other;
    aos_near = down.near;
  }
  // Up: step to LOS (or the window end, or the end of the propagation).
  last_step_ = 30.0;  // the spans of the local bounds start afresh at each crossing
  std::vector<Sample>& samples = samples_;  // kept between passes: no allocation per pass
  samples.clear();
  samples.reserve(24);
  samples.push_back(aos_s);
  double los_t = span_;
  Sample los_near;
  const Walk up = walk(aos_s, false, &samples);
  switch (up.end) {
    case Walk::kCrossed:
      los_t = up.t;
      los_near = up.near;
      samples.push_back(up.same);
      cur_ = up.other;
      break;
    case Walk::kWindowEnd:
      pass.up_at_end = true;
      los_t = span_;
      los_near = up.last;
      done_ = true;
      break;
    case Walk::kRefineFailed:
      pass.up_at_end = true;
      los_t = up.same.t;
      los_near = up.same;
      done_ = true;
      samples.push_back(up.same);
      break;
    case Walk::kPropagationFailed:
      end_inside_pass(up.last, up.bad_t, samples, pass, los_t, los_near);
      break;
  }
  const double guess = pass.up_at_start || pass.up_at_end ? -1.0 : tca_guess(aos_t, aos_near, los_t, los_near);
  finish_pass(samples, pass, guess);
  last_step_ = 30.0;
  pass.aos = at(aos_t);
  pass.los = at(los_t);
  pass.aos_az_deg = look(taylor(aos_near.ecef, aos_t - aos_near.t), false).az_deg;
  pass.los_az_deg = look(taylor(los_near.ecef, los_t - los_near.t), false).az_deg;
  return pass;
}

Searcher::Walk Searcher::walk(const Sample& from, bool below, std::vector<Sample>* keep) {
  Walk w;
  Sample cur = from;
  const auto same_side = [below](const Sample& s) { return below ? s.F < 0.0 : s.F >= 0.0; };
  const auto step_onto = [&](const Sample& s) {  // s is on cur's side: the walk goes on from there
    if (keep) keep->push_back(s);
    cur = s;
  };
  // Refines the crossing between cur and n into w; false if the propagation failed inside.
  const auto refine = [&](const Sample& n, bool single) {
    Sample up, down;
    const bool ok = refine_crossing(cur, n, single, w.t, up, down, w.near);
    w.same = below ? down : up;
    w.other = below ? up : down;
    return ok;
  };
  // A speculative sample that could not be proven yet is kept: `ahead` on cur's side, or a refined
  // crossing `cross` (held in `pending`) whose side of cur is `ahead`. Safe steps go on until the
  // proof reaches it.
  std::optional<Sample> ahead;
  bool cross = false;
  Sample n;  // the latest evaluation (outside the loop: a Sample is large, and eval fills it)
  Walk pending;
  for (;;) {
    if (cur.t >= span_) {
      w.end = Walk::kWindowEnd;
      w.last = cur;
      return w;
    }
    const double safe = below ? step_below(cur) : step_above(cur);
    if (below && cur.t + safe >= span_) {  // provably no AOS left in the window
      w.end = Walk::kWindowEnd;
      w.last = cur;
      return w;
    }
    if (ahead && keeps_sign(cur, safe, *ahead)) {
      if (cross) return pending;
      last_step_ = ahead->t - cur.t;
      step_onto(*ahead);
      ahead.reset();
      continue;
    }
    // Down, a jump beyond the window is tried at its end (which may prove there is no AOS left); up,
    // it is not tried (the window end ends the pass anyway).
    const double target = ahead ? -1.0 : speculative_target(cur, safe, below);
    if (target > 0.0 && (below || target < span_) && eval(std::min(target, span_), n)) {
      widen(n);
      if (!same_side(n)) {
        const bool single = monotone(cur, n);
        if (refine(n, single)) {
          w.end = Walk::kCrossed;
          if (single || keeps_sign(cur, safe, w.same)) return w;
          ahead = w.same;
          cross = true;
          pending = w;
        }
      } else if (keeps_sign(cur, safe, n)) {
        last_step_ = n.t - cur.t;
        step_onto(n);
        continue;
      } else {
        ahead = n;
      }
    }
    const double step = std::max(safe, min_step_);
    last_step_ = step;
    const double tn = std::min(cur.t + step, span_);
    if (!eval(tn, n)) {
      w.end = Walk::kPropagationFailed;
      w.last = cur;
      w.bad_t = tn;
      return w;
    }
    widen(n);
    if (!same_side(n)) {
      // The safe step proved F kept its sign up to cur + safe, so any crossing is in the last min_step.
      w.end = refine(n, monotone(cur, n)) ? Walk::kCrossed : Walk::kRefineFailed;
      return w;
    }
    step_onto(n);
    if (ahead && cur.t >= ahead->t) {  // stepped past it (a min_step): forget it
      ahead.reset();
      cross = false;
    }
  }
}

double Searcher::speculative_target(const Sample& s, double safe, bool below) const {
  const double xp = predict_crossing(s);
  if (xp > safe && xp < 3.0 * safe + 30.0) return s.t + xp + 0.125 * tol_ + 0.002 * xp;
  if (safe < 300.0 && (below ? s.du_y > 0.0 : s.du_y < 0.0)) {
    const double rev = kTwoPi * r_max_ * r_max_ / h_min_;
    const Angles& g = angles(s, kDu);
    double xg = 0.0;
    if (below) {  // receding from the station's foot: to the next approach
      xg = along_track(s, g, rev, true, 0.0, kGuess);
    } else {  // approaching it: across the pass
      xg = along_track(s, g, 0.25 * rev, false, 0.0, kGuess);
      if (xg > 0.0) xg = std::max(xg, along_track(s, g, std::max(1.2 * xg, 30.0), false, 0.0, kGuess));
    }
    if (xg > 2.0 * safe) return s.t + 0.99 * xg;
  }
  return -1.0;
}

void Searcher::end_inside_pass(Sample up, double bad_t, std::vector<Sample>& samples, Pass& pass, double& los_t,
                               Sample& los_near) {
  // Bisect for where the propagation ends, or a LOS before it.
  done_ = true;
  double good = up.t, bad = bad_t;
  Sample n;
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
  double t = 0.0;
  Sample in, out;
  if (set && refine_crossing(up, n, false, t, in, out, los_near)) {
    los_t = t;
    samples.push_back(in);
  } else {
    pass.up_at_end = true;
    los_t = up.t;
    los_near = up;
  }
}

}  // namespace detail

using detail::Searcher;

std::vector<Pass> find_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                              const PassOptions& options, const EarthOrientation& eo, PassSearchStats& stats) {
  if (options.mask) return detail::masked_passes(sat, o, start, stop, options, eo, stats);
  std::vector<Pass> out;
  Searcher s(sat, o, start, stop, options, eo);
  s.record_tsince(stats.tsince_minutes);
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
  if (options.mask) return detail::masked_next_pass(sat, o, from, max_days, options, eo);
  Searcher s(sat, o, from, add_seconds(from, max_days * kSecondsPerDay), options, eo);
  return s.next();
}

}  // namespace tb::orbit
