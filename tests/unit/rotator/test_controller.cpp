// The controller on the simulated rotator: pointing, dead band, the way round, park, presets,
// keyboard control, the E key, faults, stalls, calibration and the monitor line.
#include <doctest/doctest.h>

#include <tuple>

#include <cmath>

#include "fixture.h"  // Rig
#include "rotator/calibration.h"
#include "rotator/controller.h"
#include "rotator/simulated.h"

using namespace tb::rotator;
using namespace std::chrono_literals;
using tb::station::RotorStart;
using rotator_test::Rig;

namespace {

bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }
bool near(RotatorPosition a, RotatorPosition b, double tol = 0.01) {
  return near(a.az_travel, b.az_travel, tol) && near(a.el, b.el, tol);
}
constexpr double kAzBand = 3 * 360.0 / 1023;  // the default dead bands in degrees
constexpr double kElBand = 1 * 90.0 / 511;

// On target at compass (az, el): inside the dead bands, give or take the reading's last step.
void check_settled_at(const Status& s, double az, double el) {
  CHECK(s.on_target);
  CHECK(near(s.az.deg, az, kAzBand + 0.2));
  CHECK(near(s.el.deg, el, kElBand + 0.1));
}

}  // namespace

TEST_CASE("Points the simulated rotator at a target and settles inside the dead band") {
  Rig rig;
  RotatorPosition t = rig.ctl->set_target(AzEl{90.0, 45.0});
  CHECK(t == RotatorPosition{90.0, 45.0});
  auto took = rig.run(60s);
  CHECK(took < 60s);
  // 90 deg at 6 deg/s: about 15 s plus the spin-up.
  CHECK(took <= 16s);
  const Status& s = rig.ctl->status();
  CHECK(s.on_target);
  CHECK(std::abs(s.az.counts - 256) <= 3);
  CHECK(std::abs(s.el.counts - 256) <= 1);  // 45 deg = 255.5 -> 256
  CHECK(near(s.az.deg, 90.0, kAzBand + 0.2));
  CHECK(s.mode == ControlMode::target);
  // Stays put: no more drive.
  rig.idle(10s);
  CHECK(rig.ctl->status().az.motion == Drive::stop);
  CHECK(rig.ctl->status().el.motion == Drive::stop);
  CHECK(rig.ctl->next_tick_in() == 1000ms);
}

TEST_CASE("A loop that ticks only once a second still stops inside the dead band") {
  Rig rig;
  rig.ctl->set_target(AzEl{123.4, 56.7});
  auto took = rig.run(120s, 1000ms);
  CHECK(took < 120s);
  const Status& s = rig.ctl->status();
  CHECK(std::abs(*s.az.goal_counts - s.az.counts) <= 3);
  CHECK(std::abs(*s.el.goal_counts - s.el.counts) <= 1);
}

TEST_CASE("From 350 to 10 degrees the antenna goes the way the travel allows, never through the stop") {
  Rig rig({}, RotorStart::north, {350.0, 0.0});
  rig.ctl->set_target(AzEl{10.0, 0.0});
  double prev = rig.sim->true_position().az_travel;
  bool monotonic = true;
  rig.run(120s, 100ms, [&] {
    double now = rig.sim->true_position().az_travel;
    if (now > prev + 1e-9) monotonic = false;
    prev = now;
  });
  CHECK(monotonic);  // CCW all the way, 340 degrees
  CHECK(rig.ctl->status().on_target);
  CHECK(near(rig.sim->true_position().az_travel, 10.0, kAzBand + 0.2));

  SUBCASE("a South-start rotator crosses north freely and goes round the other way for south") {
    Rig south({}, RotorStart::south, {170.0, 0.0});  // compass 350
    RotatorPosition t = south.ctl->set_target(AzEl{10.0, 0.0});
    CHECK(t.az_travel == doctest::Approx(190.0));  // 20 degrees on, through north
    south.run(60s);
    CHECK(near(south.ctl->status().az.deg, 10.0, kAzBand + 0.2));
  }
  SUBCASE("a 450-degree rotator takes the overlap") {
    RotatorConfig c;
    c.az_travel_deg = 450.0;
    SimulatedRotatorParams p = SimulatedRotatorParams::matching(c);
    p.el_max_deg = 180.0;
    Rig wide(c, RotorStart::north, {350.0, 0.0}, p);
    RotatorPosition t = wide.ctl->set_target(AzEl{10.0, 0.0});
    CHECK(t.az_travel == doctest::Approx(370.0));
    wide.run(60s);
    CHECK(near(wide.sim->true_position().az_travel, 370.0, 450.0 / 1023 * 3 + 0.2));
  }
}

