#include "live/station_app.h"

#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include <spdlog/spdlog.h>

#include "gps/gpsd_client.h"
#include "radio/freqmode.h"
#include "rotator/parking_mask.h"
#include "rotator/split_travel.h"
#include "satrak/unit.h"
#include "station/clock.h"
#include "store/database.h"
#include "store/refresh.h"
#include "store/station_file.h"
#include "store/station_file_model.h"
#include "tracker/elements_refresh.h"
#include "tracker/events.h"
#include "tracker/pass_memo.h"
#include "tracker/station_loop.h"
#include "util/files.h"

namespace tb::app {

namespace asio = boost::asio;

namespace {
std::string read_text(const std::string& path) { return files::read_whole_file(path).value_or(""); }

// The first of `names` that exists in data_dir ("" when none does).
std::string data_file(const std::string& data_dir, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const std::string path = data_dir + "/" + name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  return {};
}

// The freq/mode file: freqmode.txt, else the later firmware's FREQ.DAT (either form reads).
std::string freqmode_file(const std::string& data_dir) {
  const std::string found = data_file(data_dir, {"freqmode.txt", "FREQ.DAT", "freq.dat"});
  return found.empty() ? data_dir + "/freqmode.txt" : found;
}

}  // namespace

store::Model defaults_with_data(const std::string& data_dir, std::vector<std::string>& notes) {
  store::Model m = store::factory_defaults();
  const auto sets = orbit::load_elements_file(data_dir + "/amateur.tle");
  for (const auto& p : sets.problems) notes.push_back(p.message());
  const std::string fm_path = freqmode_file(data_dir);
  const auto fm = radio::parse_freqmode(read_text(fm_path));
  for (const auto& p : fm.problems) notes.push_back(fm_path + ": " + p.message());
  m.db = store::make_database(sets.sets, fm.records);
  // Current elements by default: the shipped sets are the offline fallback, refreshed from
  // CelesTrak at the first tick (the status line says when that fails and what to do).
  m.refresh.sources.push_back(store::RefreshSource{store::kDefaultElementsUrl, "", ""});
  // The operator's station file as the firmware named it (1994 or later form), as a 6-9 upload
  // would apply it: all of it or, when it has a problem, none of it. (The shipped station.txt is
  // the manual's sample for 6-9, not a station: it is not read here.)
  if (const std::string path = data_file(data_dir, {"STATION.DAT", "station.dat"}); !path.empty()) {
    const store::StationFileParse parsed = store::parse_station_file(read_text(path));
    std::vector<std::string> problems;
    if (parsed.ok()) problems = store::apply_station_file(*parsed.file, m);
    for (const auto& p : parsed.problems) problems.push_back(p.message());
    for (const auto& p : problems) notes.push_back(path + ": " + p);
    if (!problems.empty()) notes.push_back(path + ": not used; the station keeps the factory settings");
    else if (const auto w = rotator::split_travel_warning(m.rotator, m.station.rotor_start))
      notes.push_back(path + ": " + *w);
  }
  return m;
}

struct StationApp::Impl {
  Impl(store::ModelOwner initial, store::StateFile file, std::shared_ptr<spdlog::logger> log)
      : owner(std::move(initial)), file(std::move(file)), log(std::move(log)), tracker(owner.model(), clock) {
    clock.set_offset(model.clock_offset);
  }

