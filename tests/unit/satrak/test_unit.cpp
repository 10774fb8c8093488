// A scripted Satrak session on a simulated station: every command of the seed, what it does to the
// station, and every kind of bad request answered with its error code and nothing changed.
#include "fixture.h"

using namespace satrak_test;  // with std::chrono_literals and satrak::Error

TEST_CASE("VERSION? names trakbox and the drive unit") {
  Acu acu(kT0);
  CHECK(acu.cmd("VERSION?") == "VERSION?,TRAKBOX SATRAK CU V9.9.9,DU simulated");
  CHECK(acu.cmd("VERSION?,1") == err("VERSION?", Error::parameter_count));
  CHECK(acu.cmd("VERSION=") == err("VERSION=", Error::unknown_command));
}

TEST_CASE("GOTO moves the simulated rotator; STATUS? and TPOS? report it moving and arriving") {
  Acu acu(kT0);
  CHECK(acu.cmd("GOTO=,100,30") == "GOTO=,OK");
  REQUIRE(acu.rs().target);
  CHECK(acu.rs().target->az_travel == doctest::Approx(100.0));
  CHECK(acu.rs().target->el == doctest::Approx(30.0));
  acu.run(1s);
  auto s = acu.fields("STATUS?");
  REQUIRE(s.size() == 16);
  CHECK(s[11] == "1");  // X12: X moving +
  CHECK(s[12] == "1");  // X13: Y moving +
  CHECK(s[0] == "0");   // no fault
  CHECK(acu.status_num(2) > 0.5);
  CHECK(acu.status_num(2) < 20.0);
  acu.run(30s);
  s = acu.fields("STATUS?");
  CHECK(std::stod(s[1]) == doctest::Approx(100.0).epsilon(0.012));  // within the 3-count dead band
  CHECK(std::stod(s[2]) == doctest::Approx(30.0).epsilon(0.01));
  CHECK(s[11] == "0");
  CHECK(s[12] == "0");
  CHECK(s[13] == s[1]);  // X14 = X2 with no north offset
  CHECK(s[14] == s[2]);
  CHECK(s[7] == "0");    // X8 not tracking
  CHECK(s[8] == "0");    // X9 no window
  CHECK(s[15] == "0");   // X16 auto off
  // The station's own tracker was left alone (it was off) and moved nothing.
  CHECK(acu.tracker.mode() == tracker::Mode::off);

  const auto t = acu.fields("TPOS?");
  REQUIRE(t.size() == 9);
  CHECK(t[0] == s[13]);
  CHECK(t[1] == s[14]);
  const auto c = orbit::to_civil(acu.clock.now());
  CHECK(t[2] == std::to_string(c.hour));
  CHECK(t[3] == std::to_string(c.minute));
  CHECK(t[5] == std::to_string(c.day));
  CHECK(t[7] == std::to_string(c.year));

  SUBCASE("GOTO NONE leaves an axis where it is going") {
    CHECK(acu.cmd("GOTO=,NONE,40") == "GOTO=,OK");
    CHECK(acu.rs().target->az_travel == doctest::Approx(100.0));
    CHECK(acu.rs().target->el == doctest::Approx(40.0));
    CHECK(acu.cmd("GOTO=,74.61,none") == "GOTO=,OK");
    CHECK(acu.rs().target->az_travel == doctest::Approx(74.61));
    CHECK(acu.rs().target->el == doctest::Approx(40.0));
    acu.run(20s);
    CHECK(acu.status_num(2) == doctest::Approx(74.61).epsilon(0.015));
    CHECK(acu.status_num(3) == doctest::Approx(40.0).epsilon(0.01));
  }
  SUBCASE("STEP moves relative to where the antenna is going") {
    CHECK(acu.cmd("STEP=,+2,0") == "STEP=,OK");
    CHECK(acu.rs().target->az_travel == doctest::Approx(102.0));
    CHECK(acu.cmd("STEP=,2,-1") == "STEP=,OK");
    CHECK(acu.rs().target->az_travel == doctest::Approx(104.0));
    CHECK(acu.rs().target->el == doctest::Approx(29.0));
    acu.run(5s);
    CHECK(acu.status_num(2) == doctest::Approx(104.0).epsilon(0.012));
    CHECK(acu.status_num(3) == doctest::Approx(29.0).epsilon(0.012));
  }
  SUBCASE("MOVE drives at the rate asked and STOP= stops at once") {
    const double az0 = acu.status_num(2);
    CHECK(acu.cmd("MOVE=,2,0") == "MOVE=,OK");
    acu.run(5s);
    CHECK(acu.status(12) == "1");
    const double az5 = acu.status_num(2);
    acu.run(5s);
    const double az10 = acu.status_num(2);
    // 2 deg/s: about 10 degrees in 5 s (the dead band makes it move in short pushes).
    CHECK(az10 - az5 == doctest::Approx(10.0).epsilon(0.2));
    CHECK(az5 > az0 + 6.0);
    CHECK(acu.cmd("STOP=") == "STOP=,OK");
    acu.run(500ms);
    CHECK(acu.status(12) == "0");
    const double stopped = acu.status_num(2);
    acu.run(3s);
    CHECK(acu.status_num(2) == doctest::Approx(stopped).epsilon(0.005));
    CHECK(acu.rs().mode == rotator::ControlMode::idle);
  }
  SUBCASE("MOVE faster than the axis can go runs at its speed; MOVE=,0,0 releases") {
    CHECK(acu.cmd("MOVE=,-50,0") == "MOVE=,OK");
    acu.run(5s);
    CHECK(acu.status(12) == "-1");
    const double az = acu.status_num(2);
    CHECK(az < 100.0 - 20.0);  // 6 deg/s simulated motor
    CHECK(az > 100.0 - 40.0);
    CHECK(acu.cmd("MOVE=,0,0") == "MOVE=,OK");
    acu.run(1s);
    CHECK(acu.status(12) == "0");
  }
  SUBCASE("MOVE stops at the end of travel and STATUS? shows the limit") {
    CHECK(acu.cmd("MOVE=,0,-3") == "MOVE=,OK");
    acu.run(15s);
    auto st = acu.fields("STATUS?");
    CHECK(std::stod(st[2]) == doctest::Approx(0.0).epsilon(0.01));
    CHECK(st[12] == "0");
    CHECK(st[6] == "1");  // X7: Y - limit
    CHECK(st[5] == "0");
    CHECK(acu.cmd("MOVE=,0,3") == "MOVE=,OK");
    acu.run(40s);
    st = acu.fields("STATUS?");
    CHECK(std::stod(st[2]) == doctest::Approx(90.0).epsilon(0.01));
    CHECK(st[5] == "1");  // X6: Y + limit
    CHECK(st[6] == "0");
  }
  SUBCASE("The menus taking the antenna end Satrak's motion") {
    CHECK(acu.cmd("MOVE=,3,0") == "MOVE=,OK");
    acu.run(1s);
    acu.loop->point(rotator::AzEl{10.0, 10.0});  // menu 6-6-2 / host AZ/EL
    acu.run(30s);
    CHECK(acu.status_num(2) == doctest::Approx(10.0).epsilon(0.12));
    CHECK(acu.status(12) == "0");
  }
}

