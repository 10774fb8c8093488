// The station: the one place that moves the antenna and tunes the radio. Each tick it asks the
// Tracker what to do and applies it through the rotator Controller and the radio Tuner/driver.
// Menus, host mode and the servers act through it too, so every path obeys the same limits,
// dead band, parking rules and rotor-control switch.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "gps/monitor.h"
#include "radio/doppler.h"
#include "radio/driver.h"
#include "rotator/controller.h"
#include "rotator/pass_plan.h"
#include "store/owner.h"
#include "tracker/client_follow.h"
#include "tracker/control.h"
#include "tracker/events.h"
#include "tracker/tracker.h"

namespace tb::tracker {

// The edit that copies the corrections the tuner learnt (+ / -, dial follow) into the model: the
// station does not hand them back to the tuner that made them.
inline constexpr std::string_view kCorrectionsEdit = "radio corrections";
// Dial follow switched by the realtime display's D key, which hands it to the tuner itself (the
// spot reached so far stays).
inline constexpr std::string_view kDialFollowEdit = "dial follow";
// The tone the station has just sent (StationOps::tune_tone): stored, not sent again.
inline constexpr std::string_view kToneEdit = "tone";
// A satellite's mode chosen (StationOps::choose_mode): its record replaced, the radio tuned afresh.
inline constexpr std::string_view kModeEdit = "satellite mode";

class ElementsRefresh;
struct Logging;

class StationLoop {
 public:
  // The station runs on the model its owner keeps (store/owner.h): it reads it, edits it only
  // through the owner, and follows every change the owner announces (reconfigure, save, wake).
  StationLoop(store::ModelOwner& owner, const station::Clock& clock, Tracker& tracker,
              std::unique_ptr<rotator::Controller> rotator, std::unique_ptr<radio::RadioDriver> radio);

  // Tracker tick, then antenna and radio. Call once a second or faster (next_tick_in says).
  void tick();
  std::chrono::milliseconds next_tick_in() const;

  ~StationLoop();   // a recording in progress is stopped
  StationLoop(const StationLoop&) = delete;
  StationLoop& operator=(const StationLoop&) = delete;

  // The E key, menu 6-R, a station operation: rotor control on/off (persisted in the model and
  // saved at the change through on_settings_changed).
  void set_rotor_control(bool on);
  bool rotor_control() const { return model_.rotor_control; }
  // Doppler on/off: off, the radio is left as it is (not tuned to the followed satellite) until
  // Doppler is on again. On at start; not stored.
  void set_doppler(bool on) {
    doppler_ = on;
    if (on) tuned_.reset();  // select the satellite again: everything is sent afresh
  }
  bool doppler() const { return doppler_; }

  // Every change of the stored model (any front end, through the owner) and the station's own
  // (rotor control; the Tracker's choice, recorded in model.tracking): the program saves the state
  // here, so a restart does what was asked whichever front end asked it.
  void on_settings_changed(std::function<void()> f) { settings_changed_ = std::move(f); }
  // Saves now through that hook (standby, a reservation: stored before they are acknowledged).
  void save_settings() {
    if (settings_changed_) settings_changed_();
  }

  // Direct antenna control (menus 6-6 and 8, host AZ/EL, Satrak GOTO): tracking stops, the antenna
  // goes where it is told (still inside the limits). Returns the commanded compass position.
  rotator::AzEl point(rotator::AzEl compass);
  void stop_antenna();
  // The same for whoever holds the antenna (tracker/control.h) without ending the Tracker's choice:
  // it goes on deciding (and tuning the radio while trakbox's tracking holds that), and drives the
  // antenna again when the hold ends.
  // An outside client's target (`client`: its requester label, "rotctld 127.0.0.1:51234"; `kind`:
  // "rotctld") goes through the plan of the pass its targets are recognised to follow
  // (client_follow.h): the way round trakbox's own tracking would take; a target matching no pass
  // goes the way nearest the antenna.
  rotator::AzEl point_held(rotator::AzEl compass, std::string_view client = {}, std::string_view kind = {});
  // Where a client's target is driven when it matches a pass (the plan's mapping), nothing when it
  // matches none. Satrak's GOTO asks here before it commands the rotator itself.
  std::optional<rotator::RotatorPosition> client_plan_target(rotator::AzEl compass, std::string_view client,
                                                             std::string_view kind);
  // "following rotctld's targets on the planned way round for ISS (pass to 14:32)" while a client's
  // targets are recognised as a pass; "" otherwise.
  std::string client_follow_text() const;

