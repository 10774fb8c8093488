// The GPS receiver's filter and monitor (src/gps/monitor.h): what counts as confirmed, jumps,
// nonsense, lost fixes, the clock check, and that each problem is said once.
#include <doctest/doctest.h>

#include <cmath>

#include "gps/gpsd_client.h"
#include "gps/monitor.h"

using namespace tb;
using gps::Monitor;
using gps::Report;

namespace {
const orbit::UtcTime kT0 = orbit::from_civil(2017, 10, 19, 6, 0, 0);
orbit::UtcTime at(double s) { return orbit::add_seconds(kT0, s); }

Report fix(double s, double lat = 41.01, double lon = 29.17, int mode = 3, double alt = 120.0) {
  Report r;
  r.mode = mode;
  r.lat_deg = lat;
  r.lon_deg = lon;
  if (mode >= 3) r.alt_m = alt;
  r.time = at(s);
  return r;
}
Report no_fix(double s) {
  Report r;
  r.mode = 1;
  r.time = at(s);
  return r;
}
// Metres north as degrees of latitude on the filter's sphere.
double north(double m) { return m / 6371008.8 * 180.0 / 3.14159265358979323846; }

std::vector<std::string> texts(const std::vector<gps::Note>& notes) {
  std::vector<std::string> t;
  for (const auto& n : notes) t.push_back(n.text);
  return t;
}
}  // namespace

TEST_CASE("distance: a degree of latitude on the mean sphere, and a degree of longitude at 60 degrees") {
  // 2 pi R / 360 with R = 6371008.8 m (IUGG mean radius): 111195.08 m; at 60 degrees half of it.
  CHECK(gps::distance_m(0, 0, 1, 0) == doctest::Approx(111195.08).epsilon(1e-8));
  CHECK(gps::distance_m(60, 10, 60, 11) == doctest::Approx(55595.77).epsilon(1e-4));
  CHECK(gps::distance_m(41.01, 29.17, 41.01, 29.17) == 0.0);
}

TEST_CASE("nonsense: values outside the Earth are named") {
  CHECK(gps::nonsense(fix(0, 95.0)) == "latitude 95.000000 is outside -90..90");
  CHECK(gps::nonsense(fix(0, 41.0, -181.5)) == "longitude -181.500000 is outside -180..180");
  CHECK(gps::nonsense(fix(0, 41.0, 29.0, 3, 25000.0)) == "altitude 25000.000000 is outside -1000..20000");
  CHECK(gps::nonsense(fix(0, NAN)) == "latitude nan is outside -90..90");
  CHECK_FALSE(gps::nonsense(fix(0)));
}

TEST_CASE("filter: three reports in a row confirm a position; a 2D fix has no altitude") {
  gps::PositionFilter f;
  using V = gps::PositionFilter::Verdict;
  CHECK(f.add(fix(0), kT0).verdict == V::confirming);
  CHECK(f.add(fix(1, 41.01 + north(1.5)), kT0).verdict == V::confirming);
  CHECK_FALSE(f.confirmed());
  CHECK(f.add(fix(2), kT0).verdict == V::confirmed);
  REQUIRE(f.confirmed());
  CHECK(f.fixed());
  CHECK(f.confirmed()->alt_m == 120.0);
  CHECK(f.confirmed()->time == at(2));
  CHECK(f.add(fix(3, 41.01, 29.17, 2), kT0).verdict == V::confirmed);
  CHECK_FALSE(f.confirmed()->alt_m);
  CHECK(f.confirmed()->mode == 2);
}

TEST_CASE("filter: one report 100 km away is a jump and is ignored; the chain goes on") {
  gps::PositionFilter f;
  using V = gps::PositionFilter::Verdict;
  for (int i = 0; i < 3; ++i) f.add(fix(i), kT0);
  const auto r = f.add(fix(3, 41.01 + north(100000.0)), kT0);
  CHECK(r.verdict == V::jump);
  CHECK(r.why == "100.0 km in 1.0 s");
  CHECK(f.confirmed()->lat_deg == 41.01);
  CHECK(f.add(fix(4), kT0).verdict == V::confirmed);  // back: 50 m + 300 m/s x 2 s from 2 s
  CHECK(f.confirmed()->lat_deg == 41.01);
}

