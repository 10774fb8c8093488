// Rise, culmination and set of the Sun or the Moon (orbit/sky.h). The bodies move slowly (at most
// 0.25 deg of elevation a minute), so a 10-minute grid brackets every crossing; a stretch above the
// horizon shorter than the grid shows as a local maximum of three samples, refined before it is
// dismissed.
#include <algorithm>
#include <cmath>

#include "orbit/geometry.h"
#include "orbit/horizon_mask.h"
#include "orbit/moon.h"
#include "orbit/sky.h"

namespace tb::orbit {
namespace {

constexpr double kGridS = 600.0;
constexpr double kGolden = 0.6180339887498949;

// Elevation above the search's horizon, as a function of seconds from the window's start: the
// scalar horizon, or the station's horizon mask where it is higher (issue 57), at the body's azimuth.
class Height {
 public:
  Height(Body b, const Observer& o, UtcTime start, double horizon_deg, const EarthOrientation& eo,
         const HorizonMask* mask = nullptr)
      : body_(b), observer_(o), start_(start), horizon_(horizon_deg), eo_(eo), mask_(mask) {}

  UtcTime at(double s) const { return add_seconds(start_, s); }
  LookAngles look(double s) const {
    const UtcTime t = at(s);
    StateVector st;
    st.r_km = body_ == Body::sun ? sun_position_km(t) : moon_position_teme_km(t);
    return look_angles(teme_to_ecef(st, t, eo_), observer_);
  }
  double operator()(double s) const {
    const LookAngles l = look(s);
    return l.el_deg - (mask_ ? std::max(horizon_, mask_->at(l.az_deg)) : horizon_);
  }
  // The elevation itself (the culmination is the body's highest point, whatever the mask).
  double el(double s) const { return look(s).el_deg; }

 private:
  Body body_;
  Observer observer_;
  UtcTime start_;
  double horizon_;
  EarthOrientation eo_;
  const HorizonMask* mask_;
};

// The crossing of zero in [a, b], where h(a) and h(b) differ in sign, to precision p.
double bisect(const Height& h, double a, double b, double p) {
  const bool rising = h(a) < 0.0;
  while (b - a > p) {
    const double m = 0.5 * (a + b);
    if ((h(m) < 0.0) == rising) a = m; else b = m;
  }
  return 0.5 * (a + b);
}

// The time of the highest point of f in [a, b] (one maximum there), to precision p.
template <class F>
double highest(const F& f, double a, double b, double p) {
  double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
  double hc = f(c), hd = f(d);
  while (b - a > p) {
    if (hc > hd) { b = d; d = c; hd = hc; c = b - kGolden * (b - a); hc = f(c); }
    else { a = c; c = d; hc = hd; d = a + kGolden * (b - a); hd = f(d); }
  }
  return 0.5 * (a + b);
}

// Fills the culmination of a pass from aos_s to los_s: the best grid sample, refined around it.
void culminate(const Height& h, double aos_s, double los_s, double p, Pass& pass) {
  const auto el = [&h](double s) { return h.el(s); };
  double best = aos_s, best_h = el(aos_s);
  for (double s = aos_s + kGridS; s < los_s; s += kGridS) {
    const double v = el(s);
    if (v > best_h) { best = s; best_h = v; }
  }
  if (el(los_s) > best_h) best = los_s;
  const double lo = std::max(aos_s, best - kGridS), hi = std::min(los_s, best + kGridS);
  double tca = highest(el, lo, hi, p);
  if (el(aos_s) >= el(tca)) tca = aos_s;  // still climbing when the window opens or closes
  if (el(los_s) > el(tca)) tca = los_s;
  const LookAngles top = h.look(tca), rise = h.look(aos_s), set = h.look(los_s);
  pass.aos = h.at(aos_s);
  pass.los = h.at(los_s);
  pass.tca = h.at(tca);
  pass.max_el_deg = top.el_deg;
  pass.tca_az_deg = top.az_deg;
  pass.aos_az_deg = rise.az_deg;
  pass.los_az_deg = set.az_deg;
}

}  // namespace

std::vector<Pass> find_body_passes(Body b, const Observer& o, UtcTime start, UtcTime stop,
                                   const PassOptions& options, const EarthOrientation& eo) {
  std::vector<Pass> passes;
  const double span = minutes_between(start, stop) * 60.0;
  if (!(span > 0.0)) return passes;
  const Height h(b, o, start, options.horizon_deg, eo, options.mask.get());
  const double p = options.precision_s > 0.0 ? options.precision_s : 0.1;
  auto emit = [&](double aos_s, double los_s, bool up_at_start, bool up_at_end) {
    Pass pass;
    pass.up_at_start = up_at_start;
    pass.up_at_end = up_at_end;
    culminate(h, aos_s, los_s, p, pass);
    if (pass.max_el_deg >= options.min_max_elevation_deg) passes.push_back(pass);
  };
  double prev_s = 0.0, prev_h = h(0.0), before_h = prev_h;
  bool up = prev_h >= 0.0;
  double aos_s = 0.0;
  bool aos_at_start = up;
  while (prev_s < span) {
    const double s = std::min(span, prev_s + kGridS);
    const double v = h(s);
    if (!up && v >= 0.0) {
      aos_s = bisect(h, prev_s, s, p);
      aos_at_start = false;
      up = true;
    } else if (up && v < 0.0) {
      emit(aos_s, bisect(h, prev_s, s, p), aos_at_start, false);
      up = false;
    } else if (!up && prev_s > 0.0 && prev_h > before_h && prev_h > v) {
      // Below at three samples with the middle one highest: a short stretch above may hide there.
      const double top = highest(h, prev_s - kGridS, s, p);
      if (h(top) >= 0.0) emit(bisect(h, prev_s - kGridS, top, p), bisect(h, top, s, p), false, false);
    }
    before_h = prev_h;
    prev_h = v;
    prev_s = s;
  }
  if (up) emit(aos_s, span, aos_at_start, true);
  return passes;
}

std::optional<Pass> next_body_pass(Body b, const Observer& o, UtcTime from, double max_days,
                                   const PassOptions& options, const EarthOrientation& eo) {
  const std::vector<Pass> passes =
      find_body_passes(b, o, from, add_minutes(from, max_days * kMinutesPerDay), options, eo);
  if (passes.empty()) return std::nullopt;
  return passes.front();
}

}  // namespace tb::orbit
