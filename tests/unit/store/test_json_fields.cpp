// The typed field readers the state document and the Satrak settings share (store/json_fields.h):
// every failure names the field by its path and says what was expected.
#include <doctest/doctest.h>

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "store/json_fields.h"
#include "store/model.h"

using namespace tb::store;
using namespace tb::store::json_fields;
using nlohmann::json;

TEST_CASE("Field readers return the value when it is what was expected") {
  const json j = {{"n", 1.5}, {"i", -3}, {"b", true}, {"s", "abc"}};
  CHECK(num(j, "x", "n", 0, 2) == 1.5);
  CHECK(num(j, "x", "i", -3, -3) == -3.0);  // a whole number is a number; bounds are inclusive
  CHECK(integer(j, "x", "i", -3, 0) == -3);
  CHECK(boolean(j, "x", "b"));
  CHECK(text(j, "x", "s", 3) == "abc");
  CHECK(field(j, "x", "s") == "abc");
  CHECK(path("x", "s") == "x.s");
  CHECK(path("", "s") == "s");
}

TEST_CASE("Field readers name the field and what was expected") {
  const json j = {{"n", 100}, {"f", 1.5}, {"s", "abcd"}, {"b", 1}, {"o", {{"k", "v"}}}};
  CHECK_THROWS_WITH_AS(num(j, "station", "n", -90, 90), "station.n: value 100 outside -90.0 .. 90.0", std::runtime_error);
  CHECK_THROWS_WITH_AS(num(j, "station", "s", -90, 90), "station.s: expected a number", std::runtime_error);
  CHECK_THROWS_WITH_AS(integer(j, "r", "f", 0, 9), "r.f: expected a whole number", std::runtime_error);
  CHECK_THROWS_WITH_AS(integer(j, "r", "n", 0, 9), "r.n: value 100 outside 0 .. 9", std::runtime_error);
  CHECK_THROWS_WITH_AS(boolean(j, "r", "b"), "r.b: expected true or false", std::runtime_error);
  CHECK_THROWS_WITH_AS(text(j, "r", "n", 9), "r.n: expected a string", std::runtime_error);
  CHECK_THROWS_WITH_AS(text(j, "r", "s", 3), "r.s: longer than 3 characters", std::runtime_error);
  CHECK_THROWS_WITH_AS(field(j, "r", "missing"), "r.missing: missing", std::runtime_error);
  CHECK_THROWS_WITH_AS(field(j["o"]["k"], "r.o.k", "x"), "r.o.k: expected an object", std::runtime_error);
}

