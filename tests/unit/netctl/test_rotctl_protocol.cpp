// The rotctld protocol against a whole simulated station: every command short and long, the
// Extended Response Protocol, malformed input, and the station's rules (limits, dead band,
// parking, rotor control) applied to what a client asks.
#include <doctest/doctest.h>

#include <cmath>

#include "fixture.h"
#include "netctl/rotctl_protocol.h"

using namespace tb;
using namespace nettest;
using netctl::RotctlProtocol;
using Rot = ProtocolOn<RotctlProtocol>;  // a fresh station and the protocol on it

namespace {


// The two numbers of a Default Protocol get_pos reply.
std::pair<double, double> pos_of(const std::string& reply) {
  const auto l = lines(reply);
  REQUIRE(l.size() == 2);
  return {std::stod(l[0]), std::stod(l[1])};
}

// What the antenna is doing, to check that a refused request changed nothing.
struct Snapshot {
  rotator::ControlMode mode;
  std::optional<rotator::RotatorPosition> target;
  tracker::Mode tracking;
  bool operator==(const Snapshot&) const = default;
};
Snapshot snap(SimStation& st) {
  const auto& s = st.station->rotator().status();
  return {s.mode, s.target, st.tracker.mode()};
}

}  // namespace

TEST_CASE_FIXTURE(Rot, "rotctl: P / \\set_pos points the antenna through trakbox's model; p / \\get_pos reads it back") {

  CHECK(ask(p, "P 120 30") == "RPRT 0\n");
  REQUIRE(st.settle());
  // Inside the dead band: 3 counts of azimuth (1.06 deg), 1 count of elevation (0.18 deg).
  CHECK(az_diff(st.truth().az, 120.0) < 1.1);
  CHECK(std::abs(st.truth().el - 30.0) < 0.36);
  auto [az, el] = pos_of(ask(p, "p"));
  CHECK(az_diff(az, st.truth().az) < 0.5);
  CHECK(std::abs(el - st.truth().el) < 0.3);

  CHECK(ask(p, "\\set_pos 200.5 10.25") == "RPRT 0\n");
  REQUIRE(st.settle());
  std::tie(az, el) = pos_of(ask(p, "\\get_pos"));
  CHECK(az_diff(az, 200.5) < 1.1);
  CHECK(std::abs(el - 10.25) < 0.36);

  // Arguments may follow a short command without a space, with tabs, and a CR before the newline.
  CHECK(ask(p, "P90\t45\r") == "RPRT 0\n");
  CHECK(st.station->rotator().status().target->el == doctest::Approx(45.0));

  // Negative azimuths (a -180..180 client) are compass bearings modulo 360.
  CHECK(ask(p, "P -90 20") == "RPRT 0\n");
  REQUIRE(st.settle());
  CHECK(az_diff(st.truth().az, 270.0) < 1.1);
}

TEST_CASE_FIXTURE(Rot, "rotctl: a position inside the dead band does not move the antenna") {
  REQUIRE(ask(p, "P 100 20") == "RPRT 0\n");
  REQUIRE(st.settle());
  const auto before = st.rotator_sim->true_position();
  // Half a count of azimuth away: inside the 3-count dead band.
  CHECK(ask(p, "P " + std::to_string(st.truth().az + 0.2) + " " + std::to_string(st.truth().el)) == "RPRT 0\n");
  for (int i = 0; i < 30; ++i) st.step();
  const auto after = st.rotator_sim->true_position();
  CAPTURE(before.az_travel);
  CAPTURE(after.az_travel);
  CAPTURE(before.el);
  CAPTURE(after.el);
  CHECK(std::abs(after.az_travel - before.az_travel) < 0.01);  // a 0.1 s drive would be 0.6 deg
  CHECK(std::abs(after.el - before.el) < 0.01);
}

