// The Satrak antenna control unit: every command of the Satrak document applied to trakbox's
// station, and the periodic check that runs what the protocol sets up to happen by itself (the
// auto-tracking window, MOVE's rates, tracking, TLE file pick-up and downloads, the SSPA).
//
//   satrak::Unit unit(io, station, model, rtc, settings, {.tle_dir = state / "tle",
//                                                         .image_dir = state / "images"},
//                     {.save = [&] { return app.save(); }});
//   unit.start();                                  // the periodic check on io's timer
//   satrak::Server server(io, unit, {.port = 4001});
//
// Transport-free: a payload in, a reply payload out (handle()). Everything runs on the io_context's
// thread; downloads run on a worker thread and post their results back. Nothing here blocks.
//
// The unit moves the antenna only through the StationLoop's rotator controller (the same limits,
// dead band and rotor-control switch as the menus). While Satrak moves or tracks it stops the
// station's own Tracker, as StationLoop::point does, and it yields the antenna as soon as anything
// else takes it (menu tracking, a menu GOTO, park, a preset, keyboard control). Tracking computes
// with the same orbit engine as the Tracker, adding what the Tracker has no place for: the time
// and position offsets, north offset, minimum elevation and elevation threshold (docs/satrak.md).
#pragma once
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "orbit/elements.h"
#include "orbit/passes.h"
#include "rotator/pass_plan.h"
#include "rotator/satrak/commands.h"
#include "download/download.h"
#include "rotator/satrak/frame.h"
#include "satrak/settings.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/station_loop.h"
#include "util/loop_fwd.h"

namespace tb::satrak {

struct UnitOptions {
  std::filesystem::path tle_dir;    // SATELLITE= file names live here (created if missing)
  std::filesystem::path image_dir;  // LOAD_IMAGE= file names live here
  std::string version = "0.1.0";    // VERSION?
  std::chrono::milliseconds period{200};      // the periodic check (clock time, on the io timer)
  std::chrono::seconds file_check{5};         // RTC time between checks of the TLE file for changes
  std::chrono::seconds retry_after{300};      // RTC time before a failed download is tried again
  std::chrono::milliseconds download_timeout{60000};
};

struct UnitHooks {
  // The Model or the Settings changed: persist them (the program saves the state document with
  // the Model and data["satrak"] = to_json(unit.settings())).
  // Returns the reason when the state could not be written; the command is then answered
  // `WORD,ERR,12` (internal) although the change holds in memory.
  std::function<std::optional<std::string>()> save;
};

// ERRSTATUS? X1..X12.
struct Faults {
  bool link = false;            // X1 internal communication: the rotator link is not ok
  bool tle_stale = false;       // X2 the element source is older than its update period
  bool tle_missing = false;     // X3 the TLE file was not found (last load)
  bool sat_missing = false;     // X4 the satellite was not in it (last load)
  bool download = false;        // X5 the last download failed
  bool tracking_stopped = false;  // X6 tracking stopped by something other than TRACK=,0 / STOP=
  bool setup = false;           // X7 the rotator configuration is not usable
  bool x_motor = false;         // X8 azimuth stalled
  bool y_motor = false;         // X9 elevation stalled
  int x_sensor = 0;             // X10 0 ok, 1 configuration, 2 connection (no reading)
  int y_sensor = 0;             // X11
  bool gps = false;             // X12 a receiver is expected (--gps, GPS mode) and cannot be heard
  bool any() const {
    return link || tle_stale || tle_missing || sat_missing || download || tracking_stopped || setup || x_motor ||
           y_motor || x_sensor || y_sensor || gps;
  }
};

// STATUS? X9.
enum class TrackStatus : int { not_in_track_time = 0, in_track_time = 1, completed = 2, start_before = 3 };

class Unit {
 public:
  Unit(boost::asio::io_context& io, tracker::StationLoop& station, const store::Model& model,
       station::RealTimeClock& clock, Settings settings, UnitOptions options, UnitHooks hooks = {});
  ~Unit();
  Unit(const Unit&) = delete;
  Unit& operator=(const Unit&) = delete;

  // Runs tick() every options.period on the io_context's timer until stop() or destruction.
  void start();
  void stop();

