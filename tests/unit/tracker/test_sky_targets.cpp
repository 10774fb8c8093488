// The Sun and the Moon as targets and "this is the Sun" (issue 58) on the simulated station: the
// tracker points at the body's topocentric position through the same station loop, the choice is
// stored, the radio is left alone; calibrate sets the rotator's sky offsets through the owner, and
// undo restores them. Expected positions: PyEphem 4.1.4, refraction off, Munich (48.1458 N,
// 11.625 E, 520 m) at 2026-03-20 09:00:00 UTC, the values test_sky.cpp cites
// (tests/integration/orbit_ref/sky_reference_values.py).
#include <doctest/doctest.h>

#include <cmath>

#include "orbit/sky.h"
#include "support/sim_station.h"
#include "tracker/operations.h"
#include "util/text.h"

using namespace tb;

namespace {

constexpr double kSunAz = 136.5630, kSunEl = 32.9341;    // PyEphem
constexpr double kMoonAz = 115.5078, kMoonEl = 32.4494;  // PyEphem

store::Model munich_model() {
  store::Model m = testing::shipped_model();
  m.station.lat_deg = 48.1458;
  m.station.lon_deg = 11.625;
  m.station.height_m = 520.0;
  m.rotor_control = true;
  return m;
}

struct Sky : testing::StationFixture {
  explicit Sky(std::optional<rotator::SimulatedRotatorParams> params = std::nullopt)
      : StationFixture(orbit::from_civil(2026, 3, 20, 8, 59, 0), munich_model()) {
    build_station(params);
  }
  tracker::StationOps ops() { return tracker::StationOps(*station); }
};

double az_apart(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

}  // namespace

TEST_CASE("Sky targets: SUN and MOON by name: the antenna ends on the body's topocentric position") {
  for (const auto& [name, az, el] : {std::tuple{"sun", kSunAz, kSunEl}, std::tuple{"Moon", kMoonAz, kMoonEl}}) {
    CAPTURE(name);
    Sky f;
    const tracker::OpResult r = f.ops().track(name);
    REQUIRE(r.ok());
    CHECK(r.note == "tracking " + text::upper(name));
    f.run(60.0);  // to 09:00:00: the rotator reaches the body and follows it
    REQUIRE(f.now == orbit::from_civil(2026, 3, 20, 9, 0, 0));
    const tracker::SatNow* s = f.tracker.followed();
    REQUIRE(s != nullptr);
    CHECK(s->name == text::upper(name));
    CHECK(s->list_number == 0);
    CHECK(s->in_range);
    CHECK(az_apart(s->obs.look.az_deg, az) < 0.01);
    CHECK(std::abs(s->obs.look.el_deg - el) < 0.01);
    // The rise and set from the one pass cache: up since the morning.
    REQUIRE(s->pass.has_value());
    CHECK(s->pass->aos < f.now);
    CHECK(f.now < s->pass->los);
    CHECK(f.tracker.passes().searches("tracker") == 1);
    const tracker::Decision& d = f.tracker.last_decision();
    CHECK(d.antenna == tracker::Decision::Antenna::point);
    const rotator::AzEl truth = f.truth();
    CHECK(az_apart(truth.az, az) < testing::kAzTol);
    CHECK(std::abs(truth.el - el) < testing::kElTol);
    // The choice is stored by name (catalog number 0) for a restart; the radio was not tuned.
    CHECK(f.model.tracking.mode == store::TrackingChoice::Mode::single);
    CHECK(f.model.tracking.name == text::upper(name));
    CHECK(f.model.tracking.catalog_number == 0);
    CHECK_FALSE(f.radio_sim->status().downlink_hz.has_value());
    // pass_at and pass_track serve the displays and the page's sky plot: the whole day's arc, from
    // the rise (PyEphem's, centre at -2 deg: 05:09:45 and 05:26:55; sky_bodies.py) to the set.
    const auto whole = f.tracker.pass_at(s->db_index, f.now);
    REQUIRE(whole.has_value());
    const orbit::UtcTime rise = text::upper(name) == "SUN" ? orbit::from_civil(2026, 3, 20, 5, 9, 45)
                                                            : orbit::from_civil(2026, 3, 20, 5, 26, 55);
    CHECK(std::abs(orbit::minutes_between(whole->aos, rise)) * 60.0 < 6.0);
    CHECK(std::abs(orbit::minutes_between(whole->los, s->pass->los)) * 60.0 < 2.0);
    CHECK(f.tracker.pass_track(s->db_index, *whole, 20).size() == 21);
  }
}

TEST_CASE("Sky targets: the body below the horizon: the antenna waits (parks) as for a satellite") {
  Sky f;
  f.now = orbit::from_civil(2026, 3, 20, 22, 0, 0);  // the Sun set at 17:33
  REQUIRE(f.ops().track_body(orbit::Body::sun).ok());
  f.step(std::chrono::milliseconds(100));
  const tracker::SatNow* s = f.tracker.followed();
  REQUIRE(s != nullptr);
  CHECK_FALSE(s->in_range);
  CHECK(f.tracker.last_decision().antenna == tracker::Decision::Antenna::park);
  REQUIRE(s->pass.has_value());  // the next sunrise, 05:0x on the 21st
  CHECK(orbit::to_civil(s->pass->aos).day == 21);
  CHECK(orbit::to_civil(s->pass->aos).hour == 5);
}

TEST_CASE("This is the Sun: a rotator mounted 2.0 deg off in azimuth and -1.0 in elevation") {
  rotator::SimulatedRotatorParams p = rotator::SimulatedRotatorParams::matching(munich_model().rotator);
  p.mount_az_deg = 2.0;
  p.mount_el_deg = -1.0;
  Sky f(p);
  const orbit::UtcTime t = orbit::from_civil(2026, 3, 20, 9, 0, 0);
  const orbit::LookAngles sun = orbit::body_look(orbit::Body::sun, f.model.station.observer(), t);
  const rotator::RotatorConfig before = f.model.rotator;

  SUBCASE("the reading given: exactly that correction") {
    f.now = t;
    const tracker::OpResult r = f.ops().calibrate(orbit::Body::sun, rotator::AzEl{sun.az_deg + 2.0, sun.el_deg - 1.0});
    REQUIRE(r.ok());
    CHECK(r.model_changed);
    CHECK(f.model.rotator.az_offset_deg == doctest::Approx(-2.0).epsilon(1e-12));
    CHECK(f.model.rotator.el_offset_deg == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(f.model.rotator.sky.source == "sun");
    CHECK(f.model.rotator.sky.time == "2026-03-20T09:00:00Z");
    CHECK(r.note.find("correction az -2.00 el +1.00 deg") != std::string::npos);
    CHECK(r.note.find("offsets now az -2.00 el +1.00 (were +0.00 +0.00)") != std::string::npos);
    // Undo: the offsets before, the record before; a second undo redoes.
    REQUIRE(f.ops().calibrate_undo().ok());
    CHECK(f.model.rotator.az_offset_deg == before.az_offset_deg);
    CHECK(f.model.rotator.el_offset_deg == before.el_offset_deg);
    CHECK(f.model.rotator.sky.source == before.sky.source);
    CHECK(f.model.rotator.sky.previous_source == "sun");  // what was undone, for a redo
    REQUIRE(f.ops().calibrate_undo().ok());
    CHECK(f.model.rotator.az_offset_deg == doctest::Approx(-2.0).epsilon(1e-12));
  }

  SUBCASE("the running rotator peaked on the Sun by hand: its reading, then the display tells the truth") {
    // The operator peaks it: the antenna truly on the Sun reads 2.0 more and 1.0 less.
    REQUIRE(f.ops().go_to(sun.az_deg + 2.0, sun.el_deg - 1.0).ok());
    f.run(59.0);
    f.now = t;
    f.station->tick();
    CHECK(az_apart(f.truth().az, sun.az_deg) < testing::kAzTol);
    REQUIRE(f.ops().calibrate(orbit::Body::sun).ok());
    // The reading (quantised by the ADC, stopped inside the dead band) against the computed Sun.
    CHECK(std::abs(f.model.rotator.az_offset_deg + 2.0) < testing::kAzTol);
    CHECK(std::abs(f.model.rotator.el_offset_deg - 1.0) < testing::kElTol);
    f.station->tick();  // the controller reads the same counts through the new offsets
    const auto reading = f.station->antenna();
    REQUIRE(reading.has_value());
    CHECK(az_apart(reading->az, sun.az_deg) < 1e-6);
    CHECK(std::abs(reading->el - sun.el_deg) < 1e-6);
    // Tracking the Sun now puts the antenna itself on it.
    REQUIRE(f.ops().track("SUN").ok());
    f.run(30.0);
    const orbit::LookAngles now = orbit::body_look(orbit::Body::sun, f.model.station.observer(), f.now);
    CHECK(az_apart(f.truth().az, now.az_deg) < testing::kAzTol);
    CHECK(std::abs(f.truth().el - now.el_deg) < testing::kElTol);
  }

  SUBCASE("refusals change nothing") {
    f.now = orbit::from_civil(2026, 3, 20, 22, 0, 0);
    const tracker::OpResult night = f.ops().calibrate(orbit::Body::sun, rotator::AzEl{0.0, 10.0});
    REQUIRE_FALSE(night.ok());
    CHECK(night.refusal->find("below the 2 deg a calibration needs") != std::string::npos);
    f.now = t;
    const tracker::OpResult far = f.ops().calibrate(orbit::Body::sun, rotator::AzEl{sun.az_deg + 60.0, sun.el_deg});
    REQUIRE_FALSE(far.ok());
    CHECK(*far.refusal ==
          "the azimuth offset would be -60.00 deg, beyond 45 either way: check the station's position, the clock and "
          "that the antenna is on the body");
    CHECK(f.model.rotator == before);
    CHECK(f.ops().calibrate_undo().refusal.value() == "no sky calibration to undo");
  }
}
