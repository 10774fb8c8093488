// A Satrak session tracking: SATELLITE= and TRACK= through a pass with the offsets, the station's
// radio following the unit's tracking, and the automatic windows of START_STOP_TIME.
#include "fixture.h"

using namespace satrak_test;  // with std::chrono_literals and satrak::Error

TEST_CASE("Tracking: SATELLITE= + TRACK=,1 follows the satellite through a pass, offsets applied") {
  const store::Model m = tucson_model();
  const orbit::Pass pass = iss_pass(m, kT0, 30.0, 70.0);
  Acu acu(orbit::add_minutes(pass.aos, -12.0));
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  CHECK(acu.cmd("TRACK=,1") == "TRACK=,OK");
  CHECK(acu.status(8) == "1");
  CHECK(acu.unit->tracking());
  acu.run(2s);
  CHECK_FALSE(acu.unit->tracking_target());  // below the horizon: the antenna waits

  SUBCASE("go to start before: the antenna waits at the rise point, then follows") {
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,600000,?,?,?,?,?,?") == "SETTINGS=,OK");
    acu.run_until(orbit::add_minutes(pass.aos, -1.0));
    REQUIRE(acu.rs().target);
    CHECK(acu.rs().target->el == doctest::Approx(0.0).epsilon(0.01));
    CHECK(angle_diff(acu.status_num(2), pass.aos_az_deg) < 4.0);
    double worst = 0.0;
    int samples = 0;
    while (acu.clock.now() < orbit::add_minutes(pass.los, -0.5)) {
      acu.step();
      const auto o = iss_at(acu.model, acu.clock.now());
      if (acu.clock.now() < orbit::add_minutes(pass.aos, 0.5) || o.look.el_deg < 1.0) continue;
      const auto& st = acu.rs();
      worst = std::max(worst, rotator::pointing_error_deg(st.az.deg, st.el.deg, o.look.az_deg, o.look.el_deg));
      ++samples;
    }
    CHECK(samples > 1000);
    CHECK(worst < 2.5);
    CHECK(acu.tracker.mode() == tracker::Mode::off);  // Satrak drove the antenna, not the menus' tracker
    CHECK(acu.status(8) == "1");
  }
  SUBCASE("position offsets, time offset, north offset, threshold") {
    acu.run_until(pass.tca);
    acu.step();
    auto o = iss_at(acu.model, acu.clock.now());
    REQUIRE(acu.unit->tracking_target());
    CHECK(acu.unit->tracking_target()->az == doctest::Approx(o.look.az_deg));
    CHECK(acu.unit->tracking_target()->el == doctest::Approx(o.look.el_deg));

    CHECK(acu.cmd("SETTINGS=,?,?,5,3,?,?,?,?,?,?,?") == "SETTINGS=,OK");
    acu.step();
    o = iss_at(acu.model, acu.clock.now());
    CHECK(acu.unit->tracking_target()->az == doctest::Approx(rotator::wrap360(o.look.az_deg + 5.0)));
    CHECK(acu.unit->tracking_target()->el == doctest::Approx(o.look.el_deg + 3.0));
    acu.run(5s);
    o = iss_at(acu.model, acu.clock.now());
    CHECK(rotator::pointing_error_deg(acu.rs().az.deg, acu.rs().el.deg, o.look.az_deg + 5.0, o.look.el_deg + 3.0) < 2.5);

    CHECK(acu.cmd("SETTINGS=,?,60000,0,0,?,?,?,?,?,?,?") == "SETTINGS=,OK");
    acu.step();
    o = iss_at(acu.model, acu.clock.now() + 60s);
    CHECK(acu.unit->tracking_target()->az == doctest::Approx(o.look.az_deg));
    CHECK(acu.unit->tracking_target()->el == doctest::Approx(o.look.el_deg));

    CHECK(acu.cmd("SETTINGS=,?,0,?,?,?,?,?,20,?,?,?") == "SETTINGS=,OK");
    acu.step();
    o = iss_at(acu.model, acu.clock.now());
    CHECK(acu.unit->tracking_target()->az == doctest::Approx(rotator::wrap360(o.look.az_deg - 20.0)));
    acu.run(10s);
    o = iss_at(acu.model, acu.clock.now());
    CHECK(angle_diff(acu.status_num(2), o.look.az_deg) < 2.5);          // true azimuth on the satellite
    CHECK(angle_diff(acu.status_num(14), o.look.az_deg - 20.0) < 2.5);  // the axis 20 degrees short

    // A threshold above the satellite: the antenna stops following.
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,0," "?,?,89") == "SETTINGS=,OK");
    acu.step();
    CHECK_FALSE(acu.unit->tracking_target());
    CHECK(acu.status(8) == "1");
  }
  SUBCASE("minimum elevation: the antenna never goes below it while tracking") {
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,15,?,?,?,?") == "SETTINGS=,OK");
    acu.run_until(orbit::add_minutes(pass.aos, 1.0));
    const auto o = iss_at(acu.model, acu.clock.now());
    REQUIRE(o.look.el_deg < 15.0);
    REQUIRE(acu.unit->tracking_target());
    CHECK(acu.unit->tracking_target()->el == doctest::Approx(15.0));
    acu.run(10s);
    CHECK(acu.status_num(3) == doctest::Approx(15.0).epsilon(0.02));
  }
  SUBCASE("TRACK=,0 stops tracking and the antenna") {
    acu.run_until(orbit::add_minutes(pass.aos, 1.0));
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    CHECK(acu.status(8) == "0");
    CHECK(acu.rs().mode == rotator::ControlMode::idle);
    CHECK(acu.errstatus(6) == "0");
  }
  SUBCASE("the menus starting their own tracking take over: ERRSTATUS X6") {
    acu.run_until(orbit::add_minutes(pass.aos, 1.0));
    acu.tracker.track_single(*acu.model.db.find("AO-07"));
    acu.step();
    CHECK(acu.status(8) == "0");
    CHECK(acu.errstatus(6) == "1");
    CHECK(acu.status(1) == "1");
    CHECK(acu.tracker.mode() == tracker::Mode::single);
    // The operator took it back (tracker/control.h): the Satrak client is refused until --handback
    // (30 s) has passed since the operator's action, then it may take it again.
    CHECK(acu.cmd("TRACK=,1").rfind("TRACK=,ERR,8,THE OPERATOR TOOK THE ANTENNA BACK", 0) == 0);
    CHECK(acu.tracker.mode() == tracker::Mode::single);
    acu.run(std::chrono::seconds(31));
    CHECK(acu.cmd("TRACK=,1") == "TRACK=,OK");
    CHECK(acu.tracker.mode() == tracker::Mode::off);
    CHECK(acu.errstatus(6) == "0");
  }
  SUBCASE("STOP= stops tracking too") {
    acu.run_until(orbit::add_minutes(pass.aos, 1.0));
    CHECK(acu.cmd("STOP=") == "STOP=,OK");
    CHECK(acu.status(8) == "0");
    acu.run(2s);
    CHECK(acu.rs().mode == rotator::ControlMode::idle);
  }
  SUBCASE("SSPA: on with tracking, with the satellite in view, by hand") {
    CHECK_FALSE(acu.unit->sspa_on());  // X9 = 0: disabled
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,2,0,?") == "SETTINGS=,OK");
    CHECK(acu.unit->sspa_on());  // auto, only tracking: tracking is on
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,2,1,?") == "SETTINGS=,OK");
    CHECK_FALSE(acu.unit->sspa_on());  // only "carrier lock": the satellite is below the threshold
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,2,3,?") == "SETTINGS=,OK");
    CHECK(acu.unit->sspa_on());
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,2,2,?") == "SETTINGS=,OK");
    CHECK_FALSE(acu.unit->sspa_on());
    acu.run_until(orbit::add_minutes(pass.aos, 1.0));
    CHECK(acu.unit->sspa_on());
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    CHECK_FALSE(acu.unit->sspa_on());
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,1,?,?") == "SETTINGS=,OK");
    CHECK(acu.unit->sspa_on());
  }
}