  // Who holds the antenna and the radio (issue 44). The station applies the Tracker's decisions to
  // each only while trakbox's tracking holds it; every change of holder goes through apply().
  Control& control() { return control_; }
  const Control& control() const { return control_; }
  orbit::UtcTime now() const { return clock_.now(); }
  // Logs each change at info and tells on_control (the program's events: `control`); a radio
  // handed back to tracking is tuned afresh, an antenna handed back moves at once.
  void apply(const std::vector<Change>& changes);
  void on_control(std::function<void(const Change&)> f) { control_changed_ = std::move(f); }
  // model.sharing (--handback, --exclusive, the operator's reservations) and the SatNOGS jobs into
  // the controller; reconfigure() does it too.
  void sharing_changed();
  void set_satnogs_windows(std::vector<Window> w) {
    satnogs_windows_ = std::move(w);
    sharing_changed();
  }
  // What the SatNOGS calendar's poller (--satnogs-station) last found, for status.
  struct SatnogsState {
    int station = 0;
    std::string url;
    std::size_t jobs = 0;
    std::string last_poll;             // station time, ISO 8601; "" before the first answer
    std::optional<std::string> error;  // the last poll failed: why (the last good list is kept)
  };
  void set_satnogs_state(SatnogsState s) { satnogs_state_ = std::move(s); }
  const std::optional<SatnogsState>& satnogs_state() const { return satnogs_state_; }
  // Someone moved the antenna through rotator() directly (the Satrak unit's targets and jogs):
  // tick now rather than at the end of the interval being waited out (see on_wake).
  void antenna_changed() { wake(); }

  // After the operator changed station, rotator or radio settings in the model.
  void reconfigure();

  // Called when a command changed what the antenna should do (point, stop, rotor control): the
  // event loop ticks at once rather than at the end of the interval it was waiting out, so the
  // antenna starts within milliseconds, not up to a second later.
  void on_wake(std::function<void()> wake) { wake_ = std::move(wake); }

  // Something other than the Tracker follows a satellite with the antenna: the Satrak unit's
  // TRACK. It reports each of its ticks; the station then keeps the radio on that satellite's
  // frequencies with its Doppler (when the database holds the satellite: same catalogue number)
  // and the status line names it. nullopt when it stops. The Tracker starting (menu S, 1, M)
  // ends it: whoever takes the antenna takes the radio.
  struct RemoteFollow {
    std::string owner;        // "Satrak"
    std::string name;         // the element set's name
    int catalog_number = 0;
    orbit::Observation obs;   // at the follower's time
  };
  void remote_follow(std::optional<RemoteFollow> f);
  const std::optional<RemoteFollow>& remote_followed() const { return remote_; }
  // The database satellite the radio follows for the remote follower, if any.
  std::optional<int> remote_db_index() const { return remote_db_; }

  rotator::Controller& rotator() { return *rotator_; }
  const rotator::Controller& rotator() const { return *rotator_; }
  radio::RadioDriver& radio() { return *radio_; }
  // Recording (--record; docs/radio.md "Recording a pass"): the receiver's recorder is started when
  // the satellite the receiver is tuned to rises above the rotor start elevation (the AOS of the
  // pass events) and stopped when it sets, over the radio's own connection. Each start's answer
  // (read back, or why not) and each stop is a `recording` event, told here.
  struct PassRecording {
    int db_index = -1;
    std::string satellite;
    radio::Record kind = radio::Record::off;
    orbit::UtcTime start{};
    radio::Hz frequency_hz = 0;
    std::string file;              // the receiver's file name ("" when trakbox cannot know it)
    bool answered = false;         // the receiver answered the start
  };
  const std::optional<PassRecording>& recording() const { return recording_; }
  void on_recording(std::function<void(const Event&)> f) { recording_event_ = std::move(f); }
  // A second radio for the uplink (menu 6-7's U), or none (nullptr): one radio for both links
  // again. The downlink radio stays; everything is sent again at the next tick.
  void set_uplink_radio(std::unique_ptr<radio::RadioDriver> uplink);
  radio::Tuner& tuner() { return tuner_; }
  // The database satellite the radio is tuned for (the followed one since its first tick), if any.
  std::optional<int> tuned() const { return tuned_; }
  // The tuned satellite's uplink CTCSS tone, sent now (tenths of Hz, 0 off); the caller stores it.
  void set_tone(int tenths_hz);
  // How long until a link waiting for the knob to rest moves (tick then); nothing when none waits.
  std::optional<std::chrono::milliseconds> radio_due_in() const;
  Tracker& tracker() { return tracker_; }
  const Tracker& tracker() const { return tracker_; }
  const store::Model& model() const { return owner_.model(); }
  // The one door of the stored model: named edits, each checked whole, saved and announced.
  store::ModelOwner& owner() { return owner_; }

