#include "rotator/pass_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "rotator/split_travel.h"

namespace tb::rotator {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTie = 1e-6;

// Signed step from a to b, (-180, 180].
double step(double a, double b) {
  double d = wrap360(b - a);
  return d > 180.0 ? d - 360.0 : d;
}

// hh:mm:ss of a time, the seconds cut (what the plan's sentences give).
std::string hms(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  char b[16];
  std::snprintf(b, sizeof b, "%02d:%02d:%02d", c.hour, c.minute, static_cast<int>(c.second));
  return b;
}

// Where a rotator position points, as compass az/el.
AzEl pointing(const PassGeometry& g, const RotatorPosition& p) {
  double az = p.az_travel + rotor_start_deg(g.start);
  double el = p.el;
  if (el > 90.0) {  // over the top
    el = 180.0 - el;
    az += 180.0;
  }
  return {wrap360(az), el};
}

struct Candidate {
  PassPlan plan;
  double cost = 0.0;
  double margin = 0.0;
};
}  // namespace

PassGeometry PassGeometry::from(const AdcModel& m, bool may_cross, double start_el) {
  PassGeometry g;
  g.start = m.rotor_start();
  g.az_travel = m.az_travel_range();
  g.el = m.el_range();
  g.flip_allowed = m.config().el_flip_allowed && g.el.hi > 90.0;
  g.pieces = m.az_pieces();
  g.piece = m.az_piece();
  g.choices = {g.piece};
  if (may_cross && m.config().cross_limit_sector && m.travel_split())
    for (int i = 0; i < static_cast<int>(g.pieces.size()); ++i)
      if (i != g.piece && !g.pieces[static_cast<std::size_t>(i)].empty()) g.choices.push_back(i);
  g.start_el = start_el;
  g.az_rate_deg_s = m.config().az_rate_deg_s;
  return g;
}

double pointing_error_deg(double az1, double el1, double az2, double el2) {
  // atan2(|a x b|, a . b): accurate for small angles too.
  auto unit = [](double az, double el) {
    return std::array<double, 3>{std::cos(el * kDeg) * std::sin(az * kDeg), std::cos(el * kDeg) * std::cos(az * kDeg),
                                 std::sin(el * kDeg)};
  };
  const auto a = unit(az1, el1), b = unit(az2, el2);
  const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) / kDeg;
}

RotatorPosition PassPlan::map(double az_deg, double el_deg) const {
  double az = flip ? az_deg + 180.0 : az_deg;
  double el = flip ? 180.0 - el_deg : el_deg;
  if (over_top) {
    // The direction in the plane of plane_az nearest the target: elevation 0 towards plane_az,
    // 90 at the zenith, 180 towards plane_az + 180.
    az = plane_az;
    el = std::atan2(std::sin(el_deg * kDeg), std::cos(el_deg * kDeg) * std::cos((az_deg - plane_az) * kDeg)) / kDeg;
  }
  double t = wrap360(az - rotor_start_deg(geometry.start));
  // Into the window [center - 180, center + 180).
  t += 360.0 * std::floor((window_center + 180.0 - t) / 360.0);
  if (t >= window_center + 180.0) t -= 360.0;
  RotatorPosition p{t, el};
  if (!geometry.az_travel.empty()) p.az_travel = geometry.az_travel.clamp(p.az_travel);
  if (!geometry.el.empty()) p.el = geometry.el.clamp(p.el);
  return p;
}