TEST_CASE("Satrak tracking is the station's: the radio follows with Doppler, the status line names it") {
  const store::Model m = tucson_model();
  const orbit::Pass pass = iss_pass(m, kT0, 30.0, 70.0);
  Acu acu(orbit::add_minutes(pass.aos, -3.0));
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  CHECK_FALSE(acu.loop->remote_followed());
  CHECK(acu.cmd("TRACK=,1") == "TRACK=,OK");
  acu.run(1s);
  REQUIRE(acu.loop->remote_followed());
  CHECK(acu.loop->remote_followed()->name == "ISS");
  CHECK(acu.loop->remote_followed()->owner == "Satrak");
  CHECK(acu.loop->remote_db_index() == acu.model.db.find("ISS"));
  CHECK(acu.loop->status_line().find("| Satrak: ISS |") != std::string::npos);

  // Two minutes after AOS the ISS approaches fast: the downlink the radio is tuned to is
  // 437.800 MHz (data/freqmode.txt) with the Doppler of the moment, within the FM Doppler step
  // (100 Hz, RadioConfig::doppler_step_fm_hz: an FM link is sent when it moved that far).
  acu.run_until(orbit::add_minutes(pass.aos, 2.0));
  CHECK(acu.loop->status_line().find("| Satrak: ISS AOS |") != std::string::npos);
  const orbit::Observation o = acu.loop->remote_followed()->obs;
  REQUIRE(o.look.range_rate_km_s < -3.0);
  const double expected = 437.8e6 * (1.0 - o.look.range_rate_km_s / radio::kSpeedOfLightKmS);
  const auto rs = acu.loop->radio().status();
  REQUIRE(rs.downlink_hz);
  CHECK(std::abs(static_cast<double>(*rs.downlink_hz) - expected) <= static_cast<double>(acu.model.radio.doppler_step_fm_hz));
  CHECK(*rs.downlink_hz > radio::Hz{437800000} + 5000);  // about +9 kHz: really corrected

  SUBCASE("TRACK=,0 ends it") {
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    CHECK_FALSE(acu.loop->remote_followed());
    CHECK(acu.loop->status_line().find("Satrak") == std::string::npos);
    const auto before = acu.loop->radio().status().downlink_hz;
    acu.run(5s);
    CHECK(acu.loop->radio().status().downlink_hz == before);  // nobody tunes it any more
  }
  SUBCASE("the menus' tracker taking the antenna takes the radio too") {
    acu.tracker.track_single(*acu.model.db.find("AO-07"));
    acu.step();
    CHECK_FALSE(acu.loop->remote_followed());
    CHECK(acu.loop->status_line().find("| AO-07") != std::string::npos);
  }
  SUBCASE("a satellite the database does not hold: the antenna follows, the radio is left alone") {
    acu.model.db.satellites.erase(acu.model.db.satellites.begin() + *acu.model.db.find("ISS"));
    acu.model.db.selected.clear();
    acu.loop->reconfigure();
    acu.step();
    REQUIRE(acu.loop->remote_followed());
    CHECK_FALSE(acu.loop->remote_db_index());
    const auto before = acu.loop->radio().status().downlink_hz;
    acu.run(5s);
    CHECK(acu.loop->radio().status().downlink_hz == before);
    CHECK(acu.unit->tracking_target());
  }
}

