#include "app/tracker_app.h"

#include <poll.h>
#include <unistd.h>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include "app/build_info.h"
#include "menus/menus.h"
#include "menus/standalone.h"
#include "menus/term/curses_terminal.h"
#include "menus/term/line_terminal.h"
#include "netctl/host_server.h"
#include "netctl/server.h"
#include "radio/factory.h"
#include "rotator/factory.h"
#include "satrak/client.h"
#include "satrak/server.h"
#include "satrak/unit.h"
#include "store/state_file.h"
#include "tracker/station_loop.h"
#include "util/cidr.h"

namespace tb::app {
namespace asio = boost::asio;

std::vector<OptionSpec> tracker_option_specs() {
  return {
      {"help", "", "this list"},
      {"version", "", "the program version"},
      {"state", "DIR", "state directory (default $XDG_STATE_HOME/trakbox)"},
      {"data", "DIR", "shipped data for a fresh start (default $TRAKBOX_DATA, else PREFIX/share/trakbox of an "
                      "installed trakbox, else the source tree's data/ for a build that is not installed)"},
      {"tty", "DEVICE", "run the menus as plain lines on this serial port (e.g. /dev/ttyS0)"},
      {"baud", "N", "serial port speed with --tty: 1200, 2400, 4800, 9600 (default) or 19200, 8N1"},
      {"line", "", "plain lines on stdin/stdout even when they are a terminal"},
      {"standalone", "N", "track selector position N (1-15) with no menus: LCD and AOS LED"},
      {"service", "", "unattended (a system service): no terminal, no standard input; tracks the stored "
                      "tracking list, serves the enabled ports, logs to standard error too; SIGTERM parks "
                      "(when parking is on), saves and exits 0; SIGHUP re-reads the data directory's element and "
                      "freq/mode files"},
      {"clock", "ISO8601", "start the real-time clock at this UTC time (e.g. 2026-05-21T12:00:00Z)"},
      {"clock-rate", "R", "run the clock R times faster than real time (with or without --clock)"},
      {"rotator", "SPEC", "simulated (default), hamlib:MODEL:DEVICE[:BAUD], rotctld:HOST[:PORT]"},
      {"radio", "SPEC", "simulated (default), icom:DEV, kenwood:DEV, yaesu:DEV, cat:DEV (rig of menu 6-7), "
                        "hamlib:MODEL:DEV[:BAUD], rigctld[:HOST[:PORT]]"},
      {"tick-ms", "MS", "tracking interval in milliseconds, 100 to 1000 (default 1000)"},
      {"satrak-port", "N", "Satrak ACU protocol on TCP port N (default 4001; 0 turns it off)"},
      {"satrak-bind", "ADDR", "address the Satrak server listens on (default 127.0.0.1)"},
      {"rotctld-port", "N", "answer the rotctld protocol on TCP port N (4533 by convention; off by default)"},
      {"rigctld-port", "N", "answer the rigctld protocol on TCP port N (4532 by convention; off by default)"},
      {"host-port", "N", "host mode (menu 7's commands) on TCP port N (off by default)"},
      {"listen", "ADDR", "address the host, rotctld and rigctld servers listen on (default 127.0.0.1)"},
      {"allow", "CIDR", "only clients in this address range may connect to any TCP endpoint (repeatable; "
                        "e.g. 192.168.1.0/24, 2001:db8::/32, 10.0.0.5); others are refused", true},
      {"log-level", "LEVEL", "what trakbox.log in the state directory keeps: error, warn, info (default) or "
                             "debug (every remote command and its reply)"},
  };
}

std::string default_data_directory() {
  if (const char* d = std::getenv("TRAKBOX_DATA"); d && *d) return d;
  // Installed: PREFIX/bin/trakbox finds PREFIX/share/trakbox. Only a binary that runs from the build
  // tree it was built in takes the source tree's data/; an installed one never opens the checkout.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return TRAKBOX_DATA_DIR;
  const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "trakbox";
  const std::string build_dir = TRAKBOX_BUILD_DIR;
  const bool in_build_tree = exe.string().rfind(build_dir + "/", 0) == 0;
  if (in_build_tree && !std::filesystem::exists(installed / "amateur.tle", ec)) return TRAKBOX_DATA_DIR;
  return installed.string();
}

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Factory defaults plus the shipped database (what a fresh TrakBox with a loaded database is).
store::Model defaults_with_data(const std::string& data_dir, std::vector<std::string>& notes) {
  store::Model m = store::factory_defaults();
  const auto sets = orbit::load_elements_file(data_dir + "/amateur.tle");
  for (const auto& p : sets.problems) notes.push_back(p.message());
  const auto fm = radio::parse_freqmode(read_text(data_dir + "/freqmode.txt"));
  for (const auto& p : fm.problems) notes.push_back(data_dir + "/freqmode.txt: " + p.message());
  m.db = store::make_database(sets.sets, fm.records);
  return m;
}

struct Shutdown {};

class App {
 public:
  App(store::Model model, store::StateFile file, std::shared_ptr<spdlog::logger> log)
      : model_(std::move(model)), file_(std::move(file)), log_(std::move(log)), tracker_(model_, clock_) {
    clock_.set_offset(model_.clock_offset);
  }

