// Issue 19, items 2, 3 and 7 on the unit: STEP smaller than the dead band, MOVE's steady jog and
// its STATUS? flags, STOP= through the coast, and who owns the antenna while the unit tracks.
#include "fixture.h"

using namespace satrak_test;
using namespace std::chrono_literals;

namespace {
constexpr double kAzCount = 360.0 / 1023.0, kElCount = 90.0 / 511.0;

// GOTO and wait until at rest; returns the reading (X2, X3).
std::pair<double, double> park_at(Acu& acu, const std::string& az, const std::string& el) {
  REQUIRE(acu.cmd("GOTO=," + az + "," + el) == "GOTO=,OK");
  acu.run(40s);
  REQUIRE(acu.status(12) == "0");
  REQUIRE(acu.status(13) == "0");
  return {acu.status_num(2), acu.status_num(3)};
}
}  // namespace

TEST_CASE("STEP=,1,0 moves by the step although 1 deg is inside the 3-count dead band") {
  Acu acu(kT0);
  auto [az, el] = park_at(acu, "100", "30");
  struct Case {
    const char* cmd;
    double daz, del;
  };
  for (const Case& c : {Case{"STEP=,1,0", 1, 0}, Case{"STEP=,-1,0", -1, 0}, Case{"STEP=,0,1", 0, 1},
                        Case{"STEP=,0,-1", 0, -1}, Case{"STEP=,0.5,0", 0.5, 0}}) {
    CAPTURE(c.cmd);
    CHECK(acu.cmd(c.cmd) == std::string(c.cmd).substr(0, 5) + ",OK");
    acu.step();
    CHECK((acu.status(12) != "0" || acu.status(13) != "0"));
    acu.run(3s);
    CHECK(acu.status(12) == "0");
    CHECK(acu.status(13) == "0");
    const double az2 = acu.status_num(2), el2 = acu.status_num(3);
    CHECK(std::abs(az2 - az - c.daz) <= kAzCount + 1e-6);
    CHECK(std::abs(el2 - el - c.del) <= kElCount + 1e-6);
    az = az2;
    el = el2;
  }
  // A GOTO 0.7 deg away (two counts) moves too.
  CHECK(acu.cmd("GOTO=," + tb::satrak::format_fixed(az + 0.7, 2) + ",NONE") == "GOTO=,OK");
  acu.run(3s);
  CHECK(std::abs(acu.status_num(2) - az - 0.7) <= kAzCount / 2 + 0.01);
  // Tracking's dead band is unchanged: the configuration still says 3 counts.
  CHECK(acu.loop->rotator().model().dead_band(rotator::Axis::az) == 3);
}

TEST_CASE("MOVE=,1,-1 moves both axes steadily with the flags at 1/-1; STOP= ends it within the coast") {
  Acu acu(kT0);
  park_at(acu, "100", "30");
  CHECK(acu.cmd("MOVE=,1,-1") == "MOVE=,OK");
  acu.run(300ms);
  const auto p0 = acu.rot->true_position();
  auto last = p0;
  for (int i = 0; i < 30; ++i) {
    acu.step();
    CHECK(acu.status(12) == "1");
    CHECK(acu.status(13) == "-1");
    const auto p = acu.rot->true_position();
    CHECK(p.az_travel - last.az_travel >= 0.05);  // every 100 ms: no pause, no burst
    CHECK(p.az_travel - last.az_travel <= 0.15);
    CHECK(last.el - p.el >= 0.05);
    last = p;
  }
  CHECK(last.az_travel - p0.az_travel == doctest::Approx(3.0).epsilon(0.05));
  CHECK(p0.el - last.el == doctest::Approx(3.0).epsilon(0.05));
  CHECK(acu.cmd("STOP=") == "STOP=,OK");
  CHECK(acu.rot->motion().az == rotator::Drive::stop);  // the lines are off at once
  CHECK(acu.status(12) == "1");                        // but it still coasts
  bool said_still = false;
  auto prev = acu.rot->true_position();
  for (int i = 0; i < 20; ++i) {
    acu.step();
    const auto p = acu.rot->true_position();
    if (said_still) CHECK(p == prev);  // 0 only once it no longer moves
    said_still = acu.status(12) == "0" && acu.status(13) == "0";
    prev = p;
  }
  CHECK(said_still);
  CHECK(prev.az_travel - last.az_travel <= 1.0 * 0.15 + 0.1 + 1e-6);  // the coast and the last tick
}

TEST_CASE("While the unit tracks, MOVE/STEP/GOTO are refused with ERR,8; STOP= or TRACK=,0 hands the antenna back") {
  Acu acu(kT0);
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  REQUIRE(acu.cmd("TRACK=,1") == "TRACK=,OK");
  acu.run(1s);
  for (const char* c : {"GOTO=,10,10", "GOTO=,NONE,40", "STEP=,1,0", "MOVE=,1,0", "MOVE=,0,-1"}) {
    CAPTURE(c);
    CHECK(acu.cmd(c) == std::string(c).substr(0, 5) + ",ERR,8,TRACKING: STOP= FIRST");
    CHECK(acu.unit->tracking());
    CHECK(acu.status(8) == "1");
  }
  CHECK(acu.cmd("MOVE=,0,0") == "MOVE=,OK");  // a button release: nothing to refuse
  CHECK(acu.unit->tracking());
  CHECK(acu.errstatus(6) == "0");
  acu.run(1s);
  CHECK(acu.unit->tracking());

  SUBCASE("STOP= ends tracking; then GOTO is accepted") {
    CHECK(acu.cmd("STOP=") == "STOP=,OK");
    CHECK(acu.status(8) == "0");
    CHECK(acu.cmd("GOTO=,10,10") == "GOTO=,OK");
  }
  SUBCASE("TRACK=,0 likewise") {
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    CHECK(acu.cmd("STEP=,1,0") == "STEP=,OK");
    CHECK(acu.errstatus(6) == "0");  // stopped by request, not a fault
  }
  SUBCASE("Going to the track window's start is tracking's too") {
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    const auto start = std::chrono::floor<std::chrono::seconds>(kT0 + 120s);
    const auto c = [](orbit::UtcTime t) {
      const auto v = orbit::to_civil(t);
      return std::to_string(v.hour) + "," + std::to_string(v.minute) + "," + std::to_string(static_cast<int>(v.second)) +
             "," + std::to_string(v.day) + "," + std::to_string(v.month) + "," + std::to_string(v.year);
    };
    CHECK(acu.cmd("START_STOP_TIME=," + c(start) + "," + c(start + 3600s)) == "START_STOP_TIME=,OK");
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,600000,?,?,?,?,?,?") == "SETTINGS=,OK");
    CHECK(acu.cmd("TRACK_AUTO_ENABLE=,1") == "TRACK_AUTO_ENABLE=,OK");
    acu.run(1s);
    CHECK(acu.status(9) == "3");
    CHECK(acu.cmd("GOTO=,10,10") == "GOTO=,ERR,8,TRACKING: STOP= FIRST");
    CHECK(acu.cmd("STOP=") == "STOP=,OK");
  }
}
