// Pass planning against the rotor stop: which way round, the elevation flip, holding at the stop.
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "rotator/controller.h"
#include "rotator/pass_plan.h"
#include "rotator/simulated.h"

using namespace tb::rotator;
using namespace std::chrono_literals;
using tb::orbit::from_civil;
using tb::station::ManualClock;
using tb::station::RotorStart;

namespace {

// A synthetic pass: azimuth sweeps from az0 by `sweep` degrees (+ clockwise), fastest at the middle
// as for a high pass; elevation rises from -2 to max_el and back. n samples, one a second.
std::vector<TrackPoint> synthetic_pass(double az0, double sweep, double max_el, int n = 600) {
  std::vector<TrackPoint> t;
  const auto aos = from_civil(2026, 5, 1, 10);
  for (int i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / (n - 1);  // 0..1
    const double shape = 0.5 + std::atan(6.0 * (s - 0.5)) / (2.0 * std::atan(3.0));
    TrackPoint p;
    p.time = aos + std::chrono::seconds(i);
    p.az_deg = wrap360(az0 + sweep * shape);
    p.el_deg = -2.0 + (max_el + 2.0) * std::sin(std::numbers::pi * s);
    t.push_back(p);
  }
  return t;
}

PassGeometry geometry(RotorStart start, bool flip, double travel = 360.0) {
  RotatorConfig c;
  c.az_travel_deg = travel;
  c.el_flip_allowed = flip;
  return PassGeometry::from(AdcModel(c, start));
}

// The planned track never crosses the stop: inside the travel, and no step between samples larger
// than a satellite moves in a second (a swing through the stop would be ~360 degrees).
void check_no_swing(const PassPlan& plan, const std::vector<TrackPoint>& track) {
  RotatorPosition prev = plan.map(track[0].az_deg, track[0].el_deg);
  CHECK(prev == plan.aos);
  for (const TrackPoint& p : track) {
    RotatorPosition r = plan.map(p.az_deg, p.el_deg);
    CHECK(plan.geometry.az_travel.contains(r.az_travel));
    CHECK(plan.geometry.el.contains(r.el));
    CHECK(std::abs(r.az_travel - prev.az_travel) < 5.0);
    CHECK(std::abs(r.el - prev.el) < 5.0);
    prev = r;
  }
}

// A plan that follows the whole pass (flipped or not, as `flip` says): never held at the stop, no
// pointing error, no swing through the stop.
void check_follows(const PassPlan& plan, const std::vector<TrackPoint>& track, bool flip) {
  CHECK(plan.flip == flip);
  CHECK_FALSE(plan.held_at_stop);
  CHECK(plan.max_error_deg < 1e-6);
  check_no_swing(plan, track);
}

// A plan that cannot follow the pass without a flip: not flipped, the antenna held at the stop,
// no swing through it.
void check_held(const PassPlan& plan, const std::vector<TrackPoint>& track) {
  CHECK_FALSE(plan.flip);
  CHECK(plan.held_at_stop);
  check_no_swing(plan, track);
}

}  // namespace

TEST_CASE("A pass crossing north, North-start rotator, no flip: the antenna waits at the stop") {
  auto track = synthetic_pass(300.0, 120.0, 40.0);  // 300 -> 0 -> 60
  PassPlan plan = plan_pass(track, geometry(RotorStart::north, false));
  check_held(plan, track);
  CHECK(plan.max_error_deg > 30.0);  // it cannot follow it all
}

TEST_CASE("A pass crossing north, North-start rotator, flip allowed: over the top") {
  auto track = synthetic_pass(300.0, 120.0, 40.0);
  PassPlan plan = plan_pass(track, geometry(RotorStart::north, true));
  check_follows(plan, track, /*flip=*/true);
  // AOS at compass 300, el -2 -> flipped az 120, el 182 -> clamped to 180.
  CHECK(plan.aos.az_travel == doctest::Approx(120.0));
  CHECK(plan.aos.el == doctest::Approx(180.0));
  // At the top of the pass (compass 0, el 40): az 180, el 140.
  RotatorPosition top = plan.map(0.0, 40.0);
  CHECK(top.az_travel == doctest::Approx(180.0));
  CHECK(top.el == doctest::Approx(140.0));
}