  // Compass azimuth/elevation the antenna points at now, if known.
  std::optional<rotator::AzEl> antenna() const;
  // Where the antenna is being sent (compass degrees) and why, the one answer the status and the
  // page's sky give: trakbox's decision while its tracking drives the antenna ("point",
  // "preposition", "park"); an outside holder's commanded target ("held": a client's `P`, a Satrak
  // GOTO, a SatNOGS job); with tracking off the last goto ("point"). An antenna that holds (no
  // pass, parking off, a client's move done) has its position as its target: it stays there.
  struct Aim {
    std::optional<rotator::AzEl> target;
    const char* action = "hold";   // held, point, preposition, park, hold
  };
  Aim aim() const;
  // One line for the full-screen status bar: time, satellite, rotator and radio state, and
  // "STATE NOT SAVED" while the last save failed (memory and disk differ).
  std::string status_line() const;
  // The program's last save of the state: failed (with the reason) or succeeded (nothing).
  void set_save_failure(std::optional<std::string> reason) { save_failure_ = std::move(reason); }
  const std::optional<std::string>& save_failure() const { return save_failure_; }
  // The realtime display's U key (the later firmware's alternative uplinks): the satellite whose
  // radio is tuned steps to its next uplink channel (stored, so it stays chosen). The new uplink
  // frequency, or nothing when it has no alternatives or nothing is tuned.
  std::optional<radio::Hz> next_uplink();

  // The scheduled element refresh, when the program has one (menu 3-5 and host mode use it).
  void set_refresh(ElementsRefresh* r) { refresh_ = r; }
  ElementsRefresh* refresh() const { return refresh_; }
  // A word for the end of the status line ("ELEMENTS 3 UPDATED"); "" for none.
  void set_notice(std::string notice) { notice_ = std::move(notice); }

  // The GPS receiver, when the program has one (--gps): menus 4 and 5, host mode and the Satrak
  // unit read it through here. The status line carries its word (Monitor::status_word).
  void set_gps(gps::Monitor* m) { gps_ = m; }
  gps::Monitor* gps() const { return gps_; }
  // The operator's logbook, when the program has one (tracker::LogOps reaches it through here).
  void set_logging(Logging* l) { logging_ = l; }
  Logging* logging() const { return logging_; }
  const station::Clock& clock() const { return clock_; }
  // When the station follows the receiver (model.gps.follow) and its confirmed position is farther
  // than model.gps.threshold_m from the station's (or the position was typed in): the station moves
  // there through the owner (a 2D fix keeps the stored height) and true is returned. Jitter within
  // the threshold changes nothing.
  bool apply_gps_position();
  // Counts the station's moves (menu 4, GPS, GPS_SETTINGS=): whoever caches what depends on the
  // position (the Satrak unit's pass) compares it.
  std::uint64_t position_generation() const { return position_generation_; }
  void position_changed() { ++position_generation_; }

 private:
  // What was sent is forgotten (the spot, offsets and tone stay): everything goes out again.
  void resend_radio();

  store::ModelOwner& owner_;
  const store::Model& model_;  // owner_.model(), read only
  const station::Clock& clock_;
  Tracker& tracker_;
  std::unique_ptr<rotator::Controller> rotator_;
  std::unique_ptr<radio::RadioDriver> radio_;
  radio::Tuner tuner_;
  std::optional<int> tuned_;  // db index the tuner is set up for
  bool tone_sent_ = false;    // a CTCSS tone is on (turned off for a satellite without one)
  bool rit_said_ = false;
  bool doppler_ = true;     // the log said once that RIT/XIT moved both links
  std::optional<RemoteFollow> remote_;
  std::optional<std::string> save_failure_;
  std::string notice_;
  ElementsRefresh* refresh_ = nullptr;
  gps::Monitor* gps_ = nullptr;
  Logging* logging_ = nullptr;
  std::uint64_t position_generation_ = 0;
  std::optional<int> remote_db_;  // remote_'s satellite in the database
  std::function<void()> wake_;
  std::function<void()> settings_changed_;
  Control control_;
  std::vector<Window> satnogs_windows_;
  std::optional<SatnogsState> satnogs_state_;
  std::function<void(const Change&)> control_changed_;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);  // the Tracker's hook checks this
  void record_choice();
  void on_model_changed(const store::Notice& n);
  void wake() {
    if (wake_) wake_();
  }
  void follow_radio(int db_index, const orbit::Observation& obs);
  // Recording: the satellite to record now (tuned, up, chosen by --record-satellites), -1 none.
  int to_record(bool drive_radio) const;
  void record_pass(orbit::UtcTime now, bool drive_radio);
  void recording_told(const char* state, const radio::RecorderStatus& rs, orbit::UtcTime now);
  std::optional<PassRecording> recording_;
  std::uint64_t recorder_answers_ = 0;   // the receiver's answers seen
  std::function<void(const Event&)> recording_event_;
  void find_remote_in_database();

