// Issue 30, item 4: the main menu says how to leave, Q there asks first, and Q pressed on from the
// submenus never quits; over a serial line Q detaches instead (trakbox keeps running).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string_view>

#include "menus/term/curses_terminal.h"

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
  testing::MenuFixture f("F4ABC\r48.85N\r2.35 w\r35\r\r\r\r");
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.model.station.lat_deg == 48.85);
  CHECK(f.model.station.lon_deg == -2.35);
  CHECK(f.saves == 1);
  const std::string& out = f.term.output();
  CHECK(out.find("(+ north/- south, + east/- west; 48.85N, 2.35E, 122.4W; or a locator JN18du)") != std::string::npos);
  CHECK(out.find("Station saved: F4ABC  48.850 N  2.350 W  35 m  rotor start South") != std::string::npos);
}

TEST_CASE("menu 4: a latitude that is no number of degrees is asked again, naming the letters") {
  testing::MenuFixture f("\r-48.85N\r48.85S\r\r\r\r\r\r");
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

namespace {
// The cell of the sky plot drawing (width x height) where draw_sky_plot puts a look angle: the
// zenith in the middle, the horizon on the ellipse touching the edges, north up, east right.
std::pair<int, int> sky_cell(double az, double el, int width, int height) {
  const double cx = (width - 1) / 2.0, cy = (height - 1) / 2.0, r = (90.0 - std::max(el, 0.0)) / 90.0;
  const double a = az * std::numbers::pi / 180.0;
  return {static_cast<int>(std::lround(cx + r * cx * std::sin(a))), static_cast<int>(std::lround(cy - r * cy * std::cos(a)))};
}
}  // namespace

TEST_CASE("realtime display: under --clock-rate 10 the sky plot's @ and X follow every update (issue 30 item 8)") {
  // The operator's run: --clock 2026-11-27T11:55:00Z --clock-rate 10, the display opened before
  // AOS. Each update steps the clock 10 s; its first falls on a second not divisible by 5 (the
  // pictures were redrawn only on those, so @ never showed and X stayed at S).
  testing::MenuFixture f("4\rQ", orbit::from_civil(2026, 11, 27, 11, 55, 3));  // 4: ISS
  f.station->set_rotor_control(true);
  f.term.set_full_screen(true);
  f.term.timeouts_before_key = 120;  // 20 minutes of the clock
  int waits = 0, satellite_up = 0;
  std::optional<term::Graphics> up;  // a drawing with the satellite above the horizon
  f.term.on_wait = [&](std::optional<term::Duration> timeout) {
    ++waits;
    // What the last update drew is what it read: the satellite's look angles and the antenna.
    CHECK(f.term.graphics_count() == waits);
    const term::Graphics& g = f.term.last_graphics();
    const tracker::SatNow* n = f.tracker.followed();
    if (!n && !f.tracker.candidates().empty()) n = &f.tracker.candidates().front();
    REQUIRE(n);
    REQUIRE(g.satellite);
    CHECK(g.satellite->az_deg == n->obs.look.az_deg);
    CHECK(g.satellite->el_deg == n->obs.look.el_deg);
    const auto ant = f.station->antenna();
    REQUIRE(ant);
    REQUIRE(g.antenna);
    CHECK(g.antenna->az_deg == ant->az);
    CHECK(g.antenna->el_deg == ant->el);
    if (n->obs.look.el_deg > 5.0 && ant->el > 5.0) {
      ++satellite_up;
      up = g;
    }
    f.now += 10 * std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
    // The display opened five minutes before AOS: the shown satellite's next pass (its time
    // depends on the shipped elements), on the same odd second.
    if (waits == 1) {
      REQUIRE(n->pass);
      REQUIRE(n->pass->aos - f.now > std::chrono::minutes(5));
      f.now += std::chrono::floor<std::chrono::minutes>(n->pass->aos - std::chrono::minutes(5) - f.now);
    }
    f.station->tick();
  };
  menus::menu_1_realtime_tracking(f.term, *f.services);
  REQUIRE(satellite_up > 0);  // the pass came and the antenna followed it
  // The last such drawing has @ and X where their look angles put them (the satellite's over the
  // antenna's when they share a cell).
  const auto sky = term::draw_sky_plot(*up, 41, 21);
  const auto [ax, ay] = sky_cell(up->antenna->az_deg, up->antenna->el_deg, 41, 21);
  const auto [sx, sy] = sky_cell(up->satellite->az_deg, up->satellite->el_deg, 41, 21);
  CAPTURE(up->satellite->az_deg);
  CAPTURE(up->antenna->az_deg);
  CHECK(sky[static_cast<std::size_t>(sy)][static_cast<std::size_t>(sx)] == '@');
  if (std::pair{ax, ay} != std::pair{sx, sy}) CHECK(sky[static_cast<std::size_t>(ay)][static_cast<std::size_t>(ax)] == 'X');
}

TEST_CASE("sky plot: the elevation rings are whole rings, and the symbols have a legend (issue 30 item 8)") {
  const term::Graphics none;
  const auto sky = term::draw_sky_plot(none, 41, 21);
  // Every cell the horizon and the 30 and 60 degree rings pass through, at each degree of azimuth,
  // is a dot (but the N, S, E, W letters on the horizon).
  for (int az = 0; az < 360; ++az) {
    for (double el : {0.0, 30.0, 60.0}) {
      const auto [x, y] = sky_cell(az, el, 41, 21);
      const char c = sky[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      CAPTURE(az);
      CAPTURE(el);
      CHECK((c == '.' || (el == 0.0 && std::string_view("NSEW").find(c) != std::string_view::npos)));
    }
  }
  CHECK(std::string(term::graphics_legend()) == "@ satellite  X antenna  o pass  A AOS  Q station");
}

TEST_CASE("menu 4: Esc at a prompt leaves with the station unchanged (issue 30 item 10)") {
  // The callsign answered, then Esc in the middle of the latitude; and Esc at the first prompt.
  for (const char* keys : {"F4XYZ\r48.8\x1b", "\x1b"}) {
    CAPTURE(keys);
    testing::MenuFixture f(keys);
    const station::StationConfig before = f.model.station;
    menus::menu_4_station_elements(f.term, *f.services);
    CHECK(f.model.station.callsign == before.callsign);
    CHECK(f.model.station.lat_deg == before.lat_deg);
    CHECK(f.saves == 0);
    CHECK(f.term.output().find("Station not changed.") != std::string::npos);
    CHECK_FALSE(f.term.escape_leaves());  // the other menus' prompts still ignore Esc
  }
  // Elsewhere Esc is still a control key a line prompt ignores.
  term::ScriptTerminal t("12\x1b" "3\r");
  CHECK(t.read_line() == "123");
}