TEST_CASE("filter: a new place that holds for three reports is taken") {
  gps::PositionFilter f;
  using V = gps::PositionFilter::Verdict;
  for (int i = 0; i < 3; ++i) f.add(fix(i), kT0);
  const double far = 41.01 + north(100000.0);
  CHECK(f.add(fix(3, far), kT0).verdict == V::jump);
  CHECK(f.add(fix(4, far), kT0).verdict == V::confirming);
  CHECK(f.confirmed()->lat_deg == 41.01);
  CHECK(f.add(fix(5, far), kT0).verdict == V::jump_taken);
  CHECK(f.confirmed()->lat_deg == far);
}

TEST_CASE("filter: reachability is judged on the reports' own times (a rover at 250 m/s)") {
  gps::PositionFilter f;
  using V = gps::PositionFilter::Verdict;
  for (int i = 0; i < 3; ++i) f.add(fix(i), kT0);
  for (int k = 1; k <= 40; ++k) CHECK(f.add(fix(2 + k, 41.01 + north(250.0 * k)), kT0).verdict == V::confirmed);
  // 400 m in one second is faster than 300 m/s + 50 m.
  CHECK(f.add(fix(43, 41.01 + north(250.0 * 40 + 400.0)), kT0).verdict == V::jump);
}

TEST_CASE("filter: a lost fix keeps the last position and needs three reports again") {
  gps::PositionFilter f;
  using V = gps::PositionFilter::Verdict;
  for (int i = 0; i < 3; ++i) f.add(fix(i), kT0);
  CHECK(f.add(no_fix(3), kT0).verdict == V::no_fix);
  CHECK_FALSE(f.fixed());
  REQUIRE(f.confirmed());
  CHECK(f.confirmed()->time == at(2));
  CHECK(f.add(fix(4), kT0).verdict == V::confirming);
  CHECK(f.add(fix(5), kT0).verdict == V::confirming);
  CHECK_FALSE(f.fixed());
  CHECK(f.add(fix(6), kT0).verdict == V::confirmed);
  CHECK(f.fixed());
}

TEST_CASE("monitor: each problem is said once, the last good position kept") {
  Monitor m("gpsd:localhost:2947");
  CHECK(texts(m.on_link(gps::Link::no_gpsd, "can't connect to host/port pair")) ==
        std::vector<std::string>{"GPS: no gpsd at localhost:2947 (can't connect to host/port pair); the station keeps "
                                 "its position; trying again every 2 s"});
  CHECK(m.on_link(gps::Link::no_gpsd, "can't connect to host/port pair").empty());
  CHECK(m.comm_error());
  CHECK(m.status_word() == "NO GPSD");
  CHECK(texts(m.on_link(gps::Link::receiving)) == std::vector<std::string>{"GPS: connected to gpsd at localhost:2947"});
  CHECK(texts(m.on_devices(0)) ==
        std::vector<std::string>{"GPS: gpsd at localhost:2947 has no receiver; the station keeps its position"});
  CHECK(m.on_devices(0).empty());
  CHECK(m.status_word() == "NO GPS RECEIVER");
  CHECK(texts(m.on_report(no_fix(0), at(0))) ==
        std::vector<std::string>{"GPS: gpsd has a receiver again", "GPS: no fix yet"});
  CHECK(m.on_report(no_fix(1), at(1)).empty());
  CHECK(m.status_word() == "GPS NO FIX");
  CHECK_FALSE(m.comm_error());
  CHECK(m.on_report(fix(2), at(2)).empty());
  CHECK(m.on_report(fix(3), at(3)).empty());
  CHECK(texts(m.on_report(fix(4), at(4))) == std::vector<std::string>{"GPS: fix confirmed, 41.0100N 29.1700E 120.0 m"});
  CHECK(m.status_word().empty());
  CHECK(texts(m.on_report(fix(5, 95.0), at(5))) ==
        std::vector<std::string>{"GPS: report ignored: latitude 95.000000 is outside -90..90"});
  CHECK(m.on_report(fix(6, 95.0), at(6)).empty());
  CHECK(texts(m.on_report(fix(7, 41.01 + north(100000.0)), at(7))) ==
        std::vector<std::string>{"GPS: position jumped 100.0 km in 3.0 s; ignored unless it holds for 3 reports"});
  Report hole = fix(8);
  hole.lat_deg.reset();  // what gpsd sends for a latitude of 95 degrees
  CHECK(texts(m.on_report(hole, at(8))) == std::vector<std::string>{
                                               "GPS: report ignored: a 3D fix without a latitude (gpsd left out a "
                                               "value it could not take)"});
  for (int i = 9; i < 12; ++i) m.on_report(fix(i), at(i));
  CHECK(texts(m.on_report(no_fix(12), at(12))) ==
        std::vector<std::string>{"GPS: fix lost; the station keeps 41.0100N 29.1700E 120.0 m"});
  CHECK(m.on_report(no_fix(13), at(13)).empty());
  CHECK(m.filter().confirmed()->lat_deg == 41.01);
  CHECK(texts(m.on_link(gps::Link::lost, "connection closed")) ==
        std::vector<std::string>{"GPS: gpsd at localhost:2947 went away (connection closed); the station keeps its "
                                 "position; trying again"});
  CHECK(m.status_word() == "GPSD LOST");
  CHECK(m.comm_error());
}