  // SIGTERM, SIGINT and SIGHUP end the wait of the front end (Shutdown).
  void arm_signals() {
    signals.async_wait([this](const boost::system::error_code& ec, int sig) {
      if (ec) return;
      last_signal = sig;
      log->info("signal {}: {}", sig, sig == SIGHUP && unattended ? "re-reading the elements" : "saving and leaving");
      throw Shutdown{};
    });
  }
  // The station says how soon to tick in simulated time (100 ms while the antenna moves, else the
  // --tick-ms interval); under --clock-rate R that is 1/R of it in wall time, at least
  // station::kMinWallTick: motion and tracking follow simulated time at any supported rate.
  void schedule_tick() {
    arm_tick(tb::station::wall_wait(std::min(station->next_tick_in(), tick), clock.rate()));
  }
  // (Re)arms the tick timer; a wait already pending is cancelled (its handler sees the abort).
  void arm_tick(std::chrono::microseconds in) {
    started = true;
    timer.expires_after(in);
    timer.async_wait([this](const boost::system::error_code& ec) {
      if (ec) return;
      station->tick();
      note_parking();
      if (refresh) {
        refresh->poll(tracker::ElementsRefresh::wall_now());
        station->set_notice(refresh->status_word(clock.now()));
      }
      find_events();
      if (terminal) terminal->status(station->status_line());
      schedule_tick();
    });
  }
  void run_forever() {
    for (;;) {
      if (io.stopped()) io.restart();
      io.run_one();
    }
  }
  // Runs the event loop until `done` holds or `limit` passes (steady time): done is looked at
  // after every piece of work the loop did.
  void run_until(const std::function<bool()>& done, std::chrono::milliseconds limit, StationApp& app) {
    const auto end = std::chrono::steady_clock::now() + limit;
    for (auto now = std::chrono::steady_clock::now(); !done() && now < end; now = std::chrono::steady_clock::now())
      app.wait_readable(-1, end - now);
  }
  // A terminal's input as an Asio descriptor, so that its wait is the loop's one blocking wait
  // (epoll) with the timers and the servers. The descriptor is the terminal's: released, never
  // closed, and made again when the number names another file.
  struct Input {
    Input(asio::io_context& io, int fd, const struct stat& st) : d(io, fd), dev(st.st_dev), ino(st.st_ino) {}
    ~Input() { d.release(); }
    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;
    asio::posix::stream_descriptor d;
    dev_t dev;
    ino_t ino;
    bool pending = false;  // an async_wait is outstanding (it stays so across waits)
    bool ready = false;    // it completed: the input is readable (or failed: the reader finds out)
  };
  Input* input(int fd);
  void arm_input(Input& in);
  void arm_deadline(term::Duration in);
  void start_stored_tracking();
  void find_events();
  void emit(tracker::Event e) {
    if (e.time == orbit::UtcTime{}) e.time = clock.now();
    if (events) events(e);
  }
  bool reread_data(const std::string& data_dir);  // false: the element file was not used
  void park_before_leaving(StationApp& app);

