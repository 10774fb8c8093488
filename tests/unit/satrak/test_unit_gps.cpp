// A Satrak session's GPS: without a receiver (GPS_DATA? reports the station, GPS_SETTINGS sets it,
// RTC_REUPDATE is refused) and with one through gpsd (its fix and time, the RTC set from it).
#include "fixture.h"
#include "support/gps_fix.h"

using namespace satrak_test;  // with std::chrono_literals and satrak::Error

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