RotatorPosition PassPlan::map_at(orbit::UtcTime t, double az_deg, double el_deg) const {
  RotatorPosition p = map(az_deg, el_deg);
  if (lead.size() < 2 || t < lead.front().time || lead.back().time < t) return p;
  // The schedule's azimuth at t, linear between its samples.
  const auto after = std::upper_bound(lead.begin(), lead.end(), t,
                                      [](orbit::UtcTime x, const LeadPoint& l) { return x < l.time; });
  if (after == lead.end()) {
    p.az_travel = lead.back().az_travel;
  } else {
    const LeadPoint& a = *(after - 1);
    const LeadPoint& b = *after;
    const double span = orbit::minutes_between(a.time, b.time);
    const double f = span > 0.0 ? orbit::minutes_between(a.time, t) / span : 1.0;
    p.az_travel = a.az_travel + f * (b.az_travel - a.az_travel);
  }
  if (!geometry.az_travel.empty()) p.az_travel = geometry.az_travel.clamp(p.az_travel);
  return p;
}

std::string PassPlan::keyhole_text() const {
  if (lead.size() < 2) return "";
  char b[200];
  std::snprintf(b, sizeof b, "the azimuth turns ahead of the satellite at %.1f deg/s: at most %.1f deg off (%.1f chasing it)",
                lead_rate_deg_s, max_error_deg, following_error_deg);
  return "keyhole " + hms(lead.front().time) + "-" + hms(lead.back().time) + ": " + b;
}

std::vector<orbit::UtcTime> pass_sample_times(orbit::UtcTime aos, orbit::UtcTime tca, orbit::UtcTime los,
                                              double coarse_s, double fine_s) {
  std::vector<orbit::UtcTime> out;
  const double span = orbit::minutes_between(aos, los) * 60.0;
  if (!(span > 0.0)) return {aos};
  const double at_tca = std::clamp(orbit::minutes_between(aos, tca) * 60.0, 0.0, span);
  const int coarse = std::clamp(static_cast<int>(std::ceil(span / coarse_s)), 2, 600);
  std::vector<double> s;
  for (int k = 0; k <= coarse; ++k) s.push_back(span * k / coarse);
  for (double x = std::ceil(std::max(0.0, at_tca - fine_s)); x <= std::min(span, at_tca + fine_s); x += 1.0) s.push_back(x);
  std::sort(s.begin(), s.end());
  // Samples closer than half a second to the one before are the same sample (LOS always stays).
  double last = -1.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool final_one = i + 1 == s.size();
    if (!out.empty() && s[i] - last < 0.5) {
      if (!final_one) continue;
      out.pop_back();
    }
    out.push_back(orbit::add_seconds(aos, s[i]));
    last = s[i];
  }
  return out;
}

AzEl PassPlan::pointing_at(double az_deg, double el_deg) const { return pointing(geometry, map(az_deg, el_deg)); }

bool PassPlan::lost_at(double az_deg, double el_deg) const {
  const AzEl a = pointing_at(az_deg, el_deg);
  // Over the top the plan points within its largest error (90 - the maximum elevation) by design.
  if (over_top) return pointing_error_deg(a.az, a.el, az_deg, std::max(el_deg, 0.0)) > max_error_deg + 0.05;
  return azimuth_distance(a.az, az_deg) > 0.05 && el_deg < 89.5;
}

namespace {
PassPlan plan_in_piece(std::span<const TrackPoint> track, const PassGeometry& g,
                       std::optional<double> current_travel);
PassPlan plan_by_piece(std::span<const TrackPoint> track, const PassGeometry& g, std::optional<double> current_travel,
                       double rate);

// How much of the pass a plan follows, and the highest elevation among the samples it follows
// (-1e300 when none).
struct Followed {
  PassCoverage coverage;
  double highest = -1e300;
};
Followed followed_by(const PassPlan& plan, std::span<const TrackPoint> track) {
  Followed f;
  PassCoverage& c = f.coverage;
  // The fraction is of the time: each sample stands for half the time to its neighbours (the
  // samples are denser near the culmination, pass_sample_times).
  double all = 0.0, on = 0.0;
  for (std::size_t i = 0; i < track.size(); ++i) {
    const TrackPoint& s = track[i];
    if (s.el_deg < plan.geometry.start_el) continue;
    ++c.samples;
    const double w = orbit::minutes_between(track[i ? i - 1 : i].time, track[i + 1 < track.size() ? i + 1 : i].time);
    all += w;
    // Followed: the azimuth is reached (near the zenith any azimuth points at the satellite), or
    // over the top, within the plan's error.
    if (plan.lost_at(s.az_deg, s.el_deg)) continue;
    ++c.followed;
    on += w;
    if (!c.from) c.from = s.time;
    c.to = s.time;
    f.highest = std::max(f.highest, s.el_deg);
  }
  c.fraction = c.followed == c.samples ? 1.0 : all > 0.0 ? on / all : static_cast<double>(c.followed) / c.samples;
  return f;
}
}  // namespace