TEST_CASE("monitor: the clock is warned about beyond 0.5 s for three reports, and cleared below 0.25 s") {
  Monitor m("gpsd:localhost:2947");
  m.on_link(gps::Link::receiving);
  // The clock reads 3600 s before GPS time.
  for (int i = 0; i < 2; ++i) m.on_report(fix(i), at(i - 3600));
  CHECK_FALSE(m.clock_warned());
  const auto notes = texts(m.on_report(fix(2), at(2 - 3600)));
  CHECK(notes == std::vector<std::string>{"GPS: fix confirmed, 41.0100N 29.1700E 120.0 m",
                                          "GPS: the clock is 3600.000 s behind GPS time; menu 5 (G) or RTC_REUPDATE= "
                                          "sets it from GPS"});
  CHECK(m.clock_error_s() == 3600.0);
  CHECK(m.status_word() == "GPS TIME +3600.0s");
  CHECK(m.on_report(fix(3), at(3 - 3600)).empty());  // said once
  // Near the limit: 0.4 s neither warns nor clears; 0.1 s clears after three reports.
  for (int i = 4; i < 7; ++i) CHECK(m.on_report(fix(i), at(i - 0.4)).empty());
  CHECK(m.clock_warned());
  m.on_report(fix(7), at(7 - 0.1));
  m.on_report(fix(8), at(8 - 0.1));
  CHECK(texts(m.on_report(fix(9), at(9 - 0.1))) ==
        std::vector<std::string>{"GPS: the clock agrees with GPS time again (+0.100 s)"});
  CHECK(m.status_word().empty());
  // A clock ahead of GPS time.
  for (int i = 10; i < 12; ++i) m.on_report(fix(i), at(i + 2));
  CHECK(texts(m.on_report(fix(12), at(14))) ==
        std::vector<std::string>{"GPS: the clock is 2.000 s ahead of GPS time; menu 5 (G) or RTC_REUPDATE= sets it "
                                 "from GPS"});
}

TEST_CASE("gps spec: gpsd, gpsd:HOST, gpsd:HOST:PORT") {
  std::string why;
  CHECK(gps::parse_gps_spec("gpsd", why)->text() == "gpsd:localhost:2947");
  CHECK(gps::parse_gps_spec("gpsd:10.0.0.5", why)->text() == "gpsd:10.0.0.5:2947");
  CHECK(gps::parse_gps_spec("gpsd:127.0.0.1:29470", why)->text() == "gpsd:127.0.0.1:29470");
  CHECK_FALSE(gps::parse_gps_spec("gpsd:host:0", why));
  CHECK(why == "expected a TCP port 1 to 65535 after the host; found '0'");
  CHECK_FALSE(gps::parse_gps_spec("nmea:/dev/ttyUSB0", why));
  CHECK(why == "expected gpsd, gpsd:HOST or gpsd:HOST:PORT; found 'nmea:/dev/ttyUSB0'");
  CHECK_FALSE(gps::parse_gps_spec("gpsd::2947", why));
  CHECK(why == "the host is empty in 'gpsd::2947'");
}