  asio::io_context io;
  asio::executor_work_guard<asio::io_context::executor_type> work = asio::make_work_guard(io);
  asio::signal_set signals{io, SIGTERM, SIGHUP, SIGINT};
  asio::steady_timer timer{io};
  asio::steady_timer deadline{io};  // the end of a terminal's wait
  unsigned deadline_gen = 0;        // which arm_deadline the pending wait belongs to
  bool deadline_hit = false;
  unsigned own_runs = 0;            // handlers of the wait itself (input, deadline) that have run
  std::unique_ptr<Input> in;        // the terminal's input (one terminal waits at a time)
  std::chrono::milliseconds tick{1000};
  bool started = false;  // the tick timer runs (start() was called)
  int last_signal = 0;
  bool unattended = false;
  std::function<void()> on_hangup;
  store::ModelOwner owner;                     // the one writer of the model (store/owner.h)
  const store::Model& model = owner.model();  // everyone here reads it
  store::StateFile file;
  std::shared_ptr<spdlog::logger> log;
  station::RealTimeClock clock;
  tracker::Tracker tracker;
  std::unique_ptr<tracker::StationLoop> station;
  std::unique_ptr<tracker::ElementsRefresh> refresh;
  term::Terminal* terminal = nullptr;
  satrak::Unit* satrak = nullptr;
  nlohmann::json satrak_saved;  // kept as loaded when the Satrak server is off
  std::optional<std::chrono::system_clock::time_point> last_saved;
  // Events: where they go, the pass events, and what the last tick saw of the links and refresh.
  std::function<void(const tracker::Event&)> events;
  std::unique_ptr<tracker::PassEventSource> pass_events;
  bool rotator_ok = true, radio_ok = true;
  std::string refresh_result;
  std::unique_ptr<gps::Monitor> gps;
  std::unique_ptr<gps::GpsdClient> gps_client;  // after gps: stopped before it goes
  // A parking position below the horizon mask (issue 57): logged when a change of the mask or the
  // parking makes it so (and when it is clear again), and each time the antenna goes to park; the
  // position is the operator's stow, never moved.
  std::optional<std::string> parking_warned;
  bool parking = false;
  std::optional<std::string> parking_into_mask() const {
    return rotator::parking_mask_warning(model.rotator, model.station.mask().get());
  }
  void check_parking_mask() {
    auto w = parking_into_mask();
    if (w == parking_warned) return;
    if (w) log->warn("antenna: {} (kept: menu 6-4 sets the parking position, menu 4 the mask)", *w);
    else if (parking_warned) log->info("antenna: the parking position is clear of the horizon mask now");
    parking_warned = std::move(w);
  }
  void note_parking() {
    const bool now = std::string_view(station->aim().action) == "park";
    if (now && !parking)
      if (const auto w = parking_into_mask()) log->warn("antenna: parks into the horizon mask: {}", *w);
    parking = now;
  }
  void log_notes(const std::vector<gps::Note>& notes) {
    for (const auto& n : notes) {
      if (n.warning) log->warn("{}", n.text);
      else log->info("{}", n.text);
    }
  }
  void show_status() {
    if (terminal && station) terminal->status(station->status_line());
  }
  void on_gps_report(const gps::Report& r, StationApp& app);
};

void StationApp::Impl::find_events() {
  if (!events) return;
  for (auto& e : pass_events->step(clock.now())) emit(std::move(e));
  const auto link = [this](bool now_ok, bool& was_ok, const char* what, const std::string& message) {
    if (now_ok == was_ok) return;
    was_ok = now_ok;
    tracker::Event e;
    e.kind = now_ok ? "link-back" : "link-lost";
    e.detail = now_ok ? std::string(what) : std::string(what) + ": " + message;
    emit(std::move(e));
  };
  const auto rot = station->rotator().status().link;
  link(rot.state != rotator::LinkState::fault, rotator_ok, "rotator", rot.message);
  const radio::RadioStatus rad = station->radio().status();
  link(!rad.fault, radio_ok, "radio", rad.message);
  if (refresh && refresh->last_result() != refresh_result) {
    refresh_result = refresh->last_result();
    tracker::Event e;
    e.kind = "elements";
    e.detail = refresh_result;
    emit(std::move(e));
  }
}

void StationApp::set_events(std::function<void(const tracker::Event&)> sink, std::chrono::seconds lead) {
  impl_->events = std::move(sink);
  impl_->pass_events = std::make_unique<tracker::PassEventSource>(impl_->model, impl_->tracker, lead);
  if (impl_->refresh) impl_->refresh_result = impl_->refresh->last_result();
}

std::optional<std::chrono::system_clock::time_point> StationApp::last_saved() const { return impl_->last_saved; }


void StationApp::Impl::on_gps_report(const gps::Report& r, StationApp&) {
  const std::string before = gps->status_word();
  log_notes(gps->on_report(r, clock.now()));
  if (station && station->apply_gps_position()) {
    const auto& st = model.station;
    log->info("GPS: the station is now at {:.6f} {:.6f} {:.1f} m (fix of {})", st.lat_deg, st.lon_deg, st.height_m,
              model.gps.position_time ? orbit::format_iso8601(*model.gps.position_time) : std::string("?"));
  }
  if (gps->status_word() != before) show_status();
}

StationApp::StationApp(store::ModelOwner owner, store::StateFile file, std::shared_ptr<spdlog::logger> log)
    : impl_(std::make_unique<Impl>(std::move(owner), std::move(file), std::move(log))) {
  impl_->refresh = std::make_unique<tracker::ElementsRefresh>(
      impl_->owner, [this](std::function<void()> f) { asio::post(impl_->io, std::move(f)); },
      [this] { save(); });
  impl_->refresh->set_station_clock(&impl_->clock);
}
StationApp::~StationApp() = default;

station::RealTimeClock& StationApp::clock() { return impl_->clock; }
const store::Model& StationApp::model() const { return impl_->model; }
store::ModelOwner& StationApp::owner() { return impl_->owner; }
tracker::Tracker& StationApp::tracker() { return impl_->tracker; }
tracker::StationLoop& StationApp::station() { return *impl_->station; }
tracker::ElementsRefresh& StationApp::refresh() { return *impl_->refresh; }
boost::asio::io_context& StationApp::io() { return impl_->io; }
spdlog::logger& StationApp::log() { return *impl_->log; }
void StationApp::set_terminal(term::Terminal* t) { impl_->terminal = t; }
void StationApp::set_satrak(satrak::Unit* unit) { impl_->satrak = unit; }
void StationApp::set_satrak_saved(const nlohmann::json& saved) { impl_->satrak_saved = saved; }

void StationApp::build_station(std::unique_ptr<rotator::RotatorDriver> rot, std::unique_ptr<radio::RadioDriver> rad) {
  Impl& m = *impl_;
  rotator::ControllerOptions opt;
  opt.clock_rate = m.clock.rate();
  auto controller =
      std::make_unique<rotator::Controller>(m.model.rotator, m.model.station.rotor_start, std::move(rot), opt);
  m.station = std::make_unique<tracker::StationLoop>(m.owner, m.clock, m.tracker, std::move(controller), std::move(rad));
  m.station->set_refresh(m.refresh.get());
  // Every change of the model, by whoever (the owner announces it to the station), is saved.
  m.station->on_settings_changed([this] { save(); });
  m.owner.listen([&m](const store::Notice&) { m.check_parking_mask(); });
  m.check_parking_mask();  // said once at the start too
  // Each change of who holds the antenna or the radio is an event (hooks, UDP, the stream; issue 44).
  m.station->on_control([&m](const tracker::Change& c) {
    tracker::Event e;
    e.kind = "control";
    e.detail = std::string(tracker::resource_name(c.resource)) + ": " + c.to.label + " (" + c.why + ")";
    e.control = c;
    m.emit(std::move(e));
  });
  // The receiver's recorder started (or why not) and stopped: `recording` events (--record).
  m.station->on_recording([&m](const tracker::Event& e) { m.emit(e); });
  m.station->on_wake([&m] {
    if (m.started) m.arm_tick(std::chrono::microseconds(0));
  });
}

void StationApp::start(std::chrono::milliseconds tick) {
  impl_->tick = tick;
  impl_->arm_signals();
  impl_->schedule_tick();
}

StationApp::Impl::Input* StationApp::Impl::input(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return nullptr;
  if (!in || in->d.native_handle() != fd || in->dev != st.st_dev || in->ino != st.st_ino) {
    in.reset();
    try {
      in = std::make_unique<Input>(io, fd, st);
    } catch (const boost::system::system_error&) {
      return nullptr;  // not a descriptor epoll takes (a regular file: always readable, seen by poll)
    }
  }
  return in.get();
}

void StationApp::Impl::arm_input(Input& i) {
  i.ready = false;
  if (i.pending) return;
  i.pending = true;
  i.d.async_wait(asio::posix::stream_descriptor::wait_read, [this, p = &i](const boost::system::error_code& ec) {
    ++own_runs;
    if (ec == asio::error::operation_aborted || in.get() != p) return;
    p->pending = false;
    p->ready = true;
  });
}

void StationApp::Impl::arm_deadline(term::Duration after) {
  deadline_hit = false;
  deadline.expires_after(after);  // a wait still pending from an earlier call ends aborted
  deadline.async_wait([this, gen = ++deadline_gen](const boost::system::error_code& ec) {
    ++own_runs;
    if (!ec && gen == deadline_gen) deadline_hit = true;
  });
}

// One blocking wait (run_one: epoll) until the input is readable, the deadline passes or the loop
// did some other work (a tick, a client's bytes, a timer): the callers look again and wait again.
// Nothing wakes the process while nothing is due; the tick timer is the wake-up at any --clock-rate.
bool StationApp::wait_readable(int fd, std::optional<term::Duration> timeout) {
  Impl& m = *impl_;
  asio::io_context& io = m.io;
  if (io.stopped()) io.restart();
  if (fd >= 0) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) > 0) {
      // Readable already (the descriptor's edge may be past), or hung up (a closed terminal stays
      // "readable" for ever): the loop's ready work runs first, so that a signal, the tick and the
      // clients are never starved by an input that is always there.
      io.poll();
      return true;
    }
  }
  if (timeout && *timeout <= term::Duration::zero()) {
    io.poll();
    return false;
  }
  Impl::Input* input = fd >= 0 ? m.input(fd) : nullptr;
  if (input) m.arm_input(*input);
  if (timeout) m.arm_deadline(*timeout);
  const auto done = [&](bool readable) {
    if (timeout && !m.deadline_hit) m.deadline.cancel();
    return readable;
  };
  for (;;) {
    const unsigned before = m.own_runs;
    if (io.stopped()) io.restart();
    io.run_one();
    if (input && input->ready) {
      input->ready = false;
      return done(true);
    }
    if (m.deadline_hit || m.own_runs == before) return done(false);
    // Only a wait of an earlier call ended (aborted): nothing happened yet.
  }
}