std::string PassPlan::coverage_text() const {
  // "azimuth 180.0-350.0", or "all azimuths" for a full turn ("it reaches azimuth all azimuths" before).
  std::string piece = compass_sector_text(geometry.start, geometry.az_travel);
  if (piece != "all azimuths") piece = "azimuth " + piece;
  if (coverage.followed == 0) return "PASS OUT OF ANTENNA REACH (it reaches " + piece + ")";
  char pct[16];
  std::snprintf(pct, sizeof pct, "%d%%", static_cast<int>(std::floor(coverage.fraction * 100.0 + 1e-9)));
  // What the operator needs first: when the antenna is on the satellite, then why not all the pass.
  return "antenna on target " + hms(*coverage.from) + "-" + hms(*coverage.to) + " (" + pct +
         " of the pass): it reaches " + piece;
}

namespace {

// The fastest the pass's azimuth turns between two samples, degrees a second.
double peak_az_rate(std::span<const TrackPoint> track) {
  double peak = 0.0;
  for (std::size_t i = 1; i < track.size(); ++i) {
    const double dt = orbit::minutes_between(track[i - 1].time, track[i].time) * 60.0;
    if (dt > 0.0) peak = std::max(peak, std::abs(step(track[i - 1].az_deg, track[i].az_deg)) / dt);
  }
  return peak;
}

// The largest angle between the samples and the vertical plane of azimuth a (either side).
double off_plane(std::span<const TrackPoint> track, double a) {
  double worst = 0.0;
  for (const TrackPoint& s : track) {
    const double across = std::cos(std::max(s.el_deg, 0.0) * kDeg) * std::sin((s.az_deg - a) * kDeg);
    worst = std::max(worst, std::abs(std::asin(std::clamp(across, -1.0, 1.0))) / kDeg);
  }
  return worst;
}

// The vertical plane nearest the whole pass (the largest distance from it smallest): a half-degree
// search round half the circle (a plane is both its azimuths), then a hundredth round the best. The
// samples near the culmination do not tell it (the azimuth turns there), all of them do.
double best_plane(std::span<const TrackPoint> track) {
  double best = 0.0, err = off_plane(track, 0.0);
  for (double a = 0.5; a < 180.0; a += 0.5)
    if (const double e = off_plane(track, a); e < err) best = a, err = e;
  const double around = best;
  for (double a = around - 0.5; a <= around + 0.5; a += 0.01)
    if (const double e = off_plane(track, a); e < err) best = a, err = e;
  return wrap360(best);
}

// The pass over the top in the vertical plane nearest it (perpendicular to the culmination's
// azimuth for a pass along a great circle), its elevation starting on the AOS side; the plane's azimuth taken in the travel where it is furthest from the ends (or nearest
// the antenna). Nothing when the travel cannot hold it.
std::optional<PassPlan> over_the_top(std::span<const TrackPoint> track, const PassGeometry& g,
                                     std::optional<double> current_travel) {
  PassPlan p;
  p.geometry = g;
  p.over_top = true;
  p.plane_az = best_plane(track);
  if (std::cos((track.front().az_deg - p.plane_az) * kDeg) < 0.0) p.plane_az = wrap360(p.plane_az + 180.0);
  const double t0 = wrap360(p.plane_az - rotor_start_deg(g.start));
  std::optional<double> best;
  for (int k = -1; k <= 2; ++k) {
    const double t = t0 + 360.0 * k;
    if (!g.az_travel.empty() && (t < g.az_travel.lo || t > g.az_travel.hi)) continue;
    const double score = current_travel ? -std::abs(t - *current_travel)
                                        : std::min(t - g.az_travel.lo, g.az_travel.hi - t);
    const double kept = !best ? -1e300
                              : (current_travel ? -std::abs(*best - *current_travel)
                                                : std::min(*best - g.az_travel.lo, g.az_travel.hi - *best));
    if (!best || score > kept) best = t;
  }
  if (!best) return std::nullopt;
  p.window_center = *best;
  double worst = 0.0, sum = 0.0;
  for (const TrackPoint& s : track) {
    const AzEl at = pointing(g, p.map(s.az_deg, s.el_deg));
    const double err = pointing_error_deg(at.az, at.el, s.az_deg, std::max(s.el_deg, 0.0));
    worst = std::max(worst, err);
    sum += err;
  }
  p.max_error_deg = worst;
  p.mean_error_deg = sum / static_cast<double>(track.size());
  p.aos = p.map(track.front().az_deg, track.front().el_deg);
  return p;
}

}  // namespace