TEST_CASE("A pass crossing south, South-start rotator: held without flip, flipped with it") {
  auto track = synthetic_pass(120.0, 120.0, 55.0);  // 120 -> 180 -> 240
  PassPlan held = plan_pass(track, geometry(RotorStart::south, false));
  check_held(held, track);

  PassPlan flipped = plan_pass(track, geometry(RotorStart::south, true));
  check_follows(flipped, track, /*flip=*/true);
  // Flipped azimuths 300 -> 0 -> 60 are travel 120 -> 180 -> 240 for a South start.
  CHECK(flipped.aos.az_travel == doctest::Approx(120.0));
  CHECK(flipped.map(180.0, 55.0).az_travel == doctest::Approx(180.0));
}

TEST_CASE("No flip when the pass does not need it") {
  // Crossing north is no problem for a South-start rotator.
  auto north = synthetic_pass(300.0, 120.0, 70.0);
  PassPlan a = plan_pass(north, geometry(RotorStart::south, true));
  check_follows(a, north, /*flip=*/false);
  CHECK(a.aos.az_travel == doctest::Approx(120.0));
  // Nor crossing south for a North-start one, also going counter-clockwise.
  auto south = synthetic_pass(250.0, -140.0, 30.0);
  PassPlan b = plan_pass(south, geometry(RotorStart::north, true));
  CHECK_FALSE(b.flip);
  CHECK_FALSE(b.held_at_stop);
  CHECK(b.aos.az_travel == doctest::Approx(250.0));
  check_no_swing(b, south);
}

TEST_CASE("A 450-degree rotator follows a pass across north through its overlap") {
  auto track = synthetic_pass(300.0, 120.0, 40.0);
  PassPlan plan = plan_pass(track, geometry(RotorStart::north, true, 450.0));
  CHECK_FALSE(plan.flip);
  CHECK_FALSE(plan.held_at_stop);
  CHECK(plan.aos.az_travel == doctest::Approx(300.0));
  CHECK(plan.map(60.0, -2.0).az_travel == doctest::Approx(420.0));
  check_no_swing(plan, track);
  // Counter-clockwise from 80 to 320 through north needs the overlap the other way: 440 -> 320.
  auto ccw = synthetic_pass(80.0, -120.0, 40.0);
  PassPlan p2 = plan_pass(ccw, geometry(RotorStart::north, false, 450.0));
  CHECK_FALSE(p2.held_at_stop);
  CHECK(p2.aos.az_travel == doctest::Approx(440.0));
  check_no_swing(p2, ccw);
}

TEST_CASE("Two ways round that both fit: the shorter slew from where the antenna is") {
  auto track = synthetic_pass(10.0, 70.0, 20.0);  // 10 -> 80, fits at 10..80 and 370..440
  PassGeometry g = geometry(RotorStart::north, false, 450.0);
  CHECK(plan_pass(track, g, 400.0).aos.az_travel == doctest::Approx(370.0));
  CHECK(plan_pass(track, g, 50.0).aos.az_travel == doctest::Approx(10.0));
}

TEST_CASE("A pass that crosses the stop just after AOS waits a moment at the stop, then follows") {
  auto track = synthetic_pass(2.0, -62.0, 25.0);  // 2 -> 0 -> 300
  PassPlan plan = plan_pass(track, geometry(RotorStart::north, false));
  CHECK_FALSE(plan.flip);
  CHECK(plan.held_at_stop);
  CHECK(plan.aos.az_travel == doctest::Approx(360.0));
  CHECK(plan.max_error_deg < 2.5);
  check_no_swing(plan, track);
}

TEST_CASE("Pass plans respect the rotation limits") {
  RotatorConfig c;
  c.el_flip_allowed = true;
  c.limits_enabled = true;
  c.az_limit_min = 20;
  c.az_limit_max = 340;
  c.el_limit_min = 5;
  c.el_limit_max = 170;
  PassGeometry g = PassGeometry::from(AdcModel(c, RotorStart::north));
  CHECK(g.az_travel.lo == doctest::Approx(20.0));
  CHECK(g.el.hi == doctest::Approx(170.0));
  auto track = synthetic_pass(300.0, 120.0, 60.0);
  PassPlan plan = plan_pass(track, g);
  CHECK(plan.flip);
  check_no_swing(plan, track);
}

