#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "host/host_mode.h"
#include "support/gps_fix.h"
#include "support/sim_station.h"

using namespace tb;

namespace {

// A whole simulated station (rotator, radio, tracker) with a clock the test moves, and the host
// mode interpreter on it.
struct Station : testing::StationFixture {
  explicit Station(bool rotor_control = true, rotator::RotatorPosition start = {}) : start_at(start) {
    model.rotor_control = rotor_control;
    build();
  }
  void build() {
    auto params = rotator::SimulatedRotatorParams::matching(model.rotator);
    params.start = start_at;
    build_station(params);
    host = std::make_unique<host::Interpreter>(*station);
    station->tick();
  }
  host::Reply cmd(std::string_view line) { return host->execute(line); }

  rotator::RotatorPosition start_at;
  std::unique_ptr<host::Interpreter> host;
};

using testing::kAzTol;
using testing::kElTol;

}  // namespace

TEST_CASE("Host mode greets as the manual, with MU for the OCR's ML") {
  const auto g = host::Interpreter::greeting();
  REQUIRE(g.size() == 3);
  CHECK(g[0] == "TrakBox host mode.");
  CHECK(g[1] == "Command:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,?A,?");
  // trakbox's own commands, from the command table (issue 60).
  CHECK(g[2] == "Also:RF,?R,LOG,?C,STANDBY,PB,OR,OT,CT,MODE,?T,QTH (? explains each)");
  CHECK(host::kPrompt == "TrakBox>>");
}

TEST_CASE("AZ220 EL45 points the simulated rotator there; ?A reports it in a form AZ/EL reads back") {
  Station s;
  const auto r = s.cmd("AZ220 EL45");
  CHECK(r.ok);
  CHECK(r.lines.empty());
  CHECK(!r.quit);
  s.run(90);
  CHECK(s.station->rotator().status().on_target);
  CHECK(rotator::azimuth_distance(s.truth().az, 220.0) <= kAzTol);
  CHECK(std::abs(s.truth().el - 45.0) <= kElTol);
  const auto a = s.cmd("?A");
  REQUIRE(a.lines.size() == 1);
  const auto back = host::parse_az_el(a.lines[0]);
  REQUIRE(back.args);
  CHECK(rotator::azimuth_distance(back.args->az, 220.0) <= kAzTol);
  CHECK(std::abs(back.args->el - 45.0) <= kElTol);
  // The reply is the station's own reading.
  const auto ant = s.station->antenna();
  REQUIRE(ant);
  CHECK(a.lines[0] == host::format_antenna(ant->az, ant->el));
}

TEST_CASE("AZ/EL with any spacing, case and separator") {
  for (const char* text : {"AZ220 EL45", "az220 el45", "AZ 220 EL 45", "AZ220EL45", "  AZ220\tEL45  ", "AZ220_EL45",
                           "AZ220,EL45", "AZ+220.0 EL45.00"}) {
    const auto p = host::parse_az_el(text);
    INFO(text);
    REQUIRE(p.args);
    CHECK(p.args->az == 220.0);
    CHECK(p.args->el == 45.0);
  }
  CHECK(host::parse_az_el("AZ0 EL0").args);
  CHECK(host::parse_az_el("AZ360 EL90").args);
  CHECK(host::parse_az_el("AZ359.9 EL89.5").args->az == 359.9);
}