namespace {

// The keyhole's schedule for a plan that follows the pass's azimuth (see PassPlan::lead): the
// azimuth path u (travel degrees at the samples) within the motor's rate r whose largest pointing
// error is smallest. For a bound E each sample allows the azimuths within E of the satellite at its
// elevation (any azimuth at the zenith); a path at rate r exists through those windows when the
// windows reached forward from the first sample never come out empty. E is found by bisection, the
// path then backward, each sample as near the satellite as the next one's window lets it.
void add_keyhole(PassPlan& plan, std::span<const TrackPoint> track, const PassGeometry& g) {
  const std::size_t n = track.size();
  if (n < 3 || !(g.az_rate_deg_s > 0.0) || plan.over_top) return;
  const double full = g.az_rate_deg_s, r = 0.9 * full;
  std::vector<double> u(n), el(n), dt(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const RotatorPosition p = plan.map(track[i].az_deg, track[i].el_deg);
    u[i] = p.az_travel;
    el[i] = p.el;
    if (i) dt[i] = orbit::minutes_between(track[i - 1].time, track[i].time) * 60.0;
  }
  const auto error_at = [&](std::size_t i, double travel) {
    const AzEl at = pointing(g, {travel, el[i]});
    return pointing_error_deg(at.az, at.el, track[i].az_deg, std::max(track[i].el_deg, 0.0));
  };
  // Chasing the satellite at the motor's full rate (what a plain follow does).
  double chase = 0.0, v = u[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (i) v += std::clamp(u[i] - v, -full * dt[i], full * dt[i]);
    chase = std::max(chase, error_at(i, v));
  }
  if (chase < 1.0) return;  // the motor keeps up: nothing to plan
  const double lo_end = g.az_travel.empty() ? -1e300 : g.az_travel.lo;
  const double hi_end = g.az_travel.empty() ? 1e300 : g.az_travel.hi;
  std::vector<double> lo(n), hi(n);
  const auto feasible = [&](double e) {
    const double s = std::sin(0.5 * e * kDeg);
    for (std::size_t i = 0; i < n; ++i) {
      // Azimuth within e of the satellite at elevation el: 2 asin(cos el sin(d/2)) <= e.
      const double c = std::abs(std::cos(el[i] * kDeg));
      const double half = s >= c ? 180.0 : 2.0 * std::asin(s / c) / kDeg;
      double a = std::max(lo_end, u[i] - half), b = std::min(hi_end, u[i] + half);
      if (i) {
        a = std::max(a, lo[i - 1] - r * dt[i]);
        b = std::min(b, hi[i - 1] + r * dt[i]);
      }
      if (a > b) return false;
      lo[i] = a;
      hi[i] = b;
    }
    return true;
  };
  double bad = 0.0, good = 180.0;
  if (!feasible(good)) return;
  while (good - bad > 0.01) {
    const double mid = 0.5 * (bad + good);
    (feasible(mid) ? good : bad) = mid;
  }
  feasible(good);
  std::vector<double> path(n);
  // Each sample as near the satellite as its window and the next sample's reach let it. The two
  // meet in exact arithmetic; rounding can leave the lower bound a hair above the upper one, when
  // the upper (within the next sample's reach) is taken.
  const auto nearest = [](double x, double a, double b) { return std::min(std::max(x, a), b); };
  path[n - 1] = nearest(u[n - 1], lo[n - 1], hi[n - 1]);
  for (std::size_t i = n - 1; i-- > 0;)
    path[i] = nearest(u[i], std::max(lo[i], path[i + 1] - r * dt[i + 1]), std::min(hi[i], path[i + 1] + r * dt[i + 1]));
  double worst = 0.0;
  std::size_t first = n, last = 0;
  for (std::size_t i = 0; i < n; ++i) {
    worst = std::max(worst, error_at(i, path[i]));
    if (std::abs(path[i] - u[i]) > 1e-6) {
      first = std::min(first, i);
      last = i;
    }
  }
  if (first == n || worst > chase - 0.5) return;  // no better than chasing
  first = first ? first - 1 : 0;
  last = std::min(n - 1, last + 1);
  for (std::size_t i = first; i <= last; ++i) plan.lead.push_back({track[i].time, path[i]});
  plan.following_error_deg = chase;
  plan.lead_rate_deg_s = r;
  plan.max_error_deg = std::max(plan.max_error_deg, worst);
}

}  // namespace

