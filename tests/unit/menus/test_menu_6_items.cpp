// Menu 6, the items the scripts of test_menu_6.cpp leave to a test of their own: 6-1 calibration at
// the simulated rotator's mechanical ends, the monitor line, 6-6 manual control at the limits, 6-7's
// radio questions, 6-8's live ADC3, 6-9's station file and 6-0's later firmware items.
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "fixture.h"
#include "menus/6_configuration.h"
#include "rotator/adc_model.h"
#include "store/station_file.h"
#include "store/station_file_model.h"
#include "support/manual_samples.h"

using namespace tb;
using testing::has;

namespace {

// Rebuilds the fixture's station around a simulated rotator with these mechanics.
void rebuild(testing::MenuFixture& f, rotator::SimulatedRotatorParams p) {
  f.build(p);
  f.station->tick();
}

// A simulated rotator whose pots read az_ccw..az_cw over the azimuth travel, el_0 at the horizon
// and el_90 straight up, its elevation stop at el_max degrees; then menu 6 run from the fixture's
// keys with rotor control on, `timeouts` timeouts (0.5 s each) before each key.
struct Pots {
  double az_ccw, az_cw, el_0, el_90, el_max;
  rotator::RotatorPosition start;
};
void run_6_1(testing::MenuFixture& f, const Pots& pots, int timeouts) {
  rebuild(f, rotator::SimulatedRotatorParams{.el_max_deg = pots.el_max,
                                             .az_counts_at_ccw = pots.az_ccw,
                                             .az_counts_at_cw = pots.az_cw,
                                             .el_counts_at_0 = pots.el_0,
                                             .el_counts_at_90 = pots.el_90,
                                             .start = pots.start});
  f.station->set_rotor_control(true);
  f.term.timeouts_before_key = timeouts;
  menus::menu_6_configuration(f.term, *f.services);
}

// The station file sample's limits: azimuth 270 -> 90 clockwise, elevation 0..45.
void set_sample_limits(rotator::RotatorConfig& c) {
  c.limits_enabled = true;
  c.az_limit_min = 270;
  c.az_limit_max = 90;
  c.el_limit_max = 45;
}

using testing::kAzTol;
using testing::kElTol;

const char* const kSample = testing::kManualStationFile;

}  // namespace

TEST_CASE("6-1 calibration records the simulated rotator's counts at its end stops, driven from the keys") {
  // A rotator whose pots read 3..837 over the azimuth travel and 1..460 from horizon to zenith, with
  // an elevation end stop at 90: the calibration the manual's example shows. Configured with the
  // factory span, antenna somewhere in the middle.
  testing::MenuFixture f("1\r42Y68YQ\r");
  run_6_1(f, {3, 837, 1, 460, 90, {180.0, 45.0}}, 200);  // 100 s before each key: time to reach the stop
  const std::string& out = f.term.output();
  CHECK(has(out, "ADC span value AZ:0000-1023 EL:0000-0511\n"));
  CHECK(has(out, "Rotate the antenna to fully CCW and\n"));
  CHECK(has(out, "Elevation minimum position [Y/N] ? Y\n"));
  CHECK(has(out, "Rotate the antenna to fully CW and\n"));
  CHECK(has(out, "Elevation maximum position [Y/N] ? Y\n"));
  CHECK(has(out, "AZ=   3 / 181.1deg EL=   1 / 0.2deg.\n"));  // the live line at the CCW stop
  CHECK(has(out, "ADC span value AZ:0003-0837 EL:0001-0460\n"));
  CHECK(f.model.rotator.az_span == rotator::AxisSpan{3, 837});
  CHECK(f.model.rotator.el_span == rotator::AxisSpan{1, 460});
  CHECK(f.station->rotator().config().az_span == rotator::AxisSpan{3, 837});
  CHECK(f.saves == 2);  // rotor control switched on by the first key, then the span
  // With the new span the monitor reads the true position.
  f.run(1);
  const auto a = f.station->antenna();
  REQUIRE(a);
  CHECK(rotator::azimuth_distance(a->az, f.truth().az) < 1.0);
  CHECK(std::abs(a->el - f.truth().el) < 0.3);
  CHECK(f.station->rotator().status().mode == rotator::ControlMode::idle);
}

