#include <doctest/doctest.h>

#include <map>

#include <algorithm>

#include "fixture.h"
#include "support/gps_fix.h"
#include "menus/realtime_display.h"

using namespace tb;

TEST_CASE("Menu 4 edits the station; Enter keeps each value") {
  testing::MenuFixture f("WA7GXD\r32.259\r-110.778\r842\rS\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.callsign == "WA7GXD");
  CHECK(f.model.station.lat_deg == 32.259);
  CHECK(f.model.station.lon_deg == -110.778);
  CHECK(f.model.station.height_m == 842.0);
  CHECK(f.model.station.rotor_start == station::RotorStart::south);
  CHECK(f.model.station.com_baud == 9600);
  CHECK(f.saves == 1);
  CHECK(f.term.output().find("Callsign           : NOCALL  WA7GXD") != std::string::npos);
  CHECK(f.term.output().find("Latitude  [deg]    : +27.391  32.259") != std::string::npos);
}

TEST_CASE("Menu 4: a callsign typed with a non-ASCII letter is refused with a message, not stored mangled (issue 39)") {
  testing::MenuFixture f("P\xc3\xa0ris\rF4ABC\r\r\r\r\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.term.output().find("only ASCII characters are taken here") != std::string::npos);
  CHECK(f.term.output().find("'Pris' is what is left; not changed") != std::string::npos);
  CHECK(f.model.station.callsign == "F4ABC");  // the second answer, never "PRIS"
  CHECK(f.saves == 1);
}

TEST_CASE("Esc at the satellite list leaves it with nothing chosen, not typed into the field (issue 39)") {
  testing::MenuFixture f("\x1bQY\r");
  const int marked = f.model.db.marked;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  CHECK(f.model.db.marked == marked);
  CHECK(f.tracker.mode() == tracker::Mode::off);
  CHECK(f.term.output().find("Select :QY") == std::string::npos);
  CHECK(f.saves == 0);
}

TEST_CASE("Menu 4 takes a Maidenhead locator at the latitude, as passes --station does (issue 39)") {
  // JN18du: field J,N (0 E, 40 N), square 1,8 (2 E, 48 N), subsquare d,u (3 and 20 of 24): centre
  // 2 + 3.5/12 = 2.291667 E, 48 + 20.5/24 = 48.854167 N.
  testing::MenuFixture f("\rJN18du\r\r\r\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.lat_deg == doctest::Approx(48.854167).epsilon(1e-6));
  CHECK(f.model.station.lon_deg == doctest::Approx(2.291667).epsilon(1e-6));
  CHECK(f.term.output().find("locator: the centre of its square, 48.854167 N 2.291667 E") != std::string::npos);
  CHECK(f.term.output().find("is not a number of degrees") == std::string::npos);
  CHECK(f.saves == 1);
}

TEST_CASE("Menu 4: a new rotor start takes effect at once on the antenna, not at the next start") {
  testing::MenuFixture f("\r\r\r\rN\r\r\r");
  REQUIRE(f.model.station.rotor_start == station::RotorStart::south);
  // South start: travel 0 is the South stop; North start: travel 0 is North.
  CHECK(f.station->rotator().model().compass_from_travel(0.0) == doctest::Approx(180.0));
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.rotor_start == station::RotorStart::north);
  CHECK(f.station->rotator().model().compass_from_travel(0.0) == doctest::Approx(0.0));
  // A GOTO to 90 deg now goes the North-start way: to travel 90.
  const rotator::RotatorPosition p = f.station->rotator().set_target(rotator::AzEl{90.0, 10.0});
  CHECK(p.az_travel == doctest::Approx(90.0));
}

TEST_CASE("Menu 5 sets the clock when Enter is pressed, and Y zeroes the seconds") {
  testing::MenuFixture f("\r93/07/17 03:03:15\r\r");
  menus::menu_5_realtime_clock(f.term, *f.services);
  CHECK(f.clock.now() == orbit::from_civil(1993, 7, 17, 3, 3, 15));
  CHECK(f.model.clock_offset == f.clock.offset());
  CHECK(f.term.output().find("Enter with format [YY/MM/DD HH:MM:SS]") != std::string::npos);
  CHECK(f.term.output().find("ENTER when ready.") != std::string::npos);

  testing::MenuFixture g("Y");
  g.now = orbit::from_civil(2026, 1, 1, 5, 13, 4);
  menus::menu_5_realtime_clock(g.term, *g.services);
  CHECK(g.clock.now() == orbit::from_civil(2026, 1, 1, 5, 13, 0));
}

TEST_CASE("Menu 1 tracks the marked satellite live; E switches rotor control; Q leaves") {
  // Enter = the marked one (#1, AO-07); then E, then Q.
  testing::MenuFixture f("\rEQ");
  f.term.timeouts_before_key = 2;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("*** Tracking object satellite ***") != std::string::npos);
  CHECK(out.find(" 1.*AO-07") != std::string::npos);
  CHECK(out.find("[Satellite:*AO-07]") != std::string::npos);
  // The elements' age at the clock (2026-05-21 12:00; AO-07's epoch 26141.31992461 = 07:40:41).
  CHECK(out.find("[Satellite:*AO-07]\nElements: epoch 2026/05/21 07:40:41 UTC, age 0.2 days\n") != std::string::npos);
  CHECK(out.find("HH:MM:SS     deg     deg       Km       Km    deg    deg  <256>       Hz") != std::string::npos);
  CHECK(f.model.rotor_control);  // E turned it on
  CHECK(f.tracker.mode() == tracker::Mode::single);
  REQUIRE(f.tracker.followed() != nullptr);
  CHECK(f.tracker.followed()->name == "AO-07");
}

TEST_CASE("The realtime display warns when the elements are past their orbit's limit") {
  testing::MenuFixture f("\rQ", orbit::from_civil(2031, 5, 21, 12, 0, 0));
  f.term.timeouts_before_key = 1;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  // On a line of its own, within 80 columns (issue 30: appended, it wrapped mid-sentence).
  const std::string warning = "WARNING: elements too old (limit 14 days): positions unreliable, see 3-5";
  CHECK(f.term.output().find("Elements: epoch 2026/05/21 07:40:41 UTC, age 1826.2 days\n" + warning + "\n") !=
        std::string::npos);
  CHECK(warning.size() < 80);
}

TEST_CASE("Line mode: U steps the followed satellite's uplink through its FREQ.DAT channels") {
  testing::MenuFixture f("\rUUQ");
  f.term.timeouts_before_key = 2;
  const int ao07 = *f.model.db.find("AO-07");
  auto& radio = f.model.db.satellites[static_cast<std::size_t>(ao07)].radio;
  const radio::Hz first = radio.uplink_hz;
  radio.alternate_uplinks_hz = {first + 10'000, first + 20'000};
  menus::menu_1_realtime_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("'U' next uplink channel") != std::string::npos);
  CHECK(out.find("Uplink " + radio::format_mhz(first + 10'000) + " MHz\n") != std::string::npos);
  CHECK(out.find("Uplink " + radio::format_mhz(first + 20'000) + " MHz\n") != std::string::npos);
  CHECK(radio.uplink_hz == first + 20'000);  // kept, and saved
  CHECK(f.saves >= 2);
  CHECK(f.station->tuner().satellite().uplink_hz == first + 20'000);
}

TEST_CASE("The realtime row matches the manual's columns") {
  tracker::SatNow n;
  n.obs.time = orbit::from_civil(1993, 7, 17, 4, 6, 58);
  n.obs.look = {28.54, -33.61, 22101.6, 0.0};
  n.obs.sub_point = {33.1, 36.3, 12938.7};
  n.obs.phase256 = 9.4;
  n.downlink_doppler_hz = 2226.2;
  CHECK(menus::format_realtime_row(n) == "04:06:58   28.54  -33.61  22101.6  12938.7   33.1   36.3    9.0    +2226");
  CHECK(menus::aos_indicator(true, true, n.obs.time) == "AOS");
  CHECK(menus::aos_indicator(false, true, n.obs.time) == "   ");
  // Blinking with rotor control off: on one second, off the next.
  CHECK(menus::aos_indicator(true, false, n.obs.time) != menus::aos_indicator(true, false, n.obs.time + std::chrono::seconds(1)));
}

TEST_CASE("Line mode: the realtime display's E and + / - / 0 say what they changed (issue 18, item 6)") {
  testing::MenuFixture f("\rE++-0Q");
  f.term.timeouts_before_key = 1;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("Rotor control ON\n") != std::string::npos);
  CHECK(out.find("Frequency offset +100 Hz\n") != std::string::npos);
  CHECK(out.find("Frequency offset +200 Hz\n") != std::string::npos);
  CHECK(out.find("Frequency offset +100 Hz\n", out.find("+200 Hz")) != std::string::npos);
  CHECK(out.find("Frequency offset 0 Hz\n") != std::string::npos);
  CHECK(f.station->tuner().rit_hz() == 0);
}

namespace {
// The radio lines of a line-mode realtime display from `from` on, with the sent frequencies taken
// out (they move with the Doppler): "Spot D 145.950000 U 432.150000 | dial follow".
std::vector<std::string> radio_lines(const std::string& out, std::size_t from = 0) {
  std::vector<std::string> lines;
  for (auto p = out.find("Spot D ", from); p != std::string::npos; p = out.find("Spot D ", p + 1)) {
    std::string l = out.substr(p, out.find('\n', p) - p);
    const auto a = l.find(" | sent D ");
    REQUIRE(a != std::string::npos);
    l.erase(a, l.find(" | ", a + 1) == std::string::npos ? std::string::npos : l.find(" | ", a + 1) - a);
    lines.push_back(l);
  }
  return lines;
}
bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }
}  // namespace

TEST_CASE("Line mode: the radio line shows the spot and what was sent; D turns dial follow off and on; a spot "
          "outside the passband is warned about") {
  testing::MenuFixture f("\rDDQ");
  f.term.timeouts_before_key = 1;
  const int ao07 = *f.model.db.find("AO-07");   // followed; an inverting transponder in data/freqmode.txt
  REQUIRE(f.model.db.satellites[static_cast<std::size_t>(ao07)].radio.has_passbands());
  menus::menu_1_realtime_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("'D' dial follow on/off") != std::string::npos);
  CHECK(contains(radio_lines(out), "Spot D 145.950000 U 432.150000 | dial follow"));
  const auto off = out.find("Dial follow OFF\n");
  REQUIRE(off != std::string::npos);
  CHECK(contains(radio_lines(out, off), "Spot D 145.950000 U 432.150000 | dial follow OFF"));
  CHECK(out.find("Dial follow ON\n", off) != std::string::npos);
  CHECK(f.model.radio.dial_follow);

  testing::MenuFixture g("\rQ");
  g.term.timeouts_before_key = 1;
  g.model.db.satellites[static_cast<std::size_t>(ao07)].radio.downlink_hz = 145'980'000;  // above 145.975
  menus::menu_1_realtime_tracking(g.term, *g.services);
  CHECK(contains(radio_lines(g.term.output()), "Spot D 145.980000 U 432.150000 | dial follow | SPOT OUTSIDE PASSBAND"));
}

TEST_CASE("Line mode: the + / - correction is remembered for the satellite and mode, shown, and 0 forgets it") {
  testing::MenuFixture f("\r++Q");
  f.term.timeouts_before_key = 1;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  // AO-07 is followed (USB downlink): the correction is kept in the stored radio settings.
  CHECK(f.model.radio.corrections == std::map<std::string, radio::Hz>{{"AO-07 Mode-B", 200}});
  CHECK(f.saves >= 2);
  CHECK(contains(radio_lines(f.term.output()),
                 "Spot D 145.950200 U 432.149800 | dial follow | correction +200 Hz kept for AO-07 Mode-B"));
  // The next time AO-07 is selected the correction is there from the start.
  f.station->reconfigure();
  testing::MenuFixture g("\r0Q");
  g.term.timeouts_before_key = 1;
  g.model.radio.corrections = {{"AO-07 Mode-B", 200}};
  g.station->reconfigure();
  menus::menu_1_realtime_tracking(g.term, *g.services);
  CHECK(contains(radio_lines(g.term.output()),
                 "Spot D 145.950200 U 432.149800 | dial follow | correction +200 Hz kept for AO-07 Mode-B"));
  CHECK(g.term.output().find("Frequency offset 0 Hz\n") != std::string::npos);
  CHECK(g.model.radio.corrections.empty());   // 0 forgot it
}

TEST_CASE("LinkNotices: one line when a link fails and one when it is back, not one per retry") {
  menus::LinkNotices n;
  rotator::Health rot_ok{rotator::LinkState::ok, "", 1};
  rotator::Health connecting{rotator::LinkState::connecting, "connecting to rotctld 127.0.0.1:4533", 0};
  radio::RadioStatus rad_ok;
  CHECK(n.update(connecting, rad_ok).empty());  // not yet connected is no fault
  CHECK(n.update(rot_ok, rad_ok).empty());
  rotator::Health lost{rotator::LinkState::fault, "lost rotctld 127.0.0.1:4533: IO error; motion stopped, reconnecting", 1};
  CHECK(n.update(lost, rad_ok) ==
        std::vector<std::string>{"Rotator FAULT: lost rotctld 127.0.0.1:4533: IO error; motion stopped, reconnecting"});
  lost.message = "cannot connect to rotctld 127.0.0.1:4533: IO error; retrying in 500 ms";
  CHECK(n.update(lost, rad_ok).empty());  // the retries say nothing new
  radio::RadioStatus gone;
  gone.fault = true;
  gone.message = "/dev/ttyUSB0 went away (the port hung up)";
  CHECK(n.update(rot_ok, gone) ==
        std::vector<std::string>{"Rotator link restored", "Radio FAULT: /dev/ttyUSB0 went away (the port hung up)"});
  CHECK(n.update(rot_ok, gone).empty());
  CHECK(n.update(rot_ok, rad_ok) == std::vector<std::string>{"Radio working again"});
}

TEST_CASE("Line mode: the realtime display reports a rotator or radio fault and its end") {
  testing::MenuFixture f("\rQ");
  f.term.timeouts_before_key = 3;
  f.rotator_sim->set_fault("ADC not answering");
  f.radio_sim->simulate_fault("interface not echoing");
  menus::menu_1_realtime_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("Rotator FAULT: ") != std::string::npos);
  CHECK(out.find("ADC not answering") != std::string::npos);
  CHECK(out.find("Radio FAULT: interface not echoing\n") != std::string::npos);

  testing::MenuFixture g("\rQ");
  g.term.timeouts_before_key = 3;
  menus::menu_1_realtime_tracking(g.term, *g.services);
  CHECK(g.term.output().find("FAULT") == std::string::npos);  // nothing to report, nothing said
}

namespace {
const orbit::UtcTime kGpsT0 = orbit::from_civil(2017, 10, 19, 6, 0, 0);
// A menu fixture whose station has a receiver, fed a fix of `mode` (3D, 2D; 0: none) at kGpsT0.
struct WithReceiver {
  explicit WithReceiver(std::string input, int mode = 3) : f(std::move(input)) {
    f.station->set_gps(&receiver);
    if (mode) testing::feed_gps_fix(receiver, kGpsT0, f.clock.now(), mode);
  }
  ~WithReceiver() { f.station->set_gps(nullptr); }
  testing::MenuFixture f;
  gps::Monitor receiver{"gpsd:localhost:2947"};
};
}  // namespace

TEST_CASE("Menu 4 with a GPS receiver: where the position came from, following it, its threshold") {
  WithReceiver w("\r\r\r\r\r\r\rY\r250\r");
  menus::menu_4_station_elements(w.f.term, *w.f.services);
  const std::string& out = w.f.term.output();
  CHECK(out.find("Position from      typed in") != std::string::npos);
  CHECK(out.find("GPS receiver      gpsd:localhost:2947: 3D fix 41.0100N 29.1700E 120.0 m at 2017-10-19T06:00:02Z") !=
        std::string::npos);
  const store::Model& m = w.f.model;
  CHECK(m.gps.follow);
  CHECK(m.gps.threshold_m == 250.0);
  // Following: the confirmed fix at once; the menu's settings and then the fix, each change stored.
  CHECK(m.station.lat_deg == 41.01);
  CHECK(m.station.lon_deg == 29.17);
  CHECK(m.station.height_m == 120.0);
  CHECK(m.gps.position_from_gps);
  CHECK(m.gps.position_time == orbit::add_seconds(kGpsT0, 2));
  CHECK(w.f.saves == 2);
  // Menu 4 again: the origin shown.
  WithReceiver again("\r\r\r\r\r\r\r\r\r");
  again.f.model = m;
  menus::menu_4_station_elements(again.f.term, *again.f.services);
  CHECK(again.f.term.output().find("Position from      GPS fix of 2017-10-19T06:00:02Z") != std::string::npos);
}

TEST_CASE("Menu 4: a 2D fix keeps the stored height") {
  WithReceiver w("\r\r\r\r\r\r\rY\r\r", 2);
  menus::menu_4_station_elements(w.f.term, *w.f.services);
  CHECK(w.f.model.station.lat_deg == 41.01);
  CHECK(w.f.model.station.height_m == 50.0);  // the factory height
}

TEST_CASE("Menu 5 G: the clock from GPS time; refused without a fix") {
  // GPS time is 06:00:00 (2017) when the clock reads 12:00:00 (2026-05-21): the clock goes back by the difference.
  WithReceiver w("G");
  const auto source_before = w.f.now;
  menus::menu_5_realtime_clock(w.f.term, *w.f.services);
  CHECK(w.f.clock.now() == kGpsT0 + (w.f.now - source_before));  // GPS time, and what the menu's waits took
  CHECK(w.f.model.clock_offset == w.f.clock.offset());
  CHECK(w.f.term.output().find("Enter 'G' for the clock from GPS time (3D fix 41.0100N 29.1700E 120.0 m") !=
        std::string::npos);

  WithReceiver none("GQ", 0);
  const auto offset = none.f.clock.offset();
  menus::menu_5_realtime_clock(none.f.term, *none.f.services);
  CHECK(none.f.term.output().find("no GPS fix: the clock is left alone") != std::string::npos);
  CHECK(none.f.clock.offset() == offset);
}