std::optional<std::string> StationApp::save() {
  Impl& m = *impl_;
  std::string err;
  nlohmann::json doc = store::to_json(m.model);
  doc["clock_offset_us"] = m.clock.offset().count();  // the clock as it runs (menu 5, TIME=, GPS)
  if (m.satrak) doc["satrak"] = satrak::to_json(m.satrak->settings());
  else if (!m.satrak_saved.is_null()) doc["satrak"] = m.satrak_saved;
  if (!m.file.save(doc, err)) {
    m.log->error("state not saved: {}", err);
    if (m.station) m.station->set_save_failure(err);
    tracker::Event e;
    e.kind = "save-failed";
    e.detail = err;
    m.emit(std::move(e));
    return err;
  }
  m.last_saved = m.clock.now();
  if (m.station && m.station->save_failure()) {
    m.log->info("state saved again: memory and disk agree");
    m.station->set_save_failure(std::nullopt);
  }
  return std::nullopt;
}

void StationApp::start_gps() {
  Impl& m = *impl_;
  if (m.model.gps.source.empty()) return;
  std::string why;
  const auto endpoint = gps::parse_gps_spec(m.model.gps.source, why);
  if (!endpoint) {  // the state reader checked it: not reached
    m.log->error("GPS: {}", why);
    return;
  }
  m.gps = std::make_unique<gps::Monitor>(endpoint->text());
  if (m.station) m.station->set_gps(m.gps.get());
  m.log->info("GPS: {} (the station {} the receiver, threshold {:.0f} m)", endpoint->text(),
              m.model.gps.follow ? "follows" : "does not follow", m.model.gps.threshold_m);
  gps::GpsdClient::Sink sink;
  sink.link = [&m](gps::Link l, const std::string& detail) {
    m.log_notes(m.gps->on_link(l, detail));
    m.show_status();
  };
  sink.devices = [&m](int n) {
    m.log_notes(m.gps->on_devices(n));
    m.show_status();
  };
  sink.report = [&m, this](const gps::Report& r) { m.on_gps_report(r, *this); };
  m.gps_client = std::make_unique<gps::GpsdClient>(
      *endpoint, [&m](std::function<void()> f) { asio::post(m.io, std::move(f)); }, std::move(sink));
}