TEST_CASE("6-1 reaches the mechanical ends whatever the old span and limits say") {
  // An elevation pot that reads 900 straight up (beyond the factory 90-degree count, 511) and limits
  // on (the station file sample's): calibration still drives to both stops and records them, and the
  // limits are in force again afterwards.
  testing::MenuFixture f("1\r42Y68YQ\r");
  set_sample_limits(f.model.rotator);
  run_6_1(f, {20, 1000, 10, 900, 90, {180.0, 20.0}}, 200);
  CHECK(has(f.term.output(), "ADC span value AZ:0020-1000 EL:0010-0900\n"));
  CHECK(f.model.rotator.az_span == rotator::AxisSpan{20, 1000});
  CHECK(f.model.rotator.el_span == rotator::AxisSpan{10, 900});
  CHECK(f.model.rotator.limits_enabled);
  CHECK(f.station->rotator().config() == f.model.rotator);
  // Back under the limits: asked for 0/80, the antenna stops at 45.
  f.station->point({0.0, 80.0});
  f.run(60);
  CHECK(std::abs(f.truth().el - 45) <= 0.3);
}

TEST_CASE("6-1 and 6-2 in flip mode: the second elevation point is the 180-degree one") {
  // The later firmware's example rotator (2 10 857 2 917 F): elevation pot 2 at the horizon, 917
  // over the top at 180 degrees, where its end stop is.
  testing::MenuFixture f("1\r42Y68YQ\r");
  f.model.rotator.el_flip_allowed = true;
  run_6_1(f, {10, 857, 2, 459.5, 180, {180.0, 45.0}}, 300);
  CHECK(has(f.term.output(), "Elevation 180 degree (flip) position [Y/N] ? Y\n"));
  CHECK(f.model.rotator.el_span == rotator::AxisSpan{2, 917});
  CHECK(f.model.rotator.az_span == rotator::AxisSpan{10, 857});
  // With the new span the antenna goes where it is told: 60 deg up reads 60.
  f.station->point({90.0, 60.0});
  f.run(90);
  CHECK(std::abs(f.truth().el - 60) <= 0.5);

  testing::MenuFixture g("2\r\r\r\r917\rQ\r");
  g.model.rotator.el_flip_allowed = true;
  menus::menu_6_configuration(g.term, *g.services);
  CHECK(has(g.term.output(), "EL maximum (180 deg) value ? : "));
  CHECK(g.model.rotator.el_span == rotator::AxisSpan{0, 917});
  CHECK(g.model.rotator.el_flip_allowed);
}

TEST_CASE("The monitor line reproduces the manual's example numbers") {
  // The manual's numbers fit a span starting at 0 (docs/rotator.md): AZ 0-878, EL 0-462, South.
  rotator::RotatorConfig c;
  c.az_span = {0, 878};
  c.el_span = {0, 462};
  rotator::AdcModel m(c, station::RotorStart::south);
  CHECK(rotator::format_monitor_line(519, m.az_deg_from_raw(519), 462, m.el_deg_from_raw(462)) ==
        "AZ= 519 / 32.8deg EL= 462 / 90.0deg.");
}

TEST_CASE("6-6-1 keyboard control stops at the rotation limits") {
  testing::MenuFixture f("6\r1\r8\rQ\rQ\r");
  f.model.rotator.limits_enabled = true;
  f.model.rotator.el_limit_max = 30;
  f.station->reconfigure();
  f.station->set_rotor_control(true);
  double highest = 0;
  f.term.on_wait = [&](std::optional<term::Duration> timeout) {
    f.now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
    f.station->tick();
    highest = std::max(highest, f.truth().el);
  };
  f.term.timeouts_before_key = 120;  // 60 s of Up: 180 degrees worth
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(highest <= 30 + kElTol);
  CHECK(highest >= 30 - kElTol);
}

