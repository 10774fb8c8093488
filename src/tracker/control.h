// The controller of record: who holds the antenna and, separately, the radio (issue 44).
//
// A station is shared: the operator at the menus, the page or host mode; Gpredict or a logger
// through rotctld/rigctld; a SatNOGS client; a monitor-and-control system through Satrak. Each of
// them asks here before it moves the antenna or tunes the radio (tracker::StationOps does it for
// them), and the answer is one of: granted (perhaps with a change of holder), refused in a sentence
// (standby, --exclusive), or "confirm first" (an operator taking the antenna from an outside client
// or from a reservation's window).
//
// The rules (docs/sharing.md):
//  * an outside client's move or tune suspends trakbox's own tracking of that resource only: the
//    Tracker keeps its choice, the station stops applying it to what the client holds; the antenna
//    and the radio are held separately;
//  * the hold ends when the client disconnects (left) or has been silent handback seconds
//    (0: never by silence); what held before it (trakbox's tracking, or the operator's hold) then
//    holds again, so the suspended tracking resumes exactly as it was chosen;
//  * the operator (menus, web, host) can always take a resource; when an outside client or a
//    reservation's window holds it, only after one confirmation;
//  * --exclusive KIND: while a client of that kind holds a resource, other outside clients' requests
//    for it are refused;
//  * standby: both resources are held by `standby`; outside clients are refused, the operator may
//    only turn standby off.
//
// Pure: values in, values out, the clock passed in. Each change of holder is returned as a Change,
// which the station turns into a `control` event and a log line.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/time.h"

namespace tb::tracker {

enum class HolderKind { tracking, menus, web, host, rotctld, rigctld, satrak, satnogs, pstrotator, standby };

// "tracking", "rotctld", ...; nothing for a word that names none.
std::string_view kind_name(HolderKind k);
std::optional<HolderKind> kind_named(std::string_view word);
// The operator's own front ends: menus, web, host.
bool is_operator(HolderKind k);
// Programs outside trakbox that connect to it: rotctld, rigctld, satrak, satnogs, pstrotator.
bool is_outside(HolderKind k);

enum class Resource { antenna, radio };
std::string_view resource_name(Resource r);

// Who asks: its kind and a label naming it ("rotctld 127.0.0.1:51234", "web 127.0.0.1").
struct Requester {
  HolderKind kind = HolderKind::menus;
  std::string label = "menus";
  static Requester menus() { return {HolderKind::menus, "menus"}; }
  static Requester tracking() { return {HolderKind::tracking, "trakbox tracking"}; }
};

struct Holder {
  HolderKind kind = HolderKind::tracking;
  std::string label = "trakbox tracking";
  orbit::UtcTime since{};
  std::optional<orbit::UtcTime> until;  // when the hold ends, when known (a reservation's end)
  bool operator==(const Holder&) const = default;
};

struct Change {
  Resource resource = Resource::antenna;
  Holder from, to;
  std::string why;  // "moved the antenna", "disconnected", "silent 30 s", ...
};

// A window someone else has booked (a SatNOGS observation, the operator's own reservation).
struct Window {
  std::string kind;  // "satnogs" or "operator"
  std::string id;
  orbit::UtcTime start{}, end{};
  std::string satellite;
  std::string note;
  // A SatNOGS job's own element set (tle1, tle2; tle0 is `satellite`), empty when not given: the
  // pass its client follows is planned with these, not a refreshed set (issue 57).
  std::string tle1, tle2;
};

// A connectionless client (PstRotator over UDP) has no disconnect: its silence ends its hold after
// this many seconds even when --handback is 0 (never by silence for connected clients).
inline constexpr int kConnectionlessHandbackS = 30;
// After the operator takes a resource back from an outside client, outside clients are refused for
// --handback seconds after the operator's last action on it, or this many when --handback is 0.
inline constexpr int kOperatorGuardS = 30;

struct ControlSettings {
  int handback_s = 30;                          // --handback: 0, never by silence
  std::optional<HolderKind> exclusive;          // --exclusive rotctld|rigctld|satrak (none: nothing)
};

class Control {
 public:
  struct Answer {
    bool granted = false;
    std::optional<std::string> refusal;  // why not (standby, another client holds exclusively)
    std::optional<Holder> confirm;       // the operator must confirm first: this one holds
    std::vector<Change> changes;
  };

  explicit Control(ControlSettings settings = {}) : settings_(settings) {}
  void set_settings(ControlSettings s) { settings_ = s; }
  const ControlSettings& settings() const { return settings_; }

  const Holder& holder(Resource r) const { return r == Resource::antenna ? antenna_.now : radio_.now; }
  // Does trakbox's own tracking drive this resource now?
  bool tracking_drives(Resource r) const { return holder(r).kind == HolderKind::tracking; }

  // `who` wants to move the antenna / tune the radio at `now`. confirmed: the operator has said
  // yes to taking it from an outside holder.
  // to_tracking: the operator hands it to trakbox's tracking (a "track this"), rather than holding it.
  Answer request(Resource r, const Requester& who, orbit::UtcTime now, bool confirmed = false,
                 bool to_tracking = false);
  // The outside client holding something said something (any line): its silence restarts.
  void heard(std::string_view label, orbit::UtcTime now);
  // That client disconnected: what it holds is handed back.
  std::vector<Change> left(std::string_view label, orbit::UtcTime now);
  // Hand-backs by silence, reservation windows beginning and ending.
  std::vector<Change> tick(orbit::UtcTime now);

  // Standby on (both resources held by standby) or off (trakbox's tracking holds them again).
  std::vector<Change> set_standby(bool on, orbit::UtcTime now);
  bool standby() const { return holder(Resource::antenna).kind == HolderKind::standby; }

  // The reservations, kept in start order; the one whose window holds `now`, if any.
  void set_windows(std::vector<Window> w);
  const std::vector<Window>& windows() const { return windows_; }
  const Window* window_at(orbit::UtcTime now) const;

 private:
  struct Slot {
    Holder now;
    std::optional<Holder> before;  // what held when an outside client took it: it holds again after
    std::string client;            // the outside client holding it (its requester label), if one does
    orbit::UtcTime last_heard{};
    std::string yielded;           // the reservation whose window took it from tracking already
    // The operator took it back from an outside client at this time (or acted on it since): outside
    // clients are refused until --handback has passed after it (take-back holds, issue 60).
    std::optional<orbit::UtcTime> operator_took;
  };
  Slot& slot(Resource r) { return r == Resource::antenna ? antenna_ : radio_; }
  std::optional<Change> hand_to(Resource r, Holder h, std::string why);
  std::vector<Change> windows_tick(orbit::UtcTime now);
  std::optional<Change> hand_back(Resource r, orbit::UtcTime now, std::string why);

  ControlSettings settings_;
  Slot antenna_, radio_;
  std::vector<Window> windows_;
};

// For a status line: "STANDBY", "antenna rotctld 127.0.0.1:51234, radio rigctld ..." (what trakbox's
// own tracking does not hold), "" when it holds both.
std::string held_text(const Control& c);

}  // namespace tb::tracker