PassPlan plan_pass(std::span<const TrackPoint> track, const PassGeometry& g, std::optional<double> current_travel) {
  // A pass whose azimuth outruns the motor near the zenith, on a rotator that can flip: over the top.
  const double rate = peak_az_rate(track);
  if (g.flip_allowed && g.az_rate_deg_s > 0.0 && rate > g.az_rate_deg_s && g.choices.size() <= 1)
    if (auto p = over_the_top(track, g, current_travel)) {
      p->peak_az_rate_deg_s = rate;
      p->coverage = followed_by(*p, track).coverage;
      return *p;
    }
  PassPlan plan = plan_by_piece(track, g, current_travel, rate);
  // Without the flip, a pass that outruns the motor: the keyhole's lead.
  if (rate > g.az_rate_deg_s) add_keyhole(plan, track, g);
  return plan;
}

namespace {
PassPlan plan_by_piece(std::span<const TrackPoint> track, const PassGeometry& g, std::optional<double> current_travel,
                       double rate) {
  std::optional<PassPlan> best;
  double best_high = 0.0;
  const std::vector<int> choices = g.choices.empty() ? std::vector<int>{g.piece} : g.choices;
  for (int i : choices) {
    PassGeometry gi = g;
    if (i != g.piece && i >= 0 && i < static_cast<int>(g.pieces.size())) {
      gi.piece = i;
      gi.az_travel = g.pieces[static_cast<std::size_t>(i)];
    }
    PassPlan plan = plan_in_piece(track, gi, current_travel);
    const Followed f = followed_by(plan, track);
    plan.coverage = f.coverage;
    const double high = f.highest;
    // The most of the pass, then its highest part, then the piece in force (listed first).
    bool better = !best;
    if (best) {
      if (plan.coverage.followed != best->coverage.followed) better = plan.coverage.followed > best->coverage.followed;
      else if (high != best_high) better = high > best_high;
    }
    if (better) {
      best = plan;
      best_high = high;
    }
  }
  best->peak_az_rate_deg_s = rate;
  return *best;
}

PassPlan plan_in_piece(std::span<const TrackPoint> track, const PassGeometry& g,
                       std::optional<double> current_travel) {
  PassPlan plain;
  plain.geometry = g;
  plain.window_center = g.az_travel.empty() ? 180.0 : 0.5 * (g.az_travel.lo + g.az_travel.hi);
  if (track.empty()) {
    plain.aos = plain.map(0.0, 0.0);
    return plain;
  }

  std::optional<Candidate> best;
  for (bool flip : {false, true}) {
    if (flip && !g.flip_allowed) continue;
    // The pass as one continuous azimuth path in travel degrees.
    std::vector<double> u(track.size());
    const double start = rotor_start_deg(g.start);
    double prev_az = flip ? track[0].az_deg + 180.0 : track[0].az_deg;
    u[0] = wrap360(prev_az - start);
    for (std::size_t i = 1; i < track.size(); ++i) {
      double az = flip ? track[i].az_deg + 180.0 : track[i].az_deg;
      u[i] = u[i - 1] + step(prev_az, az);
      prev_az = az;
    }
    const auto [lo_it, hi_it] = std::minmax_element(u.begin(), u.end());
    const double mid = 0.5 * (*lo_it + *hi_it);
    // Every whole-turn shift of the path that overlaps the travel (and one either side).
    const int k0 = static_cast<int>(std::floor((g.az_travel.lo - *hi_it) / 360.0)) - 1;
    const int k1 = static_cast<int>(std::ceil((g.az_travel.hi - *lo_it) / 360.0)) + 1;
    for (int k = k0; k <= k1; ++k) {
      Candidate c;
      c.plan = plain;
      c.plan.flip = flip;
      c.plan.window_center = mid + 360.0 * k;
      double sum = 0.0, worst = 0.0;
      bool held = false;
      double pmin = 1e300, pmax = -1e300;
      for (std::size_t i = 0; i < track.size(); ++i) {
        RotatorPosition p = c.plan.map(track[i].az_deg, track[i].el_deg);
        const double lifted = u[i] + 360.0 * k;
        if (std::abs(p.az_travel - lifted) > 1e-9) held = true;
        pmin = std::min(pmin, p.az_travel);
        pmax = std::max(pmax, p.az_travel);
        AzEl at = pointing(g, p);
        double err = pointing_error_deg(track[i].az_deg, std::max(track[i].el_deg, 0.0), at.az, at.el);
        sum += err;
        worst = std::max(worst, err);
      }
      c.plan.held_at_stop = held;
      c.plan.max_error_deg = worst;
      c.plan.mean_error_deg = sum / static_cast<double>(track.size());
      c.plan.aos = c.plan.map(track[0].az_deg, track[0].el_deg);
      c.cost = c.plan.mean_error_deg;
      c.margin = std::min(pmin - g.az_travel.lo, g.az_travel.hi - pmax);
      if (!best) {
        best = c;
        continue;
      }
      const double d = c.cost - best->cost;
      bool better = d < -kTie;
      if (std::abs(d) <= kTie) {
        if (c.plan.flip != best->plan.flip) {
          better = !c.plan.flip;  // flip only when it helps
        } else if (current_travel) {
          better = std::abs(c.plan.aos.az_travel - *current_travel) <
                   std::abs(best->plan.aos.az_travel - *current_travel) - kTie;
        } else {
          better = c.margin > best->margin + kTie;
        }
      }
      if (better) best = c;
    }
  }
  return best->plan;
}
}  // namespace

double slew_seconds(const RotatorPosition& from, const RotatorPosition& to, const RotatorConfig& c) {
  const double az = std::abs(to.az_travel - from.az_travel) / c.az_rate_deg_s;
  const double el = std::abs(to.el - from.el) / c.el_rate_deg_s;
  return std::max(az, el) + c.coast_s;
}

}  // namespace tb::rotator