  // One payload in, the reply payload out; the command is applied at once. `client` names the
  // connection that sent it ("satrak 127.0.0.1:50123"): the holder of record while its commands
  // drive the antenna (tracker/control.h).
  std::string handle(std::string_view payload, std::string_view client = "satrak");
  // A decoder result: a frame is handled; a bad checksum, malformed or overlong line is answered
  // with its error (and the command word when it can be read) and never acted on.
  std::string handle(const Decoded& d, std::string_view client = "satrak");
  // That client disconnected: what it held is handed back, as rotctld's clients' holds are.
  void client_left(std::string_view client);

  // The periodic check (start() runs it; tests may call it directly after moving the clock).
  void tick();

  const Settings& settings() const { return s_; }
  bool tracking() const { return tracking_; }          // STATUS X8
  TrackStatus track_status() const;                    // STATUS X9
  Faults faults() const;                               // ERRSTATUS
  bool sspa_on() const;                                // the SSPA as SETTINGS X9/X10 decide it
  const std::optional<orbit::Elements>& elements() const { return elements_; }
  // Where tracking wants the antenna now (compass axis az/el, offsets applied), if it is tracking
  // a satellite above the threshold.
  std::optional<rotator::AzEl> tracking_target() const { return last_track_target_; }
  int load_image_status() const { return image_status_; }
  // A download (SATELLITE_HTTP / SATELLITE_FTP) is in flight.
  bool downloading() const { return download_in_flight_; }

 private:
  using Reply = std::string;
  Reply dispatch(const Command& c);

  // Commands.
  Reply cmd_version(const Command& c);
  Reply cmd_move(const Command& c);
  Reply cmd_step(const Command& c);
  Reply cmd_goto(const Command& c);
  Reply cmd_stop(const Command& c);
  Reply cmd_status(const Command& c);
  Reply cmd_errstatus(const Command& c);
  Reply cmd_time(const Command& c);
  Reply cmd_start_stop_time(const Command& c);
  Reply cmd_settings(const Command& c);
  Reply cmd_angle_settings(const Command& c);
  Reply cmd_gps_data(const Command& c);
  Reply cmd_tpos(const Command& c);
  Reply cmd_track(const Command& c);
  Reply cmd_track_auto(const Command& c);
  Reply cmd_rtc_reupdate(const Command& c);
  Reply cmd_gps_settings(const Command& c);
  Reply cmd_satellite(const Command& c);
  Reply cmd_satellite_http(const Command& c);
  Reply cmd_satellite_ftp(const Command& c);
  Reply cmd_load_image(const Command& c);
  Reply cmd_reduction(const Command& c);

  // Antenna.
  // A command that moves the antenna takes control (rotor control on), as the operator pressing
  // E would: a remote client has no other way to do it.
  void take_control();
  // Asks the controller of record for the antenna for this client (tracker/control.h): refused in
  // standby and while another kind holds it under --exclusive (the reason, logged). Granted, the
  // station's Tracker stops and the client holds the antenna.
  std::optional<std::string> take_antenna();
  // Set a target and remember it as Satrak's.
  void command(rotator::RotatorPosition p,
               rotator::Controller::Approach how = rotator::Controller::Approach::dead_band);
  // MOVE/STEP/GOTO while tracking (or going to the window's start): refused, logged.
  bool refused_while_tracking(const Command& c);
  void release();                           // Satrak no longer drives the antenna
  void check_takeover();
  rotator::RotatorPosition current_position() const;  // the target in force, else the reading
  double min_el() const;

  // Tracking.
  bool start_tracking();  // false: the antenna was refused (standby, --exclusive)
  void stop_tracking(bool fault);
  void track(orbit::UtcTime now);
  void update_window(orbit::UtcTime now);
  void preposition(orbit::UtcTime start);
  rotator::AzEl adjusted(double az, double el) const;  // offsets, north offset, min elevation
  std::optional<orbit::Observation> observe(orbit::UtcTime t) const;
  const orbit::Pass* pass_at(orbit::UtcTime t);      // threshold pass in progress at t, or the next
  const rotator::PassPlan* plan_for(const orbit::Pass& p);
  void pointing_changed();                           // settings that move the antenna changed

