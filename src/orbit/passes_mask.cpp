// Passes above a horizon mask (issue 57): the fast search (passes.cpp) finds the passes above the
// mask's lowest elevation; inside each, the elevation is compared with max(mask(az), horizon) once
// a second and every change of side is bisected to the precision asked. A pass the mask splits
// (up, behind the roof, up again) gives each piece above it.
#include <algorithm>
#include <cmath>

#include "orbit/horizon_mask.h"
#include "orbit/observe.h"
#include "orbit/passes.h"
#include "orbit/passes_internal.h"

namespace tb::orbit {
namespace {

struct Masked {
  const Sgp4& sat;
  const Observer& o;
  const PassOptions& opt;  // with the mask
  const EarthOrientation& eo;

  // Elevation above the mask at t (nothing when SGP4 fails).
  std::optional<double> above(UtcTime t, Observation* seen = nullptr) const {
    const Observation ob = observe(sat, o, t, eo);
    if (!ob.ok()) return std::nullopt;
    if (seen) *seen = ob;
    return ob.look.el_deg - horizon_at(opt, ob.look.az_deg);
  }
  // The crossing between a (on side `up_at_a`) and b, to the precision.
  UtcTime crossing(UtcTime a, UtcTime b, bool up_at_a) const {
    const double tol = std::max(opt.precision_s, 1e-3);
    while (minutes_between(a, b) * 60.0 > tol) {
      const UtcTime mid = add_seconds(a, 0.5 * minutes_between(a, b) * 60.0);
      const auto m = above(mid);
      if (m && (*m >= 0.0) == up_at_a) a = mid;
      else b = mid;
    }
    return up_at_a ? a : b;  // the last instant up, or the first
  }
  Pass piece(UtcTime aos, UtcTime los, const Pass& whole) const {
    Pass p;
    p.aos = aos;
    p.los = los;
    p.up_at_start = whole.up_at_start && aos == whole.aos;
    p.up_at_end = whole.up_at_end && los == whole.los;
    Observation ob;
    if (above(aos, &ob)) p.aos_az_deg = ob.look.az_deg;
    if (above(los, &ob)) p.los_az_deg = ob.look.az_deg;
    // The culmination: the whole pass's when it lies in this piece, else the piece's highest end.
    UtcTime tca = whole.tca;
    if (tca < aos || tca > los) {
      Observation a, b;
      above(aos, &a);
      above(los, &b);
      tca = a.look.el_deg >= b.look.el_deg ? aos : los;
    }
    p.tca = tca;
    if (above(tca, &ob)) {
      p.tca_az_deg = ob.look.az_deg;
      p.max_el_deg = ob.look.el_deg;
    }
    return p;
  }
  void split(const Pass& whole, std::vector<Pass>& out) const {
    std::optional<UtcTime> aos;
    UtcTime prev = whole.aos;
    const double secs = minutes_between(whole.aos, whole.los) * 60.0;
    bool prev_up = false;
    for (double s = 0.0;; s = std::min(s + 1.0, secs)) {
      const UtcTime t = add_seconds(whole.aos, s);
      const auto m = above(t);
      const bool up = m && *m >= 0.0;
      if (up && !aos) aos = s == 0.0 ? t : crossing(prev, t, false);
      if (!up && aos) {
        out.push_back(piece(*aos, crossing(prev, t, true), whole));
        aos.reset();
      }
      prev = t;
      prev_up = up;
      if (s >= secs) break;
    }
    if (aos && prev_up) out.push_back(piece(*aos, whole.los, whole));
  }
};

// The whole passes are searched above the mask's lowest elevation (or the horizon, if higher),
// with no mask: the fast search's bounds hold for one horizon.
PassOptions unmasked(const PassOptions& options) {
  PassOptions base = options;
  base.mask.reset();
  base.horizon_deg = std::max(options.horizon_deg, options.mask->min_el());
  base.min_max_elevation_deg = std::max(options.min_max_elevation_deg, base.horizon_deg);
  return base;
}

}  // namespace

double horizon_at(const PassOptions& options, double az_deg) {
  return options.mask ? std::max(options.mask->at(az_deg), options.horizon_deg) : options.horizon_deg;
}

namespace detail {

std::vector<Pass> masked_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                                const PassOptions& options, const EarthOrientation& eo, PassSearchStats& stats) {
  const Masked m{sat, o, options, eo};
  std::vector<Pass> out;
  for (const Pass& whole : find_passes(sat, o, start, stop, unmasked(options), eo, stats)) {
    std::vector<Pass> pieces;
    m.split(whole, pieces);
    for (const Pass& p : pieces)
      if (p.max_el_deg >= options.min_max_elevation_deg) out.push_back(p);
  }
  return out;
}

std::optional<Pass> masked_next_pass(const Sgp4& sat, const Observer& o, UtcTime from, double max_days,
                                     const PassOptions& options, const EarthOrientation& eo) {
  const Masked m{sat, o, options, eo};
  const PassOptions base = unmasked(options);
  Searcher s(sat, o, from, add_seconds(from, max_days * 86400.0), base, eo);
  while (const auto whole = s.next()) {
    std::vector<Pass> pieces;
    m.split(*whole, pieces);
    for (const Pass& p : pieces)
      if (p.max_el_deg >= options.min_max_elevation_deg) return p;
  }
  return std::nullopt;
}

}  // namespace detail

std::vector<Pass> find_passes_masked(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                                     const HorizonMask& mask, const PassOptions& options, const EarthOrientation& eo) {
  PassOptions po = options;
  po.mask = std::make_shared<const HorizonMask>(mask);
  return find_passes(sat, o, start, stop, po, eo);
}

}  // namespace tb::orbit
