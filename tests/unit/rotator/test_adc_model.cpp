// The ADC-count model: counts <-> degrees, skew, limits, the dead band decision, the manual's
// resolution figures and monitor lines.
#include <doctest/doctest.h>

#include <cmath>

#include "rotator/adc_model.h"
#include "rotator/controller.h"

using namespace tb::rotator;
using tb::station::RotorStart;

namespace {
RotatorConfig span(int az_min, int az_max, int el_min, int el_max) {
  RotatorConfig c;
  c.az_span = {az_min, az_max};
  c.el_span = {el_min, el_max};
  return c;
}
}  // namespace

TEST_CASE("Azimuth counts to degrees, rotor start North") {
  AdcModel m(RotatorConfig{}, RotorStart::north);  // span 0..1023 = 0..360 from the stop in the north
  CHECK(m.az_travel_from_counts(0) == doctest::Approx(0.0));
  CHECK(m.compass_from_travel(m.az_travel_from_counts(0)) == doctest::Approx(0.0));
  CHECK(m.az_travel_from_counts(1023) == doctest::Approx(360.0));
  CHECK(m.compass_from_travel(360.0) == doctest::Approx(0.0));
  CHECK(m.az_travel_from_counts(511.5) == doctest::Approx(180.0));
  CHECK(m.az_deg_from_raw(256) == doctest::Approx(256 * 360.0 / 1023));

  AdcModel n(span(3, 837, 1, 460), RotorStart::north);  // the manual's 6-0 example span
  CHECK(n.az_travel_from_counts(3) == doctest::Approx(0.0));
  CHECK(n.az_travel_from_counts(420) == doctest::Approx(180.0));
  CHECK(n.az_travel_from_counts(837) == doctest::Approx(360.0));
  CHECK(n.el_from_counts(1) == doctest::Approx(0.0));
  CHECK(n.el_from_counts(460) == doctest::Approx(90.0));
  CHECK(n.el_from_counts(230.5) == doctest::Approx(45.0));
}

TEST_CASE("Azimuth counts to degrees, rotor start South: the span covers 180 -> 360/0 -> 180") {
  AdcModel m(RotatorConfig{}, RotorStart::south);
  CHECK(m.az_deg_from_raw(0) == doctest::Approx(180.0));
  CHECK(m.compass_from_travel(m.az_travel_from_counts(255.75)) == doctest::Approx(270.0));
  CHECK(m.compass_from_travel(m.az_travel_from_counts(511.5)) == doctest::Approx(0.0));
  CHECK(m.compass_from_travel(m.az_travel_from_counts(767.25)) == doctest::Approx(90.0));
  CHECK(m.compass_from_travel(m.az_travel_from_counts(1023)) == doctest::Approx(180.0));

  AdcModel n(span(9, 887, 3, 465), RotorStart::south);  // the manual's 6-2 example span
  CHECK(n.compass_from_travel(n.az_travel_from_counts(9)) == doctest::Approx(180.0));
  CHECK(n.compass_from_travel(n.az_travel_from_counts(448)) == doctest::Approx(0.0));
  CHECK(n.compass_from_travel(n.az_travel_from_counts(887)) == doctest::Approx(180.0));
}

TEST_CASE("Counts -> degrees -> counts round trip for several spans and both rotor starts") {
  const AxisSpan spans[] = {{0, 1023}, {3, 837}, {9, 887}, {100, 400}, {500, 511}, {0, 10}};
  for (RotorStart start : {RotorStart::north, RotorStart::south}) {
    for (const AxisSpan& s : spans) {
      RotatorConfig c;
      c.az_span = s;
      c.el_span = s;
      AdcModel m(c, start);
      for (int count = s.min; count <= s.max; ++count) {
        CHECK(m.counts_from_az_travel(m.az_travel_from_counts(count)) == doctest::Approx(count));
        CHECK(m.counts_from_el(m.el_from_counts(count)) == doctest::Approx(count));
        // Compass bearing and back through the chosen travel (nearest the same travel).
        double travel = m.az_travel_from_counts(count);
        double compass = m.compass_from_travel(travel);
        CHECK(m.travel_for(compass, travel) == doctest::Approx(travel).epsilon(1e-9));
      }
    }
  }
}