  // Element sets.
  struct Loaded {
    std::optional<orbit::Elements> elements;
    Error error = Error::internal;   // when no elements: file_not_found, satellite_not_found, invalid_file
  };
  Loaded load_file(const std::string& file, const std::string& satellite) const;
  void set_elements(std::optional<orbit::Elements> e);
  void apply_load(const Loaded& l);
  void check_file(orbit::UtcTime now);
  void schedule_download(orbit::UtcTime now);
  void start_download();
  void on_download(TleSource source, std::uint64_t generation, download::DownloadResult r);
  void download_failed();
  std::string active_file() const;
  std::string active_satellite() const;
  // For a unit that has had no SATELLITE=: the station's database as a TLE file (written to the TLE
  // directory as database.tle unless a file of that name is there) and the first satellite of the
  // tracking list (of the database when the list is empty). Nothing when the database is empty.
  struct Source {
    std::string file, satellite;
  };
  std::optional<Source> default_source();
  double active_period_days() const;

  void changed();  // settings or model changed: persist
  // The station's clock offset stored (TIME=, RTC_REUPDATE=, GPS time).
  void store_clock_offset();
  // RTC_REUPDATE= and SETTINGS X1: the RTC's offset from the receiver's last report (false: no fix).
  bool update_rtc_from_gps();

  boost::asio::io_context& io_;
  tracker::StationLoop& station_;
  const store::Model& model_;  // station_.model(): changed only through station_.owner()
  station::RealTimeClock& clock_;
  std::string client_ = "satrak";  // the connection whose command is being handled
  std::string holder_;             // the connection whose commands drive the antenna, if any
  Settings s_;
  UnitOptions opt_;
  UnitHooks hooks_;
  bool save_failed_ = false;  // the command being handled could not store its change
  struct Timer;  // the periodic check's Asio timer, kept out of this header
  std::unique_ptr<Timer> timer_;
  bool running_ = false;

  // Who drives the antenna.
  enum class Owner { none, move, go, track };
  Owner owner_ = Owner::none;
  std::optional<rotator::RotatorPosition> commanded_;
  struct Move {
    double az_rate = 0.0, el_rate = 0.0;  // deg/s, capped at the axis speeds; the controller jogs
  };
  std::optional<Move> move_;

  // Tracking.
  bool tracking_ = false;
  bool auto_started_ = false;        // tracking_ was started by the window
  bool window_started_ = false;      // the window's start has been acted on
  bool window_prepositioned_ = false;
  bool tracking_stopped_fault_ = false;
  std::optional<rotator::AzEl> last_track_target_;
  std::optional<orbit::Elements> elements_;
  std::unique_ptr<orbit::Sgp4> sgp4_;
  std::uint64_t pointing_generation_ = 0;
  std::optional<orbit::Pass> pass_;  // the last pass_at's, from the station's pass cache
  struct PlanCache {
    orbit::UtcTime aos{};
    std::uint64_t generation = 0;
    rotator::PassPlan plan;
  };
  std::optional<PlanCache> plan_cache_;

  // Element sources.
  bool tle_missing_ = false, sat_missing_ = false, download_failed_ = false;
  bool file_seen_ = false;          // file_stat_us_/file_size_ describe the active file as last read
  std::int64_t file_stat_us_ = 0;   // its modification time, microseconds since 1970
  std::uintmax_t file_size_ = 0;
  orbit::UtcTime last_file_check_{};
  std::optional<orbit::UtcTime> last_download_ok_;
  std::optional<orbit::UtcTime> next_download_;
  std::uint64_t download_generation_ = 0;
  bool download_in_flight_ = false;
  std::unique_ptr<download::Downloader> downloader_;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);

  bool rtc_from_gps_ = false;                 // STATUS X10: the RTC was set from GPS
  std::uint64_t position_generation_seen_ = 0;  // StationLoop::position_generation at the last tick
  int image_status_ = 0;  // LOAD_IMAGE?: 0 none, 1 loaded, 2 failed
  std::optional<bool> sspa_last_;  // for logging changes
};

// "0.1.0" -> "VERSION?,TRAKBOX SATRAK CU V0.1.0,..." etc. are built by the unit; exposed for the
// client and tests: the number of fields each reply carries.
inline constexpr int kStatusFields = 16;
inline constexpr int kErrStatusFields = 12;

}  // namespace tb::satrak
