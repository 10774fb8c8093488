// The station's operations, one home for every front end: the menus, host mode, rotctld, the
// Satrak unit's neighbours and the web API all "track this satellite", "park", "stop", "rotor
// control on/off", "go to az/el", "Doppler on/off" and "refresh the elements now" through here, so
// each is validated once and refused with the same sentence wherever it is asked for.
//
// StationOps holds references only (to the StationLoop and the Model it runs on): make one where it
// is needed. Every operation validates its input fully before it changes anything; a refusal is a
// sentence naming what was wrong ("unknown satellite 'ISSS'") and leaves the station as it was.
// An operation that changes the stored model does it through the model's owner (store/owner.h),
// which checks, saves and announces it; model_changed says it happened.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/sky.h"
#include "rotator/controller.h"
#include "tracker/control.h"

namespace tb::store {
struct Model;
class ModelOwner;
enum class Origin;
}

namespace tb::tracker {

class StationLoop;

struct OpResult {
  std::optional<std::string> refusal;  // why nothing was done; nothing when done
  std::string note;                    // what happened, when it is worth saying ("limited to ...")
  bool model_changed = false;          // the stored state changed: the caller saves
  std::optional<rotator::AzEl> commanded;  // go_to: where the antenna was sent (inside the limits)
  // Refused until the operator confirms: this outside client or reservation holds (tracker/control.h).
  std::optional<Holder> confirm;
  bool ok() const { return !refusal; }
  static OpResult refuse(std::string why) {
    OpResult r;
    r.refusal = std::move(why);
    return r;
  }
};

class StationOps {
 public:
  // `who` asks (tracker/control.h): the menus when not said. An outside client's (rotctld, rigctld,
  // satrak, pstrotator) move or tune suspends trakbox's tracking of what it holds; the operator's
  // (menus, web, host) is refused with `confirm` set while an outside client or a reservation's
  // window holds, unless `confirmed` (the operator said yes); standby refuses every move.
  explicit StationOps(StationLoop& station, Requester who = Requester::menus(), bool confirmed = false);

  // The database index of a satellite by name: exact first (the manual's names are case
  // sensitive), else the one whose name matches ignoring case and surrounding blanks.
  std::optional<int> find_satellite(std::string_view name) const;
  // "unknown satellite 'RS44'; did you mean RS-44?" (util/closest.h), for every front end's refusal.
  std::string unknown_satellite(std::string_view name) const;