TEST_CASE("Limits from the configuration show in STATUS? and bound every motion command") {
  store::Model m = tucson_model();
  m.rotator.limits_enabled = true;
  m.rotator.az_limit_min = 20.0;
  m.rotator.az_limit_max = 300.0;
  m.rotator.el_limit_min = 5.0;
  m.rotator.el_limit_max = 80.0;
  Acu acu(kT0, {}, m);
  CHECK(acu.cmd("GOTO=,330,85") == "GOTO=,OK");  // clamped like every other command
  acu.run(70s);
  auto s = acu.fields("STATUS?");
  CHECK(std::stod(s[1]) == doctest::Approx(300.0).epsilon(0.005));
  CHECK(std::stod(s[2]) == doctest::Approx(80.0).epsilon(0.01));
  CHECK(s[3] == "1");  // X+ limit
  CHECK(s[5] == "1");  // Y+ limit
  CHECK(acu.cmd("MOVE=,-6,-3") == "MOVE=,OK");
  acu.run(70s);
  s = acu.fields("STATUS?");
  CHECK(std::stod(s[1]) == doctest::Approx(20.0).epsilon(0.06));
  CHECK(std::stod(s[2]) == doctest::Approx(5.0).epsilon(0.06));
  CHECK(s[4] == "1");  // X- limit
  CHECK(s[6] == "1");  // Y- limit
}

