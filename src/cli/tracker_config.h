// The options of `trakbox [options]` and `trakbox host`, read and checked before anything starts:
// every value has its type and range, device specs are parsed, combinations that cannot work are
// refused. Pure: arguments in, a TrackerConfig or a one-line error out (tests/unit/app).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <spdlog/common.h>

#include "live/event_hooks.h"
#include "cli/options.h"
#include "live/udp_events.h"
#include "orbit/time.h"
#include "radio/factory.h"
#include "rotator/registry.h"
#include "util/cidr.h"

namespace tb::app {

std::vector<OptionSpec> tracker_option_specs();

// How the program talks to its operator.
enum class FrontEnd {
  menus,  // the TrakBox menus (or standalone with --standalone)
  host,   // `trakbox host`: host mode (menu 7's command set) on stdin/stdout, no echo; Q ends
};

struct TrackerConfig {
  FrontEnd front_end = FrontEnd::menus;
  std::filesystem::path state_dir;  // --state, else the default state directory
  std::string data_dir;             // --data, else default_data_directory()
  std::optional<std::string> tty;   // --tty DEVICE
  std::optional<int> baud;          // --baud (else the station's COM speed)
  bool line = false;                // --line
  bool service = false;             // --service
  std::optional<int> standalone;    // --standalone N (1..15)
  std::optional<orbit::UtcTime> clock_start;
  std::optional<double> clock_rate;
  int tick_ms = 1000;
  // The rotator, as a row of the rotator registry read it (a driver spec or a Satrak ACU).
  rotator::RotatorChoice rotator;
  radio::RadioSpec radio;
  // --uplink-radio: a second radio's spec ("" for none); unset: the stored choice (menu 6-7).
  std::optional<std::string> uplink_radio_text;
  // The uplink radio to drive: --uplink-radio's, else the stored one (apply_stored_drivers), read
  // once; none: the radio carries both links.
  std::optional<radio::RadioSpec> uplink_radio;
  // --dial-rest, --doppler-step (SSB/CW, FM): the operating practice, stored in the model's radio.
  std::optional<int> dial_rest_ms;
  std::optional<std::pair<radio::Hz, radio::Hz>> doppler_steps;
  // --rotator and --radio as given; unset: the stored ones (store::Model::rotator_driver, ...).
  std::optional<std::string> rotator_text, radio_text;
  // Endpoints. satrak_port 0 is off; explicit says --satrak-port was given (a busy port is then an
  // error rather than a note).
  int satrak_port = 4001;
  bool satrak_port_explicit = false;
  std::string satrak_bind = "127.0.0.1";
  std::optional<int> rotctld_port, rigctld_port, host_port;
  std::optional<int> pst_port;   // --pst-port: PstRotator's UDP commands (12000 by convention); off by default
  std::string listen = "127.0.0.1";
  std::vector<inet::Cidr> allow;
  std::vector<inet::Cidr> guess_exempt;  // --guess-exempt: never locked out for wrong secrets
  // Shared secrets of the rotctld, rigctld and host-mode servers (read from --*-secret-file; empty:
  // none) and how long a client has to give one.
  std::string rotctld_secret, rigctld_secret, host_secret;
  // The files they came from, re-read on SIGHUP (secret_reload.h).
  struct SecretFiles {
    std::string rotctld, rigctld, host, http;
  } secret_files;
  // The web page and API (src/web): --http-port, its secret (--http-secret-file) and whether viewing
  // needs it (--http-public-view).
  std::optional<int> http_port;
  std::string http_secret;
  bool http_public_view = false;
  std::vector<std::string> http_hosts;  // --http-host: names the page answers to (issue 46)
  int auth_timeout_s = 10;
  // The scheduled element refresh: --elements-url (replaces the stored sources when given),
  // --elements-refresh-hours, --elements-timeout.
  std::vector<std::string> elements_urls;
  std::optional<double> elements_refresh_hours;
  int elements_timeout_s = 60;
  // --cross-limit-sector yes|no: whether limits that split the rotator's travel may be crossed
  // between passes (RotatorConfig::cross_limit_sector); stored in the state when given.
  std::optional<bool> cross_limit_sector;
  // --station LAT,LON[,HEIGHT_M]|LOCATOR: the station's position (menu 4's), stored when given.
  struct Position {
    double lat_deg = 0.0, lon_deg = 0.0;
    std::optional<double> height_m;  // none typed: the stored height stays (as host mode's QTH)
  };
  std::optional<Position> station;
  // --az-travel DEG: the rotator's azimuth travel from its stop (RotatorConfig::az_travel_deg: 450
  // for an overlap rotator); stored in the state when given.
  std::optional<double> az_travel_deg;
  // --rotor-control on|off: the E key's switch, stored (a service starts moving its antenna);
  // --event-min-el DEG: no AOS/LOS event for a pass whose maximum stays under it (stored).
  std::optional<bool> rotor_control;
  std::optional<double> event_min_el_deg;
  // --horizon-mask FILE|none: the mask's points as station.horizon_mask keeps them ("" none), stored.
  std::optional<std::string> horizon_mask;
  std::optional<std::string> record;              // --record: audio, iq or off (radio.record)
  std::optional<std::string> record_satellites;   // --record-satellites: names, "" every one
  // --handback S and --exclusive KIND (store::Sharing; "" for none), stored (issue 44).
  std::optional<int> handback_s;
  std::optional<std::string> exclusive;
  // --satnogs-station ID (0: none) and --satnogs-url URL, stored (issue 44).
  std::optional<int> satnogs_station;
  std::optional<std::string> satnogs_url;
  // --logger SPEC ("" for none; checked by logbook::parse_logger_spec), --logger-key-file FILE
  // (the path; the key is read at the start), --logger-station-id N: stored (issue 45).
  std::optional<std::string> logger;
  std::optional<std::string> logger_key_file;
  std::optional<int> logger_station_id;
  // The station's socket (attach, status, events): --socket, else STATE_DIR/trakbox.sock.
  std::string socket;
  // --on-event hooks, their time limit (--hook-timeout) and the AOS event's lead (--event-lead).
  std::vector<EventHook> hooks;
  // --udp-events HOST:PORT (repeatable; stored): nullopt keeps the stored destinations, an empty
  // list (--udp-events none) clears them.
  std::optional<std::vector<UdpTarget>> udp_events;
  int hook_timeout_s = 60;
  int event_lead_s = 0;
  // --gps gpsd[:HOST[:PORT]] (canonical "gpsd:HOST:PORT") or none (""), --gps-follow, --gps-threshold:
  // stored in the state when given (docs/gps.md).
  std::optional<std::string> gps_source;
  std::optional<bool> gps_follow;
  std::optional<double> gps_threshold_m;
  std::vector<std::string> warnings;  // e.g. a secret file others can read: said at start
  spdlog::level::level_enum log_level = spdlog::level::info;
};

// What the command line asks for: run with a configuration, print a text and exit 0 (--help,
// --version), or refuse with a usage error.
struct ConfigOutcome {
  std::optional<TrackerConfig> config;
  std::string print;                  // --help / --version text (config empty, error empty)
  std::optional<std::string> error;   // "--baud: expected ..." (exit kExitUsage)
  static ConfigOutcome run(TrackerConfig c) { return {std::move(c), {}, std::nullopt}; }
  static ConfigOutcome text(std::string t) { return {std::nullopt, std::move(t), std::nullopt}; }
  static ConfigOutcome refuse(std::string e) { return {std::nullopt, {}, std::move(e)}; }
};
ConfigOutcome parse_tracker_config(const std::vector<std::string>& args, FrontEnd front_end);

// Where the shipped data lives: --data, else $TRAKBOX_DATA, else PREFIX/share/trakbox of an installed
// binary, else (a binary in its own build tree) the source tree's data/.
std::string default_data_directory();

// Sets c's rotator (or Satrak rotator) / radio from a spec; the reason when it is not one.
std::optional<std::string> set_rotator_spec(TrackerConfig& c, const std::string& text);
std::optional<std::string> set_radio_spec(TrackerConfig& c, const std::string& text);

}  // namespace tb::app