  station::RealTimeClock& clock() { return clock_; }
  store::Model& model() { return model_; }

  void build_station(std::unique_ptr<rotator::RotatorDriver> rot, std::unique_ptr<radio::RadioDriver> rad) {
    auto controller = std::make_unique<rotator::Controller>(model_.rotator, model_.station.rotor_start, std::move(rot));
    station_ = std::make_unique<tracker::StationLoop>(model_, clock_, tracker_, std::move(controller), std::move(rad));
    station_->on_wake([this] {
      if (started_) arm_tick(std::chrono::milliseconds(0));
    });
  }
  tracker::StationLoop& station() { return *station_; }

  void start(std::chrono::milliseconds tick) {
    tick_ = tick;
    arm_signals();
    schedule_tick();
  }
  // SIGTERM, SIGINT and SIGHUP end the wait of the front end (Shutdown); last_signal() says which.
  void arm_signals() {
    signals_.async_wait([this](const boost::system::error_code& ec, int sig) {
      if (ec) return;
      last_signal_ = sig;
      log_->info("signal {}: {}", sig, sig == SIGHUP && unattended_ ? "re-reading the elements" : "saving and leaving");
      throw Shutdown{};
    });
  }
  int last_signal() const { return last_signal_; }
  void set_unattended(bool on) { unattended_ = on; }
  std::shared_ptr<spdlog::logger> log() { return log_; }
  // Runs the event loop until `done` holds or `limit` passes (steady time).
  void run_until(const std::function<bool()>& done, std::chrono::milliseconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!done() && std::chrono::steady_clock::now() < end) wait_readable(-1, std::chrono::milliseconds(50));
  }

  // The terminal's way of waiting: run the event loop until fd is readable or the timeout passes.
  bool wait_readable(int fd, std::optional<term::Duration> timeout) {
    const auto deadline = timeout ? std::optional(std::chrono::steady_clock::now() + *timeout) : std::nullopt;
    for (;;) {
      if (io_.stopped()) io_.restart();
      io_.poll();
      int ms = 20;
      if (deadline) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - std::chrono::steady_clock::now());
        ms = static_cast<int>(std::clamp<long long>(left.count(), 0, 20));
      }
      if (fd >= 0) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, ms) > 0) return true;
      } else if (ms > 0) {
        ::usleep(static_cast<useconds_t>(ms) * 1000);
      }
      if (deadline && std::chrono::steady_clock::now() >= *deadline) return false;
    }
  }

  void run_forever() {
    for (;;) {
      if (io_.stopped()) io_.restart();
      io_.run_one();
    }
  }

  void set_terminal(term::Terminal* t) { terminal_ = t; }

  std::optional<std::string> save() {
    model_.clock_offset = clock_.offset();
    std::string err;
    nlohmann::json doc = store::to_json(model_);
    if (satrak_) doc["satrak"] = satrak::to_json(satrak_->settings());
    else if (!satrak_saved_.is_null()) doc["satrak"] = satrak_saved_;
    if (!file_.save(doc, err)) {
      log_->error("state not saved: {}", err);
      return err;
    }
    return std::nullopt;
  }

  tracker::Tracker& tracker() { return tracker_; }
  boost::asio::io_context& io() { return io_; }
  // Settings of the Satrak unit, persisted beside the model (data["satrak"]).
  void set_satrak(satrak::Unit* unit) { satrak_ = unit; }

 private:
  void schedule_tick() { arm_tick(std::min(station_->next_tick_in(), tick_)); }
  // (Re)arms the tick timer; a wait already pending is cancelled (its handler sees the abort).
  void arm_tick(std::chrono::milliseconds in) {
    started_ = true;
    timer_.expires_after(in);
    timer_.async_wait([this](const boost::system::error_code& ec) {
      if (ec) return;
      station_->tick();
      if (terminal_) terminal_->status(station_->status_line());
      schedule_tick();
    });
  }

  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_ = asio::make_work_guard(io_);
  asio::signal_set signals_{io_, SIGTERM, SIGHUP, SIGINT};
  asio::steady_timer timer_{io_};
  std::chrono::milliseconds tick_{1000};
  bool started_ = false;  // the tick timer runs (start() was called)
  int last_signal_ = 0;
  bool unattended_ = false;
  store::Model model_;
  store::StateFile file_;
  std::shared_ptr<spdlog::logger> log_;
  station::RealTimeClock clock_;
  tracker::Tracker tracker_;
  std::unique_ptr<tracker::StationLoop> station_;
  term::Terminal* terminal_ = nullptr;
  satrak::Unit* satrak_ = nullptr;

 public:
  nlohmann::json satrak_saved_;  // kept as loaded when the Satrak server is off
};

