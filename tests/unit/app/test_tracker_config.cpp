// parse_tracker_config (cli/tracker_config.h): the options of `trakbox [options]` read and checked
// before anything starts, as a value the rest of run_tracker takes.
#include <doctest/doctest.h>

#include "cli/tracker_config.h"

using namespace tb::app;

namespace {
ConfigOutcome parse(std::vector<std::string> args, FrontEnd fe = FrontEnd::menus) {
  return parse_tracker_config(args, fe);
}
std::string error_of(std::vector<std::string> args, FrontEnd fe = FrontEnd::menus) {
  const auto o = parse(std::move(args), fe);
  return o.error.value_or("");
}
}  // namespace

TEST_CASE("no options: the simulated station on loopback with the default Satrak port") {
  const auto o = parse({"--state", "/tmp/x", "--data", "/tmp/d"});
  REQUIRE(o.config);
  const TrackerConfig& c = *o.config;
  CHECK(c.state_dir == "/tmp/x");
  CHECK(c.data_dir == "/tmp/d");
  CHECK(c.satrak_port == 4001);
  CHECK_FALSE(c.satrak_port_explicit);
  CHECK(c.satrak_bind == "127.0.0.1");
  CHECK(c.listen == "127.0.0.1");
  CHECK(c.tick_ms == 1000);
  REQUIRE(c.rotator.kind);
  CHECK(c.rotator.kind->name == "simulated");
  CHECK(c.rotator.rotator);
  CHECK_FALSE(c.rotator.satrak);
  CHECK(c.socket == "/tmp/x/trakbox.sock");
  CHECK_FALSE(c.rotctld_port);
  CHECK(c.allow.empty());
  CHECK(c.log_level == spdlog::level::info);
  CHECK_FALSE(c.service);
}

TEST_CASE("values are typed and ranged") {
  const auto o = parse({"--satrak-port", "0", "--rotctld-port", "4533", "--tick-ms", "250", "--standalone", "3",
                        "--clock", "2026-05-21T12:00:00Z", "--clock-rate", "20", "--allow", "192.168.1.0/24",
                        "--allow", "::1", "--log-level", "debug", "--rotator", "satrak:10.0.0.2:4001"});
  REQUIRE(o.config);
  CHECK(o.config->satrak_port == 0);
  CHECK(o.config->satrak_port_explicit);
  CHECK(o.config->rotctld_port == 4533);
  CHECK(o.config->tick_ms == 250);
  CHECK(o.config->standalone == 3);
  CHECK(o.config->clock_start);
  CHECK(o.config->clock_rate == 20.0);
  CHECK(o.config->allow.size() == 2);
  CHECK(o.config->log_level == spdlog::level::debug);
  REQUIRE(o.config->rotator.kind);
  CHECK(o.config->rotator.kind->name == "satrak");
  CHECK(o.config->rotator.satrak);
  CHECK_FALSE(o.config->rotator.rotator);
}

TEST_CASE("--az-travel: an overlap rotator's travel, 360 to 720 degrees") {
  const auto o = parse({"--az-travel", "450"});
  REQUIRE(o.config);
  CHECK(o.config->az_travel_deg == 450.0);
  CHECK_FALSE(parse({}).config->az_travel_deg);
  CHECK(error_of({"--az-travel", "300"}).rfind("--az-travel: ", 0) == 0);
  CHECK(error_of({"--az-travel", "many"}).rfind("--az-travel: ", 0) == 0);
}

TEST_CASE("--station: a locator's centre or LAT,LON[,HEIGHT_M]; a bad one named") {
  const auto loc = parse({"--station", "JN58td"});
  REQUIRE(loc.config);
  REQUIRE(loc.config->station);
  // JN58td: field J/N (0..20 E, 40..50 N), square 5/8, subsquare t/d: 11.625 E, 48.146 N at its centre.
  CHECK(loc.config->station->lat_deg == doctest::Approx(48.0 + 1.0 / 8 + 1.0 / 48).epsilon(1e-12));
  CHECK(loc.config->station->lon_deg == doctest::Approx(11.625).epsilon(1e-12));
  const auto ll = parse({"--station", "48.85N,2.35E,35"});
  REQUIRE(ll.config->station);
  CHECK(ll.config->station->lat_deg == 48.85);
  CHECK(ll.config->station->lon_deg == 2.35);
  CHECK(ll.config->station->height_m == 35.0);
  CHECK_FALSE(parse({}).config->station);
  CHECK(error_of({"--station", "nowhere"}).rfind("--station: ", 0) == 0);
  CHECK(error_of({"--station", "95,10"}).rfind("--station: ", 0) == 0);
}