TEST_CASE("Targets are clamped to the limits and the antenna stops there") {
  RotatorConfig c;
  c.limits_enabled = true;
  std::tie(c.az_limit_min, c.az_limit_max, c.el_limit_min, c.el_limit_max) = std::tuple(0.0, 340.0, 0.0, 60.0);
  Rig rig(c);
  RotatorPosition t = rig.ctl->set_target(AzEl{345.0, 80.0});
  CHECK(t == RotatorPosition{340.0, 60.0});
  rig.run(120s);
  CHECK(rig.ctl->status().on_target);
  CHECK(rig.ctl->status().limited);   // on target as near as the limits let it, said so (issue 60)
  CHECK(rig.ctl->status().az.at_high_limit);
  CHECK(rig.ctl->status().el.at_high_limit);
  CHECK(rig.sim->true_position().az_travel <= 340.0 + 3 * 0.352);
  CHECK(rig.sim->true_position().el <= 60.0 + 0.18);
  rig.ctl->set_target(AzEl{300.0, 30.0});   // inside: no longer limited
  CHECK_FALSE(rig.ctl->status().limited);
  rig.ctl->stop();
  CHECK_FALSE(rig.ctl->status().limited);
}

TEST_CASE("Park goes to the parking position only when parking is enabled") {
  RotatorConfig c;
  Rig rig(c, RotorStart::north, {200.0, 30.0});
  CHECK_FALSE(rig.ctl->park());
  CHECK(rig.ctl->status().mode == ControlMode::idle);
  c.parking_enabled = true;
  c.parking = {90.0, 45.0};  // the manual's example
  rig.ctl->set_config(c, RotorStart::north);
  CHECK(rig.ctl->park());
  rig.run(60s);
  check_settled_at(rig.ctl->status(), 90.0, 45.0);
}

TEST_CASE("Presets 1-5 of menu 6-6-3") {
  RotatorConfig c;
  c.presets = {AzEl{125, 15}, AzEl{90, 22}, AzEl{0, 45}, AzEl{270, 10}, AzEl{165, 0}};
  Rig rig(c);
  CHECK_FALSE(rig.ctl->preset(0));
  CHECK_FALSE(rig.ctl->preset(6));
  CHECK(rig.ctl->preset(4));
  rig.run(90s);
  check_settled_at(rig.ctl->status(), 270.0, 10.0);
}

TEST_CASE("A target with rotor control off is not busy: the station ticks once a second (issue 49)") {
  Rig rig;
  rig.ctl->set_control_enabled(false);
  rig.ctl->set_target(AzEl{90.0, 45.0});
  rig.idle(2s);
  CHECK_FALSE(rig.ctl->status().on_target);
  CHECK(rig.ctl->status().az.motion == Drive::stop);
  CHECK(rig.ctl->next_tick_in() == 1000ms);
  rig.ctl->set_control_enabled(true);
  rig.ctl->set_target(AzEl{90.0, 45.0});
  rig.idle(1s);
  CHECK(rig.ctl->next_tick_in() == 100ms);  // on its way: ticks every 100 ms
}