TEST_CASE("Malformed or out-of-range AZ/EL is an error and moves nothing") {
  Station s;
  const auto before = s.truth();
  const std::pair<const char*, const char*> cases[] = {
      {"AZ400 EL45", "ERROR AZ/EL: azimuth 400 out of range: expected 0 to 360"},
      {"AZ-1 EL45", "ERROR AZ/EL: azimuth -1 out of range: expected 0 to 360"},
      {"AZ220 EL91", "ERROR AZ/EL: elevation 91 out of range: expected 0 to 90"},
      {"AZ220 EL-5", "ERROR AZ/EL: elevation -5 out of range: expected 0 to 90"},
      {"AZ220", "ERROR AZ/EL: no EL: expected AZxxx ELxxx in degrees, e.g. AZ220 EL45"},
      {"AZ EL45", "ERROR AZ/EL: no azimuth after AZ: expected AZxxx ELxxx in degrees, e.g. AZ220 EL45"},
      {"AZ220 EL", "ERROR AZ/EL: no elevation after EL: expected AZxxx ELxxx in degrees, e.g. AZ220 EL45"},
      {"AZ220 EL45 X", "ERROR AZ/EL: 'X' after the elevation: expected AZxxx ELxxx in degrees, e.g. AZ220 EL45"},
      {"AZ22x0 EL45", "ERROR AZ/EL: 'x0 EL45' where EL was expected: expected AZxxx ELxxx in degrees, e.g. AZ220 EL45"},
  };
  for (const auto& [text, message] : cases) {
    const auto r = s.cmd(text);
    INFO(text);
    CHECK(!r.ok);
    REQUIRE(r.lines.size() == 1);
    CHECK(r.lines[0] == message);
  }
  s.run(10);
  CHECK(s.station->rotator().status().mode == rotator::ControlMode::idle);
  CHECK(!s.station->rotator().status().target);
  CHECK(s.truth() == before);
}

TEST_CASE("With rotor control OFF, AZ/EL switches it on (the host takes control) and the antenna goes") {
  Station s(false);
  const auto before = s.truth();
  const auto r = s.cmd("AZ90 EL10");
  CHECK(r.ok);
  CHECK(s.model.rotor_control);
  s.run(10);
  CHECK(s.station->rotator().status().target);
  CHECK(!(s.truth() == before));
}

TEST_CASE("AZ/EL stays inside the rotation limits and says where it goes instead") {
  // The station file sample's limits: azimuth 270 -> 90 clockwise (the northern half), elevation 0..45,
  // rotor start South; the antenna starts due north (travel 180 from the south stop).
  Station s(true, {180.0, 0.0});
  s.model.rotator.limits_enabled = true;
  s.model.rotator.az_limit_min = 270.0;
  s.model.rotator.az_limit_max = 90.0;
  s.model.rotator.el_limit_max = 45.0;
  s.station->reconfigure();
  const auto r = s.cmd("AZ120 EL60");
  CHECK(r.ok);
  REQUIRE(r.lines.size() == 1);
  CHECK(r.lines[0] == "LIMIT AZ90.0 EL45.0");
  bool outside = false;
  s.run(90, [&] {
    const auto t = s.truth();
    if ((t.az > 90.0 + kAzTol && t.az < 270.0 - kAzTol) || t.el > 45.0 + kElTol) outside = true;
  });
  CHECK(!outside);
  CHECK(rotator::azimuth_distance(s.truth().az, 90.0) <= kAzTol);
  CHECK(std::abs(s.truth().el - 45.0) <= kElTol);
  // Inside the limits there is nothing to say.
  CHECK(s.cmd("AZ300 EL20").lines.empty());
  s.run(90, [&] {
    const auto t = s.truth();
    if ((t.az > 90.0 + kAzTol && t.az < 270.0 - kAzTol) || t.el > 45.0 + kElTol) outside = true;
  });
  CHECK(!outside);
  CHECK(rotator::azimuth_distance(s.truth().az, 300.0) <= kAzTol);
}

TEST_CASE("MU / MD set the simulated radio's modes; bad modes change nothing") {
  Station s;
  CHECK(s.cmd("MUFM").lines.empty());
  CHECK(s.cmd("mdusb").lines.empty());
  CHECK(s.cmd("MD LSB").lines.empty());
  CHECK(s.cmd("MUcw").ok);
  CHECK(s.radio_sim->mode(radio::Link::uplink) == radio::Mode::cw);
  CHECK(s.radio_sim->mode(radio::Link::downlink) == radio::Mode::lsb);
  const auto events = s.radio_sim->history().size();
  auto r = s.cmd("MDXYZ");
  CHECK(!r.ok);
  CHECK(r.lines[0] == "ERROR MD: 'XYZ' is not a radio mode: expected FM, LSB, USB or CW, e.g. MDFM");
  CHECK(!s.cmd("MU").ok);
  CHECK(!s.cmd("MUNONE").ok);
  CHECK(s.radio_sim->history().size() == events);
  CHECK(s.radio_sim->mode(radio::Link::downlink) == radio::Mode::lsb);
}