TEST_CASE("the first bad value is named, and nothing is configured") {
  CHECK(error_of({"--baud", "300"}) == "--baud: expected 1200, 2400, 4800, 9600 or 19200; found '300'");
  CHECK(error_of({"--log-level", "loud"}) == "--log-level: expected error, warn, info or debug; found 'loud'");
  CHECK(error_of({"--allow", "10.0.0.0/33"}).rfind("--allow: ", 0) == 0);
  CHECK(error_of({"--clock", "yesterday"}).rfind("--clock: ", 0) == 0);
  CHECK(error_of({"--tick-ms", "50"}).rfind("--tick-ms: ", 0) == 0);
  // The fastest clock the tracker and the simulated rotator follow is stated and enforced.
  CHECK(error_of({"--clock-rate", "201"}) ==
        "--clock-rate: expected a rate > 0 and at most 200 (1 is real time; 200 is the fastest the tracker and "
        "the simulated rotator follow), found '201'");
  CHECK(parse({"--clock-rate", "200"}).config->clock_rate == 200.0);
  CHECK(error_of({"extra"}) == "unexpected argument 'extra'");
  // order: --baud is read before --log-level
  CHECK(error_of({"--log-level", "loud", "--baud", "300"}).rfind("--baud: ", 0) == 0);
  CHECK_FALSE(parse({"--baud", "300"}).config);
}

TEST_CASE("front ends that cannot go together are refused") {
  CHECK(error_of({"--tty", "/dev/ttyS0", "--line"}) == "--line: not with --tty (a serial port is always plain lines)");
  CHECK(error_of({"--service", "--line"}) == "--service: not with --line (a service has no terminal)");
  CHECK(error_of({"--service"}, FrontEnd::host) == "--service: not with trakbox host");
  CHECK(error_of({"--standalone", "2"}, FrontEnd::host) ==
        "--standalone: not with trakbox host (host mode talks on stdin/stdout)");
}

TEST_CASE("--help and --version are text to print, not a configuration") {
  const auto h = parse({"--help"});
  CHECK_FALSE(h.config);
  CHECK_FALSE(h.error);
  CHECK(h.print.find("--satrak-port N") != std::string::npos);
  CHECK(parse({"--version"}).print.rfind("trakbox ", 0) == 0);
}

TEST_CASE("--dial-rest and --doppler-step: the operating practice, checked before anything starts") {
  const auto o = parse({"--dial-rest", "1500", "--doppler-step", "30,250"});
  REQUIRE(o.config);
  CHECK(o.config->dial_rest_ms == 1500);
  CHECK(o.config->doppler_steps == std::pair<tb::radio::Hz, tb::radio::Hz>{30, 250});
  const auto none = parse({});
  REQUIRE(none.config);
  CHECK_FALSE(none.config->dial_rest_ms);
  CHECK_FALSE(none.config->doppler_steps);
  CHECK(error_of({"--dial-rest", "20000"}).rfind("--dial-rest: ", 0) == 0);
  CHECK(error_of({"--doppler-step", "20"}) ==
        "--doppler-step: \"20\": expected SSB,FM in Hz, e.g. 20,100 (10 .. 1000 Hz and 10 .. 10000 Hz)");
  // Each by the settings table's rule and sentence (store/settings.h).
  CHECK(error_of({"--doppler-step", "20,5"}) == "--doppler-step: radio.doppler_step_fm_hz: 5 is outside 10 .. 10000 Hz");
  CHECK(error_of({"--doppler-step", "20,5"}).rfind("--doppler-step: ", 0) == 0);
  CHECK(error_of({"--doppler-step", "x,100"}).rfind("--doppler-step: ", 0) == 0);
}

TEST_CASE("--rotor-control on|off and --event-min-el DEG are read, checked and optional (issue 39)") {
  const auto none = parse({});
  REQUIRE(none.config);
  CHECK_FALSE(none.config->rotor_control);
  CHECK_FALSE(none.config->event_min_el_deg);
  const auto on = parse({"--rotor-control", "on", "--event-min-el", "5"});
  REQUIRE(on.config);
  CHECK(on.config->rotor_control == true);
  CHECK(on.config->event_min_el_deg == 5.0);
  const auto off = parse({"--rotor-control", "off", "--event-min-el", "-2"});
  REQUIRE(off.config);
  CHECK(off.config->rotor_control == false);
  CHECK(off.config->event_min_el_deg == -2.0);
  CHECK(error_of({"--rotor-control", "maybe"}) == "--rotor-control: rotor_control: 'maybe': expected on or off");
  CHECK(error_of({"--event-min-el", "91"}) == "--event-min-el: event_min_el_deg: 91 is outside -2 .. 90 deg");
  CHECK(error_of({"--event-min-el", "-3"}) == "--event-min-el: event_min_el_deg: -3 is outside -2 .. 90 deg");
}

