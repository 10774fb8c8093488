// A scripted Satrak session on a simulated station: every command of the seed, what it does to the
// station, and every kind of bad request answered with its error code and nothing changed.
#include "fixture.h"
#include "support/gps_fix.h"

#include "rotator/pass_plan.h"
#include "satrak/settings.h"
#include "store/state_file.h"

using namespace satrak_test;
using namespace std::chrono_literals;
using tb::satrak::Error;

namespace {

const orbit::UtcTime kT0 = orbit::from_civil(2026, 5, 21, 12, 0, 0);

std::string civil(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  return std::to_string(c.hour) + "," + std::to_string(c.minute) + "," + std::to_string(static_cast<int>(c.second)) + "," +
         std::to_string(c.day) + "," + std::to_string(c.month) + "," + std::to_string(c.year);
}

orbit::UtcTime whole_seconds(orbit::UtcTime t) { return std::chrono::floor<std::chrono::seconds>(t); }

orbit::Observation iss_at(const store::Model& m, orbit::UtcTime t) {
  static const orbit::Sgp4 sgp4(iss_elements());
  return orbit::observe(sgp4, m.station.observer(), t);
}

std::string err(std::string head, Error e) { return tb::satrak::reply_error(head, e); }

}  // namespace

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

TEST_CASE("GPS: no receiver; GPS_DATA? reports the station, GPS_SETTINGS sets it, RTC_REUPDATE is refused") {
  Acu acu(kT0);
  CHECK(acu.cmd("GPS_DATA?") == "GPS_DATA?,32.2590N,110.7780W,0,12,0,0,21,5,26");
  CHECK(acu.cmd("GPS_SETTINGS?") == "GPS_SETTINGS?,0,32.2590N,110.7780W");
  CHECK(acu.cmd("GPS_SETTINGS=,0,41.02N,29.17E") == "GPS_SETTINGS=,OK");
  CHECK(acu.model.station.lat_deg == doctest::Approx(41.02));
  CHECK(acu.model.station.lon_deg == doctest::Approx(29.17));
  CHECK(acu.cmd("GPS_DATA?") == "GPS_DATA?,41.0200N,29.1700E,0,12,0,0,21,5,26");
  CHECK(acu.errstatus(12) == "0");
  CHECK(acu.cmd("GPS_SETTINGS=,1,?,?") == "GPS_SETTINGS=,OK");  // auto: there is no GPS to read
  CHECK(acu.errstatus(12) == "1");
  CHECK(acu.status(1) == "1");
  CHECK(acu.model.station.lat_deg == doctest::Approx(41.02));
  CHECK(acu.cmd("GPS_SETTINGS=,0,91N,29E") == err("GPS_SETTINGS=", Error::out_of_range));
  CHECK(acu.cmd("GPS_SETTINGS=,0,41N,29N") == err("GPS_SETTINGS=", Error::bad_value));
  CHECK(acu.cmd("GPS_SETTINGS=,0,41N") == err("GPS_SETTINGS=", Error::parameter_count));
  CHECK(acu.cmd("GPS_SETTINGS?") == "GPS_SETTINGS?,1,41.02N,29.17E");  // as written (issue 19, item 5)
  CHECK(acu.cmd("RTC_REUPDATE=") == "RTC_REUPDATE=,ERR,8,NO GPS RECEIVER");
  CHECK(acu.status(10) == "0");
  CHECK(acu.status(11) == "0");
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
    CHECK(acu.cmd("TRACK=,1") == "TRACK=,OK");  // and Satrak may take it back
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

TEST_CASE("LOAD_IMAGE: a state document, validated as a whole before it replaces anything") {
  Acu acu(kT0);
  CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,0");
  // An image made the way the program saves its state: the Model plus data["satrak"].
  store::Model m = acu.model;
  m.station.callsign = "IMAGE";
  m.station.lat_deg = 10.5;
  m.rotator.az_dead_band = 5;
  m.db.satellites.resize(3);
  m.db.normalise();
  satrak::Settings s;
  s.north_offset_deg = 7.5;
  s.tle_file = "amateur.txt";
  s.satellite = "AO-07";
  nlohmann::json data = store::to_json(m);
  data["satrak"] = satrak::to_json(s);
  {
    store::StateFile sf(acu.dir.path / "images");
    std::string e;
    REQUIRE(sf.save(data, e));
    fs::rename(sf.path(), acu.dir.path / "images" / "sysImage.json");
  }
  // Broken copies: bad checksum, bad field, not JSON.
  {
    auto doc = nlohmann::json::parse(read_file(acu.dir.path / "images" / "sysImage.json"));
    auto bad = doc;
    bad["data"]["station"]["callsign"] = "CHANGED";
    write_file(acu.dir.path / "images" / "badsum.json", bad.dump());
    auto bad2 = doc;
    bad2["data"]["satrak"]["north_offset_deg"] = 999;
    char sum[9];
    std::snprintf(sum, sizeof sum, "%08x", store::crc32(bad2["data"].dump()));
    bad2["checksum"] = sum;
    write_file(acu.dir.path / "images" / "badfield.json", bad2.dump());
    auto bad3 = doc;
    bad3["data"]["rotator"]["az_dead_band"] = -1;
    std::snprintf(sum, sizeof sum, "%08x", store::crc32(bad3["data"].dump()));
    bad3["checksum"] = sum;
    write_file(acu.dir.path / "images" / "badmodel.json", bad3.dump());
    write_file(acu.dir.path / "images" / "junk.json", "{not json");
  }
  const std::string callsign = acu.model.station.callsign;
  for (const char* f : {"badsum.json", "badfield.json", "badmodel.json", "junk.json"}) {
    CAPTURE(f);
    CHECK(acu.cmd(std::string("LOAD_IMAGE=,") + f) == "LOAD_IMAGE=,ERR,11");
    CHECK(acu.model.station.callsign == callsign);
    CHECK(acu.unit->settings().north_offset_deg == 0.0);
    CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,2");
  }
  CHECK(acu.cmd("LOAD_IMAGE=,none.json") == "LOAD_IMAGE=,ERR,9");
  CHECK(acu.saves == 0);

  CHECK(acu.cmd("LOAD_IMAGE=,sysImage.json") == "LOAD_IMAGE=,OK");
  CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,1");
  CHECK(acu.model.station.callsign == "IMAGE");
  CHECK(acu.model.db.satellites.size() == 3);
  CHECK(acu.loop->rotator().config().az_dead_band == 5);  // the station runs on it
  CHECK(acu.unit->settings().north_offset_deg == 7.5);
  CHECK(acu.unit->elements()->catalog_number == 7530);
  CHECK(acu.cmd("GPS_SETTINGS?") == "GPS_SETTINGS?,0,10.5000N,110.7780W");
  CHECK(acu.saves == 1);
}

TEST_CASE("Settings JSON: round trip, and every bad field named") {
  satrak::Settings s;
  s.time_offset_ms = -1500;
  s.az_offset_deg = 1.25;
  s.window = satrak::TrackWindow{kT0, kT0 + 300s};
  s.auto_track = true;
  s.tle_file = "iridium.txt";
  s.satellite = "IRIDIUM 70 [+]";
  s.source = satrak::TleSource::ftp;
  s.ftp = {"10.0.1.2", "user", "secret", 2121, "iridium.txt", "IRIDIUM 70 [+]", 1.0, satrak::ErrorAction::stop_tracking};
  s.reduction_x = 4000;
  const auto j = satrak::to_json(s);
  CHECK(satrak::settings_from_json(j) == s);
  CHECK(satrak::settings_from_json(nlohmann::json::parse(j.dump())) == s);
  CHECK(satrak::settings_from_json(satrak::to_json(satrak::Settings{})) == satrak::Settings{});
  auto expect_throw = [&](const char* key, nlohmann::json value, const char* needle) {
    auto bad = j;
    bad[key] = std::move(value);
    try {
      satrak::settings_from_json(bad);
      FAIL("accepted " << key);
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
    }
  };
  expect_throw("north_offset_deg", 400, "satrak.north_offset_deg");
  expect_throw("tle_file", "../x", "satrak.tle_file");
  expect_throw("auto_track", 1, "satrak.auto_track");
  expect_throw("window", nlohmann::json{{"start", "2026-05-21T12:00:00Z"}, {"stop", "2026-05-21T11:00:00Z"}}, "satrak.window");
  expect_throw("satellite", "A,B", "satrak.satellite");
  auto missing = j;
  missing.erase("min_elevation_deg");
  CHECK_THROWS_WITH_AS(satrak::settings_from_json(missing), "satrak.min_elevation_deg: missing", std::runtime_error);
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

TEST_CASE("GPS: a receiver through gpsd; GPS_DATA? answers its fix and time as the document's example") {
  // The document's example: GPS_DATA?,41.01N,29.17E,1,6,0,2,19,10,17 (06:00:02 on 19 October 2017).
  const orbit::UtcTime gps0 = orbit::from_civil(2017, 10, 19, 6, 0, 0);
  Acu acu(kT0);  // the clock reads 2026-05-21 12:00:00: far from GPS time
  gps::Monitor receiver("gpsd:127.0.0.1:2947");
  acu.loop->set_gps(&receiver);
  CHECK(acu.errstatus(12) == "1");  // expected, not heard yet
  CHECK(acu.cmd("RTC_REUPDATE=") == "RTC_REUPDATE=,ERR,8,NO GPS FIX");
  receiver.on_link(gps::Link::receiving);
  CHECK(acu.errstatus(12) == "0");
  testing::feed_gps_fix(receiver, gps0, acu.clock.now(), 3, 2);
  // Not confirmed yet: the station's position, valid 0, the RTC's time.
  CHECK(acu.cmd("GPS_DATA?") == "GPS_DATA?,32.2590N,110.7780W,0,12,0,0,21,5,26");
  receiver.on_report(testing::gps_report(orbit::add_seconds(gps0, 2)), acu.clock.now());
  CHECK(acu.cmd("GPS_DATA?") == "GPS_DATA?,41.0100N,29.1700E,1,6,0,2,19,10,17");
  // The station follows only in GPS mode.
  CHECK(acu.model.station.lat_deg == doctest::Approx(32.259));
  CHECK(acu.cmd("GPS_SETTINGS=,1,?,?") == "GPS_SETTINGS=,OK");
  CHECK(acu.model.gps.follow);
  CHECK(acu.model.station.lat_deg == 41.01);
  CHECK(acu.model.station.lon_deg == 29.17);
  CHECK(acu.model.station.height_m == 120.0);
  CHECK(acu.model.gps.position_from_gps);
  CHECK(acu.cmd("GPS_SETTINGS?") == "GPS_SETTINGS?,1,41.0100N,29.1700E");
  // RTC_REUPDATE=: the RTC reads GPS time (as of the last report).
  CHECK(acu.status(10) == "0");
  CHECK(acu.cmd("RTC_REUPDATE=") == "RTC_REUPDATE=,OK");
  CHECK(acu.cmd("TIME?") == "TIME?,6,0,2,19,10,2017,0");
  CHECK(acu.status(10) == "1");
  CHECK(acu.model.clock_offset == acu.clock.offset());
  // The fix lost: the last position, valid 0, the RTC's time; gpsd gone: X12.
  receiver.on_report(testing::gps_report(orbit::add_seconds(gps0, 3), 1), acu.clock.now());
  CHECK(acu.cmd("GPS_DATA?") == "GPS_DATA?,41.0100N,29.1700E,0,6,0,2,19,10,17");
  CHECK(acu.errstatus(12) == "0");
  CHECK(acu.cmd("RTC_REUPDATE=") == "RTC_REUPDATE=,ERR,8,NO GPS FIX");
  receiver.on_link(gps::Link::lost, "connection closed");
  CHECK(acu.errstatus(12) == "1");
  CHECK(acu.status(1) == "1");
  acu.loop->set_gps(nullptr);
}

TEST_CASE("GPS: SETTINGS X1 (RTC auto update) sets the clock from GPS time by itself once it is warned about") {
  const orbit::UtcTime gps0 = orbit::from_civil(2017, 10, 19, 6, 0, 0);
  Acu acu(kT0);
  gps::Monitor receiver("gpsd:127.0.0.1:2947");
  acu.loop->set_gps(&receiver);
  testing::feed_gps_fix(receiver, gps0, acu.clock.now());
  REQUIRE(receiver.clock_warned());
  acu.step();
  CHECK(acu.cmd("TIME?") == "TIME?,12,0,0,21,5,2026,100");  // X1 off: the clock is left alone
  CHECK(acu.cmd("SETTINGS=,1,?,?,?,?,?,?,?,?,?,?") == "SETTINGS=,OK");
  acu.step();
  // The clock error measured at the report (GPS 06:00:02 at clock 12:00:02) moved the offset.
  CHECK(acu.cmd("TIME?") == "TIME?,6,0,0,19,10,2017,200");
  CHECK(acu.status(10) == "1");
  acu.loop->set_gps(nullptr);
}