TEST_CASE("FU / FD in 10 Hz units tune the simulated radio; bad numbers change nothing") {
  Station s;
  CHECK(s.cmd("FU14595000").lines.empty());
  CHECK(s.cmd("FD43590000").lines.empty());
  CHECK(s.radio_sim->frequency(radio::Link::uplink) == 145950000);
  CHECK(s.radio_sim->frequency(radio::Link::downlink) == 435900000);
  CHECK(s.cmd("fd 129600000").ok);  // 1296.000 MHz: nine digits
  CHECK(s.radio_sim->frequency(radio::Link::downlink) == 1296000000);
  const auto events = s.radio_sim->history().size();
  for (const char* bad : {"FU0", "FU", "FU1234567890", "FU1459a000", "FU-14595000", "FU145.95", "FD 12 34"}) {
    const auto r = s.cmd(bad);
    INFO(bad);
    CHECK(!r.ok);
    REQUIRE(r.lines.size() == 1);
    CHECK(r.lines[0].rfind("ERROR F", 0) == 0);
    CHECK(r.lines[0].find("expected 1 to 9 digits in 10 Hz units") != std::string::npos);
  }
  CHECK(s.radio_sim->history().size() == events);
  CHECK(s.radio_sim->frequency(radio::Link::uplink) == 145950000);
  CHECK(host::parse_ten_hz("14595000") == 145950000);
  CHECK(host::parse_ten_hz("14595") == 145950);  // the manual's second table, literally
}

TEST_CASE("S sends the string to the radio as it is, with \\xHH for bytes") {
  Station s;
  CHECK(s.cmd("STX;").lines.empty());
  CHECK(s.cmd("S\\xFE\\xFE\\x10\\xE0\\x03\\xFD").ok);
  CHECK(s.cmd("SFA00435123450; ").ok);
  const auto h = s.radio_sim->history();
  REQUIRE(h.size() == 3);
  CHECK(h[0].kind == radio::RadioEvent::Kind::raw);
  CHECK(h[0].raw == "TX;");
  CHECK(h[1].raw == std::string("\xFE\xFE\x10\xE0\x03\xFD"));
  CHECK(h[2].raw == "FA00435123450;");
  CHECK(s.cmd("S").lines[0] == "ERROR S: nothing to send: expected the string after S, e.g. STX;");
  CHECK(!s.cmd("S\\xZZ").ok);
  CHECK(!s.cmd("S\\q").ok);
  CHECK(s.radio_sim->history().size() == 3);
}

TEST_CASE("Commands to antenna or radio stop trakbox's own tracking; queries do not") {
  Station s;
  s.tracker.track_single(0);
  s.station->tick();
  CHECK(s.cmd("?A").ok);
  CHECK(s.cmd("?").ok);
  CHECK(s.tracker.mode() == tracker::Mode::single);
  CHECK(!s.cmd("FUxx").ok);  // an error changes nothing
  CHECK(s.tracker.mode() == tracker::Mode::single);
  CHECK(s.cmd("FD43590000").ok);
  CHECK(s.tracker.mode() == tracker::Mode::off);
  s.tracker.track_single(0);
  CHECK(s.cmd("AZ10 EL10").ok);
  CHECK(s.tracker.mode() == tracker::Mode::off);
  CHECK(s.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::host);
}