TEST_CASE("slew_seconds and an empty track") {
  RotatorConfig c;
  CHECK(slew_seconds({0, 0}, {120, 30}, c) == doctest::Approx(20.0 + 0.15));
  CHECK(slew_seconds({0, 0}, {12, 90}, c) == doctest::Approx(30.0 + 0.15));
  PassPlan p = plan_pass({}, geometry(RotorStart::north, false));
  CHECK_FALSE(p.flip);
  CHECK(p.map(90.0, 10.0) == RotatorPosition{90.0, 10.0});
  CHECK(pointing_error_deg(10, 0, 350, 0) == doctest::Approx(20.0));
  CHECK(pointing_error_deg(0, 90, 180, 90) == doctest::Approx(0.0).epsilon(1e-6));
}

TEST_CASE("Controller and simulated rotator follow a flipped pass without swinging through the stop") {
  spdlog::set_level(spdlog::level::off);
  RotatorConfig c;
  c.el_flip_allowed = true;  // flip mode: the factory span 0..511 is 0..180 deg
  auto track = synthetic_pass(300.0, 120.0, 60.0, 480);
  PassPlan plan = plan_pass(track, PassGeometry::from(AdcModel(c, RotorStart::north)), 0.0);
  REQUIRE(plan.flip);

  ManualClock clock(track.front().time - std::chrono::minutes(2));
  auto owned = std::make_unique<SimulatedRotator>(clock, SimulatedRotatorParams::matching(c));
  SimulatedRotator& sim = *owned;
  Controller ctl(c, RotorStart::north, std::move(owned));
  // Ahead of AOS: to the AOS position (120 deg of azimuth, 60 s; elevation to 180, 60 s).
  CHECK(slew_seconds({0, 0}, plan.aos, c) < 120.0);
  ctl.set_target(plan.aos);
  while (clock.now() < track.front().time) {
    clock.advance(100ms);
    ctl.tick(clock.now());
  }
  CHECK(ctl.status().on_target);
  double prev = sim.true_position().az_travel, worst = 0.0;
  bool jump = false;
  for (const TrackPoint& p : track) {
    ctl.set_target(plan.map(p.az_deg, p.el_deg));
    for (int i = 0; i < 10; ++i) {
      clock.advance(100ms);
      ctl.tick(clock.now());
      double now = sim.true_position().az_travel;
      if (std::abs(now - prev) > 1.0) jump = true;
      prev = now;
    }
    RotatorPosition at = sim.true_position();
    double az = at.az_travel, el = at.el;
    if (el > 90.0) {
      az += 180.0;
      el = 180.0 - el;
    }
    if (p.el_deg > 0.0) worst = std::max(worst, pointing_error_deg(p.az_deg, p.el_deg, wrap360(az), el));
  }
  CHECK_FALSE(jump);
  CHECK(worst < 3.0);  // within a few dead bands of the satellite all pass long
}

namespace {

// A pass along a great circle tilted `miss` degrees from the zenith towards the east: from north
// (AOS, azimuth 0) over the sky to south, its culmination at azimuth 90, elevation 90 - miss. One
// sample every 5 s over 600 s (ENU vector (sin s sin d, cos s, sin s cos d), s from 0 to 180 deg);
// with `iss`, one sample a second over 200 s, the satellite moving 0.9 deg/s as the ISS does overhead.
std::vector<TrackPoint> zenith_pass(double miss, bool iss = false) {
  constexpr double k = std::numbers::pi / 180.0;
  std::vector<TrackPoint> t;
  const auto aos = from_civil(2026, 5, 23, 13, 45);
  const int step = iss ? 1 : 5;
  const double rate = iss ? 0.9 : 0.3;
  for (int i = 0; i * step * rate <= 180.0 + 1e-9; ++i) {
    const double s = rate * step * i * k;
    const double e = std::sin(s) * std::sin(miss * k), n = std::cos(s), u = std::sin(s) * std::cos(miss * k);
    TrackPoint p;
    p.time = aos + std::chrono::seconds(step * i);
    p.az_deg = wrap360(std::atan2(e, n) / k);
    p.el_deg = std::asin(std::clamp(u, -1.0, 1.0)) / k;
    t.push_back(p);
  }
  return t;
}

}  // namespace

