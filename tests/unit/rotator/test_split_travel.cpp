// Limits that split the travel (issue 21): a South rotor start (stop at 180) with azimuth limits
// 10..350 leaves two pieces of travel, 180..350 and 10..180 (compass), with the excluded 350..10
// between them. The pieces, the operator's warning, the pass planner's choice on the real ISS pass
// 335 -> 101 of 2026-05-22 12:57 (the one the soak found held at 349.97 for its whole length), and
// that the controller never drives across the excluded sector when the limits are barriers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fixture.h"
#include "orbit/elements.h"
#include "orbit/observe.h"
#include "orbit/sgp4.h"
#include "rotator/pass_plan.h"
#include "rotator/split_travel.h"

using namespace tb::rotator;
using namespace std::chrono_literals;
using tb::orbit::from_civil;
using tb::station::RotorStart;

namespace {

RotatorConfig limits_10_350(bool cross = false) {
  RotatorConfig c;
  c.limits_enabled = true;
  c.az_limit_min = 10;
  c.az_limit_max = 350;
  c.el_limit_min = 0;
  c.el_limit_max = 80;
  c.cross_limit_sector = cross;
  return c;
}

// The shipped ISS set (data/amateur.tle) and the manual's station (27.391 N, 128.657 E, 50 m).
std::vector<TrackPoint> iss_pass_335_to_101() {
  const auto parsed = tb::orbit::parse_elements(
      "ISS\n"
      "1 25544U 98067A   26141.16510469  .00005835  00000-0  11282-3 0  9994\n"
      "2 25544  51.6328  73.8715 0007529  81.3651 278.8190 15.49291753567565\n");
  REQUIRE(parsed.sets.size() == 1);
  const tb::orbit::Sgp4 sat(parsed.sets[0]);
  const tb::orbit::Observer station{27.391, 128.657, 50.0};
  // AOS 12:57:01, LOS 13:07:37 (trakbox passes), sampled as StationLoop::plan_for does: 63 even
  // steps of 636/63 s.
  const auto aos = from_civil(2026, 5, 22, 12, 57, 1);
  std::vector<TrackPoint> track;
  for (int k = 0; k <= 63; ++k) {
    const auto t = aos + std::chrono::microseconds(636'000'000LL * k / 63);
    const auto o = tb::orbit::observe(sat, station, t);
    REQUIRE(o.ok());
    track.push_back({t, o.look.az_deg, std::max(0.0, o.look.el_deg)});
  }
  return track;
}

}  // namespace

TEST_CASE("South start, limits 10..350: two pieces of travel, 180..350 and 10..180") {
  AdcModel m(limits_10_350(), RotorStart::south);
  const auto pieces = m.az_pieces();
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].lo == doctest::Approx(0.0));
  CHECK(pieces[0].hi == doctest::Approx(170.0));
  CHECK(pieces[1].lo == doctest::Approx(190.0));
  CHECK(pieces[1].hi == doctest::Approx(360.0));
  CHECK(m.travel_split());
  CHECK(compass_sector_text(RotorStart::south, pieces[0]) == "180.0-350.0");
  CHECK(compass_sector_text(RotorStart::south, pieces[1]) == "10.0-180.0");
  // Equal pieces: the first is in force until the antenna says otherwise.
  CHECK(m.az_piece() == 0);
  CHECK(m.az_piece_of(100.0) == 0);
  CHECK(m.az_piece_of(300.0) == 1);
  CHECK(m.az_piece_of(175.0) == 0);  // in the excluded sector: the nearest piece
  CHECK(m.az_piece_of(186.0) == 1);
  CHECK(m.az_piece_for_compass(340.0) == 0);
  CHECK(m.az_piece_for_compass(30.0) == 1);
  CHECK_FALSE(m.az_piece_for_compass(0.0).has_value());
  m.set_az_piece(1);
  CHECK(m.az_travel_range().lo == doctest::Approx(190.0));
  CHECK(m.travel_for(340.0, 300.0) == doctest::Approx(190.0));  // outside the piece: its nearest limit
  // A North start with the same limits: one piece, the stop at a limit's far side.
  AdcModel north(limits_10_350(), RotorStart::north);
  CHECK_FALSE(north.travel_split());
  CHECK(north.az_travel_range().lo == doctest::Approx(10.0));
  CHECK(north.az_travel_range().hi == doctest::Approx(350.0));
  // A North start with limits 250..90: 250..360 (the longer, in force by default) and 0..90.
  RotatorConfig c = limits_10_350();
  c.az_limit_min = 250;
  c.az_limit_max = 90;
  AdcModel n2(c, RotorStart::north);
  REQUIRE(n2.az_pieces().size() == 2);
  CHECK(compass_sector_text(RotorStart::north, n2.az_pieces()[0]) == "0.0-90.0");
  CHECK(compass_sector_text(RotorStart::north, n2.az_pieces()[1]) == "250.0-360.0");
  CHECK(n2.az_piece() == 1);
}