TEST_CASE("trakbox host serves no port unless one is asked for (issue 39)") {
  const auto host = parse({}, FrontEnd::host);
  REQUIRE(host.config);
  CHECK(host.config->satrak_port == 0);
  const auto asked = parse({"--satrak-port", "4100"}, FrontEnd::host);
  REQUIRE(asked.config);
  CHECK(asked.config->satrak_port == 4100);
  CHECK(parse({}, FrontEnd::menus).config->satrak_port == 4001);
}

TEST_CASE("--rotater: did you mean --rotator (issue 39)") {
  CHECK(error_of({"--rotater", "simulated"}) == "--rotater: unknown option; did you mean --rotator?");
}

TEST_CASE("--udp-events: stored destinations kept, replaced, or cleared by none; all checked first") {
  CHECK_FALSE(parse({"--state", "/tmp/x"}).config->udp_events.has_value());  // the stored ones stay
  const auto two = parse({"--udp-events", "192.168.1.20:9000", "--udp-events", "[2001:db8::2]:9001"});
  REQUIRE(two.config);
  REQUIRE(two.config->udp_events.has_value());
  CHECK(*two.config->udp_events ==
        std::vector<UdpTarget>{{"192.168.1.20", 9000}, {"2001:db8::2", 9001}});
  const auto none = parse({"--udp-events", "none"});
  REQUIRE(none.config);
  REQUIRE(none.config->udp_events.has_value());
  CHECK(none.config->udp_events->empty());
  // A bad one among good ones: nothing is configured, so nothing can be stored.
  CHECK(error_of({"--udp-events", "10.0.0.1:9000", "--udp-events", "nohost"}) ==
        "--udp-events: 'nohost': expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000");
  CHECK(error_of({"--udp-events", "none", "--udp-events", "10.0.0.1:9000"}) ==
        "--udp-events: 'none' clears the destinations: not with others");
  std::vector<std::string> many;
  for (int i = 1; i <= 17; ++i) {
    many.push_back("--udp-events");
    many.push_back("10.0.0.1:" + std::to_string(9000 + i));
  }
  CHECK(error_of(many) == "--udp-events: at most 16 destinations");
}

TEST_CASE("--handback, --exclusive, --satnogs-station and --satnogs-url are read and checked (issue 44)") {
  const auto none = parse({});
  REQUIRE(none.config);
  CHECK_FALSE(none.config->handback_s);
  CHECK_FALSE(none.config->exclusive);
  CHECK_FALSE(none.config->satnogs_station);
  const auto set = parse({"--handback", "0", "--exclusive", "rotctld", "--satnogs-station", "5024", "--satnogs-url",
                          "http://127.0.0.1:8000"});
  REQUIRE(set.config);
  CHECK(set.config->handback_s == 0);
  CHECK(set.config->exclusive == "rotctld");
  CHECK(set.config->satnogs_station == 5024);
  CHECK(set.config->satnogs_url == "http://127.0.0.1:8000");
  CHECK(parse({"--exclusive", "none"}).config->exclusive == "");
  CHECK(error_of({"--exclusive", "gpredict"}) ==
        "--exclusive: sharing.exclusive: 'gpredict' is not one of none, rotctld, rigctld or satrak");
  CHECK(error_of({"--handback", "-1"}) == "--handback: sharing.handback_s: -1 is outside 0 .. 86400 s");
  CHECK(error_of({"--satnogs-url", "ftp://x"}) ==
        "--satnogs-url: sharing.satnogs_url: 'ftp://x': expected an http:// or https:// URL");
}

TEST_CASE("--logger, --logger-key-file and --logger-station-id are read and checked (issue 45)") {
  const auto none = parse({});
  REQUIRE(none.config);
  CHECK_FALSE(none.config->logger);
  CHECK_FALSE(none.config->logger_key_file);
  CHECK_FALSE(none.config->logger_station_id);
  const auto set = parse({"--logger", "wavelog:https://log.example.org/", "--logger-key-file", "/etc/trakbox/./wl.key",
                          "--logger-station-id", "3"});
  REQUIRE(set.config);
  CHECK(set.config->logger == "wavelog:https://log.example.org");
  CHECK(set.config->logger_key_file == "/etc/trakbox/wl.key");
  CHECK(set.config->logger_station_id == 3);
  CHECK(parse({"--logger", "none"}).config->logger == "");
  CHECK(error_of({"--logger", "cloudlog:log.example.org"}) ==
        "--logger: 'log.example.org' is not an http:// or https:// URL");
  CHECK(error_of({"--logger", "eqsl:https://x"}) == "--logger: expected cloudlog:URL, wavelog:URL or none; found 'eqsl:https://x'");
  CHECK(error_of({"--logger-station-id", "-1"}) == "--logger-station-id: logger.station_id: -1 is outside 0 .. 1000000000");
}