TEST_CASE("6-6-2 never leaves the rotation limits, even for a target outside them") {
  // The station file sample's limits (270 -> 90 clockwise, el 0..45), rotor start South, antenna north.
  testing::MenuFixture f("6\r2\r120\r60\rQ\rQ\r");
  set_sample_limits(f.model.rotator);
  rotator::SimulatedRotatorParams p = rotator::SimulatedRotatorParams::matching(f.model.rotator);
  p.start = {180.0, 0.0};
  rebuild(f, p);
  f.station->set_rotor_control(true);
  bool outside = false;
  f.term.on_wait = [&](std::optional<term::Duration> timeout) {
    f.now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
    f.station->tick();
    const auto t = f.truth();
    if ((t.az > 90 + kAzTol && t.az < 270 - kAzTol) || t.el > 45 + kElTol) outside = true;
  };
  f.term.timeouts_before_key = 4000;
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(has(f.term.output(), "Limited to Az 90.0 El 45.0 (antenna rotation limit)\n"));
  CHECK(!outside);
  CHECK(rotator::azimuth_distance(f.truth().az, 90) <= kAzTol);
  CHECK(std::abs(f.truth().el - 45) <= kElTol);
}

TEST_CASE("6-6-3 after 6-6-2: the live display follows the antenna to the preset (the manual's 'display of the "
          "current position')") {
  // The event loop ticks the station when StationLoop::next_tick_in says: every second while the
  // antenna rests on a target. The display must not take the previous arrival for the new target
  // in the time before the next tick.
  testing::MenuFixture f("6\r2\r210\r20\r3\r5\rQ\rQ\rQ\r");
  f.model.rotator.presets[4] = {165, 0};
  f.station->reconfigure();
  f.station->set_rotor_control(true);
  auto last_tick = f.now;
  f.term.on_wait = [&](std::optional<term::Duration> timeout) {
    f.now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
    if (f.now - last_tick >= f.station->next_tick_in()) {
      f.station->tick();
      last_tick = f.now;
    }
  };
  f.term.timeouts_before_key = 4000;
  menus::menu_6_configuration(f.term, *f.services);
  const std::string& out = f.term.output();
  const auto preset = out.find(" Select[1-5,S,Q]: 5\n");
  REQUIRE(preset != std::string::npos);
  const auto back = out.find(" Select[1-5,S,Q]: ", preset + 1);
  REQUIRE(back != std::string::npos);
  const std::string shown = out.substr(preset, back - preset);
  // The display ran until the antenna was there, and the last line it showed is the arrival.
  CHECK(rotator::azimuth_distance(f.truth().az, 165) <= kAzTol);
  CHECK(std::abs(f.truth().el - 0) <= kElTol);
  CHECK(f.station->rotator().status().on_target);
  CHECK(has(shown, rotator::format_monitor_line(f.station->rotator().status()) + "\n"));
  CHECK(std::count(shown.begin(), shown.end(), '\n') > 3);  // more than the first line: it moved on screen
}

TEST_CASE("6-7: N is no rig; Q half way changes nothing") {
  testing::MenuFixture f("7\rKYQQ\r");
  f.model.radio.rig = radio::Rig::icom;
  const auto before = f.model.radio;
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(f.model.radio == before);
  CHECK(f.saves == 0);
  testing::MenuFixture g("7\rNNNAQ\r");
  g.model.radio.rig = radio::Rig::kenwood;
  menus::menu_6_configuration(g.term, *g.services);
  CHECK(g.model.radio.rig == radio::Rig::none);
  CHECK(!g.model.radio.uplink_correction);
}

TEST_CASE("6-7: L lists the radio registry, the same table as trakbox --radio list") {
  testing::MenuFixture f("7\rLQQ\r");
  menus::menu_6_configuration(f.term, *f.services);
  const std::string out = f.term.output();
  CHECK(has(out, "ic9700:DEVICE[:BAUD][:maindown|:mainup]"));
  CHECK(has(out, "ft847:DEVICE[:BAUD]"));
  CHECK(has(out, "(D: dial follow on/off, U: uplink radio, L: radio list)\n"));
  CHECK(f.saves == 0);
}

