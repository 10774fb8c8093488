#include "cli/tracker_config.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "live/build_info.h"
#include "cli/cli_defaults.h"
#include "rotator/registry.h"
#include "live/station_socket.h"
#include "gps/gpsd_client.h"
#include "logbook/logger.h"
#include "station/clock.h"
#include "menus/term/line_terminal.h"
#include "store/model.h"
#include "store/refresh.h"
#include "store/settings.h"
#include "store/state_file.h"
#include "orbit/horizon_mask.h"
#include "util/files.h"
#include "util/safe_text.h"
#include "util/secret.h"

namespace tb::app {

std::vector<OptionSpec> tracker_option_specs() {
  return {
      {"help", "", "this list"},
      {"version", "", "the program version"},
      {"state", "DIR", "state directory (default $XDG_STATE_HOME/trakbox)"},
      {"data", "DIR", "shipped data for a fresh start (default $TRAKBOX_DATA, else PREFIX/share/trakbox of an "
                      "installed trakbox, else the source tree's data/ for a build that is not installed)"},
      {"tty", "DEVICE", "run the menus as plain lines on this serial port (e.g. /dev/ttyS0); with --service, "
                        "the service's menus are there too"},
      {"baud", "N", "serial port speed with --tty: 1200, 2400, 4800, 9600 (default) or 19200, 8N1"},
      {"line", "", "plain lines on stdin/stdout even when they are a terminal"},
      {"standalone", "N", "track selector position N (1-15) with no menus: LCD and AOS LED"},
      {"service", "", "unattended (a system service): no terminal, no standard input; tracks the stored "
                      "tracking list, serves the enabled ports, logs to standard error too; SIGTERM parks "
                      "(when parking is on), saves and exits 0; SIGHUP re-reads the data directory's element and "
                      "freq/mode files and the endpoints' secret files"},
      {"clock", "ISO8601", "start the real-time clock at this UTC time (e.g. 2026-05-21T12:00:00Z)"},
      {"clock-rate", "R", "run the clock R times faster than real time, R at most 200 (with or without --clock)"},
      {"rotator", "SPEC", "simulated (default), hamlib:MODEL:DEVICE[:BAUD], rotctld:HOST[:PORT], easycomm3:DEVICE[:BAUD], "
                          "easycomm2:DEVICE[:BAUD], pstrotator:HOST[:PORT], satrak:HOST[:PORT] (trakbox --rotator list)"},
      {"radio", "SPEC", "simulated (default), a model MODEL:DEV[:BAUD] (ic9700, ic9100, ic910h, ft847, ft817, "
                        "ts2000 ...; `trakbox --radio list` prints them all), icom:DEV, kenwood:DEV, yaesu:DEV, "
                        "cat:DEV (rig of menu 6-7), hamlib:MODEL:DEV[:BAUD] (MODEL a number or a name such as "
                        "IC-9700), rigctld[:HOST[:PORT]], gqrx[:HOST[:PORT]] or sdrpp[:HOST[:PORT]] (receivers: "
                        "the downlink only)"},
      {"uplink-radio", "SPEC", "a second radio for the uplink, in the same forms as --radio (which then drives "
                               "the downlink); stored, so later starts use it too; none: one radio again"},
      {"dial-rest", "MS", "dial follow: the other link moves once the operator's knob has rested this many "
                          "milliseconds, 0 to 10000 (factory 1000; stored)"},
      {"doppler-step", "SSB,FM", "least Doppler change sent to the radio, Hz, for SSB/CW and for FM links, e.g. "
                                 "20,100 (the factory values; stored)"},
      {"record", "audio|iq|off", "the receiver (--radio gqrx or sdrpp) records each pass of the satellite it is tuned "
                                 "to, from AOS to LOS, over trakbox's own connection: audio, iq (GQRX with U "
                                 "IQRECORD) or off (the factory setting; stored; docs/radio.md)"},
      {"record-satellites", "NAME,...", "--record records only these satellites (names as in the database, "
                                        "comma-separated); none: every satellite (stored)"},
      {"tick-ms", "MS", "tracking interval in milliseconds, 100 to 1000 (default 1000)"},
      {"satrak-port", "N", "Satrak ACU protocol on TCP port N (default 4001; 0 turns it off)"},
      {"satrak-bind", "ADDR", "address the Satrak server listens on (default 127.0.0.1)"},
      {"rotctld-port", "N", "answer the rotctld protocol on TCP port N (4533 by convention; off by default)"},
      {"pst-port", "N", "take PstRotator's UDP commands on port N (12000 by convention; replies to the sender's "
                        "port N+1; off by default)"},
      {"rigctld-port", "N", "answer the rigctld protocol on TCP port N (4532 by convention; off by default)"},
      {"host-port", "N", "host mode (menu 7's commands) on TCP port N (off by default)"},
      {"http-port", "N", "the web page and its API (docs/web-api.md) on TCP port N (the service's is 8073; off by "
                         "default); beyond loopback only with --allow and --http-secret-file"},
      {"http-secret-file", "FILE", "the web page's login and the API's Authorization: Bearer take the secret on "
                                   "this file's first line"},
      {"http-public-view", "", "with --http-secret-file: anyone allowed may view the page; changes still need the "
                               "secret"},
      {"http-host", "NAME", "a name the web page answers to in the Host header beyond IP addresses and localhost "
                            "(the station's name on the LAN, or behind a proxy)", true},
      {"listen", "ADDR", "address the host, rotctld, rigctld and web servers listen on (default 127.0.0.1)"},
      {"rotctld-secret-file", "FILE", "rotctld clients must first send \\password with the secret on this file's "
                                      "first line (never on the command line)"},
      {"rigctld-secret-file", "FILE", "rigctld clients must first send \\password with the secret in FILE"},
      {"host-secret-file", "FILE", "host-mode clients must first send PASS with the secret in FILE"},
      {"auth-timeout", "S", "seconds a client of a port with a secret has to give it, 1 to 600 (default 10)"},
      {"allow", "CIDR", "only clients in this address range may connect to any TCP endpoint ("
                        "e.g. 192.168.1.0/24, 2001:db8::/32, 10.0.0.5); others are refused", true},
      {"guess-exempt", "CIDR", "wrong secrets from this address range are slowed but never lock it out (a trusted "
                               "station behind a shared address)", true},
      {"elements-url", "URL", "refresh the menu-3 database from this URL or file (e.g. CelesTrak's "
                              "gp.php?GROUP=amateur&FORMAT=json): sets of the same catalog number are updated. "
                              "Replaces the sources stored by menu 3-5", true},
      {"elements-refresh-hours", "H", "hours between element refreshes, 2 to 720 (default 12, or as stored)"},
      {"elements-timeout", "S", "seconds one element download may take, 1 to 600 (default 60)"},
      {"cross-limit-sector", "yes|no", "when the rotator limits split its travel (the rotor stop inside them): yes, "
                                       "they are pointing limits the antenna may cross between passes; no (the "
                                       "factory setting), they are barriers (stored)"},
      {"station", "LAT,LON[,HEIGHT_M]|LOCATOR", "the station's position (menu 4): degrees north and east, metres above "
                                                "the WGS-84 ellipsoid, or a Maidenhead locator's centre (stored)"},
      {"az-travel", "DEG", "azimuth travel from the rotor stop, 360 to 720: 360 (the factory setting), 450 for an "
                           "overlap rotator such as a G-5500 or a GS-232 in 450-degree mode (stored)"},
      {"rotor-control", "on|off", "on: the antenna follows the satellite tracked, from the start (a service moves "
                                  "it with nobody attached); off: it stays where it is (the E key, menu 6-R; stored)"},
      {"handback", "S", "an outside client (rotctld, rigctld, Satrak) silent S seconds hands the antenna or the radio "
                        "back to trakbox's tracking, 0 to 86400, 0: only when it disconnects (default 30; stored)"},
      {"exclusive", "KIND", "rotctld, rigctld or satrak: while a client of that kind holds the antenna or the radio, "
                            "other clients' moves are refused; none (the factory setting): the latest takes it "
                            "(stored)"},
      {"satnogs-station", "ID", "the SatNOGS ground station sharing this antenna: its upcoming observations are read "
                                "every 10 minutes, anonymously, and trakbox's tracking yields in their windows; 0: "
                                "none (stored; docs/sharing.md)"},
      {"satnogs-url", "URL", std::string("the SatNOGS Network whose jobs --satnogs-station reads (default ") +
                                 "https://network.satnogs.org; stored)"},
      {"logger", "cloudlog:URL|wavelog:URL|none", "the logger the QSOs go to (api/qso, kept in a queue until it "
                                                  "has them) and the radio state while tracking (api/radio); none "
                                                  "removes it (stored; docs/logbook.md)"},
      {"logger-key-file", "FILE", "the file whose first line is the logger's API key, read at the start (the path "
                                  "is stored, never the key; keep it chmod 600)"},
      {"logger-station-id", "N", "the logger's station location (Cloudlog's station_profile_id), 1 to 1000000000 "
                                 "(stored)"},
      {"event-min-el", "DEG", "no AOS/LOS event nor hook for a pass whose maximum elevation stays under DEG, "
                              "-2 to 90 (factory 0: none for a pass that never rises; stored)"},
      {"horizon-mask", "FILE|none", "where roofs, trees or hills hide the sky: AZ EL per line (.hrz), a CSV az,el "
                                    "or a step list AZ EL ... AZ; passes, AOS/LOS and pre-positioning keep above it "
                                    "(the points are stored, not the file; none removes it)"},
      {"socket", "PATH", "the station's socket for trakbox attach, status and events (default STATE/" +
                             std::string(kSocketFile) + "; the system service's is " + std::string(kServiceSocket) +
                             "), made for the user and group only"},
      {"on-event", "[KIND,...=]CMD", "run CMD (with /bin/sh) on every event, or on the kinds named: aos, los, "
                                     "recording, elements, link-lost, link-back, save-failed, control; the event is "
                                     "in its environment (TRAKBOX_EVENT, TRAKBOX_SATELLITE, TRAKBOX_AOS, ...; "
                                     "docs/service.md)", true},
      {"udp-events", "HOST:PORT", "send each event as one JSON datagram (the fields of trakbox events) to HOST:PORT, "
                                  "e.g. 192.168.1.20:9000 (stored, so later starts send there too; none: "
                                  "no more)", true},
      {"hook-timeout", "S", "seconds an --on-event command may run before it is killed, 1 to 3600 (default 60)"},
      {"event-lead", "S", "the AOS event comes S seconds before AOS, 0 to 3600 (default 0)"},
      {"gps", "SPEC", "a GPS receiver through gpsd: gpsd (localhost:2947), gpsd:HOST or gpsd:HOST:PORT; none: no "
                      "receiver (stored). Position, fix and time; the clock is checked against GPS time"},
      {"gps-follow", "yes|no", "yes: the station's position follows the receiver's confirmed fix (stored; menu 4)"},
      {"gps-threshold", "M", "metres the fix must move before the station follows, 1 to 100000 (default 100; "
                             "stored)"},
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

std::optional<spdlog::level::level_enum> log_level_named(const std::string& l) {
  if (l == "error") return spdlog::level::err;
  if (l == "warn") return spdlog::level::warn;
  if (l == "info") return spdlog::level::info;
  if (l == "debug") return spdlog::level::debug;
  return std::nullopt;
}

}  // namespace

std::optional<std::string> set_rotator_spec(TrackerConfig& c, const std::string& text) {
  // One table of rotators (rotator/registry.h) chooses the parser.
  rotator::RotatorParse rot = rotator::parse_rotator(text);
  if (!rot.error.empty()) return rot.error;
  c.rotator = rot.choice;
  return std::nullopt;
}

// --horizon-mask FILE: the file read and checked whole (a problem named with the file and line), its
// points as the setting keeps them; `none`: "" (no mask).
static std::optional<std::string> read_mask_file(const std::string& file, OptionReader& r) {
  if (file == "none") return std::string();
  const auto content = files::read_whole_file(file);
  if (!content) {
    r.fail("--horizon-mask", "cannot read " + file);
    return std::nullopt;
  }
  const auto read = orbit::read_horizon_mask(*content, file);
  if (!read.mask) {
    r.fail("--horizon-mask", read.error);
    return std::nullopt;
  }
  const std::string text = read.mask->text();
  if (const auto why = store::refusal(*store::find_setting("station.horizon_mask"), text)) {
    r.fail("--horizon-mask", *why);  // more points than the state keeps
    return std::nullopt;
  }
  return text;
}

std::optional<std::string> set_radio_spec(TrackerConfig& c, const std::string& text) {
  const auto radio_spec = radio::parse_radio_spec(text);
  if (!radio_spec.spec) return radio_spec.error;
  c.radio = *radio_spec.spec;
  return std::nullopt;
}

namespace {

// A stored setting given on the command line, read and refused by the settings table's rule and
// sentence (store/settings.h): "--event-min-el: event_min_el_deg: 91 is outside -2 .. 90 deg".
std::optional<nlohmann::json> stored_option(const ParsedOptions& o, OptionReader& r, const char* name,
                                            std::string_view key) {
  const auto v = o.value(name);
  if (!v) return std::nullopt;
  const store::ParsedSetting p = store::parse_setting(*store::find_setting(key), *v);
  if (!p.value) {
    r.fail(OptionReader::option_label(name), p.error);
    return std::nullopt;
  }
  return p.value;
}
template <typename T>
std::optional<T> stored_value(const ParsedOptions& o, OptionReader& r, const char* name, std::string_view key) {
  const auto v = stored_option(o, r, name, key);
  if (!v) return std::nullopt;
  return v->get<T>();
}

// The device specs, checked before anything starts.
void read_devices(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  c.rotator_text = o.value("rotator");
  c.radio_text = o.value("radio");
  if (const auto err = set_rotator_spec(c, c.rotator_text.value_or("simulated"))) r.fail("--rotator", *err);
  if (const auto err = set_radio_spec(c, c.radio_text.value_or("simulated"))) r.fail("--radio", *err);
  if (const auto up = o.value("uplink-radio")) {
    c.uplink_radio_text = *up == "none" ? "" : *up;
    if (!c.uplink_radio_text->empty()) {
      const auto up_spec = radio::parse_radio_spec(*up, "--uplink-radio");
      if (!up_spec.spec) r.fail("--uplink-radio", up_spec.error);
      c.uplink_radio = up_spec.spec;
    }
  }
}

// The endpoints' secrets, each for a server that is on.
void read_secrets(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  if (const auto v = r.integer("auth-timeout", false, "seconds, 1 to 600", Range{1, 600})) c.auth_timeout_s = static_cast<int>(*v);
  struct Endpoint {
    const char* option;
    const char* port_option;
    bool on;
    std::string& secret;
    std::string& file;
  };
  const Endpoint endpoints[] = {
      {"rotctld-secret-file", "rotctld-port", c.rotctld_port.has_value(), c.rotctld_secret, c.secret_files.rotctld},
      {"rigctld-secret-file", "rigctld-port", c.rigctld_port.has_value(), c.rigctld_secret, c.secret_files.rigctld},
      {"host-secret-file", "host-port", c.host_port.has_value(), c.host_secret, c.secret_files.host},
      {"http-secret-file", "http-port", c.http_port.has_value(), c.http_secret, c.secret_files.http}};
  for (const Endpoint& e : endpoints) {
    const auto path = o.value(e.option);
    if (!path) continue;
    const std::string label = std::string("--") + e.option;
    if (!e.on) {
      r.fail(label, std::string("the server is off (give --") + e.port_option + ")");
      continue;
    }
    std::string error, warning;
    if (const auto s = secret::read_file(*path, error, warning)) e.secret = *s, e.file = *path;
    else r.fail(label, error);
    if (!warning.empty()) c.warnings.push_back(warning);
  }
}

// The scheduled element refresh: its sources and interval, checked as menu 3-5 checks them.
void read_refresh(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  store::RefreshSettings probe;
  for (const std::string& url : o.values("elements-url")) {
    if (const auto why = store::add_refresh_source(probe, url)) r.fail("--elements-url", *why);
    else c.elements_urls.push_back(url);
  }
  if (const auto h = stored_value<double>(o, r, "elements-refresh-hours", "refresh.interval_hours"))
    c.elements_refresh_hours = *h;
  if (const auto v = r.integer("elements-timeout", false, "seconds, 1 to 600", Range{1, 600}))
    c.elements_timeout_s = static_cast<int>(*v);
}

// The GPS receiver: its gpsd, whether the station follows it, and how far it must move first.
// --handback, --exclusive, --satnogs-station, --satnogs-url (issue 44, docs/sharing.md); --logger,
// --logger-key-file, --logger-station-id (issue 45, docs/logbook.md).
void read_sharing(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  c.handback_s = stored_value<int>(o, r, "handback", "sharing.handback_s");
  c.satnogs_station = stored_value<int>(o, r, "satnogs-station", "sharing.satnogs_station");
  c.satnogs_url = stored_value<std::string>(o, r, "satnogs-url", "sharing.satnogs_url");
  if (const auto l = o.value("logger")) {
    const logbook::LoggerSpecParse p = logbook::parse_logger_spec(*l);
    if (!p.error.empty()) r.fail("--logger", p.error.substr(std::string_view("--logger: ").size()));
    else c.logger = p.none ? std::string() : logbook::logger_spec_text(*p.spec);
  }
  if (const auto f = o.value("logger-key-file")) {
    if (f->empty()) r.fail("--logger-key-file", "a file is expected");
    else c.logger_key_file = std::filesystem::absolute(*f).lexically_normal().string();
  }
  c.logger_station_id = stored_value<int>(o, r, "logger-station-id", "logger.station_id");
  if (const auto x = stored_value<std::string>(o, r, "exclusive", "sharing.exclusive")) c.exclusive = *x == "none" ? "" : *x;
}

void read_gps(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  if (const auto g = o.value("gps")) {
    std::string why;
    if (*g == "none") c.gps_source = "";
    else if (const auto e = gps::parse_gps_spec(*g, why)) c.gps_source = e->text();
    else r.fail("--gps", why);
  }
  c.gps_follow = stored_value<bool>(o, r, "gps-follow", "gps.follow");
  c.gps_threshold_m = stored_value<double>(o, r, "gps-threshold", "gps.threshold_m");
}

// --doppler-step SSB,FM: two whole numbers of Hz, each within what the state file takes.
void read_doppler_steps(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  const auto v = o.value("doppler-step");
  if (!v) return;
  const auto comma = v->find(',');
  if (comma == std::string::npos) {
    r.fail("--doppler-step", "\"" + *v + "\": expected SSB,FM in Hz, e.g. 20,100 (" +
                                 store::range_text(*store::find_setting("radio.doppler_step_ssb_hz")) + " and " +
                                 store::range_text(*store::find_setting("radio.doppler_step_fm_hz")) + ")");
    return;
  }
  // Each by the table's rule: "--doppler-step: radio.doppler_step_fm_hz: 5 is outside 10 .. 10000 Hz".
  const store::ParsedSetting ssb = store::parse_setting(*store::find_setting("radio.doppler_step_ssb_hz"), v->substr(0, comma));
  const store::ParsedSetting fm = store::parse_setting(*store::find_setting("radio.doppler_step_fm_hz"), v->substr(comma + 1));
  if (!ssb.value) r.fail("--doppler-step", ssb.error);
  else if (!fm.value) r.fail("--doppler-step", fm.error);
  else c.doppler_steps = std::pair<radio::Hz, radio::Hz>{ssb.value->get<radio::Hz>(), fm.value->get<radio::Hz>()};
}

// --allow ADDRESS[/PREFIX]...: who may connect to the servers.
void read_allow(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  for (const std::string& a : o.values("allow")) {
    if (const auto cidr = inet::parse_cidr(a)) {
      c.allow.push_back(*cidr);
      if (inet::has_host_bits(*cidr))
        c.warnings.push_back("--allow " + a + ": the address has bits set beyond /" + std::to_string(cidr->prefix) +
                             "; the whole range is allowed, as if the host bits were zero");
    } else {
      r.fail("--allow", "expected an address or ADDRESS/PREFIX (192.168.1.0/24, ::1, ::ffff:192.0.2.0/120); found '" +
                            a + "'");
    }
  }
  for (const std::string& a : o.values("guess-exempt")) {
    if (const auto cidr = inet::parse_cidr(a)) c.guess_exempt.push_back(*cidr);
    else r.fail("--guess-exempt", "expected an address or ADDRESS/PREFIX (192.0.2.7, 2001:db8:1::/64); found '" + a + "'");
  }
}

// The web endpoint beyond loopback: only for the --allow ranges, and only with a secret.
void check_web(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  c.http_public_view = o.has("http-public-view");
  for (const std::string& n : o.values("http-host")) {
    const bool name = !n.empty() && n.size() <= 253 && n.front() != '.' && n.front() != '-' &&
                      std::all_of(n.begin(), n.end(), [](char ch) {
                        return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                               ch == '-' || ch == '.';
                      });
    if (!name) r.fail("--http-host", "expected a host name of letters, digits, '-' and '.' (no port); found '" +
                                         text::visible_bytes(n.substr(0, 60)) + "'");
    else if (!c.http_port) r.fail("--http-host", "the web server is off (give --http-port)");
    else c.http_hosts.push_back(n);
  }
  if (c.http_public_view && !o.has("http-secret-file"))
    r.fail("--http-public-view", "only with --http-secret-file (without a secret everyone allowed may do anything)");
  if (!c.http_port || inet::is_loopback(o.value("listen").value_or("127.0.0.1"))) return;
  if (c.allow.empty() || !o.has("http-secret-file"))
    r.fail("--http-port", "listening on " + o.value("listen").value_or("") +
                              " (beyond loopback) needs --allow ranges and --http-secret-file (docs/security.md)");
}

// Front ends that cannot go together.
void check_front_end(const ParsedOptions& o, OptionReader& r, FrontEnd front_end) {
  const bool service = o.has("service");
  for (const char* other : {"line", "standalone"})
    if (service && o.has(other)) r.fail("--service", std::string("not with --") + other + " (a service has no terminal)");
  if (service && front_end == FrontEnd::host) r.fail("--service", "not with trakbox host");
  if (front_end == FrontEnd::host && (o.has("tty") || o.has("standalone")))
    r.fail(o.has("tty") ? "--tty" : "--standalone", "not with trakbox host (host mode talks on stdin/stdout)");
}

// --udp-events: every destination checked before any is kept; "none" alone clears the stored ones.
void read_udp_events(const ParsedOptions& o, OptionReader& r, TrackerConfig& c) {
  const std::vector<std::string> given = o.values("udp-events");
  if (given.empty()) return;
  std::vector<UdpTarget> targets;
  for (const std::string& u : given) {
    std::string why;
    if (u == "none") {
      if (given.size() > 1) return r.fail("--udp-events", "'none' clears the destinations: not with others");
    } else if (auto t = inet::parse_host_port(u, why)) {
      targets.push_back(std::move(*t));
    } else {
      return r.fail("--udp-events", "'" + u + "': " + why);
    }
  }
  if (targets.size() > store::kMaxUdpEvents)
    return r.fail("--udp-events", "at most " + std::to_string(store::kMaxUdpEvents) + " destinations");
  c.udp_events = std::move(targets);
}

}  // namespace

ConfigOutcome parse_tracker_config(const std::vector<std::string>& args, FrontEnd front_end) {
  const auto specs = tracker_option_specs();
  const ParseOutcome parsed = parse_options(args, specs);
  if (parsed.error) return ConfigOutcome::refuse(parsed.error->text());
  const ParsedOptions& o = parsed.options;
  if (o.has("help"))
    return ConfigOutcome::text("usage: trakbox [options]                 the TrakBox menus on the simulated station\n"
                     "       trakbox propagate|schedule|passes|next|elements ...   orbit commands (--help each)\n"
                     "       trakbox attach|status|events ...   the running station (--help each)\n"
                     "       trakbox settings [set KEY VALUE | reset KEY]   every stored setting (--help)\n"
                     "       trakbox standby on|off, trakbox reserve START END [NOTE], trakbox log ...\n"
                     "       trakbox track SAT [--mode NAME]   the running station tracks SAT in that mode\n"
                     "       trakbox host, trakbox satrak HOST:PORT CMD   host mode; a Satrak ACU's client\n\n" +
                     describe_options(specs));
  if (o.has("version")) return ConfigOutcome::text(std::string("trakbox ") + kVersion + "\n");
  if (!o.positional().empty()) return ConfigOutcome::refuse("unexpected argument '" + o.positional().front() + "'");

  TrackerConfig c;
  c.front_end = front_end;
  OptionReader r(o);
  const auto baud = r.integer("baud", false, "1200, 2400, 4800, 9600 or 19200");
  if (baud && !term::valid_terminal_baud(static_cast<int>(*baud)))
    r.fail("--baud", "expected 1200, 2400, 4800, 9600 or 19200; found '" + *o.value("baud") + "'");
  if (baud) c.baud = static_cast<int>(*baud);
  if (const auto v = r.integer("standalone", false, "a selector position 1 to 15", Range{1, 15}))
    c.standalone = static_cast<int>(*v);
  // The simulated rotator and the tracker follow simulated time up to this rate (the event loop
  // ticks every 100 ms of simulated time, at least every few ms of wall time: docs/rotator.md).
  c.clock_rate = r.number("clock-rate", false, "a rate > 0 and at most 200 (1 is real time; 200 is the fastest "
                          "the tracker and the simulated rotator follow)", Range{0.0, station::kMaxClockRate, true});
  c.dial_rest_ms = stored_value<int>(o, r, "dial-rest", "radio.dial_rest_ms");
  read_doppler_steps(o, r, c);
  if (const auto v = r.integer("tick-ms", false, "milliseconds, 100 to 1000", Range{100, 1000}))
    c.tick_ms = static_cast<int>(*v);
  if (const auto v = r.integer("satrak-port", false, "a TCP port 0 to 65535 (0: off)", Range{0, 65535})) {
    c.satrak_port = static_cast<int>(*v);
    c.satrak_port_explicit = true;
  }
  // A one-shot `trakbox host` (commands on stdin) serves nothing: no Satrak port unless asked for,
  // so it never races a running station for 4001 (issue 39).
  if (front_end == FrontEnd::host && !c.satrak_port_explicit) c.satrak_port = 0;
  auto port = [&r](const char* name, std::optional<int>& out) {
    if (const auto v = r.integer(name, false, "a TCP port 1 to 65535", Range{1, 65535})) out = static_cast<int>(*v);
  };
  port("rotctld-port", c.rotctld_port);
  if (const auto v = r.integer("pst-port", false, "a UDP port 1 to 65534", Range{1, 65534})) c.pst_port = static_cast<int>(*v);
  port("rigctld-port", c.rigctld_port);
  port("host-port", c.host_port);
  port("http-port", c.http_port);
  if (const auto t = o.value("clock")) {
    c.clock_start = orbit::parse_iso8601(*t);
    if (!c.clock_start) r.fail("--clock", "expected an ISO 8601 UTC time like 2026-05-21T12:00:00Z; found '" + *t + "'");
  }
  read_devices(o, r, c);
  c.cross_limit_sector = stored_value<bool>(o, r, "cross-limit-sector", "rotator.cross_limit_sector");
  if (const auto x = o.value("station")) {
    const store::ParsedPosition p = store::parse_position(*x);
    if (p.ok()) c.station = TrackerConfig::Position{p.lat_deg, p.lon_deg, p.height_m};
    else r.fail("--station", p.error);
  }
  c.az_travel_deg = stored_value<double>(o, r, "az-travel", "rotator.az_travel_deg");
  c.rotor_control = stored_value<bool>(o, r, "rotor-control", "rotor_control");
  c.event_min_el_deg = stored_value<double>(o, r, "event-min-el", "event_min_el_deg");
  if (const auto f = o.value("horizon-mask")) c.horizon_mask = read_mask_file(*f, r);
  c.record = stored_value<std::string>(o, r, "record", "radio.record");
  c.record_satellites = stored_value<std::string>(o, r, "record-satellites", "radio.record_satellites");
  read_sharing(o, r, c);
  read_gps(o, r, c);
  if (const auto l = o.value("log-level")) {
    if (const auto level = log_level_named(*l)) c.log_level = *level;
    else r.fail("--log-level", "expected error, warn, info or debug; found '" + *l + "'");
  }
  if (o.has("tty") && o.has("line")) r.fail("--line", "not with --tty (a serial port is always plain lines)");
  read_allow(o, r, c);
  for (const std::string& h : o.values("on-event")) {
    std::string why;
    if (auto hook = parse_event_hook(h, why)) c.hooks.push_back(std::move(*hook));
    else r.fail("--on-event", why);
  }
  read_udp_events(o, r, c);
  if (const auto v = r.integer("hook-timeout", false, "seconds, 1 to 3600", Range{1, 3600}))
    c.hook_timeout_s = static_cast<int>(*v);
  if (const auto v = r.integer("event-lead", false, "seconds, 0 to 3600", Range{0, 3600}))
    c.event_lead_s = static_cast<int>(*v);
  check_front_end(o, r, front_end);
  read_secrets(o, r, c);
  read_refresh(o, r, c);
  check_web(o, r, c);
  if (!r.ok()) return ConfigOutcome::refuse(r.error()->text());

  c.tty = o.value("tty");
  c.line = o.has("line");
  c.service = o.has("service");
  c.satrak_bind = o.value("satrak-bind").value_or("127.0.0.1");
  c.listen = o.value("listen").value_or("127.0.0.1");
  c.state_dir = o.value("state") ? std::filesystem::path(*o.value("state")) : store::default_state_directory();
  c.data_dir = o.value("data").value_or(default_data_directory());
  c.socket = o.value("socket").value_or(socket_for_state(c.state_dir.string()));
  return ConfigOutcome::run(std::move(c));
}

}  // namespace tb::app