TEST_CASE("Keyboard control 4/6/8/2/5 of menu 6-6-1") {
  Rig rig({}, RotorStart::north, {180.0, 45.0});
  CHECK(rig.ctl->manual_key('6'));  // right = CW
  CHECK(rig.ctl->manual_key('8'));  // up
  rig.idle(2s);
  CHECK(rig.ctl->status().mode == ControlMode::manual);
  CHECK(rig.ctl->status().az.motion == Drive::increase);
  CHECK(rig.ctl->status().el.motion == Drive::increase);
  CHECK(rig.ctl->next_tick_in() == 100ms);
  double az = rig.sim->true_position().az_travel, el = rig.sim->true_position().el;
  CHECK(az > 185.0);
  CHECK(el > 47.0);
  CHECK(rig.ctl->manual_key('5'));  // stop
  CHECK(rig.ctl->status().mode == ControlMode::idle);
  CHECK(rig.sim->motion().az == Drive::stop);
  CHECK(rig.sim->motion().el == Drive::stop);
  rig.idle(2s);
  CHECK(near(rig.sim->true_position().az_travel, az, 6.0 * 0.15 + 0.01));  // only the coast
  CHECK(rig.ctl->manual_key('4'));  // left = CCW
  CHECK(rig.ctl->manual_key('2'));  // down
  rig.idle(1s);
  CHECK(rig.ctl->status().az.motion == Drive::decrease);
  CHECK(rig.ctl->status().el.motion == Drive::decrease);
  CHECK_FALSE(rig.ctl->manual_key('7'));
  // Held down to the end: stops at the end of travel by itself.
  rig.idle(40s);
  CHECK(rig.ctl->status().el.motion == Drive::stop);
  CHECK(rig.ctl->status().el.at_low_limit);
  CHECK(near(rig.sim->true_position().el, 0.0, kElBand + 0.1));
  rig.ctl->manual(Axis::az, Drive::stop);
  CHECK(rig.sim->motion().az == Drive::stop);
}

TEST_CASE("Keyboard control stops at the configured limit") {
  RotatorConfig c;
  c.limits_enabled = true;
  c.az_limit_max = 200.0;
  Rig rig(c, RotorStart::north, {180.0, 0.0});
  rig.ctl->manual_key('6');
  rig.idle(20s);
  CHECK(rig.ctl->status().az.motion == Drive::stop);
  CHECK(rig.ctl->status().az.at_high_limit);
  CHECK(rig.sim->true_position().az_travel <= 200.0 + 3 * 0.352);
  CHECK(rig.sim->true_position().az_travel >= 200.0 - 3 * 0.352);
}

TEST_CASE("The E key: with control off nothing moves; on again resumes the target") {
  Rig rig;
  rig.ctl->set_target(AzEl{60.0, 20.0});
  rig.idle(2s);
  CHECK(rig.ctl->status().az.motion == Drive::increase);
  rig.ctl->toggle_control();
  CHECK_FALSE(rig.ctl->control_enabled());
  CHECK(rig.sim->motion().az == Drive::stop);  // at once, not at the next tick
  rig.idle(1s);  // let it coast to rest
  RotatorPosition at = rig.sim->true_position();
  rig.idle(10s);
  CHECK(near(rig.sim->true_position(), at));
  rig.ctl->manual_key('6');
  rig.ctl->park();
  rig.idle(2s);
  CHECK(near(rig.sim->true_position(), at));
  rig.ctl->set_target(AzEl{60.0, 20.0});
  rig.ctl->toggle_control();
  rig.run(30s);
  CHECK(rig.ctl->status().on_target);
}

TEST_CASE("stop() aborts at once and always") {
  Rig rig;
  rig.ctl->set_target(AzEl{200.0, 60.0});
  rig.idle(3s);
  rig.ctl->stop();
  CHECK(rig.sim->motion().az == Drive::stop);
  CHECK(rig.sim->motion().el == Drive::stop);
  CHECK(rig.ctl->status().mode == ControlMode::idle);
  CHECK_FALSE(rig.ctl->status().target);
  rig.idle(1s);
  RotatorPosition at = rig.sim->true_position();
  rig.idle(5s);
  CHECK(near(rig.sim->true_position(), at));
}

TEST_CASE("A rotator fault stops the motors, is reported, and the target resumes when it clears") {
  Rig rig;
  rig.ctl->set_target(AzEl{100.0, 30.0});
  rig.idle(2s);
  rig.sim->set_fault("ADC not responding");
  rig.idle(200ms);
  const Status& s = rig.ctl->status();
  CHECK(s.link.state == LinkState::fault);
  CHECK(s.message.find("ADC not responding") != std::string::npos);
  CHECK_FALSE(s.has_position);
  CHECK(s.az.motion == Drive::stop);
  CHECK(rig.sim->motion().az == Drive::stop);
  CHECK(format_monitor_line(s) == "AZ=---- / ---.-deg EL=---- / --.-deg.");
  rig.sim->clear_fault();
  rig.run(60s);
  CHECK(rig.ctl->status().on_target);
  CHECK(rig.ctl->status().link.ok());
  CHECK(rig.ctl->status().message.find("restored") != std::string::npos);
}