TEST_CASE("Auto tracking: START_STOP_TIME + TRACK_AUTO_ENABLE start and stop by themselves") {
  const store::Model m = tucson_model();
  const orbit::Pass pass = iss_pass(m, kT0, 30.0, 70.0);
  const orbit::UtcTime start = whole_seconds(orbit::add_minutes(pass.aos, 1.0));
  const orbit::UtcTime stop = whole_seconds(orbit::add_minutes(pass.aos, 4.0));
  Acu acu(orbit::add_minutes(pass.aos, -10.0));
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  CHECK(acu.cmd("START_STOP_TIME?") == "START_STOP_TIME?,0,0,0,0,0,0,0,0,0,0,0,0");
  CHECK(acu.cmd("START_STOP_TIME=," + civil(start) + "," + civil(stop)) == "START_STOP_TIME=,OK");
  CHECK(acu.cmd("START_STOP_TIME?") == "START_STOP_TIME?," + civil(start) + "," + civil(stop));
  CHECK(acu.cmd("SETTINGS=,?,?,?,?,120000,?,?,?,?,?,?") == "SETTINGS=,OK");
  CHECK(acu.cmd("TRACK_AUTO_ENABLE =,1") == "TRACK_AUTO_ENABLE=,OK");
  CHECK(acu.status(16) == "1");
  CHECK(acu.status(9) == "0");
  acu.run(5s);
  CHECK(acu.status(8) == "0");
  CHECK(acu.rs().mode == rotator::ControlMode::idle);

  acu.run_until(start - 119s);
  CHECK(acu.status(9) == "3");  // start before time
  CHECK(acu.status(8) == "0");
  REQUIRE(acu.rs().target);      // going to the start position
  acu.run_until(start - 5s);
  const auto at_start = iss_at(acu.model, start);
  CHECK(rotator::pointing_error_deg(acu.rs().az.deg, acu.rs().el.deg, at_start.look.az_deg, at_start.look.el_deg) < 2.5);

  acu.run_until(start + 1s);
  CHECK(acu.status(9) == "1");
  CHECK(acu.status(8) == "1");
  acu.run(60s);
  const auto o = iss_at(acu.model, acu.clock.now());
  CHECK(rotator::pointing_error_deg(acu.rs().az.deg, acu.rs().el.deg, o.look.az_deg, o.look.el_deg) < 2.5);

  SUBCASE("the window closes") {
    acu.run_until(stop + 1s);
    CHECK(acu.status(9) == "2");
    CHECK(acu.status(8) == "0");
    acu.run(2s);
    CHECK(acu.rs().mode == rotator::ControlMode::idle);
    CHECK(acu.status(12) == "0");
    CHECK(acu.errstatus(6) == "0");
  }
  SUBCASE("TRACK=,0 inside the window is not undone") {
    CHECK(acu.cmd("TRACK=,0") == "TRACK=,OK");
    acu.run(5s);
    CHECK(acu.status(8) == "0");
    CHECK(acu.status(9) == "1");
  }
  SUBCASE("TRACK_AUTO_ENABLE=,0 stops what the window started") {
    CHECK(acu.cmd("TRACK_AUTO_ENABLE=,0") == "TRACK_AUTO_ENABLE=,OK");
    CHECK(acu.status(8) == "0");
    CHECK(acu.status(16) == "0");
  }
  CHECK(acu.cmd("START_STOP_TIME=,0,0,0,0,0,0,0,0,0,0,0,0") == "START_STOP_TIME=,OK");  // cleared
  CHECK(acu.status(9) == "0");
}