TEST_CASE("A pass through the zenith on a rotator that can flip: over the top in one vertical plane") {
  const auto track = zenith_pass(1.2);  // culminates at 88.8 deg, azimuth 90
  const PassGeometry g = geometry(RotorStart::south, true);
  REQUIRE(g.flip_allowed);
  REQUIRE(g.az_rate_deg_s == doctest::Approx(6.0));
  const PassPlan plan = plan_pass(track, g);
  CHECK(plan.over_top);
  CHECK_FALSE(plan.flip);
  CHECK(std::min(plan.plane_az, 360.0 - plan.plane_az) < 0.05);  // north: perpendicular to 90, the AOS side
  CHECK(plan.peak_az_rate_deg_s > 6.0);
  // The largest error is at the culmination: the antenna at the zenith, the satellite 1.2 deg off.
  CHECK(plan.max_error_deg == doctest::Approx(1.2).epsilon(1e-6));
  CHECK(plan.coverage.full());
  // The azimuth stays where it is; the elevation runs 0 -> 90 -> 180 without a step.
  const RotatorPosition first = plan.map(track.front().az_deg, track.front().el_deg);
  CHECK(first == plan.aos);
  CHECK(first.el == doctest::Approx(0.0).epsilon(1e-9));
  RotatorPosition prev = first;
  for (const TrackPoint& p : track) {
    const RotatorPosition r = plan.map(p.az_deg, p.el_deg);
    CHECK(r.az_travel == doctest::Approx(first.az_travel));
    CHECK(r.el >= prev.el - 1e-9);
    CHECK(r.el - prev.el < 8.0);
    prev = r;
  }
  CHECK(prev.el == doctest::Approx(180.0).epsilon(1e-6));
  CHECK_FALSE(plan.lost_at(track[60].az_deg, track[60].el_deg));
}

TEST_CASE("A pass through the zenith without a flip, or one the motor keeps up with: no over-the-top plan") {
  const auto track = zenith_pass(1.2);
  const PassPlan plain = plan_pass(track, geometry(RotorStart::south, false));
  CHECK_FALSE(plain.over_top);
  CHECK(plain.peak_az_rate_deg_s > 6.0);
  // A 60-degree pass: the azimuth turns at most about 1.7 deg/s between 5 s samples.
  const PassPlan low = plan_pass(zenith_pass(30.0), geometry(RotorStart::south, true));
  CHECK_FALSE(low.over_top);
  CHECK(low.peak_az_rate_deg_s < 6.0);
}

TEST_CASE("A pass through the zenith without a flip: the keyhole's turn begins before the culmination") {
  // 88.8 deg at 13:46:40 (azimuth 90); near it the azimuth turns 43 deg/s, the motor 6.
  const auto track = zenith_pass(1.2, true);
  const PassPlan plan = plan_pass(track, geometry(RotorStart::south, false));
  CHECK_FALSE(plan.over_top);
  CHECK_FALSE(plan.flip);
  REQUIRE(plan.lead.size() > 10);
  CHECK(plan.lead_rate_deg_s == doctest::Approx(5.4));
  const auto tca = from_civil(2026, 5, 23, 13, 46, 40);
  CHECK(plan.lead.front().time < tca - 5s);  // the turn begins well before the culmination
  CHECK(plan.lead.back().time > tca);
  // The schedule within the rate the plan assumes, and every sample within the plan's largest error.
  for (std::size_t i = 1; i < plan.lead.size(); ++i) {
    const double dt = tb::orbit::minutes_between(plan.lead[i - 1].time, plan.lead[i].time) * 60.0;
    CHECK(std::abs(plan.lead[i].az_travel - plan.lead[i - 1].az_travel) <= plan.lead_rate_deg_s * dt + 1e-9);
  }
  double worst = 0.0;
  for (const TrackPoint& p : track) {
    const RotatorPosition r = plan.map_at(p.time, p.az_deg, p.el_deg);
    const double e = pointing_error_deg(wrap360(r.az_travel + 180.0), r.el, p.az_deg, std::max(p.el_deg, 0.0));
    worst = std::max(worst, e);
  }
  CHECK(worst == doctest::Approx(plan.max_error_deg).epsilon(1e-9));
  // Chasing the satellite at 6 deg/s the antenna falls behind by ~15 deg (half the turn still to do
  // 15 s after the culmination, the satellite 13 deg from the zenith); the keyhole halves the
  // largest error at least.
  CHECK(plan.following_error_deg > 10.0);
  CHECK(plan.max_error_deg < 0.5 * plan.following_error_deg);
  // Outside the keyhole the azimuth is the satellite's.
  CHECK(plan.map_at(track[10].time, track[10].az_deg, track[10].el_deg) == plan.map(track[10].az_deg, track[10].el_deg));
  const std::string text = plan.keyhole_text();
  CHECK(text.rfind("keyhole 13:46:", 0) == 0);
  CHECK(text.find("at 5.4 deg/s: at most ") != std::string::npos);

  // The same pass on a rotator that can flip goes over the top instead; a 60-degree pass needs
  // neither.
  CHECK(plan_pass(track, geometry(RotorStart::south, true)).lead.empty());
  CHECK(plan_pass(zenith_pass(30.0, true), geometry(RotorStart::south, false)).lead.empty());
}

