// The station's events: AOS and LOS of the satellites of the tracking list, element refreshes,
// links lost and back, failed saves. PassEventSource finds AOS and LOS from the same pass search
// `trakbox passes` uses (AOS/LOS are crossings of the rotor start elevation, -2.0 deg by default:
// the manual's rule) of the passes whose maximum reaches model.event_min_el_deg (--event-min-el,
// factory 0: none for a pass that never rises), fired at the first tick at or after AOS - lead and
// at or after LOS (none for a satellite always up: a geostationary one has no LOS); it reads
// the model and the tracker's propagators and does no I/O. What the events become (hooks, the
// event stream) is the application's (live/event_hooks.h, docs/service.md).
#pragma once
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "orbit/passes.h"
#include "orbit/time.h"
#include "tracker/control.h"

namespace tb::store {
struct Model;
}

namespace tb::tracker {

class Tracker;

struct Event {
  std::string kind;  // aos, los, recording, elements, link-lost, link-back, save-failed, control
  orbit::UtcTime time{};
  // AOS and LOS: the satellite, its pass and its frequencies (RF at the satellite, 0: none).
  std::string satellite;
  int catalog_number = 0;
  int list_number = 0;
  std::optional<orbit::Pass> pass;
  long long downlink_hz = 0, uplink_hz = 0;
  // The rest: which link (rotator, radio), what happened.
  std::string detail;
  // control: who held the antenna or the radio, who holds it now, and why (tracker/control.h).
  std::optional<Change> control;
  // recording: the receiver's recorder started (read back or not), not started (why), or stopped.
  struct Recorded {
    std::string state;           // "started", "not started", "stopped"
    std::string kind;            // "audio", "iq"
    orbit::UtcTime start{};      // when the start was sent (station time)
    long long frequency_hz = 0;  // the receiver's frequency then
    std::string file;            // the receiver's file name ("" when trakbox cannot know it)
    bool read_back = false;      // the receiver said it records (GQRX's u RECORD), not assumed
    std::string why;             // not started: "not recording: DSP off"
  };
  std::optional<Recorded> recording;
};

// The kinds, in the order the documentation lists them.
const std::vector<std::string>& event_kinds();
// {"event":"aos","time":"...","satellite":...}: one line of `trakbox events`.
nlohmann::json to_json(const Event& e);
// The hook's environment: TRAKBOX_EVENT, TRAKBOX_TIME, TRAKBOX_SATELLITE, TRAKBOX_AOS, ...
std::vector<std::pair<std::string, std::string>> event_environment(const Event& e);

class PassEventSource {
 public:
  // lead: the AOS event comes this long before AOS (0: at AOS).
  PassEventSource(const store::Model& model, const Tracker& tracker, std::chrono::seconds lead = {})
      : model_(model), tracker_(tracker), lead_(lead) {}
  // The AOS and LOS events due at `now` (each once per pass).
  std::vector<Event> step(orbit::UtcTime now);
  std::size_t searches() const { return searches_; }  // pass searches so far (each is costly)

 private:
  struct Watch {
    int catalog_number = 0;
    double epoch_day = 0;
    int epoch_year = 0;
    std::optional<orbit::Pass> pass;  // the next (or current) pass
    bool aos_fired = false;
  };
  Event pass_event(const char* kind, int db_index, const Watch& w, orbit::UtcTime now) const;
  const store::Model& model_;
  const Tracker& tracker_;
  std::chrono::seconds lead_;
  std::map<int, Watch> watches_;  // by catalog number
  std::optional<orbit::UtcTime> last_step_;  // the clock going back is a set-back
  std::size_t searches_ = 0;
};

}  // namespace tb::tracker
