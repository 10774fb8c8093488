// Issue 30, item 4: the main menu says how to leave, Q there asks first, and Q pressed on from the
// submenus never quits; over a serial line Q detaches instead (trakbox keeps running).
#include <doctest/doctest.h>

#include "fixture.h"

using namespace tb;

TEST_CASE("main menu: the Q line is shown and the manual's prompt is unchanged") {
  testing::MenuFixture f("0");
  CHECK_THROWS_AS(menus::main_menu(f.term, *f.services), menus::InputClosed);
  CHECK(f.term.output().find("     8. Direct Antenna control.\n     Q. Leave trakbox.\n     Select [1-8,S,M]:") !=
        std::string::npos);
}

TEST_CASE("main menu: Q asks, N stays, Y leaves") {
  testing::MenuFixture stay("QN");
  CHECK_THROWS_AS(menus::main_menu(stay.term, *stay.services), menus::InputClosed);
  CHECK(stay.term.output().find("leave trakbox? [Y/N]") != std::string::npos);
  testing::MenuFixture leave("QY");
  CHECK_NOTHROW(menus::main_menu(leave.term, *leave.services));  // returns: trakbox saves and exits
}

TEST_CASE("main menu: Q pressed on while backing out of submenus never quits") {
  // 3 (update menu), Q back to the main menu, then a second and third Q: the question, answered No.
  testing::MenuFixture f("3QQQ");
  CHECK_THROWS_AS(menus::main_menu(f.term, *f.services), menus::InputClosed);
  testing::MenuFixture g("6QQQ2Q");
  CHECK_THROWS_AS(menus::main_menu(g.term, *g.services), menus::InputClosed);
}

TEST_CASE("serial line: Q detaches and the menu comes back on a key") {
  testing::MenuFixture f("QYx");
  f.services->leave = menus::detach_serial_line;
  CHECK_THROWS_AS(menus::main_menu(f.term, *f.services), menus::InputClosed);
  const std::string& out = f.term.output();
  CHECK(out.find("detach from trakbox? [Y/N]") != std::string::npos);
  const auto detached = out.find("Detached: trakbox keeps tracking. Any key brings the menu back.");
  REQUIRE(detached != std::string::npos);
  CHECK(out.find("----- MAIN MENU -----", detached) != std::string::npos);
}

TEST_CASE("menu 4: hemispheres after the number, which sign is which, and the save confirmed (issue 30 item 10)") {
  testing::MenuFixture f("F4ABC\r48.85N\r2.35 w\r35\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.lat_deg == 48.85);
  CHECK(f.model.station.lon_deg == -2.35);
  CHECK(f.saves == 1);
  const std::string& out = f.term.output();
  CHECK(out.find("(+ north / - south, + east / - west; or 48.85N, 2.35E, 122.4W)") != std::string::npos);
  CHECK(out.find("Station saved: F4ABC  48.850 N  2.350 W  35 m  rotor start South") != std::string::npos);
}

TEST_CASE("menu 4: a latitude that is no number of degrees is asked again, naming the letters") {
  testing::MenuFixture f("\r-48.85N\r48.85S\r\r\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.lat_deg == -48.85);
  CHECK(f.term.output().find("'-48.85N' is not a number of degrees (a sign, or N or S after it)") != std::string::npos);
}

TEST_CASE("realtime display: Q on a full screen clears the sky plot and map before the menu (issue 30 item 6)") {
  testing::MenuFixture f("\rQ");
  f.term.set_full_screen(true);
  f.term.timeouts_before_key = 6;  // a few seconds of display: the graphics are drawn
  menus::menu_1_realtime_tracking(f.term, *f.services);
  REQUIRE(f.term.graphics_count() > 0);
  CHECK_FALSE(f.term.graphics_shown());
}