TEST_CASE("6-7: D turns dial follow off and on at once; U names an uplink radio at once, none goes back to one") {
  testing::MenuFixture f("7\rDQQ\r");
  menus::menu_6_configuration(f.term, *f.services);
  CHECK_FALSE(f.model.radio.dial_follow);
  CHECK_FALSE(f.station->tuner().config().dial_follow);
  CHECK(f.saves == 1);
  CHECK(has(f.term.output(), "Dial follow OFF   Uplink radio: none (one radio)   (D: dial follow on/off, U: uplink radio, L: radio list)\n"));
  testing::MenuFixture g("7\rUsim\rQQ\r");
  menus::menu_6_configuration(g.term, *g.services);
  CHECK(g.model.radio.uplink_radio == "sim");
  CHECK(g.station->radio().describe() == "downlink: simulated radio; uplink: simulated radio");
  CHECK(has(g.term.output(), "Radio: downlink: simulated radio; uplink: simulated radio\n"));
  testing::MenuFixture h("7\rUsim\rUnone\rUbogus:x\rQQ\r");
  menus::menu_6_configuration(h.term, *h.services);
  CHECK(h.model.radio.uplink_radio.empty());
  CHECK(h.station->radio().describe() == "simulated radio");
  CHECK(has(h.term.output(), "uplink radio \"bogus:x\": unknown radio \"bogus\""));
}

TEST_CASE("6-7: P sets the knob's rest and the Doppler steps at once") {
  testing::MenuFixture f("7\rP1500\r30\r250\rQQ\r");
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(f.model.radio.dial_rest_ms == 1500);
  CHECK(f.model.radio.doppler_step_ssb_hz == 30);
  CHECK(f.model.radio.doppler_step_fm_hz == 250);
  CHECK(f.station->tuner().config().dial_rest_ms == 1500);
  CHECK(f.station->tuner().doppler_step(radio::Mode::fm) == 250);
  CHECK(f.saves == 1);
  CHECK(has(f.term.output(), "Knob rest 1000 ms   Doppler step SSB/CW 20 Hz, FM 100 Hz   (P: change them)\n"));
  CHECK(has(f.term.output(), "Knob rest 1500 ms   Doppler step SSB/CW 30 Hz, FM 250 Hz   (P: change them)\n"));
  // Out of range: explained and asked again.
  testing::MenuFixture g("7\rP20000\r\r\r\rQQ\r");
  menus::menu_6_configuration(g.term, *g.services);
  CHECK(g.model.radio.dial_rest_ms == 1000);
}

TEST_CASE("6-8 Measure shows ADC3 live from the simulated discriminator: a satellite above the horizon, the radio "
          "tuned 1 kHz high") {
  testing::MenuFixture f;
  // A satellite with a downlink that is up at the fixture's time.
  int up = -1;
  for (int i = 0; i < static_cast<int>(f.model.db.satellites.size()) && up < 0; ++i) {
    const auto n = f.tracker.observe(i, f.now);
    if (n && n->obs.ok() && n->obs.look.el_deg > 5 && f.model.db.satellites[static_cast<std::size_t>(i)].radio.has_downlink())
      up = i;
  }
  REQUIRE(up >= 0);
  // Mic-click Doppler: the tuner sets the radio once at AOS (with the Doppler, as no automatic up
  // pulses are asked for), then leaves it alone.
  f.model.db.satellites[static_cast<std::size_t>(up)].radio.doppler = radio::DopplerControl::mic_click;
  f.model.radio.mic_click.auto_up_at_aos = false;
  f.station->reconfigure();
  f.tracker.track_single(up);
  f.station->tick();
  const auto tuned = f.radio_sim->frequency(radio::Link::downlink);
  REQUIRE(tuned);
  f.radio_sim->set_frequency(radio::Link::downlink, *tuned + 1000);
  // 1 kHz below where the radio listens: 40 counts under the modem's centre (550).
  const int adc = menus::simulated_adc3(*f.services);
  CHECK(adc >= 505);
  CHECK(adc <= 515);
  f.term.feed("8\rMxQ\r");
  f.term.timeouts_before_key = 3;
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(has(f.term.output(), "center 550 span 10: below\n"));
}

