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