TEST_CASE_FIXTURE(Rot, "rotctl: Extended Response Protocol with '+' and other separators") {
  CHECK(ask(p, "+P 90 45") == "set_pos: 90 45\nRPRT 0\n");
  CHECK(ask(p, "+\\set_pos 90 45") == "set_pos: 90 45\nRPRT 0\n");
  REQUIRE(st.settle());
  const std::string r = ask(p, "+\\get_pos");
  const auto l = lines(r);
  REQUIRE(l.size() == 4);
  CHECK(l[0] == "get_pos:");
  CHECK(l[1].rfind("Azimuth: ", 0) == 0);
  CHECK(l[2].rfind("Elevation: ", 0) == 0);
  CHECK(l[3] == "RPRT 0");
  CHECK(std::stod(l[1].substr(9)) == doctest::Approx(90.0).epsilon(0.02));
  CHECK(ask(p, "+p").rfind("get_pos:\nAzimuth: ", 0) == 0);

  const std::string semi = ask(p, ";\\get_pos");
  CHECK(semi.rfind("get_pos:;Azimuth: ", 0) == 0);
  CHECK(semi.find(";Elevation: ") != std::string::npos);
  CHECK(semi.size() > 8);
  CHECK(semi.substr(semi.size() - 8) == ";RPRT 0\n");
  CHECK(ask(p, "|P 135 22.5") == "set_pos: 135 22.5|RPRT 0\n");
  CHECK(ask(p, "+S") == "stop:\nRPRT 0\n");
  CHECK(ask(p, "+\\stop") == "stop:\nRPRT 0\n");
  CHECK(ask(p, "+M 8 50") == "move: 8 50\nRPRT 0\n");
  CHECK(ask(p, "+P 400 100") == "set_pos: 400 100\nRPRT -1\n");
  CHECK(ask(p, "+Z") == "Z:\nRPRT -11\n");
  CHECK(ask(p, "+\\get_info").rfind("get_info:\nInfo: trakbox rotator (simulated)\nRPRT 0\n", 0) == 0);
}

TEST_CASE_FIXTURE(Rot, "rotctl: malformed requests are answered RPRT -1 / -8 / -11 and change nothing") {
  REQUIRE(ask(p, "P 50 10") == "RPRT 0\n");
  st.step();
  const Snapshot before = snap(st);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"P abc 10", "RPRT -1\n"},
      {"P 10 abc", "RPRT -1\n"},
      {"P 400 100", "RPRT -1\n"},  // elevation beyond 90 (no flip)
      {"P 541 10", "RPRT -1\n"},   // azimuth beyond the protocol's -180..540
      {"P -181 10", "RPRT -1\n"},
      {"P 10 -1", "RPRT -1\n"},
      {"P nan 10", "RPRT -1\n"},
      {"P inf 10", "RPRT -1\n"},
      {"P 10", "RPRT -1\n"},       // missing argument
      {"P", "RPRT -1\n"},
      {"\\set_pos", "RPRT -1\n"},
      {"P 10 10 10", "RPRT -1\n"}, // extra argument
      {"P 10x 10", "RPRT -1\n"},
      {"M 3 50", "RPRT -1\n"},     // no such direction
      {"M 8 0", "RPRT -1\n"},      // speed 1..100 or -1
      {"M 8 101", "RPRT -1\n"},
      {"M 8", "RPRT -1\n"},
      {"M up 50", "RPRT -1\n"},
      {"\\move 16 1.5", "RPRT -1\n"},
      {"K now", "RPRT -1\n"},
      {"p 1", "RPRT -1\n"},
      {"Z", "RPRT -11\n"},         // unknown
      {"\\frobnicate 1 2", "RPRT -11\n"},
      {"R 1", "RPRT -11\n"},       // Hamlib's reset: not offered
      {"C key val", "RPRT -11\n"},
      {std::string(netctl::kMaxLineLength + 1, 'P'), "RPRT -8\n"},
  };
  for (const auto& [line, want] : cases) {
    CAPTURE(line);
    CHECK(ask(p, line) == want);
    CHECK(snap(st) == before);
  }
  CHECK(p.overlong().text == "RPRT -8\n");
  // Blank lines and comments are not answered.
  CHECK(ask(p, "") == "");
  CHECK(ask(p, "   \r") == "");
  CHECK(ask(p, "# P 10 10") == "");
  CHECK(snap(st) == before);
}