  // The plan for the pass being followed (or coming): which way round, flip, where to wait.
  struct PlannedPass {
    int db_index = -1;
    orbit::UtcTime aos{};
    rotator::PassPlan plan;
  };
  std::optional<PlannedPass> planned_;
  const rotator::PassPlan* plan_for(const SatNow& s);
  // The pass an outside client's targets follow (issue 57), and what the status says of it.
  ClientPassMatcher client_match_;
  struct ClientFollow {
    std::string kind;  // "rotctld"
    std::string name;  // the satellite
    orbit::UtcTime los{};
    bool flip = false;
  };
  std::optional<ClientFollow> client_follow_;
  void end_client_follow(std::string_view why);
  // The last client target that went through a plan with a keyhole (PassPlan::lead): the plan's
  // key and when. Inside the keyhole the azimuth runs on time, so the station keeps moving the
  // target between the client's targets (a client moves when the satellite has moved 4 degrees,
  // or once a second: the schedule would stand still between them).
  struct ClientLead {
    int key = -1;
    orbit::UtcTime at{};
  };
  std::optional<ClientLead> client_lead_;
  // Unwinding after a pass (issue 57): the LOS of the last pass followed on a plan (trakbox's own,
  // a client's recognised one, a SatNOGS job's). Once it is over and the antenna is trakbox's again
  // (no client holds it, tracking does not point it), an antenna left more than a turn from the stop
  // goes one turn back, the same direction, unless a pass is due within kUnwindClearMinutes (its
  // own plan then chooses the way round from where the antenna is).
  std::optional<orbit::UtcTime> unwind_after_;
  static constexpr double kUnwindClearMinutes = 15.0;
  void unwind_after_pass(orbit::UtcTime now);
  // The first pass due before `until`: a tracked satellite's next AOS or a SatNOGS window's start
  // ("SO-50's pass at 14:05"); nothing when none is.
  std::optional<std::string> pass_due(orbit::UtcTime now, orbit::UtcTime until) const;
  void client_keyhole(orbit::UtcTime now);
  // A client's target through `plan` at now (the keyhole's schedule when one holds).
  rotator::RotatorPosition client_mapped(int key, const rotator::PassPlan& plan, SkyTarget target);
  // The plan of a pass whose samples `look` gives (AOS to LOS), kept as planned_ under (key, AOS).
  using Look = std::function<std::optional<orbit::Observation>(orbit::UtcTime)>;
  const rotator::PassPlan* plan_of(int key, const std::string& name, const orbit::Pass& pass, const Look& look);
  // The SatNOGS job whose window holds, with its own elements (tle0/1/2), planned with them.
  static constexpr int kJobKey = -2;
  struct JobOrbit {
    std::string id;
    std::unique_ptr<orbit::Sgp4> sgp4;  // nothing when its elements do not read
  };
  std::optional<JobOrbit> job_;
  const orbit::Sgp4* job_orbit(const Window& w);
  // Before a SatNOGS window whose job carries its elements, unless trakbox's own satellite is up and
  // followed: the antenna goes to the start of that pass's plan (above the horizon mask),
  // Tracker::kPrepositionMinutes ahead (issue 57). Whether it went.
  bool preposition_for_job(orbit::UtcTime now);
  std::string prepositioned_;  // the job it went for (said once)
  // The client's target through the job's pass plan, when it matched the job.
  std::optional<rotator::RotatorPosition> job_plan_target(const Window& w, SkyTarget target, std::string_view kind);

 public:
  // The plan in force, if any (for displays and tests).
  const rotator::PassPlan* current_plan() const { return planned_ ? &planned_->plan : nullptr; }
  // When the plan for this satellite's pass does not follow all of it (limits, a split travel, the
  // stop): "antenna on target 12:57:01-12:59:02 (20% of the pass): it reaches azimuth 180.0-350.0"
  // or "PASS OUT OF ANTENNA REACH (it reaches azimuth 180.0-350.0)". The realtime display and the status line show it.
  std::optional<std::string> coverage_note(int db_index) const;
};

}  // namespace tb::tracker