TEST_CASE("An axis that cannot reach its count is stopped and reported stalled") {
  // The pot reads only 1000 at the CW stop but the span says 1023: the manual's smoke scenario.
  RotatorConfig c;
  SimulatedRotatorParams p = SimulatedRotatorParams::matching(c);
  p.az_counts_at_cw = 1000.0;
  Rig rig(c, RotorStart::north, {340.0, 0.0}, p);
  rig.ctl->set_target(RotatorPosition{359.0, 0.0});
  rig.idle(15s);
  const Status& s = rig.ctl->status();
  CHECK(s.az.stalled);
  CHECK(s.az.motion == Drive::stop);
  CHECK(rig.sim->motion().az == Drive::stop);
  CHECK(s.message.find("azimuth stalled") != std::string::npos);
  CHECK_FALSE(s.on_target);
  // A new target clears it.
  rig.ctl->set_target(RotatorPosition{300.0, 0.0});
  rig.run(30s);
  CHECK(rig.ctl->status().on_target);
  CHECK_FALSE(rig.ctl->status().az.stalled);
}

TEST_CASE("Rotator error detection off (STATION.DAT line 6): an axis that cannot reach its count is driven on, never declared stalled") {
  RotatorConfig c;
  SimulatedRotatorParams p = SimulatedRotatorParams::matching(c);
  p.az_counts_at_cw = 1000.0;
  Rig rig(c, RotorStart::north, {340.0, 0.0}, p);
  rig.ctl->set_error_detection(false);
  rig.ctl->set_target(RotatorPosition{359.0, 0.0});
  rig.idle(15s);
  const Status& s = rig.ctl->status();
  CHECK_FALSE(s.az.stalled);
  CHECK(s.az.motion != Drive::stop);  // still driven against the stop, pulse by pulse
  CHECK(s.message.find("stalled") == std::string::npos);
  // Switched back on, the stall watch takes it from there.
  rig.ctl->set_error_detection(true);
  rig.idle(15s);
  CHECK(rig.ctl->status().az.stalled);
}

TEST_CASE("Monitor line in the manual's format") {
  CHECK(format_monitor_line(519, 32.8, 462, 90.0) == "AZ= 519 / 32.8deg EL= 462 / 90.0deg.");
  CHECK(format_monitor_line(926, 199.7, 431, 84.0) == "AZ= 926 / 199.7deg EL= 431 / 84.0deg.");
  CHECK(format_monitor_line(967, 216.5, 400, 77.9) == "AZ= 967 / 216.5deg EL= 400 / 77.9deg.");
  CHECK(format_monitor_line(3, 0.0, 1, 0.0) == "AZ=   3 / 0.0deg EL=   1 / 0.0deg.");
  CHECK(format_monitor_line(1023, 359.97, 0, -0.01) == "AZ=1023 / 0.0deg EL=   0 / 0.0deg.");
}

TEST_CASE("The manual's monitor lines come out of the model with a span of width 878 / 462, rotor start South") {
  // The three azimuth/elevation pairs in the manual (6-5, 6-6-1, 6-6-2) fit deg = counts * 360/878
  // and counts * 90/462 (the widths of the 6-2 example span 9-887 / 3-465) with the stop in the
  // south: i.e. a span starting at count 0. See docs/rotator.md.
  RotatorConfig c;
  c.az_span = {0, 878};
  c.el_span = {0, 462};
  AdcModel m(c, RotorStart::south);
  auto line = [&](int az, int el) { return format_monitor_line(az, m.az_deg_from_raw(az), el, m.el_deg_from_raw(el)); };
  CHECK(line(519, 462) == "AZ= 519 / 32.8deg EL= 462 / 90.0deg.");
  CHECK(line(926, 431) == "AZ= 926 / 199.7deg EL= 431 / 84.0deg.");
  CHECK(line(967, 400) == "AZ= 967 / 216.5deg EL= 400 / 77.9deg.");
}