int usage_error(const std::string& text) {
  std::fprintf(stderr, "trakbox: %s (see trakbox --help)\n", text.c_str());
  return kExitUsage;
}

}  // namespace

namespace {

// --service: what the stored configuration says to track. The first multi_count satellites of the
// tracking list in multiple tracking (the stored normal or priority sub-mode) when the list holds
// two or more; else the satellite marked '*' (or #1) alone.
void start_stored_tracking(App& app) {
  const store::Database& db = app.model().db;
  if (db.selected.size() >= 2 && db.multi_count >= 2) {
    app.tracker().track_multi(app.model().priority_mode);
    app.log()->info("service: multiple tracking of the first {} of the tracking list ({} mode)", db.multi_count,
                    app.model().priority_mode ? "priority" : "normal");
  } else if (const auto m = db.marked_index()) {
    app.tracker().track_single(*m);
    app.log()->info("service: tracking {}", db.satellites[static_cast<std::size_t>(*m)].elements.name);
  } else if (!db.selected.empty()) {
    app.tracker().track_single(db.selected.front());
  } else {
    app.log()->warn("service: the tracking list is empty: nothing to track");
  }
  if (!app.station().rotor_control())
    app.log()->warn("service: rotor control is off (E key): the antenna will not move");
}

// SIGHUP: the element sets of the data directory's amateur.tle replace those of the same catalog
// numbers in the database (the operator refreshed the file); the rest stays as it is.
void reread_elements(App& app, const std::string& data_dir) {
  const std::string path = data_dir + "/amateur.tle";
  const orbit::ParseResult parsed = orbit::load_elements_file(path);
  if (parsed.sets.empty()) {
    app.log()->warn("SIGHUP: {} not used: {}", path,
                    parsed.problems.empty() ? "no element set" : parsed.problems.front().message());
    return;
  }
  int updated = 0;
  for (auto& sat : app.model().db.satellites)
    for (const auto& e : parsed.sets)
      if (e.catalog_number == sat.elements.catalog_number && !(e.epoch_year == sat.elements.epoch_year && e.epoch_day == sat.elements.epoch_day)) {
        sat.elements = e;
        ++updated;
      }
  app.log()->info("SIGHUP: {} element set(s) updated from {}", updated, path);
  // The freq/mode file: the radio entries of the satellites it names; the operator's tracking list
  // (which a 3-3 upload would rebuild in the file's order) stays as it is.
  const std::string fm_path = data_dir + "/freqmode.txt";
  const auto fm = radio::parse_freqmode(read_text(fm_path));
  for (const auto& problem : fm.problems) app.log()->warn("SIGHUP: {}: {}", fm_path, problem.message());
  if (!fm.records.empty()) {
    store::Database db = app.model().db;
    const store::FreqModeUpload up = store::apply_freqmode(db, fm.records);
    db.selected = app.model().db.selected;
    db.marked = app.model().db.marked;
    app.model().db = std::move(db);
    app.log()->info("SIGHUP: radio entries of {} satellite(s) read from {}", up.updated.size(), fm_path);
  }
  app.save();
}

// The unattended front end: tracks, serves, and waits for signals.
int run_service(App& app, const std::string& data_dir) {
  app.set_unattended(true);
  start_stored_tracking(app);
  for (;;) {
    try {
      app.run_forever();
    } catch (const Shutdown&) {
      if (app.last_signal() == SIGHUP) {
        reread_elements(app, data_dir);
        app.arm_signals();
        continue;
      }
    }
    break;
  }
  // SIGTERM: park first when parking is on (within two minutes), then the caller saves.
  app.arm_signals();
  if (app.model().rotator.parking_enabled && app.station().rotor_control()) {
    app.tracker().stop();
    if (app.station().rotator().park()) {
      app.log()->info("service: parking the antenna");
      app.run_until([&app] { return app.station().rotator().status().on_target; }, std::chrono::minutes(2));
      app.log()->info("service: antenna {}", app.station().rotator().status().on_target ? "parked" : "not parked in time");
    }
  }
  return kExitOk;
}

}  // namespace