TEST_CASE("START_STOP_TIME= refuses windows that are not windows") {
  Acu acu(kT0);
  CHECK(acu.cmd("START_STOP_TIME=,20,35,0,11,8,2017,20,30,0,11,8,2017") == err("START_STOP_TIME=", Error::out_of_range));
  CHECK(acu.cmd("START_STOP_TIME=,20,30,0,31,9,2017,20,35,0,11,10,2017") == err("START_STOP_TIME=", Error::out_of_range));
  CHECK(acu.cmd("START_STOP_TIME=,20,30,0,11,8,2017,20,35,0,11,8") == err("START_STOP_TIME=", Error::parameter_count));
  CHECK(acu.cmd("START_STOP_TIME?") == "START_STOP_TIME?,0,0,0,0,0,0,0,0,0,0,0,0");
  CHECK(acu.cmd("START_STOP_TIME=,20,30,0,11,8,2017,20,35,0,11,8,2017") == "START_STOP_TIME=,OK");  // the seed's
  CHECK(acu.cmd("START_STOP_TIME?") == "START_STOP_TIME?,20,30,0,11,8,2017,20,35,0,11,8,2017");
  CHECK(acu.status(9) == "2");  // that window is long past
  CHECK(acu.cmd("TRACK_AUTO_ENABLE=,2") == err("TRACK_AUTO_ENABLE=", Error::out_of_range));
  CHECK(acu.cmd("TRACK_AUTO_ENABLE=") == err("TRACK_AUTO_ENABLE=", Error::parameter_count));
}

TEST_CASE("After the station moves, the unit's pass is the new place's: it waits at the new rise point (issue 55)") {
  const store::Model m = tucson_model();
  const orbit::Pass pass = iss_pass(m, kT0, 30.0, 70.0);
  Acu acu(orbit::add_minutes(pass.aos, -30.0));
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  CHECK(acu.cmd("SETTINGS=,?,?,?,?,600000,?,?,?,?,?,?") == "SETTINGS=,OK");
  CHECK(acu.cmd("TRACK=,1") == "TRACK=,OK");
  acu.run(2s);
  // Half an hour before the pass the station moves 300 km north (a GPS fix, a typed position: the
  // one door either way); the unit's next pass is searched again from the new place.
  const orbit::Observer there{35.2, -110.9, 2100.0};
  REQUIRE(acu.owner.set_position(there.lat_deg, there.lon_deg, there.height_m, store::Origin::gps).ok());
  const orbit::Sgp4 sgp4(iss_elements());
  std::optional<orbit::Pass> moved;
  for (const auto& p : orbit::find_passes(sgp4, there, acu.clock.now(), orbit::add_minutes(pass.aos, 60.0)))
    if (!p.up_at_start && !moved) moved = p;
  REQUIRE(moved);
  REQUIRE(angle_diff(moved->aos_az_deg, pass.aos_az_deg) > 3.0);   // the two rise points differ
  acu.run_until(orbit::add_minutes(moved->aos, -1.0));
  REQUIRE(acu.rs().target);
  CHECK(acu.rs().target->el == doctest::Approx(0.0).epsilon(0.01));
  CHECK(angle_diff(acu.status_num(2), moved->aos_az_deg) < 2.0);   // the new place's rise point
  CHECK(angle_diff(acu.status_num(2), pass.aos_az_deg) > 1.0);     // not the old one's
}
