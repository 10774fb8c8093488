// Pass search: AOS, TCA (time of maximum elevation), LOS.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "orbit/observe.h"

namespace tb::orbit {

class HorizonMask;

struct PassOptions {
  double horizon_deg = kAosThresholdDeg;  // AOS/LOS are crossings of this elevation
  double min_max_elevation_deg = -90.0;   // drop passes whose maximum stays below this
  double precision_s = 0.1;               // AOS/LOS/TCA to this precision
  // The station's horizon mask (orbit/horizon_mask.h), when it has one: AOS/LOS are then the
  // crossings of max(mask(az), horizon_deg) and every search below is the masked one
  // (find_passes_masked). Nothing: the one scalar horizon.
  std::shared_ptr<const HorizonMask> mask;
};
// The lowest elevation a satellite counts as up at this azimuth under these options.
double horizon_at(const PassOptions& options, double az_deg);

struct Pass {
  UtcTime aos{}, tca{}, los{};
  double max_el_deg = 0.0;
  double aos_az_deg = 0.0, los_az_deg = 0.0, tca_az_deg = 0.0;
  bool up_at_start = false;   // already above the horizon at the window start (aos = start)
  bool up_at_end = false;     // still above at the window end (los = stop)
};

// What a search cost, for benchmarks and tests.
struct PassSearchStats {
  long propagations = 0;  // SGP4 calls
  // When set, the tsince (minutes from epoch) of every SGP4 call is appended, in order: the
  // benchmark replays them through SGP4 alone to measure what a step costs beyond the propagation.
  std::vector<double>* tsince_minutes = nullptr;
};

// All passes overlapping [start, stop). A satellite always above the horizon (geostationary, in
// view) gives one pass with both flags set; one never above gives none. A propagation failure ends
// the search at the failure time (a decayed satellite has no more passes): a pass still up then
// ends there, with up_at_end. Passes shorter than precision_s / 2 may be missed. How the search
// works and what it was measured to do: docs/passes.md.
std::vector<Pass> find_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                              const PassOptions& options = {}, const EarthOrientation& eo = {});
// The same, adding the propagations it made to stats.
std::vector<Pass> find_passes(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                              const PassOptions& options, const EarthOrientation& eo, PassSearchStats& stats);

// The next pass whose maximum reaches options.min_max_elevation_deg, searching up to max_days. A pass
// in progress at `from` counts, as up_at_start with aos = from, when what is left of it reaches the
// minimum.
std::optional<Pass> next_pass(const Sgp4& sat, const Observer& o, UtcTime from, double max_days = 10.0,
                              const PassOptions& options = {}, const EarthOrientation& eo = {});

// The passes above a horizon mask (orbit/horizon_mask.h) and options.horizon_deg, whichever is
// higher at each azimuth: found above the mask's lowest elevation by the search above, then each
// pass's crossings of the mask refined to options.precision_s from one-second steps. A pass the
// mask splits gives each piece above it; max_el_deg and tca are the piece's. find_passes and
// next_pass do this when options.mask is set.
std::vector<Pass> find_passes_masked(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop,
                                     const HorizonMask& mask, const PassOptions& options = {},
                                     const EarthOrientation& eo = {});

}  // namespace tb::orbit
