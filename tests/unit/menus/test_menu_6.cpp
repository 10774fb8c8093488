// Menu 6 through the whole simulated station: every transcript of the manual's section 6, then what
// the screen does not show (model, rotator controller, simulated rotator and radio). The items that
// need a test of their own are in test_menu_6_items.cpp.
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fixture.h"
#include "menus/6_configuration.h"
#include "rotator/adc_model.h"

using namespace tb;
using testing::has;

namespace {

using testing::kAzTol;
using testing::kElTol;

using Fixture = testing::MenuFixture;

// One run of menu 6 on a fresh fixture: the keys typed, what is set before the menu runs, what the
// screen must show, how often the menu saved the state, and what the model and station hold after
// (`was`: the model as it was when the menu started).
struct Script {
  std::string name;
  std::string keys;
  std::function<void(Fixture& f)> setup = {};
  std::vector<std::string> shown = {};
  std::optional<int> saves = std::nullopt;
  std::function<void(Fixture& f, const store::Model& was)> then = {};
};

// Each script in a subcase of its own, named by the script.
void run_scripts(const std::vector<Script>& scripts) {
  for (const Script& s : scripts) {
    DOCTEST_SUBCASE(s.name.c_str()) {
      Fixture f(s.keys);
      if (s.setup) s.setup(f);
      f.saves = 0;  // what the menu saves, not the setting up
      f.changes.clear();
      const store::Model was = f.model;
      menus::menu_6_configuration(f.term, *f.services);
      for (const std::string& text : s.shown) CHECK_MESSAGE(has(f.term.output(), text), "not shown: " << text);
      std::string changes;
      for (const auto& c : f.changes) changes += c + "; ";
      CAPTURE(changes);
      if (s.saves) CHECK(f.saves == *s.saves);
      if (s.then) s.then(f, was);
    }
  }
}

}  // namespace