TEST_CASE("At the top level a field is named by its key alone") {
  const json j = {{"clock_offset_us", "soon"}, {"rotor_control", 1}};
  CHECK_THROWS_WITH_AS(integer(j, "", "clock_offset_us", 0, 1), "clock_offset_us: expected a whole number",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(boolean(j, "", "rotor_control"), "rotor_control: expected true or false", std::runtime_error);
  CHECK_THROWS_WITH_AS(field(j, "", "db"), "db: missing", std::runtime_error);
  CHECK_THROWS_WITH_AS(field(json::array(), "", "db"), "document: expected an object", std::runtime_error);
}

TEST_CASE("The state document's errors name the field") {
  CHECK_THROWS_WITH_AS(model_from_json(json::array()), "state: expected an object", std::runtime_error);
  CHECK_THROWS_WITH_AS(model_from_json(json::object()), "station: missing", std::runtime_error);
  json j = to_json(Model{});
  CHECK(to_json(model_from_json(j)) == j);
  j["station"]["lat_deg"] = 91;
  CHECK_THROWS_WITH_AS(model_from_json(j), "station.lat_deg: 91 is outside -90 .. 90 deg", std::runtime_error);
  j = to_json(Model{});
  j["rotor_control"] = "yes";
  CHECK_THROWS_WITH_AS(model_from_json(j), "rotor_control: expected on or off (true or false)", std::runtime_error);
  j = to_json(Model{});
  j["radio"]["rig"] = "collins";
  CHECK_THROWS_WITH_AS(model_from_json(j), "radio.rig: 'collins' is not one of none, kenwood, yaesu, icom",
                       std::runtime_error);
}

TEST_CASE("the GPS settings round-trip; a bad source or threshold is refused by name; older states have none") {
  Model m = factory_defaults();
  m.gps.source = "gpsd:127.0.0.1:2947";
  m.gps.follow = true;
  m.gps.threshold_m = 250.0;
  m.gps.position_from_gps = true;
  m.gps.position_time = tb::orbit::from_civil(2017, 10, 19, 6, 0, 2);
  json j = to_json(m);
  CHECK(model_from_json(j).gps == m.gps);
  j["gps"]["source"] = "nmea:/dev/ttyUSB0";
  CHECK_THROWS_WITH_AS(model_from_json(j),
                       "gps.source: expected gpsd, gpsd:HOST or gpsd:HOST:PORT; found 'nmea:/dev/ttyUSB0'",
                       std::runtime_error);
  j["gps"]["source"] = "";
  j["gps"]["threshold_m"] = 0.5;
  CHECK_THROWS_WITH_AS(model_from_json(j), "gps.threshold_m: 0.5 is outside 1 .. 100000 m", std::runtime_error);
  j.erase("gps");
  CHECK(model_from_json(j).gps == tb::station::GpsSettings{});
}

TEST_CASE("The radio's operating practice and remembered corrections round-trip; bad ones name their field") {
  Model m;
  m.radio.dial_rest_ms = 1500;
  m.radio.doppler_step_ssb_hz = 30;
  m.radio.doppler_step_fm_hz = 250;
  m.radio.corrections = {{"SO-50 FM", 300}, {"RS-44 USB", -1200}};
  json j = to_json(m);
  CHECK(j["radio"]["corrections"]["SO-50 FM"] == 300);
  CHECK(model_from_json(j).radio == m.radio);
  // A state file from before them: the factory values.
  json old = j;
  for (const char* k : {"dial_rest_ms", "doppler_step_ssb_hz", "doppler_step_fm_hz", "corrections"}) old["radio"].erase(k);
  const Model back = model_from_json(old);
  CHECK(back.radio.dial_rest_ms == 1000);
  CHECK(back.radio.doppler_step_ssb_hz == 20);
  CHECK(back.radio.doppler_step_fm_hz == 100);
  CHECK(back.radio.corrections.empty());
  json bad = j;
  bad["radio"]["corrections"] = json::array();
  CHECK_THROWS_WITH_AS(model_from_json(bad), "radio.corrections: expected an object of \"SATELLITE MODE\": Hz",
                       std::runtime_error);
  bad = j;
  bad["radio"]["corrections"]["SO-50 FM"] = "lots";
  CHECK_THROWS_AS(model_from_json(bad), std::runtime_error);
  bad = j;
  bad["radio"]["doppler_step_fm_hz"] = 5;
  CHECK_THROWS_WITH_AS(model_from_json(bad), "radio.doppler_step_fm_hz: 5 is outside 10 .. 10000 Hz", std::runtime_error);
}

TEST_CASE("the tracking choice and --event-min-el round-trip; a bad mode is refused by name; older states have none") {
  Model m = factory_defaults();
  CHECK(m.tracking.mode == tb::store::TrackingChoice::Mode::list);
  CHECK(m.event_min_el_deg == 0.0);
  m.tracking = {tb::store::TrackingChoice::Mode::single, 25544, "ISS"};
  m.event_min_el_deg = 10.0;
  m.rotor_control = true;
  json j = to_json(m);
  CHECK(j["tracking"] == json{{"mode", "single"}, {"catalog_number", 25544}, {"name", "ISS"}});
  const Model back = model_from_json(j);
  CHECK(back.tracking == m.tracking);
  CHECK(back.event_min_el_deg == 10.0);
  CHECK(back.rotor_control);
  j["tracking"]["mode"] = "pass";
  CHECK_THROWS_WITH_AS(model_from_json(j), "tracking.mode: expected list, single or multi; found 'pass'",
                       std::runtime_error);
  j["tracking"]["mode"] = "multi";
  j["event_min_el_deg"] = 91;
  CHECK_THROWS_WITH_AS(model_from_json(j), "event_min_el_deg: 91 is outside -2 .. 90 deg", std::runtime_error);
  j.erase("tracking");
  j.erase("event_min_el_deg");
  CHECK(model_from_json(j).tracking == tb::store::TrackingChoice{});
  CHECK(model_from_json(j).event_min_el_deg == 0.0);
}

TEST_CASE("the --udp-events destinations round-trip in their one written form; bad ones name their entry") {
  Model m = factory_defaults();
  CHECK(to_json(m)["udp_events"] == json::array());
  m.udp_events = {"192.168.1.20:9000", "[2001:db8::2]:9001", "logger.local:1"};
  json j = to_json(m);
  CHECK(j["udp_events"] == json({"192.168.1.20:9000", "[2001:db8::2]:9001", "logger.local:1"}));
  CHECK(model_from_json(j).udp_events == m.udp_events);
  j["udp_events"][1] = "2001:db8::2:9001";
  CHECK_THROWS_WITH_AS(model_from_json(j),
                       "udp_events[1]: '2001:db8::2:9001': too many ':' (an IPv6 address goes in brackets)",
                       std::runtime_error);
  j["udp_events"] = "192.168.1.20:9000";
  CHECK_THROWS_WITH_AS(model_from_json(j), "udp_events: expected a list of HOST:PORT", std::runtime_error);
  j["udp_events"] = json::array();
  for (int i = 0; i < 17; ++i) j["udp_events"].push_back("10.0.0.1:" + std::to_string(9000 + i));
  CHECK_THROWS_WITH_AS(model_from_json(j), "udp_events: more than 16 destinations", std::runtime_error);
  j.erase("udp_events");  // a state file from before they were stored
  CHECK(model_from_json(j).udp_events.empty());
}

TEST_CASE("sharing (issue 44) round-trips; a bad --exclusive or a reservation ending first is refused by name") {
  Model m = factory_defaults();
  CHECK(m.sharing == Sharing{});
  CHECK(m.sharing.handback_s == 30);
  m.sharing.handback_s = 0;
  m.sharing.exclusive = "rigctld";
  m.sharing.standby = true;
  m.sharing.satnogs_station = 5024;
  m.sharing.reservations = {{"op-1893492000", 1893492000, 1893495600, "EME"}};
  json j = to_json(m);
  CHECK(model_from_json(j).sharing == m.sharing);
  j["sharing"]["exclusive"] = "gpredict";
  CHECK_THROWS_WITH_AS(model_from_json(j), "sharing.exclusive: 'gpredict' is not one of none, rotctld, rigctld or satrak",
                       std::runtime_error);
  j["sharing"]["exclusive"] = "";
  j["sharing"]["reservations"][0]["end_unix"] = 1893492000;
  CHECK_THROWS_WITH_AS(model_from_json(j), "sharing.reservations[0].end_unix: expected after start_unix",
                       std::runtime_error);
  j.erase("sharing");
  CHECK(model_from_json(j).sharing == Sharing{});  // older states
}