TEST_CASE("Skew is added to the reading") {
  RotatorConfig c;
  c.az_skew = 5;
  c.el_skew = -2;
  AdcModel m(c, RotorStart::north);
  CHECK(m.corrected(Axis::az, 100) == 105);
  CHECK(m.corrected(Axis::el, 100) == 98);
  CHECK(m.raw(Axis::az, 105) == 100);
  CHECK(m.az_deg_from_raw(100) == doctest::Approx(105 * 360.0 / 1023));
  CHECK(m.el_deg_from_raw(100) == doctest::Approx(98 * 90.0 / 511));
  // A target is in corrected counts: with +5 skew the raw pot stops 5 counts short of it.
  CHECK(m.target_counts(Axis::az, {90.0, 0.0}) == 256);  // 90 deg = 255.75 -> 256
  // The skewed frame cannot reach beyond the mechanical stops: raw 0 reads corrected 5.
  CHECK(m.az_travel_range().lo == doctest::Approx(5 * 360.0 / 1023));
  CHECK(m.az_travel_range().hi == doctest::Approx(360.0));
  CHECK(m.el_range().lo == doctest::Approx(0.0));
  CHECK(m.el_range().hi == doctest::Approx(509 * 90.0 / 511));
}

TEST_CASE("Dead band edges: error exactly at, inside and outside") {
  AxisLoopInput in;
  in.reading = 500;
  in.dead_band = 3;
  in.rate = 17.0;
  for (int e : {-3, -2, -1, 0, 1, 2, 3}) {
    in.target = 500 + e;
    CAPTURE(e);
    CHECK(decide(in).drive == Drive::stop);
  }
  in.target = 504;
  CHECK(decide(in).drive == Drive::increase);
  CHECK(decide(in).run_for_s == doctest::Approx(4.0 / 17.0));
  in.target = 496;
  CHECK(decide(in).drive == Drive::decrease);
  // Dead band 1 (the elevation default).
  in.dead_band = 1;
  in.target = 501;
  CHECK(decide(in).drive == Drive::stop);
  in.target = 502;
  CHECK(decide(in).drive == Drive::increase);
  // Dead band 0: any error drives.
  in.dead_band = 0;
  in.target = 499;
  CHECK(decide(in).drive == Drive::decrease);
  in.target = 500;
  CHECK(decide(in).drive == Drive::stop);
}

TEST_CASE("A driven axis carries on to the centre of the dead band and stops when coasting will get there") {
  AxisLoopInput in;
  in.reading = 500;
  in.target = 502;  // inside the dead band of 3
  in.dead_band = 3;
  in.rate = 10.0;
  in.coast_s = 0.2;
  in.driving = Drive::increase;
  in.velocity = 0.0;
  AxisCommand c = decide(in);
  CHECK(c.drive == Drive::increase);
  CHECK(c.run_for_s == doctest::Approx(0.2));
  // At full speed the coast alone (10 counts/s * 0.2 s = 2 counts) reaches the target: stop now.
  in.velocity = 10.0;
  CHECK(decide(in).drive == Drive::stop);
  // A stopped axis still coasting onto its target is not driven again.
  in.driving = Drive::stop;
  in.reading = 496;
  in.target = 500;
  in.velocity = 10.0;  // 2 more counts to come: predicted error 2 <= 3
  CHECK(decide(in).drive == Drive::stop);
  // Overshot while driven: stop (no reversal within the same command).
  in.driving = Drive::increase;
  in.velocity = 0.0;
  in.reading = 503;
  in.target = 500;
  CHECK(decide(in).drive == Drive::stop);
}

TEST_CASE("An axis at a limit is not driven further even when the target lies beyond it") {
  AxisLoopInput in;
  in.reading = 800;
  in.target = 900;
  in.dead_band = 3;
  in.range = {100, 800};
  AxisCommand c = decide(in);
  CHECK(c.drive == Drive::stop);
  CHECK(c.at_limit);
  in.reading = 810;  // beyond it
  CHECK(decide(in).drive == Drive::stop);
  in.target = 700;  // back inside is fine
  CHECK(decide(in).drive == Drive::decrease);
  in.reading = 100;
  in.target = 0;
  CHECK(decide(in).drive == Drive::stop);
  CHECK(decide(in).at_limit);
  in.driving = Drive::decrease;  // also while already driven
  CHECK(decide(in).drive == Drive::stop);
}

TEST_CASE("Target clamping to the rotation limits (menu 6-4)") {
  RotatorConfig c;
  c.limits_enabled = true;
  c.az_limit_min = 0;
  c.az_limit_max = 340;  // the manual's example
  c.el_limit_min = 0;
  c.el_limit_max = 60;
  AdcModel m(c, RotorStart::north);
  CHECK(m.az_travel_range().lo == doctest::Approx(0.0));
  CHECK(m.az_travel_range().hi == doctest::Approx(340.0));
  CHECK(m.target_for({345, 10}, 100).az_travel == doctest::Approx(340.0));  // nearer 340 than 0
  CHECK(m.target_for({355, 10}, 100).az_travel == doctest::Approx(0.0));    // nearer 0
  CHECK(m.target_for({200, 80}, 100).el == doctest::Approx(60.0));
  CHECK(m.target_for({200, -5}, 100).el == doctest::Approx(0.0));
  CHECK(m.target_for({200, 30}, 100) == RotatorPosition{200.0, 30.0});
  // Targets never leave the counts range either.
  CHECK(m.target_counts(Axis::az, {400.0, 0.0}) == 966);  // 340 deg = 966.2 counts: whole counts inside
}

