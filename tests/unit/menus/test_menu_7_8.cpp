// Menu 7 (host mode on the terminal) and menu 8 (direct antenna control from the main menu).
#include <doctest/doctest.h>

#include <cmath>

#include "fixture.h"
#include "rotator/adc_model.h"

using namespace tb;
using testing::has;

namespace {

using testing::kAzTol;
using testing::kElTol;

}  // namespace

TEST_CASE("Menu 7 greets as the manual and prompts TrakBox>> after every command until Q") {
  testing::MenuFixture f("?\rQ\r");
  menus::menu_7_host_mode(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.rfind("TrakBox host mode.\nCommand:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,?A,?\nAlso:RF,?R,LOG,?C,STANDBY,PB,OR,OT,CT,MODE,?T,QTH (? explains each)\nTrakBox>>?\n", 0) == 0);
  CHECK(has(out, "AZxxx ELxxx  point the antenna, degrees        AZ220 EL45\n"));
  CHECK(has(out, "Q            quit to the main menu\nTrakBox>>Q\n"));
  CHECK(out.substr(out.size() - 2) == "Q\n");  // nothing after Q: back to the main menu
}

TEST_CASE("Menu 7 drives the simulated rotator and radio; errors change nothing") {
  testing::MenuFixture f(
      "AZ220 EL45\rMUFM\rMDUSB\rFU14595000\rFD43590000\rSTX;\rFU14x\rAZ400 EL10\rBOGUS\rQ\r");
  f.station->set_rotor_control(true);
  menus::menu_7_host_mode(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "TrakBox>>AZ220 EL45\nTrakBox>>MUFM\nTrakBox>>MDUSB\nTrakBox>>FU14595000\nTrakBox>>FD43590000\n"
                 "TrakBox>>STX;\nTrakBox>>FU14x\nERROR FU: '14x' is not a frequency"));
  CHECK(has(out, "TrakBox>>AZ400 EL10\nERROR AZ/EL: azimuth 400 out of range: expected 0 to 360\n"));
  CHECK(has(out, "TrakBox>>BOGUS\nERROR unknown command 'BOGUS'"));
  CHECK(f.radio_sim->mode(radio::Link::uplink) == radio::Mode::fm);
  CHECK(f.radio_sim->mode(radio::Link::downlink) == radio::Mode::usb);
  CHECK(f.radio_sim->frequency(radio::Link::uplink) == 145950000);
  CHECK(f.radio_sim->frequency(radio::Link::downlink) == 435900000);
  const auto h = f.radio_sim->history();
  REQUIRE(h.size() == 5);
  CHECK(h.back().raw == "TX;");
  // The antenna goes to 220/45 (not 400) while the event loop runs on.
  f.run(90);
  CHECK(rotator::azimuth_distance(f.truth().az, 220) <= kAzTol);
  CHECK(std::abs(f.truth().el - 45) <= kElTol);
  // ?A answers where it is, in a form AZ/EL reads back.
  f.term.clear_output();
  f.term.feed("?A\rQ\r");
  menus::menu_7_host_mode(f.term, *f.services);
  const auto a = f.station->antenna();
  REQUIRE(a);
  char want[48];
  std::snprintf(want, sizeof want, "TrakBox>>?A\nAZ%.1f EL%.1f\n", a->az, a->el);
  CHECK(has(f.term.output(), want));
}

TEST_CASE("Menu 8 is the 6-6 sub-menu: keyboard control from the main menu") {
  testing::MenuFixture f("1\r8\rQ\r");
  f.station->set_rotor_control(true);
  f.term.timeouts_before_key = 20;  // 10 s before each key
  f.tracker.track_single(0);
  menus::menu_8_direct_antenna(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.rfind("1.Direct rotor control from key board.\n2.Enter direction value.\n3.Preset Control.\nSelect[1-3,Q]:1\n"
                  "Left(4),Right(6),Up(8),Dwn(2),Stop(5)or Ret\n",
                  0) == 0);
  CHECK(f.tracker.mode() == tracker::Mode::off);
  // Up for 10 s at 3 deg/s, then Enter: stopped there.
  const double el = f.rotator_sim->true_position().el;
  CHECK(el > 20);
  CHECK(el < 35);
  f.run(5);
  CHECK(f.rotator_sim->true_position().el == doctest::Approx(el).epsilon(0.02));
  CHECK(f.station->rotator().status().mode == rotator::ControlMode::idle);
}