TEST_CASE("rotctl: outside trakbox's rotation limits a position is clamped to the nearest limit") {
  store::Model m;
  m.rotator.limits_enabled = true;
  m.rotator.az_limit_min = 270.0;  // the northern half, clockwise from 270 to 90
  m.rotator.az_limit_max = 90.0;
  m.rotator.el_limit_min = 5.0;
  m.rotator.el_limit_max = 60.0;
  SimStation st(m);
  RotctlProtocol p(*st.station);
  CHECK(ask(p, "P 120 80") == "RPRT 0\n");  // inside the protocol's range: clamped, not refused
  REQUIRE(st.settle());
  CHECK(az_diff(st.truth().az, 90.0) < 1.1);
  CHECK(std::abs(st.truth().el - 60.0) < 0.36);
  const auto [az, el] = pos_of(ask(p, "p"));  // p says where it went
  CHECK(az_diff(az, 90.0) < 1.1);
  CHECK(el == doctest::Approx(60.0).epsilon(0.01));
  CHECK(ask(p, "P 250 0") == "RPRT 0\n");
  REQUIRE(st.settle());
  CHECK(az_diff(st.truth().az, 270.0) < 1.1);
  CHECK(std::abs(st.truth().el - 5.0) < 0.36);
}

TEST_CASE("rotctl: elevation up to 180 where the rotator may flip over the top") {
  store::Model m;
  m.rotator.el_flip_allowed = true;
  SimStation st(m);
  RotctlProtocol p(*st.station);
  CHECK(p.max_el() == 180.0);
  CHECK(ask(p, "P 10 120") == "RPRT 0\n");
  REQUIRE(st.settle());
  CHECK(std::abs(st.rotator_sim->true_position().el - 120.0) < 0.36);
  CHECK(ask(p, "P 10 181") == "RPRT -1\n");
  CHECK(ask(p, "\\dump_state").find("max_el=180.000000\n") != std::string::npos);
}

TEST_CASE("rotctl: P suspends trakbox's tracking (the client holds the antenna); S stops the rotator and always works") {
  SimStation st(shipped_model());
  RotctlProtocol p(*st.station);
  const auto iss = st.model.db.find("ISS");
  REQUIRE(iss);
  st.tracker.track_single(*iss);
  st.step();
  CHECK(st.tracker.mode() == tracker::Mode::single);
  CHECK(ask(p, "P 45 45") == "RPRT 0\n");
  CHECK(st.tracker.mode() == tracker::Mode::single);  // suspended, not stopped (issue 44)
  CHECK(st.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::rotctld);
  CHECK(st.station->control().tracking_drives(tracker::Resource::radio));
  for (int i = 0; i < 20; ++i) st.step();
  CHECK(st.station->rotator().status().az.motion != rotator::Drive::stop);

  CHECK(ask(p, "S") == "RPRT 0\n");
  st.step();
  CHECK(st.station->rotator().status().mode == rotator::ControlMode::idle);
  CHECK(!st.station->rotator().status().target);
  for (int i = 0; i < 10; ++i) st.step();  // the motor coasts to a stop (0.15 s time constant)
  const auto still = st.rotator_sim->true_position();
  for (int i = 0; i < 20; ++i) st.step();
  const auto after = st.rotator_sim->true_position();
  CHECK(std::abs(after.az_travel - still.az_travel) < 0.01);

  st.tracker.track_single(*iss);  // the operator's choice: trakbox's tracking holds again
  CHECK(st.station->control().tracking_drives(tracker::Resource::antenna));
  // A stop is always obeyed, but the operator has just taken the antenna back: the client does not
  // hold it again until --handback has passed since the operator's action (issue 60).
  CHECK(ask(p, "\\stop") == "RPRT 0\n");
  CHECK(st.station->control().tracking_drives(tracker::Resource::antenna));
  st.now += std::chrono::seconds(31);
  CHECK(ask(p, "\\stop") == "RPRT 0\n");
  CHECK_FALSE(st.station->control().tracking_drives(tracker::Resource::antenna));
  // The client goes: tracking drives the antenna again, what was chosen.
  p.client_left("");
  CHECK(st.station->control().tracking_drives(tracker::Resource::antenna));
  CHECK(st.tracker.mode() == tracker::Mode::single);
}