int run_tracker(const std::vector<std::string>& args, FrontEnd front_end) {
  const auto specs = tracker_option_specs();
  const ParseOutcome parsed = parse_options(args, specs);
  if (parsed.error) return usage_error(parsed.error->text());
  const ParsedOptions& o = parsed.options;
  if (o.has("help")) {
    std::printf("usage: trakbox [options]                 the TrakBox menus on the simulated station\n"
                "       trakbox propagate|schedule|passes ...   non-interactive orbit commands (--help each)\n\n%s",
                describe_options(specs).c_str());
    return kExitOk;
  }
  if (o.has("version")) {
    std::printf("trakbox %s\n", kVersion);
    return kExitOk;
  }
  if (!o.positional().empty()) return usage_error("unexpected argument '" + o.positional().front() + "'");

  OptionReader r(o);
  const auto baud = r.integer("baud", false, "1200, 2400, 4800, 9600 or 19200");
  if (baud && !term::valid_terminal_baud(static_cast<int>(*baud)))
    r.fail("--baud", "expected 1200, 2400, 4800, 9600 or 19200; found '" + *o.value("baud") + "'");
  const auto standalone = r.integer("standalone", false, "a selector position 1 to 15", Range{1, 15});
  const auto rate = r.number("clock-rate", false, "a rate > 0 (1 is real time)", Range{0.0, 10000.0, true});
  const auto tick_ms = r.integer("tick-ms", false, "milliseconds, 100 to 1000", Range{100, 1000});
  const auto satrak_port = r.integer("satrak-port", false, "a TCP port 0 to 65535 (0: off)", Range{0, 65535});
  const auto rotctld_port = r.integer("rotctld-port", false, "a TCP port 1 to 65535", Range{1, 65535});
  const auto rigctld_port = r.integer("rigctld-port", false, "a TCP port 1 to 65535", Range{1, 65535});
  const auto host_port = r.integer("host-port", false, "a TCP port 1 to 65535", Range{1, 65535});
  std::optional<orbit::UtcTime> clock_start;
  if (const auto c = o.value("clock")) {
    clock_start = orbit::parse_iso8601(*c);
    if (!clock_start) r.fail("--clock", "expected an ISO 8601 UTC time like 2026-05-21T12:00:00Z; found '" + *c + "'");
  }
  // Device specs are checked before anything starts.
  const std::string rot_text = o.value("rotator").value_or("simulated");
  std::optional<satrak::SatrakRotatorOptions> satrak_rotator;
  rotator::SpecResult rot_spec;
  if (rot_text.rfind("satrak:", 0) == 0) {
    std::string err;
    satrak_rotator = satrak::parse_rotator_spec(rot_text, err);
    if (!satrak_rotator) r.fail("--rotator", err);
  } else {
    rot_spec = rotator::parse_rotator_spec(rot_text);
    if (!rot_spec.spec) r.fail("--rotator", rot_spec.error);
  }
  const auto radio_spec = radio::parse_radio_spec(o.value("radio").value_or("simulated"));
  if (!radio_spec.spec) r.fail("--radio", radio_spec.error);
  spdlog::level::level_enum log_level = spdlog::level::info;
  if (const auto l = o.value("log-level")) {
    if (*l == "error") log_level = spdlog::level::err;
    else if (*l == "warn") log_level = spdlog::level::warn;
    else if (*l == "info") log_level = spdlog::level::info;
    else if (*l == "debug") log_level = spdlog::level::debug;
    else r.fail("--log-level", "expected error, warn, info or debug; found '" + *l + "'");
  }
  if (o.has("tty") && o.has("line")) r.fail("--line", "not with --tty (a serial port is always plain lines)");
  std::vector<net::Cidr> allow;
  for (const std::string& a : o.values("allow")) {
    if (const auto c = net::parse_cidr(a)) allow.push_back(*c);
    else r.fail("--allow", "expected an address or ADDRESS/PREFIX (192.168.1.0/24, ::1); found '" + a + "'");
  }
  const bool service = o.has("service");
  for (const char* other : {"tty", "line", "standalone"})
    if (service && o.has(other)) r.fail("--service", std::string("not with --") + other + " (a service has no terminal)");
  if (service && front_end == FrontEnd::host) r.fail("--service", "not with trakbox host");
  if (front_end == FrontEnd::host && (o.has("tty") || o.has("standalone")))
    r.fail(o.has("tty") ? "--tty" : "--standalone", "not with trakbox host (host mode talks on stdin/stdout)");
  if (!r.ok()) return usage_error(r.error()->text());

  const std::filesystem::path state_dir = o.value("state") ? std::filesystem::path(*o.value("state"))
                                                           : store::default_state_directory();
  std::error_code ec;
  const bool state_dir_existed = std::filesystem::exists(state_dir, ec);
  std::filesystem::create_directories(state_dir, ec);
  if (ec) return usage_error("--state " + state_dir.string() + ": cannot create: " + ec.message());
  if (!state_dir_existed)  // 0700: the state document holds the element downloads' credentials
    std::filesystem::permissions(state_dir, std::filesystem::perms::owner_all, ec);

  std::vector<spdlog::sink_ptr> sinks{
      std::make_shared<spdlog::sinks::basic_file_sink_mt>((state_dir / "trakbox.log").string())};
  if (service) {  // the journal reads standard error; it stamps the time itself
    auto err = std::make_shared<spdlog::sinks::stderr_sink_mt>();
    err->set_pattern("trakbox[%l]: %v");
    sinks.push_back(std::move(err));
  }
  auto log = std::make_shared<spdlog::logger>("trakbox", sinks.begin(), sinks.end());
  log->set_level(log_level);
  log->flush_on(std::min(log_level, spdlog::level::info));  // a debug log is read while it grows
  spdlog::set_default_logger(log);  // drivers and servers log here, never on the terminal the UI owns

  // Battery-backed RAM test.
  store::StateFile file(state_dir);
  std::vector<std::string> startup_notes;
  const std::string data_dir = o.value("data").value_or(default_data_directory());
  store::Model model;
  bool ram_lost = false;
  std::string kept;
  // A save killed midway leaves its temporary file; an older trakbox wrote the state readable by all.
  for (const auto& stale : store::remove_stale_temporaries(state_dir))
    log->info("removed {}, left by a save that did not finish", stale.string());
  for (const auto& note : file.tighten_permissions()) log->warn("{}", note);
  const store::LoadOutcome loaded = file.load();
  satrak::Settings satrak_settings;
  nlohmann::json satrak_saved;
  if (loaded.kind == store::LoadOutcome::Kind::loaded) {
    try {
      model = store::model_from_json(loaded.data);
      if (loaded.data.contains("satrak")) {
        satrak_settings = satrak::settings_from_json(loaded.data["satrak"]);
        satrak_saved = loaded.data["satrak"];
      }
    } catch (const std::exception& e) {
      ram_lost = true;
      kept = file.keep_aside().string();
      log->error("state {}: {}", file.path().string(), e.what());
      startup_notes.push_back(std::string("(") + e.what() + ")");
    }
  } else if (loaded.kind == store::LoadOutcome::Kind::corrupt) {
    ram_lost = true;
    kept = loaded.kept_aside.string();
    log->error("{}", loaded.reason);
    startup_notes.push_back("(" + loaded.reason + ")");
  }
  if (loaded.kind != store::LoadOutcome::Kind::loaded || ram_lost) {
    model = defaults_with_data(data_dir, startup_notes);
    satrak_settings = satrak::Settings{};
    satrak_saved = nlohmann::json();
  }

  App app(std::move(model), file, log);
  if (clock_start) app.clock().start_at(*clock_start, rate.value_or(1.0));
  else if (rate) app.clock().start_at(station::system_now(), *rate);
  radio::MakeRadio made = radio::make_radio(*radio_spec.spec, app.model().radio);
  if (!made.driver) return usage_error("--radio: " + made.error);
  std::unique_ptr<rotator::RotatorDriver> rot_driver =
      satrak_rotator ? std::make_unique<satrak::SatrakRotator>(*satrak_rotator)
                     : rotator::make_rotator(*rot_spec.spec, app.clock(),
                                             rotator::SimulatedRotatorParams::matching(app.model().rotator));
  const std::string rot_name = rot_driver->description();
  app.build_station(std::move(rot_driver), std::move(made.driver));
  log->info("rotator: {}; radio: {}", rot_name, app.station().radio().describe());
  app.station().tick();  // the antenna's position is known before the first prompt
  app.satrak_saved_ = satrak_saved;

  // Remote control on the same event loop: the Satrak ACU protocol, rotctld/rigctld compatibles.
  std::unique_ptr<satrak::Unit> satrak_unit;
  std::unique_ptr<satrak::Server> satrak_server;
  std::unique_ptr<netctl::RotctldServer> rotctld;
  std::unique_ptr<netctl::RigctldServer> rigctld;
  std::unique_ptr<netctl::HostServer> host_server;
  const int sat_port = static_cast<int>(satrak_port.value_or(satrak::kDefaultPort));
  if (sat_port != 0) {
    satrak::UnitOptions uo;
    uo.tle_dir = state_dir / "tle";
    uo.image_dir = state_dir / "images";
    uo.version = kVersion;
    satrak_unit = std::make_unique<satrak::Unit>(app.io(), app.station(), app.model(), app.clock(), satrak_settings, uo,
                                                 satrak::UnitHooks{[&app] { return app.save(); }});
    satrak::ServerOptions so;
    so.address = o.value("satrak-bind").value_or("127.0.0.1");
    so.port = static_cast<unsigned short>(sat_port);
    so.allow = allow;
    try {
      satrak_server = std::make_unique<satrak::Server>(app.io(), *satrak_unit, so);
      satrak_unit->start();
      app.set_satrak(satrak_unit.get());
      log->info("Satrak server on {}:{}", so.address, satrak_server->port());
    } catch (const std::exception& e) {
      const std::string msg = "Satrak server not started on " + so.address + ":" + std::to_string(sat_port) + ": " + e.what();
      log->error("{}", msg);
      if (satrak_port) return usage_error("--satrak-port: " + msg);  // asked for explicitly: refuse
      startup_notes.push_back(msg);                                   // the default port is busy: say so, go on
      satrak_unit.reset();
    }
  }
  const std::string listen = o.value("listen").value_or("127.0.0.1");
  const char* starting = "";
  try {
    auto opts = [&listen, &allow](netctl::ServerOptions so) {
      so.address = listen;
      so.allow = allow;
      return so;
    };
    starting = "--rotctld-port";
    if (rotctld_port)
      rotctld = std::make_unique<netctl::RotctldServer>(app.io(), static_cast<std::uint16_t>(*rotctld_port), app.station(),
                                                         opts(netctl::RotctldServer::named("rotctld")));
    starting = "--rigctld-port";
    if (rigctld_port)
      rigctld = std::make_unique<netctl::RigctldServer>(app.io(), static_cast<std::uint16_t>(*rigctld_port), app.station(),
                                                         opts(netctl::RotctldServer::named("rigctld")));
    starting = "--host-port";
    if (host_port)
      host_server = std::make_unique<netctl::HostServer>(app.io(), static_cast<std::uint16_t>(*host_port), app.station(),
                                                          opts(netctl::HostServer::defaults()));
  } catch (const std::exception& e) {
    return usage_error(std::string(starting) + ": " + e.what());
  }
  // Beyond loopback with no allow-list, anyone who can reach a port can swing the antenna.
  const auto open_to_all = [&](const std::string& what, const std::string& address, bool on) {
    if (!on || !allow.empty() || net::is_loopback(address)) return;
    const std::string msg = what + " listens on " + address +
                            " for every address: anyone who can reach it can move the antenna and tune the radio "
                            "(name the stations with --allow CIDR; docs/security.md)";
    log->warn("{}", msg);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", msg.c_str());
  };
  open_to_all("the Satrak server", o.value("satrak-bind").value_or("127.0.0.1"), satrak_server != nullptr);
  open_to_all("the rotctld server", listen, rotctld != nullptr);
  open_to_all("the rigctld server", listen, rigctld != nullptr);
  open_to_all("the host-mode server", listen, host_server != nullptr);
  app.start(std::chrono::milliseconds(tick_ms.value_or(1000)));
  if (ram_lost || loaded.kind == store::LoadOutcome::Kind::fresh) app.save();
  log->info("trakbox {} started, state {}", kVersion, file.path().string());

  if (service) {
    for (const auto& n : startup_notes) log->warn("{}", n);
    if (ram_lost) log->error("Data in RAM was lost !! Set default parameter ! (the damaged state was kept as {})", kept);
    int code = run_service(app, data_dir);
    rotctld.reset();
    rigctld.reset();
    host_server.reset();
    satrak_server.reset();
    if (auto err = app.save()) code = kExitFailure;
    app.set_satrak(nullptr);
    satrak_unit.reset();
    log->info("trakbox stopped");
    return code;
  }

  auto wait = [&app](int fd, std::optional<term::Duration> t) { return app.wait_readable(fd, t); };
  std::unique_ptr<term::Terminal> terminal;
  if (front_end == FrontEnd::host) {
    terminal = std::make_unique<term::LineTerminal>(STDIN_FILENO, STDOUT_FILENO, wait, false);
    terminal->set_echo(false);
  } else if (const auto dev = o.value("tty")) {
    std::string err;
    terminal = term::LineTerminal::open_serial(*dev, static_cast<int>(baud.value_or(app.model().station.com_baud)), wait, err);
    if (!terminal) return usage_error(err);
  } else if (!o.has("line") && ::isatty(STDIN_FILENO) && ::isatty(STDOUT_FILENO) && std::getenv("TERM")) {
    terminal = std::make_unique<term::CursesTerminal>(wait);
  } else {
    terminal = std::make_unique<term::LineTerminal>(STDIN_FILENO, STDOUT_FILENO, wait, false);
  }
  app.set_terminal(terminal.get());
  terminal->status(app.station().status_line());

  menus::Services services{app.model(), app.clock(), app.tracker(), app.station(), [&app] { return app.save(); },
                           kVersion};
  int code = kExitOk;
  try {
    if (ram_lost) {
      terminal->line("Data in RAM was lost !! Set default parameter !");
      terminal->line("(the damaged state was kept as " + kept + ")");
    }
    for (const auto& n : startup_notes) terminal->line(n);
    if (front_end == FrontEnd::host) {
      menus::menu_7_host_mode(*terminal, services);
    } else if (standalone) {
      menus::standalone(*terminal, services, static_cast<int>(*standalone));
    } else {
      menus::sign_on(*terminal, services);
      menus::main_menu(*terminal, services);
    }
  } catch (const menus::InputClosed&) {
  } catch (const Shutdown&) {
  }
  app.set_terminal(nullptr);
  terminal.reset();
  rotctld.reset();
  rigctld.reset();
  host_server.reset();
  satrak_server.reset();
  if (auto err = app.save()) {
    std::fprintf(stderr, "trakbox: state not saved: %s\n", err->c_str());
    code = kExitFailure;
  }
  app.set_satrak(nullptr);
  satrak_unit.reset();
  log->info("trakbox stopped");
  return code;
}

}  // namespace tb::app
