// `trakbox [options]` and `trakbox host`: run_tracker reads the configuration (tracker_config.h),
// then runs named steps in order: the state directory and the log, the state (the battery-backed
// RAM test), the station with its drivers, the remote-control servers, the front end (menus,
// standalone, host mode or the unattended service), and the final save.
#include "app/tracker_app.h"

#include "app/log_guard.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include "cli/attach_client.h"
#include "live/attach_server.h"
#include "live/build_info.h"
#include "live/event_hooks.h"
#include "live/log_requests.h"
#include "app/secret_reload.h"
#include "app/servers.h"
#include "live/state_lock.h"
#include "live/station_app.h"
#include "live/status.h"
#include "live/logger_upload.h"
#include "live/satnogs_poll.h"
#include "live/station_command.h"
#include "live/udp_events.h"
#include "menus/menus.h"
#include "menus/standalone.h"
#include "menus/term/curses_terminal.h"
#include "menus/term/line_terminal.h"
#include "netctl/host_server.h"
#include "netctl/pst_server.h"
#include "netctl/server.h"
#include "satrak/server.h"
#include "satrak/unit.h"
#include "station/clock.h"
#include "app/stored_drivers.h"
#include "rotator/config.h"
#include "store/drivers.h"
#include "tracker/elements_refresh.h"
#include "tracker/events.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "web/access.h"
#include "web/api.h"
#include "web/server.h"

