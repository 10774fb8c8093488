// The running station of `trakbox [options]`: the model and its state file, the clock, the
// tracker and the StationLoop on one Asio event loop, the tick timer, the signals, and saving.
// Asio stays behind a pimpl: the menus' terminals wait through wait_readable(), the servers get
// io(). The unattended front end (--service) is here too (run_service).
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "menus/term/terminal.h"
#include "store/model.h"
#include "store/owner.h"
#include "store/state_file.h"
#include "util/loop_fwd.h"

namespace tb::gps {
class Monitor;
}
namespace tb::radio {
class RadioDriver;
}
namespace tb::rotator {
class RotatorDriver;
}
namespace tb::satrak {
class Unit;
}
namespace tb::station {
class RealTimeClock;
}
namespace tb::tracker {
struct Event;
class ElementsRefresh;
class StationLoop;
class Tracker;
}

namespace tb::app {

// Thrown out of the event loop by SIGTERM, SIGINT and SIGHUP: it ends the wait of the front end;
// StationApp::last_signal() says which signal it was.
struct Shutdown {};

class StationApp {
 public:
  // The station on the model `owner` keeps (store/owner.h), saved in `file`.
  StationApp(store::ModelOwner owner, store::StateFile file, std::shared_ptr<spdlog::logger> log);
  ~StationApp();
  StationApp(const StationApp&) = delete;
  StationApp& operator=(const StationApp&) = delete;

  station::RealTimeClock& clock();
  const store::Model& model() const;
  // The one door of the model (store/owner.h): every change goes through it, and is saved.
  store::ModelOwner& owner();
  tracker::Tracker& tracker();
  tracker::StationLoop& station();
  tracker::ElementsRefresh& refresh();  // the scheduled element refresh (polled on every tick)
  boost::asio::io_context& io();
  spdlog::logger& log();

  void build_station(std::unique_ptr<rotator::RotatorDriver> rot, std::unique_ptr<radio::RadioDriver> rad);
  // Starts the tick timer (every `tick`, sooner when the station asks) and the signal wait.
  void start(std::chrono::milliseconds tick);

  // The terminal's way of waiting: one blocking wait of the event loop (run_one) until fd is
  // readable (fd < 0: no input), the timeout passes, or the loop did other work (false: the caller
  // looks again). Nothing wakes the process meanwhile; the tick timer is one of the loop's timers.
  bool wait_readable(int fd, std::optional<term::Duration> timeout);
  void set_terminal(term::Terminal* t);  // gets the status line after every tick

  // Settings of the Satrak unit, persisted beside the model (data["satrak"]); `saved` is what the
  // state held, kept as it was while the Satrak server is off.
  void set_satrak(satrak::Unit* unit);
  void set_satrak_saved(const nlohmann::json& saved);
  // Writes the state document; the reason when it could not.
  std::optional<std::string> save();

  // When the state was last saved (the station's clock), nothing before the first save.
  std::optional<std::chrono::system_clock::time_point> last_saved() const;

  // Where the station's events go (tracker/events.h: AOS and LOS of the tracking list, element
  // refreshes, links lost and back, failed saves), found on every tick; lead: the AOS event comes
  // this long before AOS.
  void set_events(std::function<void(const tracker::Event&)> sink, std::chrono::seconds lead);
  // The GPS receiver of model().gps.source (nothing when none): its client thread reports to the
  // loop, which logs each problem once, follows the receiver when model().gps.follow says so (and
  // saves then), and shows the GPS word on the status line. stop_gps() ends the thread.
  void start_gps();
  void stop_gps();
  // The receiver's state as the loop last heard it; nullptr when no GPS is configured or started.
  const gps::Monitor* gps() const;

  // --service: tracks what the stored configuration says, serves, re-reads the data directory's
  // element and freq/mode files on SIGHUP, and on SIGTERM parks (when parking is on). `menus`,
  // when given, runs the menus for attached terminals on the event loop meanwhile (it is started
  // again after a SIGHUP). Returns the exit status; the caller saves.
  int run_service(const std::string& data_dir, const std::function<void()>& menus = {});
  // Also run on each SIGHUP of run_service, after the data files (the endpoints' secret files).
  void on_hangup(std::function<void()> f);

  // The menus at a terminal: what the operator last chose to track (model.tracking, a satellite or
  // multiple tracking), resumed as the service resumes it; nothing when no choice was made. The
  // sentence to show, or "".
  std::string resume_chosen_tracking();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Factory defaults plus the shipped database of data_dir (what a fresh TrakBox with a loaded
// database is); problems with the files are added to notes.
store::Model defaults_with_data(const std::string& data_dir, std::vector<std::string>& notes);

}  // namespace tb::app