TEST_CASE("rotctl: with rotor control off (the E key) S changes nothing; P takes control") {
  store::Model m;
  m.rotator.parking_enabled = true;
  m.rotator.parking = {90.0, 10.0};
  SimStation st(m, /*rotor_control=*/false);
  RotctlProtocol p(*st.station);
  CHECK(ask(p, "S") == "RPRT 0\n");
  CHECK_FALSE(st.station->rotor_control());
  CHECK(ask(p, "P 10 10") == "RPRT 0\n");
  CHECK(st.station->rotor_control());
}

TEST_CASE("rotctl: K / \\park goes to the parking position, refused when parking is off") {
  {
    SimStation st;
    RotctlProtocol p(*st.station);
    const Snapshot before = snap(st);
    CHECK(ask(p, "K") == "RPRT -9\n");
    CHECK(ask(p, "+\\park") == "park:\nRPRT -9\n");
    CHECK(snap(st) == before);
  }
  store::Model m;
  m.rotator.parking_enabled = true;
  m.rotator.parking = {90.0, 10.0};
  SimStation st(shipped_model());
  st.model.rotator = m.rotator;
  st.station->reconfigure();
  RotctlProtocol p(*st.station);
  st.tracker.track_single(*st.model.db.find("ISS"));
  CHECK(ask(p, "K") == "RPRT 0\n");
  CHECK(st.tracker.mode() == tracker::Mode::single);  // suspended while the client holds (issue 44)
  CHECK_FALSE(st.station->control().tracking_drives(tracker::Resource::antenna));
  REQUIRE(st.settle());
  CHECK(az_diff(st.truth().az, 90.0) < 1.1);
  CHECK(std::abs(st.truth().el - 10.0) < 0.36);
  CHECK(ask(p, "P 0 0") == "RPRT 0\n");
  CHECK(ask(p, "\\park") == "RPRT 0\n");
  CHECK(st.station->rotator().status().target->el == doctest::Approx(10.0));
}

TEST_CASE_FIXTURE(Rot, "rotctl: M / \\move drives an axis at the rotator's rate until S") {
  REQUIRE(ask(p, "P 100 20") == "RPRT 0\n");
  REQUIRE(st.settle());
  const auto start = st.truth();

  CHECK(ask(p, "M 16 50") == "RPRT 0\n");  // CW
  for (int i = 0; i < 50; ++i) st.step();  // 5 s
  const double cw = st.truth().az - start.az;
  CHECK(cw > 20.0);                        // 6 deg/s, less the spin-up
  CHECK(cw < 31.0);
  CHECK(st.rotator_sim->true_velocity(rotator::Axis::az) == doctest::Approx(6.0).epsilon(0.05));
  CHECK(ask(p, "S") == "RPRT 0\n");
  for (int i = 0; i < 10; ++i) st.step();
  CHECK(std::abs(st.rotator_sim->true_velocity(rotator::Axis::az)) < 0.05);
  const double stopped_at = st.truth().az;
  for (int i = 0; i < 20; ++i) st.step();
  CHECK(std::abs(st.truth().az - stopped_at) < 0.01);

  CHECK(ask(p, "\\move 8 -1") == "RPRT 0\n");  // CCW, speed unchanged
  for (int i = 0; i < 20; ++i) st.step();
  CHECK(st.truth().az < stopped_at - 5.0);
  CHECK(ask(p, "S") == "RPRT 0\n");

  CHECK(ask(p, "M 2 100") == "RPRT 0\n");  // up
  for (int i = 0; i < 20; ++i) st.step();
  CHECK(st.truth().el > start.el + 3.0);
  CHECK(ask(p, "M 4 1") == "RPRT 0\n");  // down
  for (int i = 0; i < 40; ++i) st.step();
  CHECK(st.truth().el < start.el);
  CHECK(ask(p, "S") == "RPRT 0\n");
}