const gps::Monitor* StationApp::gps() const { return impl_->gps.get(); }

void StationApp::stop_gps() {
  impl_->gps_client.reset();
  if (impl_->station) impl_->station->set_gps(nullptr);
}

// --service: what the stored configuration says to track: the operator's last choice
// (model.tracking: a satellite, or multiple tracking in the stored normal or priority sub-mode);
// without one, the first multi_count satellites of the tracking list in multiple tracking when the
// list holds two or more, else the satellite marked '*' (or #1) alone.
void StationApp::Impl::start_stored_tracking() {
  const store::Database& db = model.db;
  const store::TrackingChoice& chosen = model.tracking;
  using Choice = store::TrackingChoice::Mode;
  std::optional<int> single;
  const auto body = chosen.catalog_number == 0 ? orbit::parse_body(chosen.name) : std::nullopt;
  if (chosen.mode == Choice::single && body) {
    single = tracker::target_index(*body);  // the Sun or the Moon (issue 58)
  } else if (chosen.mode == Choice::single) {
    for (std::size_t i = 0; i < db.satellites.size(); ++i)
      if (db.satellites[i].elements.catalog_number == chosen.catalog_number) single = static_cast<int>(i);
    if (!single)
      log->warn("service: {} (catalog number {}), the satellite last chosen, is no longer in the database: "
                "tracking the tracking list", chosen.name, chosen.catalog_number);
  }
  const bool multi = chosen.mode == Choice::multi || (chosen.mode == Choice::list && db.multi_count >= 2);
  if (single) {
    tracker.track_single(*single);
    log->info("service: tracking {}, as last chosen",
              body ? chosen.name : db.satellites[static_cast<std::size_t>(*single)].elements.name);
  } else if (db.selected.size() >= 2 && multi) {
    tracker.track_multi(model.priority_mode);
    log->info("service: multiple tracking of the first {} of the tracking list ({} mode)", db.multi_count,
              model.priority_mode ? "priority" : "normal");
  } else if (const auto marked = db.marked_index()) {
    tracker.track_single(*marked);
    log->info("service: tracking {}", db.satellites[static_cast<std::size_t>(*marked)].elements.name);
  } else if (!db.selected.empty()) {
    tracker.track_single(db.selected.front());
  } else {
    log->warn("service: the tracking list is empty: nothing to track");
  }
  if (station->rotor_control()) log->info("service: rotor control is on: the antenna follows");
  else log->warn("service: rotor control is off (E key, menu 6-R, --rotor-control on): the antenna will not move");
}