TEST_CASE("The controller and simulated rotator on the keyhole's schedule stay within the plan's error") {
  spdlog::set_level(spdlog::level::off);
  RotatorConfig c;
  const auto track = zenith_pass(1.2, true);
  const PassPlan plan = plan_pass(track, PassGeometry::from(AdcModel(c, RotorStart::south)));
  REQUIRE_FALSE(plan.lead.empty());
  // The same rotator twice: once on the plan's schedule, once chasing the satellite.
  double worst_planned = 0.0, worst_chasing = 0.0;
  for (const bool planned : {true, false}) {
    ManualClock clock(track.front().time - std::chrono::minutes(1));
    auto owned = std::make_unique<SimulatedRotator>(clock, SimulatedRotatorParams::matching(c));
    SimulatedRotator& sim = *owned;
    Controller ctl(c, RotorStart::south, std::move(owned));
    ctl.set_target(plan.aos);
    while (clock.now() < track.front().time) {
      clock.advance(100ms);
      ctl.tick(clock.now());
    }
    double& worst = planned ? worst_planned : worst_chasing;
    for (const TrackPoint& p : track) {
      ctl.set_target(planned ? plan.map_at(p.time, p.az_deg, p.el_deg) : plan.map(p.az_deg, p.el_deg));
      for (int i = 0; i < 10; ++i) {
        clock.advance(100ms);
        ctl.tick(clock.now());
      }
      const RotatorPosition at = sim.true_position();
      if (p.el_deg > 0.0) worst = std::max(worst, pointing_error_deg(p.az_deg, p.el_deg, wrap360(at.az_travel + 180.0), at.el));
    }
  }
  MESSAGE("keyhole: worst ", worst_planned, " deg (plan ", plan.max_error_deg, "); chasing: ", worst_chasing,
          " deg (plan's estimate ", plan.following_error_deg, ")");
  CHECK(worst_planned < plan.max_error_deg + 1.5);  // the dead band and the motor's coast
  CHECK(worst_chasing > plan.following_error_deg - 1.5);
  CHECK(worst_planned < 0.5 * worst_chasing);
}

TEST_CASE("Pass sample times: every coarse step, every second near the culmination, AOS and LOS") {
  const auto aos = from_civil(2026, 5, 23, 13, 45);
  const auto ts = pass_sample_times(aos, aos + 300s, aos + 600s, 10.0, 60.0);
  REQUIRE(ts.size() == 61 + 120 - 12);   // 61 coarse, 121 fine, 13 of them shared
  CHECK(ts.front() == aos);
  CHECK(ts.back() == aos + 600s);
  CHECK(std::is_sorted(ts.begin(), ts.end()));
  CHECK(std::count(ts.begin(), ts.end(), aos + 300s) == 1);
  CHECK(std::count(ts.begin(), ts.end(), aos + 241s) == 1);
  CHECK(std::count(ts.begin(), ts.end(), aos + 239s) == 0);
  // A culmination at the edge, an uneven span: LOS kept.
  const auto edge = pass_sample_times(aos, aos, aos + 95500ms, 10.0, 5.0);
  CHECK(edge.back() == aos + 95500ms);
  CHECK(edge[1] == aos + 1s);
  CHECK(pass_sample_times(aos, aos, aos).size() == 1);
}

TEST_CASE("Wound: more than a turn from the stop, where the travel also reaches one turn back") {
  RotatorConfig c;
  c.az_travel_deg = 450.0;
  const AdcModel m(c, RotorStart::north);
  CHECK(m.unwound_travel(400.0) == std::optional<double>(40.0));
  CHECK(m.unwound_travel(450.0) == std::optional<double>(90.0));
  CHECK_FALSE(m.unwound_travel(360.0));   // north at the stop's own turn
  CHECK_FALSE(m.unwound_travel(360.4));
  CHECK_FALSE(m.unwound_travel(200.0));
  CHECK_FALSE(AdcModel(RotatorConfig{}, RotorStart::south).unwound_travel(359.0));  // 360 degrees: never
}
