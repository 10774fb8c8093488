// The tracking loop's brain: once a tick it computes the satellites in play, decides which one is
// followed (single, multiple, priority), and what the antenna should do (point, pre-position for
// the next AOS, park, hold). Pure with respect to I/O: it reads the model and a clock and returns
// a decision; the Station (station_loop.h) applies decisions to the rotator and the radio.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orbit/passes.h"
#include "orbit/sky.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/pass_memo.h"

namespace tb::tracker {

enum class Mode { off, single, multi };

// The Sun and the Moon as targets (issue 58): indices below every database index (and apart from
// -1, "none"), taken wherever a database index is by track_single, observe, pass_at and pass_track.
// Their SatNow has list_number 0, no downlink Doppler, and a pass from orbit::next_body_pass through
// the one pass cache.
inline constexpr int kSunTarget = -2;
inline constexpr int kMoonTarget = -3;
std::optional<orbit::Body> body_target(int index);
int target_index(orbit::Body b);

// One satellite, now.
struct SatNow {
  int db_index = -1;
  int list_number = 0;        // #n in the tracking list (1-15), 0 when not listed
  std::string name;
  orbit::Observation obs;     // obs.ok() is false when propagation failed (decayed, ...)
  bool in_range = false;      // elevation >= -2.0 deg (the manual's AOS rule)
  double downlink_doppler_hz = 0.0;  // Doppler on F1 (0 without F1), the realtime "Doppler Hz"
  std::optional<orbit::Pass> pass;   // the pass in progress, or the next one (within a day)
};

struct Decision {
  enum class Antenna { hold, point, preposition, park };
  Antenna antenna = Antenna::hold;
  double az_deg = 0.0;
  double el_deg = 0.0;
  std::optional<int> followed;   // db index of the satellite followed, if any
};

// Multi-tracking choice among candidates (in tracking-list order). Normal mode stays with the
// current one while it is in range; priority mode always takes the lowest list number in range.
// Returns the chosen candidate's position in `in_range_by_list_order`, or nullopt.
std::optional<std::size_t> choose_multi(const std::vector<bool>& in_range_by_list_order,
                                        std::optional<std::size_t> current, bool priority);

class Tracker {
 public:
  Tracker(const store::Model& model, const station::Clock& clock);

  // What to track. Each choice is told to on_choice (the station records it in the model, so a
  // restart tracks it again); stop() is not a choice (direct control, a park, leaving).
  void track_single(int db_index);
  void track_multi(bool priority);
  void stop();
  Mode mode() const { return mode_; }
  bool priority() const { return priority_; }
  int single_index() const { return single_; }
  void on_choice(std::function<void()> f) { on_choice_ = std::move(f); }

  // Recomputes everything at the clock's now; the decision for the antenna.
  Decision tick();
  orbit::UtcTime last_tick_time() const { return last_time_; }

  // The satellites in play after the last tick: the single one, or the first N of the list.
  const std::vector<SatNow>& candidates() const { return candidates_; }
  // The one followed after the last tick.
  const SatNow* followed() const;
  const Decision& last_decision() const { return decision_; }

  // Any satellite of the database, now (for displays that are not the tracked set).
  // with_pass: its pass in progress at t or the next, from the pass cache (passes()).
  std::optional<SatNow> observe(int db_index, orbit::UtcTime t, bool with_pass = false) const;
  // The pass in progress at t (with its real AOS), or the next one within a day, for a display
  // that looks at another time than now (menu 2): searched afresh, the live pass left as it is.
  std::optional<orbit::Pass> pass_at(int db_index, orbit::UtcTime t) const;
  // The lowest elevation a satellite is up at here, at this azimuth: the AOS rule (-2 deg) or the
  // station's horizon mask where it is higher (issue 57).
  double horizon_at(double az_deg) const;
  // A propagator for a database entry (cached; rebuilt when its elements change).
  const orbit::Sgp4* propagator(int db_index) const;
  // For the displays' pictures, `intervals` + 1 evenly spaced observations (those SGP4 can
  // compute): over one orbital period from `from` (the ground track), or from a pass's AOS to its
  // LOS (its path in the sky). Empty when the entry has no usable orbit.
  std::vector<orbit::Observation> orbit_track(int db_index, orbit::UtcTime from, int intervals) const;
  std::vector<orbit::Observation> pass_track(int db_index, const orbit::Pass& pass, int intervals) const;

  // The station's one cache of the next pass (pass_memo.h), which the tracker's candidates, the
  // AOS/LOS events, the status document and the Satrak unit share.
  PassMemo& passes() const { return passes_; }

  // How long before AOS the antenna moves to the AOS position.
  static constexpr double kPrepositionMinutes = 5.0;

 private:
  SatNow compute(int db_index, orbit::UtcTime t, bool with_pass) const;
  SatNow compute_body(orbit::Body b, orbit::UtcTime t, bool with_pass) const;
  bool known(int index) const;  // a database index or a body's
  std::vector<orbit::Observation> track(int db_index, orbit::UtcTime from, double minutes, int intervals) const;
  const store::Model& model_;
  const station::Clock& clock_;
  Mode mode_ = Mode::off;
  bool priority_ = false;
  int single_ = -1;
  std::function<void()> on_choice_;
  std::optional<int> current_;  // db index followed in multi mode
  std::vector<SatNow> candidates_;
  Decision decision_;
  orbit::UtcTime last_time_{};
  struct Cached {
    orbit::Elements elements;
    std::unique_ptr<orbit::Sgp4> sgp4;
  };
  mutable std::map<int, Cached> cache_;
  mutable PassMemo passes_;
  Cached& cached(int db_index) const;
};

}  // namespace tb::tracker