TEST_CASE_FIXTURE(Rot, "rotctl: a rotator that stopped answering: P, K, M and p answer RPRT -6") {
  st.rotator_sim->set_fault("ADC not answering");
  st.step();
  CHECK(ask(p, "p") == "RPRT -6\n");
  CHECK(ask(p, "+p") == "get_pos:\nRPRT -6\n");
  CHECK(ask(p, "P 10 10") == "RPRT -6\n");
  CHECK(ask(p, "M 16 10") == "RPRT -6\n");
  CHECK(ask(p, "S") == "RPRT 0\n");
  st.rotator_sim->clear_fault();
  st.step();
  CHECK(lines(ask(p, "p")).size() == 2);
}

TEST_CASE_FIXTURE(Rot, "rotctl: _ / \\get_info, \\dump_state, 1 / \\dump_caps, q / Q") {
  CHECK(ask(p, "_") == "trakbox rotator (simulated)\n");
  CHECK(ask(p, "\\get_info") == "trakbox rotator (simulated)\n");
  CHECK(ask(p, "\\dump_state") ==
        "1\n1\nmin_az=-180.000000\nmax_az=540.000000\nmin_el=0.000000\nmax_el=90.000000\n"
        "south_zero=0\nrot_type=AzEl\ndone\n");
  CHECK(ask(p, "+\\dump_state").rfind("dump_state:\n1\n1\nmin_az=", 0) == 0);
  const std::string caps = ask(p, "1");
  CHECK(caps.find("Can set Position:\tY\n") != std::string::npos);
  CHECK(caps.find("Can Park:\tN\n") != std::string::npos);
  CHECK(ask(p, "\\dump_caps") == caps);
  CHECK(caps.find("RPRT") == std::string::npos);

  const auto q = p.handle("q");
  CHECK(q.close);
  CHECK(q.text == "RPRT 0\n");
  CHECK(p.handle("Q").close);
  CHECK(p.handle("\\quit").close);
  CHECK(!p.handle("p").close);
}

// Gpredict's rotator controller (gtk-rot-ctrl.c) each cycle reads p and sends P again when either
// axis differs from its target by more than its tolerance (5 deg by default); set to -180..180 it
// sends azimuths above 180 as az - 360. Answered in the other frame, the two never agree and it
// re-sends P every cycle (31 in 30 s against about 20). Both settings follow a target moving
// from 300 to 312 deg of azimuth in 30 one-second cycles.
TEST_CASE("rotctl: p answers in the azimuth frame of the client's P (Gpredict -180..180 and 0..360)") {
  for (const bool minus180 : {true, false}) {
    CAPTURE(minus180);
    SimStation st;
    RotctlProtocol p(*st.station);
    auto frame = [minus180](double az) { return minus180 && az > 180.0 ? az - 360.0 : az; };
    auto send_p = [&](double az, double el) {
      char line[64];
      std::snprintf(line, sizeof line, "P %.2f %.2f", frame(az), el);
      CHECK(ask(p, line) == "RPRT 0\n");
    };
    send_p(300.0, 20.0);
    REQUIRE(st.settle());
    int sent = 0;
    for (int cycle = 0; cycle < 30; ++cycle) {
      const double az = 300.0 + 0.4 * cycle, el = 20.0 + 0.1 * cycle;
      const auto [read_az, read_el] = pos_of(ask(p, "p"));
      // In the client's own frame: what it reads is comparable with what it sends.
      CHECK(read_az == doctest::Approx(frame(st.station->rotator().status().az.deg)).epsilon(1e-3));
      if (std::abs(frame(az) - read_az) > 5.0 || std::abs(el - read_el) > 5.0) {
        send_p(az, el);
        ++sent;
      }
      for (int k = 0; k < 10; ++k) st.step();
    }
    CHECK(sent <= 3);
    CHECK(p.az_frame_lo() == (minus180 ? -180.0 : 0.0));
  }
  // 0..180 says nothing about the frame; an azimuth above 180 puts it back to 0..360.
  CHECK(RotctlProtocol::in_frame(307.39, -180.0) == doctest::Approx(-52.61));
  CHECK(RotctlProtocol::in_frame(180.0, -180.0) == 180.0);
  CHECK(RotctlProtocol::in_frame(307.39, 0.0) == 307.39);
}