  // Single tracking of a database satellite (menu 1; S adds rotor_control(true)). When it is in the
  // tracking list it becomes the marked one ('*').
  OpResult track(int db_index);
  OpResult track(std::string_view name);
  // The Sun or the Moon (issue 58; also track(kSunTarget), track("SUN") when no satellite has that
  // name): the antenna follows its centre through the same limits and pass plan; no radio tuning.
  OpResult track_body(orbit::Body body);
  // Multiple tracking of the tracking list's first multi_count (menu M), normal or priority.
  OpResult track_multi(bool priority);
  // Multiple tracking of these satellites (2 to 5, by name, no repeats): they move to the front of
  // the tracking list in this order, multi_count becomes their number (menus 3-2 and 3-4), then M.
  OpResult track_list(const std::vector<std::string>& names, bool priority);
  // The antenna stops where it is, held by whoever asked; the Tracker's choice stays and the radio
  // keeps its Doppler (unless Doppler is off): Stop stops the rotator only.
  OpResult stop();
  // Tracking stops and the antenna goes to its parking position; rotor control is switched on
  // (parking is a movement). Refused when parking is off (menu 6-4).
  OpResult park();
  // The E key.
  OpResult rotor_control(bool on);
  // Direct pointing: compass azimuth 0..360, elevation 0..90 (0..180 for a rotator whose
  // elevation flips over the top) (host AZ/EL, rotctld set_pos, the
  // web's goto). Tracking stops, rotor control goes on, the limits clamp: commanded says where the
  // antenna was sent and note says "limited to AZ.. EL.." when that is not where it was asked.
  OpResult go_to(double az_deg, double el_deg);
  // The radio follows the tracked satellite with Doppler (on, the default) or is left alone.
  OpResult doppler(bool on);
  // An outside client (rigctld) is about to tune the radio: the radio's hold, or why not.
  OpResult take_radio();
  // Standby on: parks (parking on) or stops, no automatic tracking, CAT paused, outside clients
  // refused; off: trakbox's tracking holds again. Stored.
  OpResult standby(bool on);
  // The operator takes the antenna and the radio back for trakbox's tracking, which resumes what
  // was chosen (the confirmation rule applies).
  OpResult take_back();
  // The operator's own reservation (`trakbox reserve`, the web): from start to end trakbox's
  // tracking yields, as to a SatNOGS observation; stored. Refused when it ends before it starts or
  // is over, or when 64 are kept; those already over are forgotten.
  OpResult reserve(orbit::UtcTime start, orbit::UtcTime end, std::string note);
  // Tuning the radio (the page, host mode, menu 1), on the satellite the radio is tuned for:
  //  - tune_spot: a linear transponder's passband position, the downlink's spot in the satellite's
  //    frame (inside its downlink passband); the uplink moves to the pair by the transponder's rule.
  //  - tune_offsets: the operator's RX and TX offsets in Hz (nothing: that one stays), at most
  //    radio::kMaxOffsetHz either way, kept per satellite and mode for its next pass (0 forgets);
  //    they are the corrections the + / - keys and the dial follow keep (model.radio.corrections).
  //  - tune_tone: the uplink's CTCSS tone in Hz (60.0 to 300.0, tenths; 0 off), sent and stored in
  //    the satellite's radio record.
  OpResult tune_spot(std::int64_t downlink_hz);
  OpResult tune_offsets(std::optional<std::int64_t> rx_hz, std::optional<std::int64_t> tx_hz);
  OpResult tune_tone(double hz);
  // A satellite's mode (issue 59: the page's picker, host mode's MODE, `trakbox mode`, the API):
  // the satellite named ("": the one the radio is tuned for), its mode by name (case aside). The
  // choice is stored (the satellite's default mode from then on) and, when the radio follows that
  // satellite, the radio goes to the mode's spot with Doppler, its link modes and tone, and the
  // operator's corrections of that mode. Refused, naming the modes there are, for a mode it lacks.
  OpResult choose_mode(std::string_view satellite, std::string_view mode);
  // The station's position (menu 4's; --station, the page, host QTH): latitude -90..90, longitude
  // -180..180, height as the settings table takes them (store/settings.h); stored through the
  // model's owner, the geometry redone, GPS no longer its source.
  OpResult set_station(double lat_deg, double lon_deg, double height_m);
  // The station's callsign (menu 4's; the page's Station card), upper case, by the settings table.
  OpResult set_callsign(const std::string& callsign);
  // The station's horizon mask (menu 4's; the page's Station card; issue 57): `text` as
  // station.horizon_mask keeps it ("" for none; station::read_mask_entry reads what an operator
  // types), stored through the model's owner. The note says what the mask is now and, when the
  // parking position lies below it, that too (rotator::parking_mask_warning): the parking position
  // is the operator's, never moved.
  OpResult set_horizon_mask(const std::string& text);
  // The element refresh from the stored sources, now (menu 3-5 R, host RF).
  OpResult refresh_elements(std::int64_t now_unix);
  // "This is the Sun" / "this is the Moon" (`trakbox calibrate sun|moon`, the page; issue 58): the
  // operator has peaked the antenna on the body; the rotator's reading now (or `reading`, when given)
  // against the body's computed position sets the sky calibration's offsets (calibrate_offsets).
  OpResult calibrate(orbit::Body body, std::optional<rotator::AzEl> reading = std::nullopt);
  // A sun-noise scan's result (`trakbox calibrate sun --scan --store`): the correction it fitted
  // (true - reading) at time t, stored as calibrate's with the source "sun scan".
  OpResult calibrate_scan(orbit::UtcTime t, double az_correction_deg, double el_correction_deg);
  // `trakbox calibrate undo`: the offsets before the last calibration back (undo_calibration).
  OpResult calibrate_undo();

 private:
  // The controller's answer for `r`, applied: nothing when granted, else the refusal.
  std::optional<OpResult> ask(Resource r, bool to_tracking = false);
  bool outside() const { return is_outside(who_.kind); }
  // Who asked, as the model's owner records it.
  store::Origin origin() const;
  // The parking position below the horizon mask, said (rotator::parking_mask_warning).
  std::optional<std::string> parking_into_mask() const;

  StationLoop& station_;
  const store::Model& model_;
  Requester who_;
  bool confirmed_ = false;
};

// The sky calibration through the model's owner, for a running station (StationOps::calibrate) and
// for the state file when none runs (`trakbox calibrate` with --reading): the body's topocentric
// position from the stored station at `t` against `reading`; the offsets become old + (computed -
// reading) and are stored (Area rotator: the controller takes them at once) with the time and the
// body, the ones replaced kept for undo. Refused, with the reason, when the body is below 2 deg, the
// reading is flipped, or an offset would leave its range; nothing changes then. The note gives the
// computed position, the reading, the correction and the offsets before and after.
// `source` names what measured it in the record ("sun scan"); by default the body ("sun", "moon").
OpResult calibrate_offsets(store::ModelOwner& owner, orbit::Body body, orbit::UtcTime t, rotator::AzEl reading,
                           store::Origin origin, const std::string& source = "");
OpResult undo_calibration(store::ModelOwner& owner, store::Origin origin);
// The stored calibration in a line: "offsets az -2.00 el +1.00 deg from the SUN at 2026-...", or none.
std::string calibration_text(const rotator::RotatorConfig& c);

}  // namespace tb::tracker