// SIGHUP: the newer element sets of the data directory's amateur.tle replace those of the same catalog
// numbers in the database (the operator refreshed the file); the rest stays as it is. Then the
// freq/mode file: the radio entries of the satellites it names; the operator's tracking list
// (which a 3-3 upload would rebuild in the file's order) stays as it is.
bool StationApp::Impl::reread_data(const std::string& data_dir) {
  const std::string path = data_dir + "/amateur.tle";
  const orbit::ParseResult parsed = orbit::load_elements_file(path);
  if (parsed.sets.empty()) {
    log->warn("SIGHUP: {} not used: {}", path,
              parsed.problems.empty() ? "no element set" : parsed.problems.front().message());
    return false;
  }
  // As the scheduled refresh does: newer sets of the same catalog numbers, the database's names kept.
  const std::string fm_path = freqmode_file(data_dir);
  const auto fm = radio::parse_freqmode(read_text(fm_path));
  for (const auto& problem : fm.problems) log->warn("SIGHUP: {}: {}", fm_path, problem.message());
  store::Database db = model.db;
  const store::RefreshReport report = store::apply_refresh(db, parsed.sets);
  log->info("SIGHUP: {} element set(s) updated from {} ({})", report.updated.size(), path, report.summary());
  std::size_t radio_entries = 0;
  if (!fm.records.empty()) {
    const store::FreqModeUpload up = store::apply_freqmode(db, fm.records);
    db.selected = model.db.selected;
    db.marked = model.db.marked;
    radio_entries = up.updated.size();
  }
  // One edit through the owner: stored, announced (the station tunes the radio afresh to the new
  // radio entries, the pass cache searches the new elements), saved.
  const store::EditResult r = owner.replace_database(
      std::move(db), store::bit(store::Area::elements) | store::bit(store::Area::radio_entries), "SIGHUP data",
      store::Origin::signal);
  if (!r.ok()) {
    log->warn("SIGHUP: {} and {} not used: {}", path, fm_path, *r.refusal);
    return false;
  }
  if (radio_entries) log->info("SIGHUP: radio entries of {} satellite(s) read from {}", radio_entries, fm_path);
  return true;
}

// SIGTERM: park first when parking is on (within two minutes), then the caller saves.
void StationApp::Impl::park_before_leaving(StationApp& app) {
  if (!model.rotator.parking_enabled || !station->rotor_control()) return;
  tracker.stop();
  if (!station->rotator().park()) return;
  log->info("service: parking the antenna");
  if (const auto w = parking_into_mask()) log->warn("antenna: parks into the horizon mask: {}", *w);
  run_until([this] { return station->rotator().status().on_target; }, std::chrono::minutes(2), app);
  log->info("service: antenna {}", station->rotator().status().on_target ? "parked" : "not parked in time");
}

void StationApp::on_hangup(std::function<void()> f) { impl_->on_hangup = std::move(f); }

std::string StationApp::resume_chosen_tracking() {
  Impl& m = *impl_;
  if (m.model.tracking.mode == store::TrackingChoice::Mode::list) return "";
  m.start_stored_tracking();
  const tracker::SatNow* f = m.tracker.followed();
  if (m.tracker.mode() == tracker::Mode::off) return "";
  return m.tracker.mode() == tracker::Mode::multi ? "Resumed: multiple tracking, as last chosen"
                                                  : "Resumed: tracking " + (f ? f->name : m.model.tracking.name) +
                                                        ", as last chosen";
}

int StationApp::run_service(const std::string& data_dir, const std::function<void()>& menus) {
  Impl& m = *impl_;
  m.unattended = true;
  m.start_stored_tracking();
  for (;;) {
    try {
      if (menus) menus();
      else m.run_forever();
    } catch (const Shutdown&) {
      if (m.last_signal == SIGHUP) {
        if (m.reread_data(data_dir)) save();
        if (m.on_hangup) m.on_hangup();
        m.arm_signals();
        continue;
      }
    }
    break;
  }
  m.arm_signals();
  m.park_before_leaving(*this);
  return 0;
}

}  // namespace tb::app