TEST_CASE("SETTINGS: north offset and minimum elevation change where GOTO/STEP/MOVE point") {
  Acu acu(kT0);
  const std::string before = acu.cmd("SETTINGS?");
  CHECK(before == "SETTINGS?,0,0,0.00,0.00,0,0,0.00,0.00,0,0,0,0.00");
  CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,10,?,?,?") == "SETTINGS=,OK");
  CHECK(acu.cmd("SETTINGS?") == "SETTINGS?,0,0,0.00,0.00,0,0,0.00,10.00,0,0,0,0.00");
  CHECK(acu.saves == 1);
  CHECK(acu.cmd("GOTO=,100,30") == "GOTO=,OK");
  CHECK(acu.rs().target->az_travel == doctest::Approx(90.0));  // the axis: true azimuth - north offset
  acu.run(30s);
  auto s = acu.fields("STATUS?");
  CHECK(std::stod(s[1]) == doctest::Approx(100.0).epsilon(0.012));  // X2: true azimuth
  CHECK(std::stod(s[13]) == doctest::Approx(90.0).epsilon(0.012));  // X14: the X axis angle
  CHECK(std::stod(acu.fields("TPOS?")[0]) == doctest::Approx(90.0).epsilon(0.012));

  CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,20,?,?,?,?") == "SETTINGS=,OK");
  CHECK(acu.cmd("GOTO=,100,5") == "GOTO=,OK");
  CHECK(acu.rs().target->el == doctest::Approx(20.0));
  CHECK(acu.cmd("STEP=,0,-10") == "STEP=,OK");
  CHECK(acu.rs().target->el == doctest::Approx(20.0));
  acu.run(10s);
  CHECK(acu.cmd("MOVE=,0,-3") == "MOVE=,OK");
  acu.run(10s);
  CHECK(acu.status_num(3) == doctest::Approx(20.0).epsilon(0.02));
  CHECK(acu.status(13) == "0");
}

TEST_CASE("SETTINGS= takes ? for unchanged, 11 or 12 fields, and checks every field before changing any") {
  Acu acu(kT0);
  CHECK(acu.cmd("SETTINGS=,1,100,1.0,2.0,60000,1,?,6.0,0,2,3.0") == "SETTINGS=,OK");  // the seed's example
  CHECK(acu.cmd("SETTINGS?") == "SETTINGS?,1,100,1.00,2.00,60000,1,0.00,6.00,0,2,0,3.00");
  const std::string good = acu.cmd("SETTINGS?");
  const int saves = acu.saves;
  CHECK(acu.cmd("SETTINGS=,1,100,1.0,2.0,60000,1,?,6.0,0,2") == err("SETTINGS=", Error::parameter_count));
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,0,0,0,0,0,0,0") == err("SETTINGS=", Error::parameter_count));
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,0,0,0,4,0") == err("SETTINGS=", Error::out_of_range));    // SSPA option
  CHECK(acu.cmd("SETTINGS=,2,0,0,0,0,0,0,0,0,0,0") == err("SETTINGS=", Error::out_of_range));    // X1 flag
  CHECK(acu.cmd("SETTINGS=,0,x,0,0,0,0,0,0,0,0,0") == err("SETTINGS=", Error::bad_value));       // ms
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,95,0,0,0,0") == err("SETTINGS=", Error::out_of_range));   // min el
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,0,0,0,0,91") == err("SETTINGS=", Error::out_of_range));   // threshold
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,0,0,0,0,0,1,0") == err("SETTINGS=", Error::parameter_count));
  // 12 fields (what SETTINGS? returns): X11 is the TLE source; web needs SATELLITE_HTTP first.
  CHECK(acu.cmd("SETTINGS=,0,0,0,0,0,0,0,0,0,0,1,0") ==
        tb::satrak::reply_error("SETTINGS=", Error::not_allowed, "NO HTTP SETTINGS: SATELLITE_HTTP= FIRST"));
  CHECK(acu.cmd("SETTINGS?") == good);
  CHECK(acu.saves == saves);
  CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,?,?,?,5") == "SETTINGS=,OK");
  CHECK(acu.fields("SETTINGS?")[11] == "5.00");
}