TEST_CASE("The monitor line from a live status shows raw counts and skewed degrees") {
  RotatorConfig c;
  c.az_skew = 10;
  Rig rig(c, RotorStart::north, {90.0, 45.0});
  const Status& s = rig.ctl->status();
  CHECK(s.has_position);
  CHECK(s.az.counts == 255);
  CHECK(format_monitor_line(s) == "AZ= 255 / 93.3deg EL= 255 / 44.9deg.");
}

TEST_CASE("Calibration of the span (menu 6-1)") {
  RotatorConfig c;  // factory span 0-1023 / 0-511, but this rotator's pots read 12..1010 and 5..470
  SimulatedRotatorParams p;
  p.az_counts_at_ccw = 12;
  p.az_counts_at_cw = 1010;
  p.el_counts_at_0 = 5;
  p.el_counts_at_90 = 470;
  p.el_max_deg = 90;
  Rig rig(c, RotorStart::north, {0.0, 0.0}, p);
  SpanCalibration cal;
  CHECK_FALSE(cal.result().ok());
  CHECK(cal.result().error.find("CCW") != std::string::npos);
  // "Rotate the antenna to fully CCW and Elevation minimum position": it is there now.
  cal.record_min(*rig.ctl->raw_counts());
  // "Rotate the antenna to fully CW and Elevation maximum position": keyboard control to the ends.
  rig.ctl->manual_key('6');
  rig.ctl->manual_key('8');
  rig.idle(75s);
  // The factory span asks for more than these pots give: each axis stalls at its end stop and is
  // switched off (stalled), which is exactly where the reading is wanted.
  CHECK(rig.ctl->status().az.motion == Drive::stop);
  CHECK(rig.ctl->status().el.motion == Drive::stop);
  cal.record_max(*rig.ctl->raw_counts());
  REQUIRE(cal.result().ok());
  RotatorConfig got = cal.apply(c);
  CHECK(got.az_span == AxisSpan{12, 1010});
  CHECK(got.el_span == AxisSpan{5, 470});
  rig.ctl->set_config(got, RotorStart::north);
  rig.ctl->set_target(AzEl{180.0, 45.0});
  rig.run(60s);
  CHECK(near(rig.sim->true_position().az_travel, 180.0, 3 * 360.0 / 998 + 0.2));
  CHECK(near(rig.sim->true_position().el, 45.0, 90.0 / 465 + 0.1));

  SpanCalibration bad;
  bad.record_min({500, 100});
  bad.record_max({400, 300});
  CHECK_FALSE(bad.result().ok());
  CHECK(bad.result().error.find("azimuth ADC span 500-400") != std::string::npos);
  CHECK(bad.apply(c) == c);
}

TEST_CASE("A new target shows in the status at once: no previous arrival is taken for the new one") {
  Rig r;
  r.ctl->set_control_enabled(true);
  r.ctl->set_target(AzEl{100.0, 20.0});
  REQUIRE(r.run(60s) < 60s);
  REQUIRE(r.ctl->status().on_target);

  // Far away: not on target before any tick, and the goals are the new target's.
  const RotatorPosition far = r.ctl->set_target(AzEl{200.0, 40.0});
  CHECK_FALSE(r.ctl->status().on_target);
  CHECK(r.ctl->status().az.goal_counts == static_cast<int>(std::lround(r.ctl->model().target_counts(Axis::az, far))));
  CHECK(r.ctl->status().el.goal_counts == static_cast<int>(std::lround(r.ctl->model().target_counts(Axis::el, far))));
  REQUIRE(r.run(60s) < 60s);

  // Inside the dead band of where it rests: on target at once, and nothing moves.
  const double az = r.ctl->status().az.deg, el = r.ctl->status().el.deg;
  r.ctl->set_target(AzEl{az + kAzBand / 4, el});
  CHECK(r.ctl->status().on_target);
  r.idle(2s);
  CHECK(r.ctl->status().on_target);
  CHECK(r.ctl->status().az.motion == Drive::stop);
}