namespace tb::app {
namespace {

int usage_error(const std::string& text) {
  std::fprintf(stderr, "trakbox: %s (see trakbox --help)\n", text.c_str());
  return kExitUsage;
}

// The state directory, created 0700 when new: the state document holds the element downloads'
// credentials. The error when it cannot be created.
std::optional<std::string> prepare_state_dir(const std::filesystem::path& state_dir) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(state_dir, ec);
  std::filesystem::create_directories(state_dir, ec);
  if (ec) return "--state " + state_dir.string() + ": cannot create: " + ec.message();
  if (!existed) std::filesystem::permissions(state_dir, std::filesystem::perms::owner_all, ec);
  return std::nullopt;
}

// trakbox.log in the state directory (and standard error for a service: the journal reads it and
// stamps the time itself), made the default logger: drivers and servers log there, never on the
// terminal the menus own.
std::shared_ptr<spdlog::logger> open_log(const TrackerConfig& c) {
  LogFile file = open_log_file(c.state_dir, LogLimits{});
  std::vector<spdlog::sink_ptr> sinks;
  if (file.sink) sinks.push_back(std::move(file.sink));
  if (c.service || !file.notes.empty()) {
    auto err = std::make_shared<spdlog::sinks::stderr_sink_mt>();
    err->set_pattern("trakbox[%l]: %v");
    sinks.push_back(std::move(err));
  }
  // Every line passes the guard: credentials scrubbed, floods of one kind of line counted, not written.
  auto guarded = std::make_shared<GuardedSink>(std::move(sinks), LogLimits{});
  auto log = std::make_shared<spdlog::logger>("trakbox", guarded);
  log->set_level(c.log_level);
  log->flush_on(std::min(c.log_level, spdlog::level::info));  // a debug log is read while it grows
  spdlog::set_default_logger(log);
  for (const auto& note : file.notes) log->warn("{}", note);
  return log;
}

// What the start found in the state directory.
struct Startup {
  store::Model model;
  satrak::Settings satrak_settings;
  nlohmann::json satrak_saved;     // data["satrak"] as stored
  bool fresh = false;              // no state yet
  bool ram_lost = false;           // the state did not load: defaults, the damaged file kept aside
  std::string kept;                // where it was kept
  std::vector<std::string> notes;  // shown to the operator (and logged by a service)
  std::vector<std::string> drivers_said;  // the stored drivers in use: under the sign-on banner
};

// The battery-backed RAM test: the stored state, or factory defaults with the shipped database.
Startup load_state(store::StateFile& file, const TrackerConfig& c, spdlog::logger& log) {
  Startup s;
  // A save killed midway leaves its temporary file; an older trakbox wrote the state readable by all.
  for (const auto& stale : store::remove_stale_temporaries(c.state_dir))
    log.info("removed {}, left by a save that did not finish", stale.string());
  for (const auto& note : file.tighten_permissions()) log.warn("{}", note);
  const store::LoadOutcome loaded = file.load();
  s.fresh = loaded.kind == store::LoadOutcome::Kind::fresh;
  if (loaded.kind == store::LoadOutcome::Kind::loaded) {
    try {
      s.model = store::model_from_json(loaded.data);
      if (loaded.data.contains("satrak")) {
        s.satrak_settings = satrak::settings_from_json(loaded.data["satrak"]);
        s.satrak_saved = loaded.data["satrak"];
      }
      return s;
    } catch (const std::exception& e) {
      s.ram_lost = true;
      s.kept = file.keep_aside().string();
      log.error("state {}: {}", file.path().string(), e.what());
      s.notes.push_back(std::string("(") + e.what() + ")");
    }
  } else if (loaded.kind == store::LoadOutcome::Kind::corrupt) {
    s.ram_lost = true;
    s.kept = loaded.kept_aside.string();
    log.error("{}", loaded.reason);
    s.notes.push_back("(" + loaded.reason + ")");
  }
  s.model = defaults_with_data(c.data_dir, s.notes);
  if (s.model.db.satellites.empty()) {
    // A binary run away from its data (issue 39): where it looked, and how to say where they are,
    // on the screen (under the banner) and in the log, not only "the database is empty" later.
    const std::string said = "No shipped elements in " + c.data_dir + " (amateur.tle): the database is empty. Give "
                             "--data DIR (or TRAKBOX_DATA=DIR), or load elements with menu 3-3 or 3-5.";
    log.warn("{}", said);
    if (c.service) s.notes.push_back(said);
    else s.drivers_said.push_back(said);
  }
  s.satrak_settings = satrak::Settings{};
  s.satrak_saved = nlohmann::json();
  return s;
}

// The clock as --clock/--clock-rate set it, the drivers the specs name, and the station on them.
std::optional<std::string> build_station(StationApp& app, const TrackerConfig& c) {
  if (c.clock_start) app.clock().start_at(*c.clock_start, c.clock_rate.value_or(1.0));
  else if (c.clock_rate) app.clock().start_at(station::system_now(), *c.clock_rate);
  radio::MakeRadio made = radio::make_radios(c.radio, c.uplink_radio, app.model().radio);
  if (!made.driver) return "--radio: " + made.error;
  std::unique_ptr<rotator::RotatorDriver> rot =
      rotator::make_rotator(c.rotator, {app.clock(), rotator::SimulatedRotatorParams::matching(app.model().rotator)});
  const std::string rot_name = rot->description();
  app.build_station(std::move(rot), std::move(made.driver));
  app.log().info("rotator: {}; radio: {}", rot_name, app.station().radio().describe());
  app.station().tick();  // the antenna's position is known before the first prompt
  return std::nullopt;
}

// The Satrak unit and server. A busy default port is a note; a port asked for is an error.
std::optional<std::string> start_satrak(StationApp& app, const TrackerConfig& c, Startup& s, Servers& out) {
  if (c.satrak_port == 0) return std::nullopt;
  satrak::UnitOptions uo;
  uo.tle_dir = c.state_dir / "tle";
  uo.image_dir = c.state_dir / "images";
  uo.version = kVersion;
  out.satrak_unit = std::make_unique<satrak::Unit>(app.io(), app.station(), app.model(), app.clock(), s.satrak_settings,
                                                   uo, satrak::UnitHooks{[&app] { return app.save(); }});
  satrak::ServerOptions so;
  so.address = c.satrak_bind;
  so.port = static_cast<unsigned short>(c.satrak_port);
  so.allow = c.allow;
  try {
    out.satrak = std::make_unique<satrak::Server>(app.io(), *out.satrak_unit, so);
    out.satrak_unit->start();
    app.set_satrak(out.satrak_unit.get());  // the server logs "satrak: listening on ..." itself
  } catch (const std::exception& e) {
    const std::string msg =
        "Satrak server not started on " + so.address + ":" + std::to_string(c.satrak_port) + ": " + e.what();
    app.log().error("{}", msg);
    if (c.satrak_port_explicit) return "--satrak-port: " + msg;
    s.notes.push_back(msg);
    out.satrak_unit.reset();
  }
  return std::nullopt;
}

// The operator's terminal: stdin/stdout for host mode, the serial port of --tty, curses on a
// real terminal, else plain lines.
std::unique_ptr<term::Terminal> open_terminal(StationApp& app, const TrackerConfig& c, std::string& err) {
  auto wait = [&app](int fd, std::optional<term::Duration> t) { return app.wait_readable(fd, t); };
  if (c.front_end == FrontEnd::host) {
    auto t = std::make_unique<term::LineTerminal>(STDIN_FILENO, STDOUT_FILENO, wait, false);
    t->set_echo(false);
    return t;
  }
  if (c.tty) return term::LineTerminal::open_serial(*c.tty, c.baud.value_or(app.model().station.com_baud), wait, err);
  if (!c.line && ::isatty(STDIN_FILENO) && ::isatty(STDOUT_FILENO) && std::getenv("TERM"))
    return std::make_unique<term::CursesTerminal>(wait);
  return std::make_unique<term::LineTerminal>(STDIN_FILENO, STDOUT_FILENO, wait, false);
}

// The menus (or standalone tracking, or host mode) until the operator leaves or a signal comes.
void run_front_end(StationApp& app, const TrackerConfig& c, const Startup& s, term::Terminal& terminal) {
  menus::Services services{app.model(), app.clock(), app.tracker(), app.station(), [&app] { return app.save(); },
                           kVersion, {}};
  // Over a serial line the main menu's Q detaches: the line is the box's own terminal.
  if (c.tty) services.leave = menus::detach_serial_line;
  try {
    if (s.ram_lost) {
      terminal.line("Data in RAM was lost !! Set default parameter !");
      terminal.line("(the damaged state was kept as " + s.kept + ")");
    }
    for (const auto& n : s.notes) terminal.line(n);
    if (c.front_end == FrontEnd::host) menus::menu_7_host_mode(terminal, services);
    else if (c.standalone) menus::standalone(terminal, services, *c.standalone);
    else {
      menus::sign_on(terminal, services);
      for (const auto& line : s.drivers_said) terminal.line(line);
      if (const std::string resumed = app.resume_chosen_tracking(); !resumed.empty()) terminal.line(resumed);
      menus::main_menu(terminal, services);
    }
  } catch (const menus::InputClosed&) {
  } catch (const Shutdown&) {
  }
}

int run_service(StationApp& app, const TrackerConfig& c, const Startup& s, AttachServer* attach) {
  for (const auto& n : s.notes) app.log().warn("{}", n);
  if (s.ram_lost) app.log().error("Data in RAM was lost !! Set default parameter ! (the damaged state was kept as {})", s.kept);
  if (!attach) return app.run_service(c.data_dir);
  // The menus for attached terminals, on the station's loop; with nobody attached they wait at
  // their prompt as the box's did with no terminal plugged in.
  return app.run_service(c.data_dir, [&app, attach] {
    term::Terminal& t = attach->terminal();
    app.set_terminal(&t);
    // Attached, the main menu's Q detaches (it never stops the service).
    menus::Services services{app.model(), app.clock(), app.tracker(), app.station(), [&app] { return app.save(); },
                             kVersion, menus::detach_attached};
    for (;;) {
      try {
        menus::sign_on(t, services);
        menus::main_menu(t, services);
        // The operator left the main menu: attached, leaving is detaching; the menus start again
        // for the next one.
        attach->detach_keyboard();
      } catch (const menus::InputClosed&) {
      }
    }
  });
}

// A second trakbox on a state directory in use: at a terminal it attaches to the running one,
// anything else refuses (two processes on one state would both save it).
int state_in_use(const TrackerConfig& c, const LockHolder& holder, const std::string& error) {
  if (!error.empty()) {
    std::fprintf(stderr, "trakbox: %s\n", error.c_str());
    return kExitFailure;
  }
  const std::string who = "the state directory " + c.state_dir.string() + " is in use by a running trakbox" +
                          (holder.pid ? " (pid " + std::to_string(holder.pid) + ")" : std::string());
  const bool at_terminal = c.front_end == FrontEnd::menus && !c.service && !c.standalone && !c.tty;
  if (at_terminal && !holder.socket.empty()) {
    std::fprintf(stderr, "trakbox: %s: attaching to it (Ctrl-] detaches)\n", who.c_str());
    return attach_to(holder.socket, c.line);
  }
  std::fprintf(stderr, "trakbox: %s; not started, so that only one saves it%s\n", who.c_str(),
               holder.socket.empty() ? "" : ("; its menus: trakbox attach --socket " + holder.socket).c_str());
  return kExitFailure;
}

// The station's socket: status and events always, the menus too for a service. A socket that
// cannot be made is said and the station runs without it.
std::unique_ptr<AttachServer> open_socket(StationApp& app, const TrackerConfig& c, StateLock& lock,
                                          const Servers& servers) {
  AttachServerOptions o;
  o.path = c.socket;
  o.menus = c.service;
  // The server itself, once made (who is attached is part of the status).
  auto self = std::make_shared<AttachServer*>(nullptr);
  o.status = [&app, &c, self, &servers] {
    StatusContext cx{kVersion, c.state_dir.string(), {}, {}, c.service, [&servers] { return servers_json(servers); }};
    if (*self) cx.attached = (*self)->attached(), cx.keyboard = (*self)->keyboard();
    return station_status(app, cx);
  };
  o.log = [requests = std::make_shared<LogRequests>(app)](const std::string& request,
                                                        std::function<void(std::string)> reply) {
    requests->handle(request, std::move(reply));
  };
  o.is_command = is_station_command;
  o.command = [&app](const std::string& line) { return run_station_command(app, line); };
  try {
    auto server = std::make_unique<AttachServer>(
        app.io(), [&app](int fd, std::optional<term::Duration> t) { return app.wait_readable(fd, t); }, o, app.log());
    *self = server.get();
    lock.announce(c.socket);
    app.log().info("socket {} (trakbox attach, status, events)", c.socket);
    return server;
  } catch (const std::exception& e) {
    app.log().warn("no attach socket: {}", e.what());
    std::fprintf(stderr, "trakbox: WARNING: no attach socket: %s\n", e.what());
    return nullptr;
  }
}

// --udp-events: the destinations stored (as the command line just set them, or as last given). One
// named on this command line that cannot be resolved stops the start (nothing is saved before); a
// stored one that cannot (a name while the network is down) is warned about and the station runs
// without them, so a service is not kept down by its logger.
std::optional<std::string> open_udp_events(StationApp& app, const TrackerConfig& c, spdlog::logger& log,
                                           std::unique_ptr<UdpEvents>& udp) {
  std::vector<UdpTarget> targets;
  for (const std::string& text : app.model().udp_events) {
    std::string why;
    if (auto t = inet::parse_host_port(text, why)) targets.push_back(std::move(*t));
  }
  if (targets.empty()) return std::nullopt;
  try {
    udp = std::make_unique<UdpEvents>(app.io(), targets, log);
  } catch (const std::exception& e) {
    if (c.udp_events) return std::string(e.what());
    log.warn("{} (stored; events go to no other computer: --udp-events none forgets them)", e.what());
    if (!c.service) std::fprintf(stderr, "trakbox: WARNING: %s (stored)\n", e.what());
  }
  return std::nullopt;
}

// What the command line sets over the stored state, through the model's one door (store/owner.h):
// each option checked as the state reader will check it at the next start (a value refused there
// is refused here, naming the option and the range), then stored. The drivers (stored_drivers.h;
// what that says goes to the log and where the operator sees it) and the GPS too.
std::optional<std::string> apply_command_line(TrackerConfig& c, store::ModelOwner& owner, Startup& startup,
                                              spdlog::logger& log) {
  using store::Origin;
  std::optional<std::string> refused;
  auto set = [&](const char* option, const char* key, const store::ModelOwner::Value& v) {
    if (refused) return;
    const store::EditResult r = owner.set(key, v, Origin::command_line);
    if (!r.ok()) refused = std::string("--") + option + ": " + *r.refusal;
  };
  if (c.cross_limit_sector) set("cross-limit-sector", "rotator.cross_limit_sector", *c.cross_limit_sector);
  if (c.station) {  // typed in, as menu 4 would: the GPS's position no longer stands for it
    const store::EditResult r =
        owner.set_position(c.station->lat_deg, c.station->lon_deg,
                           c.station->height_m.value_or(owner.model().station.height_m), Origin::command_line);
    if (!r.ok() && !refused) refused = "--station: " + *r.refusal;
  }
  if (c.az_travel_deg) set("az-travel", "rotator.az_travel_deg", *c.az_travel_deg);
  if (c.event_min_el_deg) set("event-min-el", "event_min_el_deg", *c.event_min_el_deg);
  if (c.horizon_mask) set("horizon-mask", "station.horizon_mask", *c.horizon_mask);
  if (c.record) set("record", "radio.record", *c.record);
  if (c.record_satellites) set("record-satellites", "radio.record_satellites", *c.record_satellites);
  if (c.handback_s) set("handback", "sharing.handback_s", static_cast<long long>(*c.handback_s));
  if (c.exclusive) set("exclusive", "sharing.exclusive", c.exclusive->empty() ? std::string("none") : *c.exclusive);
  if (c.satnogs_station) set("satnogs-station", "sharing.satnogs_station", static_cast<long long>(*c.satnogs_station));
  if (c.satnogs_url) set("satnogs-url", "sharing.satnogs_url", *c.satnogs_url);
  if (c.logger) set("logger", "logger.spec", *c.logger);
  if (c.logger_key_file) set("logger-key-file", "logger.key_file", *c.logger_key_file);
  if (c.logger_station_id) set("logger-station-id", "logger.station_id", static_cast<long long>(*c.logger_station_id));
  if (c.dial_rest_ms) set("dial-rest", "radio.dial_rest_ms", static_cast<long long>(*c.dial_rest_ms));
  if (c.doppler_steps) {
    set("doppler-step", "radio.doppler_step_ssb_hz", static_cast<long long>(c.doppler_steps->first));
    set("doppler-step", "radio.doppler_step_fm_hz", static_cast<long long>(c.doppler_steps->second));
  }
  if (c.gps_source) set("gps", "gps.source", *c.gps_source);
  if (c.gps_follow) set("gps-follow", "gps.follow", *c.gps_follow);
  if (c.gps_threshold_m) set("gps-threshold", "gps.threshold_m", *c.gps_threshold_m);
  if (c.elements_refresh_hours) set("elements-refresh-hours", "refresh.interval_hours", *c.elements_refresh_hours);
  if (c.rotor_control) set("rotor-control", "rotor_control", *c.rotor_control);
  if (refused) return refused;
  std::vector<std::string> said;
  if (c.rotor_control)
    said.push_back(*c.rotor_control ? "rotor control on (--rotor-control, stored): the antenna follows the satellite "
                                      "tracked"
                                    : "rotor control off (--rotor-control, stored): the antenna stays where it is");
  if (auto err = apply_stored_drivers(c, owner, said)) return err;
  for (const auto& line : said) {
    log.info("{}", line);
    if (c.service) continue;
    if (c.front_end == FrontEnd::host) std::fprintf(stderr, "trakbox: %s\n", line.c_str());
    else startup.drivers_said.push_back(line);
  }
  if (c.udp_events) {
    std::vector<std::string> targets;
    for (const UdpTarget& t : *c.udp_events) targets.push_back(inet::host_port_text(t));
    const store::EditResult r = owner.edit(store::bit(store::Area::other), "udp_events", Origin::command_line,
                                           [&](store::Model& m) { m.udp_events = targets; });
    if (!r.ok()) return "--udp-events: " + *r.refusal;
  }
  if (!c.elements_urls.empty()) {
    // --elements-url replaces the stored sources (keeping the validators of a URL that stays).
    std::vector<store::RefreshSource> sources;
    for (const std::string& url : c.elements_urls) {
      store::RefreshSource src{url, "", ""};
      for (const auto& old : owner.model().refresh.sources)
        if (old.url == url) src = old;
      sources.push_back(src);
    }
    const store::EditResult r = owner.edit(store::bit(store::Area::other), "refresh sources", Origin::command_line,
                                           [&](store::Model& m) { m.refresh.sources = sources; });
    if (!r.ok()) return "--elements-url: " + *r.refusal;
  }
  return std::nullopt;
}

}  // namespace