TEST_CASE("Resolution at full span: about 0.35 deg azimuth and 0.18 deg elevation, as the manual says") {
  // "+5 volts DC at one extreme of the rotator position and 0 volts at the other": azimuth 0..360
  // over the 10-bit ADC, elevation 0..180 (a rotator that goes over the top) over it, i.e. 0..90
  // over half of it. These are the factory spans.
  AdcModel m(RotatorConfig{}, RotorStart::north);
  CHECK(m.deg_per_count(Axis::az) == doctest::Approx(360.0 / 1023));
  CHECK(m.deg_per_count(Axis::el) == doctest::Approx(90.0 / 511));
  CHECK(std::round(m.deg_per_count(Axis::az) * 100) / 100 == doctest::Approx(0.35));
  CHECK(std::round(m.deg_per_count(Axis::el) * 100) / 100 == doctest::Approx(0.18));
  // A narrower span is coarser: the manual's 6-0 example span 3-837 / 1-460.
  AdcModel n(span(3, 837, 1, 460), RotorStart::north);
  CHECK(n.deg_per_count(Axis::az) == doctest::Approx(360.0 / 834));
  CHECK(n.deg_per_count(Axis::el) == doctest::Approx(90.0 / 459));
  // One count of the factory span moves the displayed azimuth by the resolution.
  CHECK(m.az_deg_from_raw(101) - m.az_deg_from_raw(100) == doctest::Approx(0.352).epsilon(0.001));
  CHECK(m.el_deg_from_raw(101) - m.el_deg_from_raw(100) == doctest::Approx(0.176).epsilon(0.001));
}

TEST_CASE("Limit sectors in travel, for both rotor starts (station file sample: South, 270 -> 90)") {
  RotatorConfig c;
  c.limits_enabled = true;
  c.az_limit_min = 270;
  c.az_limit_max = 90;
  AdcModel south(c, RotorStart::south);
  CHECK(south.az_limit_travel().lo == doctest::Approx(90.0));
  CHECK(south.az_limit_travel().hi == doctest::Approx(270.0));
  CHECK(south.target_for({0.0, 10.0}, 0.0).az_travel == doctest::Approx(180.0));
  CHECK(south.target_for({180.0, 10.0}, 0.0).az_travel == doctest::Approx(90.0));  // equidistant: nearest the antenna
  // For a North start a sector 250 -> 90 contains the stop: the longer piece (250 -> 360) is kept.
  c.az_limit_min = 250;
  AdcModel north(c, RotorStart::north);
  CHECK(north.az_limit_travel().lo == doctest::Approx(250.0));
  CHECK(north.az_limit_travel().hi == doctest::Approx(360.0));
  // 0 -> 360 is no limit for either start.
  c.az_limit_min = 0;
  c.az_limit_max = 360;
  CHECK(AdcModel(c, RotorStart::south).az_limit_travel().width() == doctest::Approx(360.0));
  CHECK(validate(c).empty());
  c.az_limit_max = 0;
  CHECK(validate(c).size() == 1);
}

TEST_CASE("Elevation beyond 90 for rotators allowed to flip: the span is 0..180 degrees") {
  RotatorConfig c;
  c.el_flip_allowed = true;  // flip mode calibrates 0 and 180 degrees: factory span 0-511 is 0..180
  AdcModel m(c, RotorStart::north);
  CHECK(m.el_range().hi == doctest::Approx(180.0));
  CHECK(m.counts_from_el(180.0) == doctest::Approx(511.0));
  CHECK(m.counts_from_el(90.0) == doctest::Approx(255.5));
  CHECK(m.el_from_counts(383.25) == doctest::Approx(135.0));
  CHECK(m.deg_per_count(Axis::el) == doctest::Approx(180.0 / 511.0));
  CHECK(m.clamp({100.0, 150.0}).el == doctest::Approx(150.0));
  c.el_flip_allowed = false;
  CHECK(AdcModel(c, RotorStart::north).counts_from_el(90.0) == doctest::Approx(511.0));
  CHECK(AdcModel(c, RotorStart::north).clamp({100.0, 150.0}).el == doctest::Approx(90.0));
  // The firmware's example, 2 10 857 2 917 F: the whole span is usable, nothing extrapolated.
  c.el_flip_allowed = true;
  c.el_span = {2, 917};
  CHECK(validate(c).empty());
  CHECK(AdcModel(c, RotorStart::north).counts_range(Axis::el).hi == doctest::Approx(917.0));
}