TEST_CASE("TIME? / TIME= read and set the real-time clock of menu 5") {
  Acu acu(kT0 + 250ms);
  CHECK(acu.cmd("TIME?") == "TIME?,12,0,0,21,5,2026,250");
  CHECK(acu.cmd("TIME=,16,43,0,17,3,2017") == "TIME=,OK");
  CHECK(acu.cmd("TIME?") == "TIME?,16,43,0,17,3,2017,0");
  CHECK(acu.clock.now() == orbit::from_civil(2017, 3, 17, 16, 43, 0));
  CHECK(acu.model.clock_offset == acu.clock.offset());
  CHECK(acu.saves == 1);
  acu.base += 1500ms;
  CHECK(acu.cmd("TIME?") == "TIME?,16,43,1,17,3,2017,500");
  CHECK(acu.cmd("TIME=,0,0,0,29,2,2024,999") == "TIME=,OK");  // a leap day; the ms field is taken
  CHECK(acu.cmd("TIME?") == "TIME?,0,0,0,29,2,2024,999");
  const std::string now = acu.cmd("TIME?");
  CHECK(acu.cmd("TIME=,0,0,0,29,2,2023") == err("TIME=", Error::out_of_range));
  CHECK(acu.cmd("TIME=,24,0,0,1,1,2020") == err("TIME=", Error::out_of_range));
  CHECK(acu.cmd("TIME=,0,60,0,1,1,2020") == err("TIME=", Error::out_of_range));
  CHECK(acu.cmd("TIME=,0,0,0,1,13,2020") == err("TIME=", Error::out_of_range));
  CHECK(acu.cmd("TIME=,0,0,0,1,1,1969") == err("TIME=", Error::out_of_range));
  CHECK(acu.cmd("TIME=,a,0,0,1,1,2020") == err("TIME=", Error::bad_value));
  CHECK(acu.cmd("TIME=,0,0,0,1,1") == err("TIME=", Error::parameter_count));
  CHECK(acu.cmd("TIME?") == now);
  CHECK(acu.saves == 2);
  CHECK(acu.cmd("TIME=,1,2,3,4,5,26") == "TIME=,OK");  // a two-digit year is 20YY
  CHECK(acu.cmd("TIME?") == "TIME?,1,2,3,4,5,2026,0");
}

TEST_CASE("ANGLE_SETTINGS: sensor and angle references become the rotator's skew") {
  Acu acu(kT0);
  CHECK(acu.cmd("ANGLE_SETTINGS?") == "ANGLE_SETTINGS?,0,0.00,0,0.00");
  // Sensor counts are the document's 16 bits (0..65535), scaled to the 10-bit ADC: 32768 is ADC
  // count 511.5, which reads 180.00 with no skew; to read 185 it takes +14 counts of skew.
  CHECK(acu.cmd("ANGLE_SETTINGS=0,32768,185.0,16384,46.0") == "ANGLE_SETTINGS=,OK");
  CHECK(acu.model.rotator.az_skew == 14);
  CHECK(acu.model.rotator.el_skew == 5);
  CHECK(acu.loop->rotator().config().az_skew == 14);  // the station was reconfigured
  // Read back as given, not as the whole-count skew makes the count read (185.18, 46.07).
  CHECK(acu.cmd("ANGLE_SETTINGS?") == "ANGLE_SETTINGS?,32768,185.0,16384,46.0");
  SUBCASE("automatic: the antenna's present counts read the angles given") {
    acu.run(1s);
    const auto raw = acu.loop->rotator().raw_counts();
    REQUIRE(raw);
    CHECK(acu.cmd("ANGLE_SETTINGS=,1,0,10.0,0,5.0") == "ANGLE_SETTINGS=,OK");
    acu.run(1s);
    CHECK(acu.status_num(14) == doctest::Approx(10.0).epsilon(0.04));
    CHECK(acu.status_num(15) == doctest::Approx(5.0).epsilon(0.04));
    CHECK(acu.cmd("ANGLE_SETTINGS?") == "ANGLE_SETTINGS?," + std::to_string(tb::satrak::sensor_from_adc(raw->az)) +
                                            ",10.0," + std::to_string(tb::satrak::sensor_from_adc(raw->el)) + ",5.0");
  }
  SUBCASE("a skew changed since (menu 6-3): the query answers what the reference reads now") {
    acu.model.rotator.az_skew = 20;
    acu.loop->reconfigure();
    const auto q = acu.fields("ANGLE_SETTINGS?");
    CHECK(q[1] == "187.04");  // ADC 511.5 + 20 through 1023 counts for 360 degrees
    CHECK(q[3] == "46.0");
  }
  SUBCASE("the document's example: 16-bit counts") {
    CHECK(acu.cmd("ANGLE_SETTINGS=0,39049,160.0,36838,40.0") == "ANGLE_SETTINGS=,OK");
    CHECK(acu.model.rotator.az_skew == -155);  // 39049 -> ADC 609.55; 160 deg is ADC 454.67
    CHECK(acu.model.rotator.el_skew == -348);  // 36838 -> ADC 575.04; 40 deg is ADC 227.11 (511 for 90)
    CHECK(acu.cmd("ANGLE_SETTINGS?") == "ANGLE_SETTINGS?,39049,160.0,36838,40.0");
  }
  CHECK(acu.cmd("ANGLE_SETTINGS=0,65536,160.0,0,40.0") == err("ANGLE_SETTINGS=", Error::out_of_range));
  CHECK(acu.cmd("ANGLE_SETTINGS=0,-1,160.0,0,40.0") == err("ANGLE_SETTINGS=", Error::out_of_range));
  CHECK(acu.cmd("ANGLE_SETTINGS=,2,0,1,0,1") == err("ANGLE_SETTINGS=", Error::out_of_range));
  CHECK(acu.cmd("ANGLE_SETTINGS=,0,0,1,0") == err("ANGLE_SETTINGS=", Error::parameter_count));
}