TEST_CASE("The warning when limits split the travel, with barriers and with crossing") {
  CHECK(split_travel_warning(limits_10_350(), RotorStart::south) ==
        "Limits split the travel: with the rotor stop at 180.0 (South start) the antenna can reach 180.0-350.0 or "
        "10.0-180.0, and keeps to the one it is in, as the limits bar the excluded 350.0-10.0 between them. A pass "
        "is followed as far as that piece allows; the realtime display says how much (--cross-limit-sector yes lets it "
        "cross between passes).");
  CHECK(split_travel_warning(limits_10_350(true), RotorStart::south) ==
        "Limits split the travel: with the rotor stop at 180.0 (South start) the antenna can reach 180.0-350.0 or "
        "10.0-180.0, and may cross between passes (never during one), as the limits are pointing limits only. A "
        "pass is followed in the piece that covers the most of it; the realtime display says how much.");
  CHECK_FALSE(split_travel_warning(limits_10_350(), RotorStart::north).has_value());
  CHECK_FALSE(split_travel_warning(RotatorConfig{}, RotorStart::south).has_value());
  RotatorConfig off = limits_10_350();
  off.limits_enabled = false;
  CHECK_FALSE(split_travel_warning(off, RotorStart::south).has_value());
}

TEST_CASE("Planner on the ISS pass 335 -> 101, South start, limits 10..350") {
  const auto track = iss_pass_335_to_101();
  REQUIRE(track.front().az_deg == doctest::Approx(334.9).epsilon(0.001));
  REQUIRE(track.back().az_deg == doctest::Approx(100.9).epsilon(0.001));

  SUBCASE("crossing between passes: the piece that covers the most of the pass") {
    AdcModel m(limits_10_350(true), RotorStart::south);
    const PassPlan plan = plan_pass(track, PassGeometry::from(m, true), 160.0);
    CHECK(plan.geometry.piece == 1);
    CHECK(plan.coverage.samples == 64);
    CHECK(plan.coverage.followed == 41);  // 13 samples lie in 180..350, 10 in the excluded 350..10
    CHECK(plan.coverage_text() == "antenna on target 13:00:53-13:07:37 (64% of the pass): it reaches azimuth 10.0-180.0");
    CHECK(plan.aos.az_travel == doctest::Approx(190.0));  // waits at 10 for the satellite to come round
    // Once the pass has begun, no crossing: the piece in force only.
    const PassPlan during = plan_pass(track, PassGeometry::from(m, false), 160.0);
    CHECK(during.geometry.piece == 0);
  }
  SUBCASE("a rotator that turns all the way round reaches all azimuths, said once (issue 30)") {
    const PassPlan plan = plan_pass(track, PassGeometry::from(AdcModel(RotatorConfig{}, RotorStart::south), true), 160.0);
    const std::string text = plan.coverage_text();
    CHECK(text.find("it reaches all azimuths") != std::string::npos);
    CHECK(text.find("azimuth all") == std::string::npos);
  }
  SUBCASE("barriers: the piece the antenna is in, with its coverage") {
    AdcModel m(limits_10_350(), RotorStart::south);
    m.set_az_piece(m.az_piece_of(160.0));  // the antenna at 340
    const PassPlan plan = plan_pass(track, PassGeometry::from(m, true), 160.0);
    CHECK(plan.geometry.piece == 0);
    CHECK(plan.coverage.followed == 13);
    // Of the time: 13 samples 10.1 s apart, each standing for half the time to its neighbours (the
    // first for 5 s): 126 s of the pass's 636 s, 19.8%.
    CHECK(plan.coverage_text() == "antenna on target 12:57:01-12:59:02 (19% of the pass): it reaches azimuth 180.0-350.0");
    CHECK_FALSE(plan.coverage.full());
    for (const TrackPoint& p : track) CHECK(plan.map(p.az_deg, p.el_deg).az_travel <= 170.0);
  }
  SUBCASE("a pass wholly in the excluded sector, or the other piece, is said to be outside the limits") {
    AdcModel m(limits_10_350(), RotorStart::south);
    m.set_az_piece(0);
    std::vector<TrackPoint> east(track.end() - 20, track.end());  // 30..101 deg, in the other piece
    const PassPlan plan = plan_pass(east, PassGeometry::from(m, true), 160.0);
    CHECK(plan.coverage.followed == 0);
    CHECK(plan.coverage_text() == "PASS OUT OF ANTENNA REACH (it reaches azimuth 180.0-350.0)");
  }
}