TEST_CASE("Menu 6 scripts: the keys typed, what the screen shows, what the model and the station hold") {
  run_scripts({
      {.name = "The Configuration Menu lists items 0 to 9 and Q returns",
       .keys = "x\rQ\r",
       .shown = {"====== Configuration Menu ======\n"
                 " 0. Display all configured value\n"
                 " 1. Calibration of antenna span value\n"
                 " 2. Set ADC span value\n"
                 " 3. Set Dead Band and Skew value\n"
                 " 4. Set Antenna Parking and Limit position\n"
                 " 5. Monitor ADC value & Antenna position\n"
                 " 6. Direct antenna control\n"
                 " 7. Radio CAT port configuration\n"
                 " 8. Mic click configuration\n"
                 " 9. Set default parameter\n"
                 " R. Rotor control (kept over a restart)\n"
                 " Select: "},
       .saves = 0},

      {.name = "6-R switches rotor control on and saves it; the antenna is then driven",
       .keys = "R\rY\rQ\r",
       .shown = {"Rotor control is OFF: the antenna stays where it is\n", "Rotor control switched ON\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model& was) {
         CHECK(!was.rotor_control);
         CHECK(f.model.rotor_control);
         CHECK(f.station->rotator().control_enabled());
       }},

      {.name = "6-R: N turns it off; the same answer again changes and saves nothing; Q leaves it",
       .keys = "R\rN\rR\rN\rR\rQ\rQ\r",
       .setup = [](Fixture& f) { f.station->set_rotor_control(true); },
       .shown = {"Rotor control switched OFF\n", "Rotor control unchanged.\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) { CHECK(!f.model.rotor_control); }},

      {.name = "6-0 displays every configured value in the manual's layout",
       .keys = "0\r Q\r",
       .shown = {"Callsign:NOCALL  Lat:27.4 Long:128.7 Hgt:50.0\n",
                 "ADC span value   AZ:   0 - 1023  EL:   0 -  511\n",
                 "Dead band        AZ:3.0 EL:1.0  Skew AZ:0.0 EL:0.0\n",
                 "Antenna parking  Off\n",
                 "Rotator limit    Off\n",
                 "Preset position  1:0.0/0.0 2:0.0/0.0 3:0.0/0.0 4:0.0/0.0 5:0.0/0.0\n",
                 "CAT Rig          NONE AOS\n",
                 "Doppler correct. Up:Y Down:Y\n",
                 "Step control ADC value Center:550 Reff:560\n",
                 "Frequency step   100 Hz\n",
                 "Mic click at AOS CAT:Y Up pulse:Y Polarity:Normal\n",
                 "Rotor start      South\n",
                 "COM port         9600 Baud 8-N-1\n",
                 "Press any key to continue\n"},
       .then = [](Fixture& f, const store::Model&) {
         // Parking, limits and an Icom rig as they appear when set.
         store::Model m = f.model;
         m.rotator.parking_enabled = true;
         m.rotator.parking = {90, 0};
         m.rotator.limits_enabled = true;
         m.rotator.az_limit_min = 270;
         m.rotator.az_limit_max = 90;
         m.rotator.el_limit_max = 45;
         m.radio.rig = radio::Rig::icom;
         m.radio.icom_rx_address = 0x10;
         m.radio.icom_tx_address = 0x14;
         m.radio.downlink_correction = radio::DownlinkCorrection::reverse;
         const auto lines = menus::configuration_lines(m);
         CHECK(lines[3] == "Antenna parking  On  AZ:90.0 EL:0.0");
         CHECK(lines[4] == "Rotator limit    On  AZ:270.0-90.0 EL:0.0-45.0");
         CHECK(lines[6] == "CAT Rig          ICOM AOS  RX:10H TX:14H");
         CHECK(lines[7] == "Doppler correct. Up:Y Down:R");
       }},

      // 6-1: N leaves the span alone; a span too narrow is refused.
      {.name = "6-1: N leaves the span alone",
       .keys = "1\rNQ\r",
       .setup = [](Fixture& f) { f.station->set_rotor_control(true); },
       .shown = {"Elevation minimum position [Y/N] ? N\nNot changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) { CHECK(f.model.rotator == was.rotator); }},

      {.name = "6-1: Esc leaves the span alone, as N does (issue 39)",
       .keys = "1\r\x1bQ\r",
       .setup = [](Fixture& f) { f.station->set_rotor_control(true); },
       .shown = {"Elevation minimum position [Y/N] ? N\nNot changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) { CHECK(f.model.rotator == was.rotator); }},

      {.name = "6-2: Esc at a value leaves the span as it was (issue 39)",
       .keys = "2\r9\r\x1bQ\r",
       .shown = {"Not changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) { CHECK(f.model.rotator == was.rotator); }},

      {.name = "6-1: both points at the same place are refused",
       .keys = "1\rYYQ\r",
       .setup = [](Fixture& f) {
         f.station->set_rotor_control(true);
         f.term.timeouts_before_key = 2;
       },
       .shown = {"maximum must exceed minimum by at least 10 counts", "Not changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) {
         CHECK(f.model.rotator == was.rotator);
         CHECK(f.station->rotator().config() == was.rotator);
       }},

      {.name = "6-1 opened on a fresh unit does not take rotor control; N leaves it off (issue 39)",
       .keys = "1\rNQ\r",
       .shown = {"Not changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model&) {
         CHECK(!has(f.term.output(), "Rotor control switched ON"));
         CHECK(!f.model.rotor_control);
       }},

      {.name = "6-1 on a fresh unit (rotor control off): the first key that moves takes rotor control, no question",
       .keys = "1\r6NQ\r",
       .setup = [](Fixture& f) { f.term.timeouts_before_key = 20; },
       .shown = {"Rotor control switched ON (E key in the realtime display switches it OFF).\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         CHECK(!has(f.term.output(), "Switch rotor control ON"));
         CHECK(f.model.rotor_control);
       }},

      {.name = "6-2 sets the ADC span by hand, as in the manual's example",
       .keys = "2\r9\r887\r3\r465\rQ\r",
       .setup = [](Fixture& f) {
         f.model.rotator.az_span = {8, 492};
         f.model.rotator.el_span = {2, 424};
       },
       .shown = {"ADC span value AZ: 0008 - 0492\n"
                 "AZ minimum value ? : 9\n"
                 "AZ maximum value ? : 887\n"
                 "ADC span value EL: 0002 - 0424\n"
                 "EL minimum value ? : 3\n"
                 "EL maximum value ? : 465\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         CHECK(f.model.rotator.az_span == rotator::AxisSpan{9, 887});
         CHECK(f.model.rotator.el_span == rotator::AxisSpan{3, 465});
         CHECK(f.station->rotator().config().el_span == rotator::AxisSpan{3, 465});
       }},

      {.name = "6-2 refuses an invalid span and changes nothing; bad answers are asked again",
       .keys = "2\r500\r2000\rabc\r400\r\r\rQ\r",
       .shown = {"2000 is out of range: expected 0 to 1023", "'abc' is not a number",
                 "azimuth ADC span 500-400: maximum must exceed minimum by at least 10 counts", "Not changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) {
         CHECK(f.model.rotator == was.rotator);
         CHECK(f.station->rotator().config() == was.rotator);
       }},

      {.name = "6-2: Q at a prompt leaves with nothing changed",
       .keys = "2\r9\rQ\rQ\r",
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) { CHECK(f.model.rotator == was.rotator); }},

      {.name = "6-3 sets dead band and skew, as in the manual's example",
       .keys = "3\r5\r3\r\r-4\rQ\r",
       .shown = {"Azimuth Dead Band : 3.0  5\n"
                 "Elevation Dead Band : 1.0  3\n"
                 "Azimuth Skew value : 0.0  \n"
                 "Elevation Skew value : 0.0  -4\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         CHECK(f.model.rotator.az_dead_band == 5);
         CHECK(f.model.rotator.el_dead_band == 3);
         CHECK(f.model.rotator.az_skew == 0);
         CHECK(f.model.rotator.el_skew == -4);
         CHECK(f.station->rotator().config().az_dead_band == 5);
       }},

      {.name = "6-3 refuses a fractional dead band and asks again",
       .keys = "3\r2.5\r101\r4\r\r\r\rQ\r",
       .shown = {"2.5 is not a whole number", "101 is out of range: expected 0 to 100"},
       .then = [](Fixture& f, const store::Model&) { CHECK(f.model.rotator.az_dead_band == 4); }},

      {.name = "6-4 sets parking and limits, as in the manual's example",
       // With the factory South start, 0..340 holds the rotor stop (180): the limits split the
       // travel, and 6-4 says what is reachable (barriers: the factory setting), asking nothing more.
       .keys = "4\rY90\r45\rY\r\r340\r\r60\rQ\r",  // Y<Enter> ends the answer (issue 18)
       .shown = {"Set Antenna Parking position ? [Y/N] Y\n"
                 "Azimuth Parking value : 0.0  90\n"
                 "Elevation Parking value : 0.0  45\n"
                 "Set Antenna rotation limit ? [Y/N] Y\n"
                 "Azimuth minmum value : 0.0  \n"
                 "Azimuth maximum value : 360.0  340\n"
                 "Elevation minmum value : 0.0  \n"
                 "Elevation maximum value : 90.0  60\n",
                 "Limits split the travel: with the rotor stop at 180.0 (South start) the\n"
                 "  antenna can reach 180.0-340.0 or 0.0-180.0, and keeps to the one it is in,\n"
                 "  as the limits bar the excluded 340.0-0.0 between them. A pass is followed as\n"
                 "  far as that piece allows; the realtime display says how much\n"
                 "  (--cross-limit-sector yes lets it cross between passes).\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         const auto& r = f.model.rotator;
         CHECK(r.parking_enabled);
         CHECK(r.parking == rotator::AzEl{90, 45});
         CHECK(r.limits_enabled);
         CHECK(r.az_limit_min == 0);
         CHECK(r.az_limit_max == 340);
         CHECK(r.el_limit_min == 0);
         CHECK(r.el_limit_max == 60);
         CHECK_FALSE(r.cross_limit_sector);
         CHECK(menus::configuration_lines(f.model)[4] == "Rotator limit    On  AZ:0.0-340.0 EL:0.0-60.0");
         CHECK(f.station->rotator().config() == r);
         // Parking now acts, within the limits as barriers: the antenna is in the piece 180..340
         // (the South stop), and 90 lies beyond the excluded 340..0, so it goes as far as it may
         // and never enters the excluded sector.
         f.station->set_rotor_control(true);
         f.station->rotator().park();
         f.run(60);
         CHECK(std::abs(f.truth().el - 45) <= kElTol);
         CHECK(f.truth().az >= 180.0 - kAzTol);
         CHECK(f.truth().az <= 340.0 + kAzTol);
       }},

      // 6-4 refuses limits that leave nowhere to go; N switches parking and limits off.
      {.name = "6-4 refuses limits that leave nowhere to go",
       .keys = "4\rN" "Y\r\r\r50\r40\rQ\r",
       .shown = {"elevation limits 50..40: maximum must not be below minimum", "Not changed.\n"},
       .saves = 0,
       .then = [](Fixture& f, const store::Model& was) { CHECK(f.model.rotator == was.rotator); }},

      {.name = "6-4: N switches parking and limits off",
       .keys = "4\rNNQ\r",
       .setup = [](Fixture& f) {
         f.model.rotator.parking_enabled = true;
         f.model.rotator.limits_enabled = true;
       },
       .then = [](Fixture& f, const store::Model&) {
         CHECK(!f.model.rotator.parking_enabled);
         CHECK(!f.model.rotator.limits_enabled);
       }},

      {.name = "6-5 shows the live monitor line until Q",
       .keys = "5\rQQ\r",
       .setup = [](Fixture& f) {
         f.term.timeouts_before_key = 3;
         f.run(1);  // a first reading, as the program has one before its first prompt
       },
       .shown = {"=== ADC value & Antenna position ===\nAZ=   0 / 180.0deg EL=   0 / 0.0deg.\n"}},

      {.name = "6-6-1 keyboard control drives the simulated rotator; 5 stops, Enter leaves with motion stopped",
       .keys = "6\r1\r65\rQ\rQ\r",
       .setup = [](Fixture& f) {
         f.station->set_rotor_control(true);
         f.run(1);                         // a first reading, as the program has one before its first prompt
         f.term.timeouts_before_key = 20;  // 10 s before each key
       },
       .shown = {"1.Direct rotor control from key board.\n"
                 "2.Enter direction value.\n"
                 "3.Preset Control.\n"
                 "Select[1-3,Q]:1\n"
                 "Left(4),Right(6),Up(8),Dwn(2),Stop(5)or Ret\n"
                 "AZ=   0 / 180.0deg EL=   0 / 0.0deg.\n"},
       .then = [](Fixture& f, const store::Model&) {
         // About 10 s clockwise at 6 deg/s.
         const double travel = f.rotator_sim->true_position().az_travel;
         CHECK(travel > 40.0);
         CHECK(travel < 70.0);
         f.run(5);
         CHECK(f.rotator_sim->true_position().az_travel == doctest::Approx(travel).epsilon(0.02));
         CHECK(f.station->rotator().status().mode == rotator::ControlMode::idle);
       }},

      {.name = "6-6-2 points the simulated rotator at the value entered, as in the manual's example",
       .keys = "6\r2\r210\r20\rQ\rQ\r",
       .setup = [](Fixture& f) {
         f.station->set_rotor_control(true);
         f.run(1);  // a first reading, as the program has one before its first prompt
         f.tracker.track_single(0);
         f.term.timeouts_before_key = 4000;  // the live display ends by itself on arrival
       },
       .shown = {"Azimuth: 180.0  210\nElevation: 0.0  20\nAZ=   0 / 180.0deg EL=   0 / 0.0deg.\n"},
       .then = [](Fixture& f, const store::Model&) {
         CHECK(f.tracker.mode() == tracker::Mode::off);  // direct control stops tracking
         CHECK(f.station->rotator().status().on_target);
         CHECK(rotator::azimuth_distance(f.truth().az, 210) <= kAzTol);
         CHECK(std::abs(f.truth().el - 20) <= kElTol);
         // The last live line is the arrival.
         const auto a = f.station->antenna();
         REQUIRE(a);
         CHECK(has(f.term.output(), rotator::format_monitor_line(f.station->rotator().status()) + "\n"));
       }},

      {.name = "6-6-2 asks again for a value out of range",
       .keys = "6\r2\r400\r10\r95\r10\rQ\rQ\r",
       .setup = [](Fixture& f) {
         f.station->set_rotor_control(true);
         f.term.timeouts_before_key = 4000;
       },
       .shown = {"400 is out of range: expected 0 to 360", "95 is out of range: expected 0 to 90"},
       .then = [](Fixture& f, const store::Model&) {
         CHECK(rotator::azimuth_distance(f.truth().az, 10) <= kAzTol);
         CHECK(std::abs(f.truth().el - 10) <= kElTol);
       }},

      // 6-6 with rotor control off (a fresh unit): the manual's keystrokes work, control is taken.
      {.name = "6-6-2 on a fresh unit takes rotor control and goes where the manual's keystrokes say",
       .keys = "6\r2\r30\r10\rQ\rQ\r",
       .setup = [](Fixture& f) { f.term.timeouts_before_key = 4000; },
       .shown = {"Rotor control switched ON (E key in the realtime display switches it OFF).\n", "Azimuth:"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         CHECK(f.model.rotor_control);
         CHECK(rotator::azimuth_distance(f.truth().az, 30) <= kAzTol);
       }},

      {.name = "6-6-3 stores five presets and goes to one, as in the manual's example",
       .keys = "6\r3\rS\r125\r15\r90\r22\r0\r45\r270\r10\r165\r0\r1\rQ\rQ\rQ\r",
       .setup = [](Fixture& f) {
         f.station->set_rotor_control(true);
         f.term.timeouts_before_key = 4000;
       },
       .shown = {" 1:0.0/0.0 2:0.0/0.0 3:0.0/0.0 4:0.0/0.0 5:0.0/0.0\n"
                 " Select[1-5,S,Q]: S\n"
                 " Preset position 1 Az: 0.0  125\n"
                 "                   El: 0.0  15\n"
                 " Preset position 2 Az: 0.0  90\n"
                 "                   El: 0.0  22\n"
                 " Preset position 3 Az: 0.0  0\n"
                 "                   El: 0.0  45\n"
                 " Preset position 4 Az: 0.0  270\n"
                 "                   El: 0.0  10\n"
                 " Preset position 5 Az: 0.0  165\n"
                 "                   El: 0.0  0\n"
                 " 1:125.0/15.0 2:90.0/22.0 3:0.0/45.0\n"
                 "   4:270.0/10.0 5:165.0/0.0\n"
                 " Select[1-5,S,Q]: 1\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         const auto& pr = f.model.rotator.presets;
         CHECK(pr[0] == rotator::AzEl{125, 15});
         CHECK(pr[1] == rotator::AzEl{90, 22});
         CHECK(pr[2] == rotator::AzEl{0, 45});
         CHECK(pr[3] == rotator::AzEl{270, 10});
         CHECK(pr[4] == rotator::AzEl{165, 0});
         CHECK(f.station->rotator().config().presets == pr);
         CHECK(rotator::azimuth_distance(f.truth().az, 125) <= kAzTol);
         CHECK(std::abs(f.truth().el - 15) <= kElTol);
       }},

      {.name = "6-7 configures an Icom pair, as in the manual's example",
       .keys = "7\rI14\r10\rYYAQ\r",
       .setup = [](Fixture& f) {
         f.model.radio.icom_tx_address = 0x10;  // the example shows the value stored before
         f.station->reconfigure();
       },
       .shown = {"CAT Rig KENWOOD,YAESU,ICOM [K/Y/I] ? I\n"
                 "IC-275:10H IC-375/475:14H IC-970:2EH IC-271:20H IC-371/471:22H\n"
                 "Enter destination Address for RX (00) 14\n"
                 "Enter destination Address for TX (10) 10\n"
                 "Uplink Doppler correction ? [Y/N] Y\n"
                 "Downlink Doppler correction ? [Y/N/R] Y\n"
                 "Select Full orbit or AOS CAT control ? [F/A] A\n"
                 "Radio: simulated radio\n"
                 "The new rig settings reach the radio driver when trakbox next starts (--radio cat:DEVICE).\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         const auto& r = f.model.radio;
         CHECK(r.rig == radio::Rig::icom);
         CHECK(r.icom_rx_address == 0x14);
         CHECK(r.icom_tx_address == 0x10);
         CHECK(r.uplink_correction);
         CHECK(r.downlink_correction == radio::DownlinkCorrection::on);
         CHECK(r.cat_policy == radio::CatPolicy::aos_only);
         CHECK(f.station->tuner().config() == r);
       }},

      {.name = "6-7 Yaesu asks about the FT-736 wide FM filter",
       .keys = "7\rYYNRFQ\r",
       .shown = {"FT-736 FM filter changed for a wider one (UO-22) ? [Y/N] Y\n"},
       .then = [](Fixture& f, const store::Model&) {
         const auto& r = f.model.radio;
         CHECK(r.rig == radio::Rig::yaesu);
         CHECK(r.ft736_wide_fm);
         CHECK(!r.uplink_correction);
         CHECK(r.downlink_correction == radio::DownlinkCorrection::reverse);
         CHECK(r.cat_policy == radio::CatPolicy::full_orbit);
         CHECK(f.station->tuner().config() == r);
       }},

      {.name = "6-7: bad addresses are asked again",
       .keys = "7\rIE0\rXYZ\r2EH\r\rYYAQ\r",
       .shown = {"'E0' is not a CI-V address: expected hex 00 to DF (E0 is TrakBox's own)",
                 "'XYZ' is not a CI-V address"},
       .then = [](Fixture& f, const store::Model&) {
         CHECK(f.model.radio.icom_rx_address == 0x2E);
         CHECK(f.model.radio.icom_tx_address == 0x00);
       }},

      {.name = "6-8 sets the mic click values, as in the manual's example",
       .keys = "8\rS525\r500\r50\rYYNQ\r",
       .shown = {"Set new value or Measure ADC value ? [S/M] S\n"
                 "Modem locked center ADC value: 550  525\n"
                 "Reference ADC value : 560  500\n"
                 "Enter Step Frequency [Hz]: 50\n"
                 "Frequency set CAT command at AOS ? [Y/N] Y\n"
                 "Automatic up pulse generation at AOS ? [Y/N] Y\n"
                 "Polarity of step pulse, Normal/Reverse? [N/R] N\n"},
       .saves = 1,
       .then = [](Fixture& f, const store::Model&) {
         const auto& m = f.model.radio.mic_click;
         CHECK(m.centre_adc == 525);
         CHECK(m.reference_adc == 500);
         CHECK(m.span() == 25);
         CHECK(m.step_hz == 50);
         CHECK(m.cat_at_aos);
         CHECK(m.auto_up_at_aos);
         CHECK(m.polarity == radio::PulsePolarity::normal);
         CHECK(f.station->tuner().config().mic_click == m);
       }},

      {.name = "6-8: a reference equal to the centre is asked again; Reverse polarity",
       .keys = "8\rS\r\r550\r540\r\rNNRQ\r",
       .shown = {"The reference must differ from the center"},
       .then = [](Fixture& f, const store::Model&) {
         const auto& m = f.model.radio.mic_click;
         CHECK(m.reference_adc == 540);
         CHECK(m.step_hz == 100);
         CHECK(!m.cat_at_aos);
         CHECK(m.polarity == radio::PulsePolarity::reverse);
       }},

      {.name = "6-8 Measure shows ADC3 live from the simulated discriminator: no signal, the centre",
       .keys = "8\rMxQ\r",
       .setup = [](Fixture& f) { f.term.timeouts_before_key = 3; },
       .shown = {"ADC3 value (any key to stop)\nADC3=  550 center 550 span 10: locked\n"}},

      {.name = "6-9 resets everything, empties the kepele database and loads the manual's station file",
       .keys = "9\rYY" + testing::read_file(TRAKBOX_SOURCE_DIR "/data/station.txt") + "\x1a" + "0\r Q\r",
       .setup = [](Fixture& f) {
         f.model.radio.mic_click.step_hz = 50;
         f.model.rotator.presets[0] = {10, 10};
         f.model.clock_offset = std::chrono::seconds(42);
         f.station->set_rotor_control(true);
         f.tracker.track_single(0);
         REQUIRE(!f.model.db.satellites.empty());
       },
       .shown = {"Stored data in memory will be lost.\n"
                 "Are you sure ? [Y/N] ? Y\n"
                 "\aConfigure your station elements by uploading data file ? [Y/N] Y\n"
                 "Upload Station info data file (EOF:ctrl-Z)\n"
                 "1 WA7GXD 32.259 -110.778 842 S\n"
                 "2 3 1017 5 454\n"
                 "3 5 3 0 0\n"
                 "4 ICOM A 10 14\n"
                 "5 1 90 0 1 270 90 0 45\n"
                 "Station file loaded. Verify it with 6-0 (Display all configured value).\n",
                 // 6-0 afterwards, as the manual suggests.
                 "Callsign:WA7GXD  Lat:32.3 Long:-110.8 Hgt:842.0\n",
                 "ADC span value   AZ:   3 - 1017  EL:   5 -  454\n",
                 "Dead band        AZ:5.0 EL:3.0  Skew AZ:0.0 EL:0.0\n",
                 "Antenna parking  On  AZ:90.0 EL:0.0\n",
                 "Rotator limit    On  AZ:270.0-90.0 EL:0.0-45.0\n",
                 "CAT Rig          ICOM AOS  RX:10H TX:14H\n",
                 "Rotor start      South\n"},
       .saves = 2,
       .then = [](Fixture& f, const store::Model&) {
         // The database is gone, the rest is at factory values, the clock kept its time.
         CHECK(f.model.db.satellites.empty());
         CHECK(f.model.db.selected.empty());
         CHECK(f.tracker.mode() == tracker::Mode::off);
         CHECK(!f.model.rotor_control);
         CHECK(f.model.radio.mic_click.step_hz == 100);
         CHECK(f.model.rotator.presets[0] == rotator::AzEl{0, 0});
         CHECK(f.model.clock_offset == std::chrono::seconds(42));
         CHECK(f.station->rotator().config() == f.model.rotator);
         CHECK(f.station->tuner().config() == f.model.radio);
       }},

      {.name = "6-9 with an error on line 4 applies nothing of the file",
       .keys = std::string("9\rYY") +
               "1 WA7GXD 32.259 -110.778 842 S\r2 3 1017 5 454\r3 5 3 0 0\r4 ICOM X 10 14\r"
               "5 1 90 0 1 270 90 0 45\r\x1aQ\r",
       .shown = {"  line 4, item 3 (F/A): found \"X\", expected F (full orbit) or A (AOS only)\n"
                 "Station file not applied: every parameter is at its default.\n"},
       .saves = 1,  // the reset only
       .then = [](Fixture& f, const store::Model&) {
         const store::Model d = store::factory_defaults();
         CHECK(f.model.station.callsign == d.station.callsign);
         CHECK(f.model.rotator == d.rotator);
         CHECK(f.model.radio == d.radio);
         CHECK(f.model.db.satellites.empty());
       }},
  });
}

// The scripts below need more than one run of the menu, a terminal of their own or a look at the
// station while the menu runs.