// The element refresh's bound of one download (its sources and interval are stored settings,
// set by apply_command_line).
void configure_refresh(StationApp& app, const TrackerConfig& c) {
  app.refresh().set_timeout(std::chrono::seconds(c.elements_timeout_s));
}

int run_tracker(const std::vector<std::string>& args, FrontEnd front_end) {
  const ConfigOutcome outcome = parse_tracker_config(args, front_end);
  if (outcome.error) return usage_error(*outcome.error);
  if (!outcome.config) {
    std::fputs(outcome.print.c_str(), stdout);
    return kExitOk;
  }
  TrackerConfig c = *outcome.config;
  if (auto err = prepare_state_dir(c.state_dir)) return usage_error(*err);
  LockHolder holder;
  std::string lock_error;
  std::optional<StateLock> lock = StateLock::take(c.state_dir, holder, lock_error);
  if (!lock) return state_in_use(c, holder, lock_error);
  auto log = open_log(c);
  store::StateFile file(c.state_dir);
  Startup startup = load_state(file, c, *log);
  store::ModelOwner owner(std::move(startup.model),
                          startup.fresh || startup.ram_lost ? store::Origin::defaults : store::Origin::state);
  if (auto err = apply_command_line(c, owner, startup, *log)) return usage_error(*err);

  // "trakbox stopped" is the log's last line: written after the station, its drivers' workers and
  // the servers are gone, whose last words (a link closing) came after it before (issue 30).
  struct StoppedLine {
    std::shared_ptr<spdlog::logger> log;
    bool started = false;
    ~StoppedLine() {
      if (started) log->info("trakbox stopped");
    }
  } stopped_line{log};
  StationApp app(std::move(owner), file, log);
  if (auto err = build_station(app, c)) return usage_error(*err);
  const std::unique_ptr<tracker::Logging> logging = open_logging(app, c.state_dir, c.data_dir);
  configure_refresh(app, c);
  app.start_gps();
  app.set_satrak_saved(startup.satrak_saved);
  Servers servers;
  if (auto err = start_satrak(app, c, startup, servers)) return usage_error(*err);
  if (auto err = start_netctl(app, c, servers)) return usage_error(*err);
  warn_open_endpoints(c, servers, *log);
  for (const auto& w : c.warnings) {
    log->warn("{}", w);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", w.c_str());
  }
  std::unique_ptr<AttachServer> attach = open_socket(app, c, *lock, servers);
  if (auto err = start_web(app, c, servers, attach.get())) return usage_error(*err);
  std::vector<SecretEndpoint> secrets = secret_endpoints(c, servers);
  app.on_hangup([&secrets, &log] { reload_secrets(secrets, *log); });
  if (c.service && c.tty) {
    // The box's serial port: the service's menus there as well, for good.
    if (!attach) return usage_error("--tty: the service's menus need its socket");
    std::string err;
    const int fd = term::LineTerminal::open_serial_fd(*c.tty, c.baud.value_or(app.model().station.com_baud), err);
    if (fd < 0) return usage_error(err);
    attach->add_serial(fd, *c.tty);
  }
  EventHooks hooks(app.io(), c.hooks, std::chrono::seconds(c.hook_timeout_s), *log);
  std::unique_ptr<UdpEvents> udp;
  if (auto err = open_udp_events(app, c, *log, udp)) return usage_error(*err);
  const auto satnogs = start_satnogs(app, c.rigctld_port, std::chrono::seconds(c.elements_timeout_s), *log);
  std::unique_ptr<LoggerUpload> logger;
  if (auto err = start_logger(app, *logging, std::chrono::seconds(c.elements_timeout_s), logger)) {
    // Named on this command line: bad input, refused. Stored from an earlier run (the key file gone
    // since): the station still tracks and tunes; the QSOs stay queued and status says why.
    if (c.logger || c.logger_key_file || c.logger_station_id) return usage_error(*err);
    logger_not_started(app.model().logger, *logging, *err, *log);
  }
  app.set_events(
      [&](const tracker::Event& e) {
        const nlohmann::json j = tracker::to_json(e);
        // Named, not repeated: the detail (a link's fault) is logged by whoever met it.
        log->info("event: {}{}", e.kind, e.satellite.empty() ? "" : " " + e.satellite);
        hooks.fire(e);
        if (attach) attach->publish(j);
        if (servers.web) servers.web->publish_event(j);
        if (udp) udp->send(j);
      },
      std::chrono::seconds(c.event_lead_s));
  app.start(std::chrono::milliseconds(c.tick_ms));
  // Stored options given on the command line are stored now, not only at the next save.
  if (startup.ram_lost || startup.fresh || c.rotor_control || c.event_min_el_deg || c.az_travel_deg || c.handback_s || c.exclusive ||
      c.satnogs_station || c.satnogs_url || c.station || c.logger || c.logger_key_file || c.logger_station_id ||
      c.record || c.record_satellites)
    app.save();
  log->info("trakbox {} started, state {}", kVersion, file.path().string());
  stopped_line.started = true;

  int code = kExitOk;
  if (c.service) {
    code = run_service(app, c, startup, attach.get());
    app.set_terminal(nullptr);
  } else {
    std::string err;
    std::unique_ptr<term::Terminal> terminal = open_terminal(app, c, err);
    if (!terminal) return usage_error(err);
    app.set_terminal(terminal.get());
    terminal->status(app.station().status_line());
    run_front_end(app, c, startup, *terminal);
    app.set_terminal(nullptr);
  }
  servers.close_listeners();
  if (auto err = app.save()) {
    if (!c.service) std::fprintf(stderr, "trakbox: state not saved: %s\n", err->c_str());
    code = kExitFailure;
  }
  app.set_events({}, {});
  app.set_satrak(nullptr);
  servers.satrak_unit.reset();
  app.stop_gps();
  attach.reset();
  return code;
}

}  // namespace tb::app
