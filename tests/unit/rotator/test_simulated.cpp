// The simulated rotator: motors, end stops, coast, 10-bit potentiometers, simulated time.
#include <doctest/doctest.h>

#include "rotator/simulated.h"

using namespace tb::rotator;
using namespace std::chrono_literals;
using tb::orbit::from_civil;
using tb::station::ManualClock;

TEST_CASE("Simulated rotator reads its potentiometers through the 10-bit ADC") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotatorParams p;
  p.start = {90.0, 45.0};
  SimulatedRotator sim(clock, p);
  auto c = sim.read();
  REQUIRE(c);
  CHECK(c->az == 255);  // 90 deg of 360 over 0..1023 = 255.75, floored by the ADC
  CHECK(c->el == 255);  // 45 deg: 255.5
  CHECK(sim.health().ok());
  CHECK(sim.description() == "simulated");
}

TEST_CASE("Simulated motors run at their rate, spin up and coast, and advance only with the clock") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotator sim(clock);  // 6 deg/s az, 3 deg/s el, coast 0.15 s
  sim.drive(Axis::az, Drive::increase, 100s);
  sim.drive(Axis::el, Drive::increase, 100s);
  CHECK(sim.true_position() == RotatorPosition{0.0, 0.0});  // no time has passed
  clock.advance(10s);
  // 10 s at full speed less the spin-up lag (rate * tau).
  CHECK(sim.true_position().az_travel == doctest::Approx(6.0 * (10.0 - 0.15)).epsilon(1e-6));
  CHECK(sim.true_position().el == doctest::Approx(3.0 * (10.0 - 0.15)).epsilon(1e-6));
  CHECK(sim.true_velocity(Axis::az) == doctest::Approx(6.0).epsilon(1e-6));
  CHECK(sim.motion().az == Drive::increase);
  sim.stop();
  CHECK(sim.motion().az == Drive::stop);
  double at_stop = sim.true_position().az_travel;
  clock.advance(5s);
  // Coasts on rate * tau after switching off.
  CHECK(sim.true_position().az_travel == doctest::Approx(at_stop + 6.0 * 0.15).epsilon(1e-6));
  CHECK(sim.true_velocity(Axis::az) == doctest::Approx(0.0).epsilon(1e-6));
}

TEST_CASE("A pulse from rest moves rate * duration: spin-up lag and coast cancel") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotatorParams p;
  p.start = {100.0, 10.0};
  SimulatedRotator sim(clock, p);
  sim.drive(Axis::az, Drive::decrease, 500ms);
  sim.drive(Axis::el, Drive::increase, 200ms);
  clock.advance(3s);
  CHECK(sim.true_position().az_travel == doctest::Approx(100.0 - 3.0).epsilon(1e-4));
  CHECK(sim.true_position().el == doctest::Approx(10.0 + 0.6).epsilon(1e-4));
  CHECK(sim.motion().az == Drive::stop);
}

TEST_CASE("Run-for is a watchdog: the motor stops by itself") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotator sim(clock);
  sim.drive(Axis::az, Drive::increase, 1s);
  clock.advance(10min);  // an event loop that stalled for ten minutes
  CHECK(sim.true_position().az_travel == doctest::Approx(6.0).epsilon(1e-4));
  CHECK(sim.motion().az == Drive::stop);
}

TEST_CASE("Mechanical end stops hold the axis and raise the limit flags") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotator sim(clock);
  sim.drive(Axis::az, Drive::decrease, 2s);
  sim.drive(Axis::el, Drive::decrease, 2s);
  clock.advance(3s);
  CHECK(sim.true_position() == RotatorPosition{0.0, 0.0});
  CHECK(sim.limits().az.low);
  CHECK(sim.limits().el.low);
  CHECK_FALSE(sim.limits().az.high);
  CHECK(sim.read()->az == 0);
  sim.drive(Axis::el, Drive::increase, 100s);
  clock.advance(90s);  // 3 deg/s: the 0..180 elevation rotator reaches its top
  CHECK(sim.true_position().el == doctest::Approx(180.0));
  CHECK(sim.limits().el.high);
  CHECK(sim.read()->el == 1022);  // 180 deg = 2 * 511 counts
}

TEST_CASE("A clock stepped back is no time passed") {
  ManualClock clock(from_civil(2026, 1, 1, 12));
  SimulatedRotator sim(clock);
  sim.drive(Axis::az, Drive::increase, 2s);
  clock.advance(1s);
  double a = sim.true_position().az_travel;
  clock.set(from_civil(2026, 1, 1, 11));  // an hour back
  CHECK(sim.true_position().az_travel == doctest::Approx(a));
  clock.advance(10s);
  // The remaining second of the 2 s command ran, then the coast.
  CHECK(sim.true_position().az_travel == doctest::Approx(12.0).epsilon(1e-3));
}

TEST_CASE("A simulated fault stops the motors and the ADC") {
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotator sim(clock);
  sim.drive(Axis::az, Drive::increase, 10s);
  sim.set_fault("ADC cable unplugged");
  CHECK(sim.health().state == LinkState::fault);
  CHECK(sim.health().message == "ADC cable unplugged");
  CHECK_FALSE(sim.read());
  CHECK(sim.motion().az == Drive::stop);
  sim.drive(Axis::az, Drive::increase, 10s);  // ignored while faulted
  CHECK(sim.motion().az == Drive::stop);
  sim.clear_fault();
  CHECK(sim.health().ok());
  CHECK(sim.health().connects == 2);
  CHECK(sim.read());
}

TEST_CASE("A simulator matching a configuration reads that configuration's span") {
  RotatorConfig c;
  c.az_span = {9, 887};
  c.el_span = {3, 465};
  SimulatedRotatorParams p = SimulatedRotatorParams::matching(c);
  p.start = {360.0, 90.0};
  ManualClock clock(from_civil(2026, 1, 1));
  SimulatedRotator sim(clock, p);
  CHECK(sim.read() == Counts{887, 465});
  CHECK(sim.params().el_max_deg == 90.0);
}