TEST_CASE("AZ/EL while an outside client holds the antenna: refused once, done when sent again (issue 44)") {
  Station s;
  s.tracker.track_single(0);
  s.station->tick();
  const tracker::Requester gpredict{tracker::HolderKind::rotctld, "rotctld 127.0.0.1:51234"};
  REQUIRE(tracker::StationOps(*s.station, gpredict).go_to(200.0, 30.0).ok());
  const auto first = s.cmd("AZ10 EL10");
  CHECK_FALSE(first.ok);
  REQUIRE(!first.lines.empty());
  CHECK(first.lines[0] == "ERROR AZ/EL: rotctld 127.0.0.1:51234 holds the antenna: confirm to take it back "
                          "(send it again to confirm)");
  CHECK(s.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::rotctld);
  CHECK(s.cmd("AZ10 EL10").ok);
  CHECK(s.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::host);
  const auto who = s.cmd("?C");
  REQUIRE(who.lines.size() == 1);
  CHECK(who.lines[0] == "CONTROL ANTENNA host RADIO trakbox tracking");
  const auto sb = s.cmd("standby on");
  CHECK(sb.ok);
  CHECK(s.station->control().standby());
  CHECK(s.model.sharing.standby);
  CHECK_FALSE(s.cmd("AZ20 EL10").ok);  // standby: nothing moves
  CHECK(s.cmd("STANDBY OFF").ok);
  CHECK_FALSE(s.station->control().standby());
}

TEST_CASE("Q, ?, blank lines and unknown commands") {
  Station s;
  CHECK(s.cmd("Q").quit);
  CHECK(s.cmd(" q \r").quit);
  const auto blank = s.cmd("   ");
  CHECK(blank.ok);
  CHECK(blank.lines.empty());
  CHECK(!blank.quit);
  const auto help = s.cmd("?");
  CHECK(help.lines == host::Interpreter::help());
  CHECK(help.lines.front().rfind("AZxxx ELxxx", 0) == 0);
  const auto bad = s.cmd("XY12");
  CHECK(!bad.ok);
  REQUIRE(bad.lines.size() == 1);
  CHECK(bad.lines[0] ==
        "ERROR unknown command 'XY12': expected AZxxx ELxxx, MUxxx, MDxxx, FUxxx, FDxxx, Sxxx, ?A, ? or Q");
  CHECK(!s.cmd("QUIT").quit);
  CHECK(!s.cmd("?B").ok);
}

TEST_CASE("Faults are reported, not hidden") {
  Station s;
  s.radio_sim->simulate_fault("CAT cable unplugged");
  const auto r = s.cmd("FU14595000");
  CHECK(!r.ok);
  CHECK(r.lines[0] == "ERROR FU: radio fault: CAT cable unplugged");
  s.rotator_sim->set_fault("ADC not answering");
  s.run(1);
  const auto a = s.cmd("?A");
  CHECK(!a.ok);
  CHECK(a.lines[0].rfind("ERROR ?A: no antenna position", 0) == 0);
}

TEST_CASE("The ?A format") {
  CHECK(host::format_antenna(220.04, 45.0) == "AZ220.0 EL45.0");
  CHECK(host::format_antenna(359.96, 0.0) == "AZ0.0 EL0.0");
  CHECK(host::format_antenna(0.0, -0.04) == "AZ0.0 EL0.0");
  CHECK(host::format_antenna(12.345, 89.96) == "AZ12.3 EL90.0");
}

TEST_CASE("?A with a GPS receiver: a second line with its fix") {
  Station s;
  gps::Monitor receiver("gpsd:localhost:2947");
  s.station->set_gps(&receiver);
  CHECK(s.cmd("?A").lines.at(1) == "GPS no fix [GPS CONNECTING]");
  const orbit::UtcTime t = orbit::from_civil(2017, 10, 19, 6, 0, 0);
  testing::feed_gps_fix(receiver, t, t);
  const auto a = s.cmd("?A");
  REQUIRE(a.lines.size() == 2);
  CHECK(host::parse_az_el(a.lines[0]).args);
  CHECK(a.lines[1] == "GPS 3D fix 41.0100N 29.1700E 120.0 m at 2017-10-19T06:00:02Z");
  receiver.on_link(gps::Link::lost, "connection closed");
  CHECK(s.cmd("?A").lines.at(1) == "GPS no fix (last 41.0100N 29.1700E 120.0 m) at 2017-10-19T06:00:02Z [GPSD LOST]");
  s.station->set_gps(nullptr);
}