TEST_CASE("With barriers the controller never drives across the excluded sector or outside the limits") {
  // The antenna at compass 340 (travel 160), in the piece 180..350.
  rotator_test::Rig rig(limits_10_350(), RotorStart::south, {160.0, 10.0});
  const AdcModel& m = rig.ctl->model();
  CHECK(m.az_piece() == 0);
  const auto piece = m.counts_range(Axis::az);
  double highest = 0.0;
  auto watch = [&] {
    highest = std::max(highest, rig.sim->true_position().az_travel);
    if (const auto& g = rig.ctl->status().az.goal_counts) {
      CHECK(*g >= piece.lo - 1e-9);
      CHECK(*g <= piece.hi + 1e-9);
    }
  };
  // A target in the other piece (compass 30) goes to this piece's nearest limit, 350.
  const RotatorPosition t = rig.ctl->set_target(AzEl{30.0, 10.0});
  CHECK(t.az_travel == doctest::Approx(170.0));
  rig.run(60s, 100ms, watch);
  rig.idle(10s);
  CHECK(highest <= 170.5);
  // Nor does the planner's choice move it: select_az_piece refuses the other piece.
  CHECK_FALSE(rig.ctl->select_az_piece(1));
  CHECK(rig.ctl->model().az_piece() == 0);
  // The real pass, followed through the plan, every 1 s.
  const auto track = iss_pass_335_to_101();
  const PassPlan plan = plan_pass(track, PassGeometry::from(rig.ctl->model(), true), 160.0);
  for (const TrackPoint& p : track) {
    rig.ctl->set_target(plan.map(p.az_deg, p.el_deg));
    for (int i = 0; i < 10; ++i) rig.run(1s, 1s, watch);
  }
  CHECK(highest <= 170.5);
  CHECK(rig.sim->true_position().az_travel == doctest::Approx(170.0).epsilon(0.01));
  // Park and presets do not cross either.
  RotatorConfig c = limits_10_350();
  c.parking_enabled = true;
  c.parking = {30.0, 5.0};
  rig.ctl->set_config(c, RotorStart::south);
  CHECK(rig.ctl->model().az_piece() == 0);
  rig.ctl->park();
  CHECK(rig.ctl->status().target->az_travel == doctest::Approx(170.0));
}

TEST_CASE("Crossing allowed: the antenna moves to the other piece when asked, through the excluded sector") {
  RotatorConfig c = limits_10_350(true);
  c.parking_enabled = true;
  c.parking = {30.0, 5.0};
  rotator_test::Rig rig(c, RotorStart::south, {160.0, 10.0});
  CHECK(rig.ctl->model().az_piece() == 0);
  CHECK(rig.ctl->select_az_piece(1));
  rig.ctl->set_target(RotatorPosition{200.0, 10.0});
  rig.run(60s);
  CHECK(rig.ctl->status().on_target);
  CHECK(rig.sim->true_position().az_travel == doctest::Approx(200.0).epsilon(0.01));
  // Park goes to the piece that holds the parking position (10..180: compass 30 is travel 210).
  CHECK(rig.ctl->select_az_piece(0));
  rig.ctl->park();
  CHECK(rig.ctl->model().az_piece() == 1);
  CHECK(rig.ctl->status().target->az_travel == doctest::Approx(210.0));
  CHECK_FALSE(rig.ctl->select_az_piece(2));
}

TEST_CASE("compass sectors an operator reads: a whole turn, one azimuth, a sector (issue 30)") {
  using tb::rotator::compass_sector_text;
  CHECK(compass_sector_text(tb::station::RotorStart::south, {0.0, 360.0}) == "all azimuths");
  CHECK(compass_sector_text(tb::station::RotorStart::south, {0.0, 450.0}) == "all azimuths");
  CHECK(compass_sector_text(tb::station::RotorStart::south, {10.0, 10.0}) == "190.0 only");
  CHECK(compass_sector_text(tb::station::RotorStart::north, {10.0, 180.0}) == "10.0-180.0");
}