TEST_CASE("6-9: any answer but Y leaves everything") {
  testing::MenuFixture f("9\rXQ\r");
  const auto n = f.model.db.satellites.size();
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(f.model.db.satellites.size() == n);
  CHECK(f.saves == 0);
  // Y then N: reset, no upload.
  testing::MenuFixture g("9\rYNQ\r");
  g.model.station.callsign = "WA7GXD";
  menus::menu_6_configuration(g.term, *g.services);
  CHECK(g.model.station.callsign == "NOCALL");
  CHECK(g.model.db.satellites.empty());
  CHECK(!has(g.term.output(), "Upload Station info"));
}

TEST_CASE("6-9 the station file round trip through the menu") {
  store::Model m = store::factory_defaults();
  REQUIRE(store::apply_station_file(*store::parse_station_file(kSample).file, m).empty());
  testing::MenuFixture f("9\rYY" + store::write_station_file(m) + "\x1aQ\r");
  menus::menu_6_configuration(f.term, *f.services);
  CHECK(f.model.rotator == m.rotator);
  CHECK(f.model.radio == m.radio);
  CHECK(f.model.station.callsign == "WA7GXD");
}

TEST_CASE("6-0 shows the later firmware's items only when they differ from the factory values") {
  store::Model m = store::factory_defaults();
  const auto factory = menus::configuration_lines(m);
  REQUIRE(factory.size() == 14);  // the manual's screen and trakbox's Drivers line (issue 30)
  CHECK(factory.back() == "Drivers          Rotor SIM (simulated)  Radio SIM (simulated)");
  m.radio.rig = radio::Rig::yaesu;
  m.radio.rig_model = radio::RigModel::yaesu_847;
  m.radio.cat_baud = 9600;
  m.pass_events = {-1.5, 0.5, -0.5};
  m.radio.parking = {true, 145'800'000, 0, radio::Mode::fm, radio::Mode::none};
  m.rotator_error_detection = false;
  const auto lines = menus::configuration_lines(m);
  REQUIRE(lines.size() == 17);
  CHECK(lines[6] == "CAT Rig          YAESU AOS  FT-847  9600 Bd");
  CHECK(lines[11] == "Rotor start      " + std::string(station::to_string(m.station.rotor_start)) + "  above EL:-1.5");
  CHECK(lines[13] == "Radio parking    On  RX:145.800 FM TX:- None");
  CHECK(lines[14] == "AOS/LOS line     On above EL:0.5  Off below EL:-0.5");
  CHECK(lines[15] == "Rotator error    Detection off");
}

TEST_CASE("6-0 shows an overlap rotator's travel, and nothing for the TrakBox's 360") {
  store::Model m = store::factory_defaults();
  CHECK(menus::configuration_lines(m)[1] == "ADC span value   AZ:   0 - 1023  EL:   0 -  511");
  m.rotator.az_travel_deg = 450;
  CHECK(menus::configuration_lines(m)[1] == "ADC span value   AZ:   0 - 1023  EL:   0 -  511  travel 450 deg");
}

TEST_CASE("6-0 and the status bar name the drivers (issue 30)") {
  store::Model m = store::factory_defaults();
  m.rotator_driver = "hamlib:603:/dev/ttyUSB0";
  m.radio_driver = "rigctld:localhost:4532";
  m.radio.uplink_radio = "icom:/dev/ttyUSB1";
  CHECK(menus::configuration_lines(m).back() ==
        "Drivers          Rotor hamlib 603 (hamlib:603:/dev/ttyUSB0)  Radio rigctld localhost "
        "(rigctld:localhost:4532)  Uplink icom (icom:/dev/ttyUSB1)");
  testing::MenuFixture f;
  f.model.rotator_driver = "hamlib:603:/dev/ttyUSB0";
  CHECK(f.station->status_line().find("| Rotor hamlib 603 OFF") != std::string::npos);
  CHECK(f.station->status_line().find("| Radio SIM D ") != std::string::npos);
}