TEST_CASE("REDUCTION is kept and reported") {
  Acu acu(kT0);
  CHECK(acu.cmd("REDUCTION?") == "REDUCTION?,1,1");
  CHECK(acu.cmd("REDUCTION=,4000,4000") == "REDUCTION=,OK");
  CHECK(acu.cmd("REDUCTION?") == "REDUCTION?,4000,4000");
  CHECK(acu.cmd("REDUCTION=,62.5,0") == err("REDUCTION=", Error::out_of_range));
  CHECK(acu.cmd("REDUCTION=,62.5") == err("REDUCTION=", Error::parameter_count));
  CHECK(acu.cmd("REDUCTION?") == "REDUCTION?,4000,4000");
  CHECK(acu.unit->settings().reduction_x == 4000);
}

TEST_CASE("SATELLITE= names a file in the TLE directory and a satellite in it") {
  Acu acu(kT0);
  CHECK(acu.cmd("SATELLITE?") == "SATELLITE?,,,0,0,0.00");
  CHECK(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  const auto q = acu.fields("SATELLITE?");
  CHECK(q[0] == "amateur.txt");
  CHECK(q[1] == "ISS");
  CHECK(q[2] == "1");
  CHECK(q[3] == "25544");
  CHECK(std::stod(q[4]) > 0.0);  // the next pass's maximum elevation
  CHECK(acu.unit->elements()->catalog_number == 25544);
  CHECK(acu.cmd("SATELLITE=,amateur.txt,25544,1,1") == "SATELLITE=,OK");  // a catalog number works too
  CHECK(acu.cmd("SATELLITE=,amateur.txt,iss,1,1") == "SATELLITE=,OK");    // and any case

  const std::string before = acu.cmd("SATELLITE?");
  CHECK(acu.cmd("SATELLITE=,missing.txt,ISS,1,1") == err("SATELLITE=", Error::file_not_found));
  CHECK(acu.errstatus(3) == "1");
  CHECK(acu.status(1) == "1");
  CHECK(acu.cmd("SATELLITE=,amateur.txt,NO SUCH SAT,1,1") == err("SATELLITE=", Error::satellite_not_found));
  CHECK(acu.errstatus(3) == "0");
  CHECK(acu.errstatus(4) == "1");
  // ... and text a terminal could not show: an invalid byte, a C1 control (issue 38).
  for (const char* bad : {"../amateur.txt", "tle/amateur.txt", "..", ".hidden", "a\\b", "a\xff.txt", "a\xc2\x85.txt"})
    CHECK(acu.cmd(std::string("SATELLITE=,") + bad + ",ISS,1,1") == err("SATELLITE=", Error::bad_value));
  write_file(acu.dir.path / "tle" / "junk.txt", "not elements\n");
  CHECK(acu.cmd("SATELLITE=,junk.txt,ISS,1,1") == err("SATELLITE=", Error::invalid_file));
  CHECK(acu.cmd("SATELLITE=,amateur.txt,ISS,-1,1") == err("SATELLITE=", Error::out_of_range));
  CHECK(acu.cmd("SATELLITE=,amateur.txt,ISS,1") == err("SATELLITE=", Error::parameter_count));
  CHECK(acu.cmd("SATELLITE?") == before);
  CHECK(acu.unit->elements()->catalog_number == 25544);
  // A good SATELLITE= clears what the failed ones flagged.
  CHECK(acu.cmd("SATELLITE=,amateur.txt,AO-07,0,0") == "SATELLITE=,OK");
  CHECK(acu.errstatus(3) == "0");
  CHECK(acu.errstatus(4) == "0");
  CHECK(acu.unit->elements()->catalog_number == 7530);
}

TEST_CASE("ERRSTATUS? reports real conditions") {
  Acu acu(kT0);
  CHECK(acu.cmd("ERRSTATUS?") == "ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,0");
  acu.rot->set_fault("ADC not answering");
  acu.run(1s);
  auto e = acu.fields("ERRSTATUS?");
  CHECK(e[0] == "1");   // internal communication: the rotator link
  CHECK(e[9] == "2");   // no position: sensor connection
  CHECK(e[10] == "2");
  CHECK(acu.status(1) == "1");
  acu.rot->clear_fault();
  acu.run(1s);
  CHECK(acu.cmd("ERRSTATUS?") == "ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,0");
  CHECK(acu.status(1) == "0");

  SUBCASE("an element file older than its update period is not up to date") {
    CHECK(acu.cmd("SATELLITE=,amateur.txt,ISS,2,1") == "SATELLITE=,OK");
    const auto file = acu.dir.path / "tle" / "amateur.txt";
    const auto sys_now = std::chrono::file_clock::now();
    // The RTC (kT0) and the file times differ: put the file at RTC time minus one day.
    const auto rtc_minus_1d = acu.clock.now() - std::chrono::hours(24);
    const auto to_file = [&](orbit::UtcTime t) {
      return sys_now + std::chrono::duration_cast<std::filesystem::file_time_type::duration>(t - station::system_now());
    };
    fs::last_write_time(file, to_file(rtc_minus_1d));
    acu.run(2s);  // the unit notices the file changed and reads it again
    CHECK(acu.errstatus(2) == "0");
    fs::last_write_time(file, to_file(acu.clock.now() - std::chrono::hours(72)));
    acu.run(2s);
    CHECK(acu.errstatus(2) == "1");
    CHECK(acu.status(1) == "1");
  }
}

TEST_CASE("TLE files dropped into the directory are picked up") {
  const store::Model m = tucson_model();
  const orbit::Pass pass = iss_pass(m, kT0, 30.0, 70.0);
  Acu acu(orbit::add_minutes(pass.aos, 1.0));
  const auto file = acu.dir.path / "tle" / "mine.tle";
  orbit::Elements iss = iss_elements();
  write_file(file, orbit::format_nasa(iss));
  REQUIRE(acu.cmd("SATELLITE=,mine.tle,ISS,0,1") == "SATELLITE=,OK");
  REQUIRE(acu.cmd("TRACK=,1") == "TRACK=,OK");
  acu.run(2s);
  // A newer set with a different element set number replaces the old one.
  iss.element_set_number = 999;
  iss.epoch_day += 0.1;
  write_file(file, orbit::format_nasa(iss));
  acu.run(3s);
  CHECK(acu.unit->elements()->element_set_number == 999);
  CHECK(acu.status(8) == "1");
  // The satellite disappears from the file: flagged, and tracking continues from the last data.
  orbit::Elements other = iss;
  other.name = "OTHER";
  write_file(file, orbit::format_nasa(other));
  acu.run(3s);
  CHECK(acu.errstatus(4) == "1");
  CHECK(acu.status(8) == "1");
  CHECK(acu.unit->elements()->element_set_number == 999);
  // The file is removed: flagged, still tracking.
  fs::remove(file);
  acu.run(3s);
  CHECK(acu.errstatus(3) == "1");
  CHECK(acu.status(8) == "1");
  // Back again.
  write_file(file, orbit::format_nasa(iss));
  acu.run(3s);
  CHECK(acu.errstatus(3) == "0");
  CHECK(acu.errstatus(4) == "0");
}

TEST_CASE("Bad requests are answered with their error code and change nothing") {
  Acu acu(kT0);
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  REQUIRE(acu.cmd("GOTO=,50,20") == "GOTO=,OK");
  acu.run(20s);
  const std::vector<std::string> queries = {"SETTINGS?", "START_STOP_TIME?", "SATELLITE?", "SATELLITE_HTTP?",
                                            "SATELLITE_FTP?", "GPS_SETTINGS?", "ANGLE_SETTINGS?", "REDUCTION?",
                                            "TIME?", "LOAD_IMAGE?", "STATUS?"};
  auto snapshot = [&] {
    std::string s;
    for (const auto& q : queries) s += acu.cmd(q) + "\n";
    return s;
  };
  const std::string before = snapshot();
  const auto target = acu.rs().target;
  const int saves = acu.saves;
  const std::pair<std::string, std::string> cases[] = {
      {"FOO?", "FOO?,ERR,4"},
      {"FOO=,1", "FOO=,ERR,4"},
      {"STOP?", "STOP?,ERR,4"},
      {"STATUS=", "STATUS=,ERR,4"},
      {"HELLO", "HELLO,ERR,4"},
      // Found by fuzzing: a word with a tab inside, or hundreds of letters long, came back as it was
      // ("STATU\tS?,ERR,4": a control byte on the wire; a reply past the peer's 512-byte line).
      // What is not a command is echoed as sanitize_word() makes it: letters, digits, '_', 32 at most.
      {"STATU\tS?", "STATUS?,ERR,4"},
      // Found by fuzzing: a line starting "ERR," was answered "ERR,ERR,4"; ERR is the replies' word.
      {"ERR,STATUS?", "ERR,4"},
      {"ERR?", "ERR?,ERR,4"},  // a command word like any other, unknown
      {std::string(300, 'X') + "=,1", std::string(32, 'X') + "=,ERR,4"},
      {"", "ERR,4"},
      {"GOTO=,1", "GOTO=,ERR,5"},
      {"GOTO=,1,2,3", "GOTO=,ERR,5"},
      {"GOTO=", "GOTO=,ERR,5"},
      {"GOTO=,abc,2", "GOTO=,ERR,6"},
      {"GOTO=,,2", "GOTO=,ERR,6"},
      {"GOTO=,1e2,2", "GOTO=,ERR,6"},
      {"GOTO=,400,2", "GOTO=,ERR,7"},
      {"GOTO=,10,-91", "GOTO=,ERR,7"},
      {"MOVE=,1", "MOVE=,ERR,5"},
      {"MOVE=,x,0", "MOVE=,ERR,6"},
      {"MOVE=,91,0", "MOVE=,ERR,7"},
      {"STEP=,1,2,3", "STEP=,ERR,5"},
      {"STEP=,361,0", "STEP=,ERR,7"},
      {"STOP=,1", "STOP=,ERR,5"},
      {"STATUS?,1", "STATUS?,ERR,5"},
      {"TPOS?,1", "TPOS?,ERR,5"},
      {"TRACK=", "TRACK=,ERR,5"},
      {"TRACK=,2", "TRACK=,ERR,7"},
      {"TRACK=,yes", "TRACK=,ERR,6"},
      {"SETTINGS=,1", "SETTINGS=,ERR,5"},
      {"SATELLITE_HTTP=,ftp://x/y,1,1,1", "SATELLITE_HTTP=,ERR,6"},
      {"SATELLITE_HTTP=,http://x/y,1,1", "SATELLITE_HTTP=,ERR,5"},
      {"SATELLITE_HTTP=,http://x/y,-1,1,1", "SATELLITE_HTTP=,ERR,7"},
      {"SATELLITE_FTP=,host,u,p,0,f.txt,ISS,1,1", "SATELLITE_FTP=,ERR,7"},
      {"SATELLITE_FTP=,host,u,p,21,../f.txt,ISS,1,1", "SATELLITE_FTP=,ERR,6"},
      {"SATELLITE_FTP=,host,u,p,21,f.txt", "SATELLITE_FTP=,ERR,5"},
      {"LOAD_IMAGE=,../x.json", "LOAD_IMAGE=,ERR,6"},
      // Found by fuzzing: '$' and '*' (which a bare payload may hold) were stored, and the state
      // file's reader refuses them, so the next start lost every Satrak setting.
      {"SATELLITE_HTTP=,https://exampl$.invalid/a.txt,1,0,1", "SATELLITE_HTTP=,ERR,6"},
      {"SATELLITE_FTP=,ho*st,u,p,21,f.txt,ISS,1,1", "SATELLITE_FTP=,ERR,6"},
      {"SATELLITE_FTP=,host,u,p$,21,f.txt,ISS,1,1", "SATELLITE_FTP=,ERR,6"},
      {"SATELLITE_FTP=,host,u,p,21,f*.txt,ISS,1,1", "SATELLITE_FTP=,ERR,6"},
      {"LOAD_IMAGE=", "LOAD_IMAGE=,ERR,5"},
      {"GPS_DATA?,1", "GPS_DATA?,ERR,5"},
  };
  for (const auto& [request, reply] : cases) {
    CAPTURE(request);
    CHECK(acu.cmd(request) == reply);
  }
  CHECK(snapshot() == before);
  CHECK(acu.rs().target == target);
  CHECK(acu.saves == saves);

  SUBCASE("a bad checksum is answered and never acted on") {
    tb::satrak::Decoder d;
    const auto ev = d.feed("$GOTO=,10,10*00\r\n");
    REQUIRE(ev.size() == 1);
    CHECK(acu.unit->handle(ev[0]) == "GOTO=,ERR,1");
    CHECK(acu.rs().target == target);
    CHECK(acu.unit->handle(d.feed("$GOTO=,10,10\r\n").at(0)) == "GOTO=,ERR,2");
    CHECK(acu.unit->handle(d.feed("$GOTO=,10,10*zz\r\n").at(0)) == "GOTO=,ERR,2");
    CHECK(acu.unit->handle(d.feed("$\x01\x02*04\r\n").at(0)) == "ERR,1");
    tb::satrak::Decoder small(32);
    CHECK(acu.unit->handle(small.feed("$GOTO=,10,10," + std::string(100, '1')).at(0)) == "GOTO=,ERR,3");
    CHECK(acu.rs().target == target);
  }
  SUBCASE("rotor control off (the E key): a command that moves the antenna takes control") {
    acu.loop->set_rotor_control(false);
    CHECK(acu.cmd("STOP=") == "STOP=,OK");  // stopping never takes control
    CHECK_FALSE(acu.model.rotor_control);
    CHECK(acu.cmd("GOTO=,10,10") == "GOTO=,OK");
    CHECK(acu.model.rotor_control);
  }
  SUBCASE("TRACK=,1 without a satellite: the station's database and its first satellite") {
    Acu fresh(kT0);
    CHECK(fresh.cmd("TRACK=,1") == "TRACK=,OK");
    CHECK(fresh.cmd("SATELLITE?").rfind("SATELLITE?,database.tle,AO-07,0,7530,", 0) == 0);
    CHECK(fresh.status(8) == "1");
    Acu empty(kT0);
    empty.model.db = {};
    CHECK(empty.cmd("TRACK=,1") == "TRACK=,ERR,8,NO SATELLITE: SATELLITE= FIRST");
  }
}

TEST_CASE("The periodic check runs on the io_context's timer") {
  Acu acu(kT0);
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  const auto start = whole_seconds(kT0 + 2s);
  CHECK(acu.cmd("START_STOP_TIME=," + civil(start) + "," + civil(start + 3600s)) == "START_STOP_TIME=,OK");
  CHECK(acu.cmd("TRACK_AUTO_ENABLE=,1") == "TRACK_AUTO_ENABLE=,OK");
  acu.unit->start();
  acu.base = kT0 + 3s;
  acu.io.run_for(1s);
  CHECK(acu.unit->tracking());
  acu.unit->stop();
  acu.io.restart();
  acu.io.run_for(300ms);
}
