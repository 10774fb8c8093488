// Standalone mode: the LCD lines, the AOS LED, the selector keys, the 0-and-back toggle, and the
// simulated rotator following once the track switch is on. The shipped tracking list begins
// #1 AO-07  #2 AO-27  #3 FO-29  #4 ISS; on 2026-05-21 at 12:00 UTC AO-27 and FO-29 are up from the
// fixture's station (test_menu_m.cpp checks these passes).
#include <doctest/doctest.h>

#include "fixture.h"
#include "menus/standalone.h"

using namespace tb;
using testing::count;
using namespace tb::menus;
using orbit::from_civil;

namespace {

bool no_terminal_mode() {
  FAIL("terminal mode was not asked for");
  return false;
}

}  // namespace

// ---- the LCD and the LED ----

TEST_CASE("The LCD lines of the manual") {
  const auto t = from_civil(1993, 7, 17, 7, 34, 54);
  CHECK(lcd_top(t, "UO-14") == "07:34:54 UO-14");
  CHECK(lcd_azel(146.7, -62.8) == "Az 146.7El -62.8");
  CHECK(lcd_ma(110.2, 19.6, 119.25) == "A110 E20 P119.2");
  CHECK(lcd_azel(146.7, -62.8).size() == kLcdColumns);
  // Small and extreme values keep the 16 columns.
  CHECK(lcd_azel(5.0, 3.04) == "Az   5.0El   3.0");
  CHECK(lcd_azel(359.94, -90.0) == "Az 359.9El -90.0");
  CHECK(lcd_azel(0.01, -0.04) == "Az   0.0El   0.0");  // no "-0.0"
  CHECK(lcd_ma(359.6, -0.3, 255.99) == "A0 E0 P255.9");
  CHECK(lcd_ma(5.0, -62.8, 0.04) == "A5 E-63 P0.0");
  CHECK(lcd_ma(270.0, -90.0, 200.5).size() <= kLcdColumns);
  // Names longer than 7 characters are cut: the line is 16 characters.
  CHECK(lcd_top(t, "ISS (ZARYA)") == "07:34:54 ISS (ZA");
  CHECK(lcd_top(t, "ISS (ZARYA)").size() == kLcdColumns);
  // Multiple tracking shows its marker between time and name.
  CHECK(lcd_top(t, "UO-14", '!') == "07:34:54!UO-14");
  CHECK(lcd_top(t, "UO-14", '&') == "07:34:54&UO-14");
  CHECK(lcd_no_satellite(t, 12) == Lcd{"07:34:54", "No satellite #12"});
}

TEST_CASE("The LCD of a satellite: Az/El, or A/E/P with the MA display") {
  tracker::SatNow n;
  n.name = "UO-14";
  n.obs.time = from_civil(1993, 7, 17, 7, 34, 54);
  n.obs.look = {146.7, -62.8, 9000.0, 0.0};
  n.obs.phase256 = 119.27;
  CHECK(lcd_for(n, false) == Lcd{"07:34:54 UO-14", "Az 146.7El -62.8"});
  CHECK(lcd_for(n, true) == Lcd{"07:34:54 UO-14", "A147 E-63 P119.2"});
  n.obs.error = orbit::Sgp4Error::decayed;
  CHECK(lcd_for(n, false).bottom == "No position");
}

TEST_CASE("The AOS LED: off out of range, blinking with the track switch off, steady with it on") {
  CHECK(aos_led(false, false) == Led::off);
  CHECK(aos_led(false, true) == Led::off);
  CHECK(aos_led(true, false) == Led::blinking);
  CHECK(aos_led(true, true) == Led::on);
  const auto even = from_civil(2026, 5, 21, 12, 0, 0);
  const auto odd = even + std::chrono::seconds(1);
  CHECK(led_lit(Led::on, even));
  CHECK(led_lit(Led::on, odd));
  CHECK_FALSE(led_lit(Led::off, even));
  CHECK_FALSE(led_lit(Led::off, odd));
  CHECK(led_lit(Led::blinking, even));
  CHECK_FALSE(led_lit(Led::blinking, odd));
  CHECK(led_lit(Led::blinking, even + std::chrono::milliseconds(999)));
}

TEST_CASE("Line mode and full-screen pictures of the panel") {
  const Lcd lcd{"07:34:54 UO-14", "Az 146.7El -62.8"};
  CHECK(lcd_line(lcd, Led::blinking) == "|07:34:54 UO-14  |Az 146.7El -62.8| LED blink");
  CHECK(lcd_line(lcd, Led::on) == "|07:34:54 UO-14  |Az 146.7El -62.8| LED on");
  CHECK(lcd_line(lcd, Led::off) == "|07:34:54 UO-14  |Az 146.7El -62.8| LED off");
  const auto t = from_civil(1993, 7, 17, 7, 34, 54);  // an even second: a blinking LED is lit
  const std::vector<std::string> expected{
      "+----------------+",
      "|07:34:54 UO-14  |   AOS (*) blink",
      "|Az 146.7El -62.8|   Track switch OFF",
      "+----------------+",
  };
  CHECK(lcd_panel(lcd, Led::blinking, t, false) == expected);
  CHECK(lcd_panel(lcd, Led::blinking, t + std::chrono::seconds(1), false)[1] == "|07:34:54 UO-14  |   AOS ( ) blink");
  CHECK(lcd_panel(lcd, Led::on, t, true)[2] == "|Az 146.7El -62.8|   Track switch ON");
}

TEST_CASE("Selector keys: digits, + and - within 0 to 15, nothing else") {
  CHECK(selector_key('0', 5) == 0);
  CHECK(selector_key('7', 5) == 7);
  CHECK(selector_key('9', 0) == 9);
  CHECK(selector_key('+', 9) == 10);
  CHECK(selector_key('=', 14) == 15);
  CHECK(selector_key('+', 15) == 15);
  CHECK(selector_key('-', 10) == 9);
  CHECK(selector_key('-', 1) == 0);
  CHECK(selector_key('-', 0) == 0);
  CHECK_FALSE(selector_key('E', 3));
  CHECK_FALSE(selector_key('Q', 3));
  CHECK_FALSE(selector_key('A', 3));
  CHECK_FALSE(selector_key('\r', 3));
}

// ---- the mode ----

TEST_CASE("Standalone: the selector's satellite, LED blinking until E, then steady; the rotator follows") {
  // AO-27 (#2) is up; the track switch starts off. 30 s, E, 90 s, Q.
  testing::MenuFixture f("ExxxQ");
  f.now = from_civil(2026, 5, 21, 12, 4, 0);
  f.model.rotor_control = true;  // standalone starts with the track switch off whatever was saved
  f.term.timeouts_before_key = 30;
  std::optional<rotator::AzEl> antenna_first, antenna_before_e;
  int waits = 0;
  const auto tick = f.term.on_wait;
  f.term.on_wait = [&](std::optional<term::Duration> timeout) {
    tick(timeout);
    ++waits;
    if (waits == 1) antenna_first = f.station->antenna();
    if (waits == 29) antenna_before_e = f.station->antenna();
  };
  standalone(f.term, *f.services, 2, no_terminal_mode);
  const std::string& out = f.term.output();
  CHECK(out.find("Selector 2: AO-27, single tracking") != std::string::npos);
  CHECK(out.find("|12:04:00 AO-27  |Az") != std::string::npos);
  const auto e = out.find("Track switch ON");
  REQUIRE(e != std::string::npos);
  CHECK(out.find("| LED blink") < e);
  CHECK(out.find("| LED on", e) != std::string::npos);
  CHECK(out.find("| LED on") > e);
  CHECK(out.find("| LED off") == std::string::npos);
  CHECK(f.tracker.mode() == tracker::Mode::single);
  CHECK(f.model.rotor_control);
  // Before E the antenna had not moved from its power-on position; after 90 s it is on AO-27.
  REQUIRE(antenna_first);
  REQUIRE(antenna_before_e);
  CHECK(antenna_before_e->az == antenna_first->az);
  CHECK(antenna_before_e->el == antenna_first->el);
  const tracker::SatNow* sat = f.tracker.followed();
  REQUIRE(sat);
  REQUIRE(sat->in_range);
  const auto ant = f.station->antenna();
  REQUIRE(ant);
  CHECK(std::abs(ant->az - sat->obs.look.az_deg) < 6.0);
  CHECK(std::abs(ant->el - std::max(0.0, sat->obs.look.el_deg)) < 6.0);
}

TEST_CASE("Standalone: exact LCD line for the selector's satellite with the MA display") {
  testing::MenuFixture f("Q");
  const int db = f.model.db.selected[2];  // FO-29, up
  f.model.db.satellites[static_cast<std::size_t>(db)].radio.lcd_ma_display = true;
  const auto t0 = f.now;
  standalone(f.term, *f.services, 3, no_terminal_mode);
  const auto n = f.tracker.observe(db, t0);
  REQUIRE(n);
  REQUIRE(n->in_range);
  const std::string expected = lcd_line(lcd_for(*n, true), Led::blinking);
  CHECK(expected.find("|12:00:00 FO-29  |A") == 0);
  CHECK(f.term.output().find(expected + "\n") != std::string::npos);
}

TEST_CASE("Standalone: 0 and back toggles single and multiple tracking; moving between satellites does not") {
  // #3 FO-29; multiple tracking of #1-#2, where AO-27 (#2) is AOS.
  testing::MenuFixture f("03" "2" "03" "05" "-0+" "Q");
  f.term.timeouts_before_key = 2;
  standalone(f.term, *f.services, 3, no_terminal_mode);
  const std::string& out = f.term.output();
  const auto pos = [&](const std::string& s, std::size_t from = 0) { return out.find(s, from); };
  const auto single3 = pos("Selector 3: FO-29, single tracking");
  const auto zero1 = pos("Selector 0: terminal mode", single3);
  const auto multi3 = pos("Selector 3: FO-29, multiple tracking (normal) of #1-#2", zero1);
  const auto multi2 = pos("Selector 2: AO-27, multiple tracking (normal) of #1-#2", multi3);
  const auto zero2 = pos("Selector 0: terminal mode", multi2);
  const auto single3b = pos("Selector 3: FO-29, single tracking", zero2);
  const auto zero3 = pos("Selector 0: terminal mode", single3b);
  const auto multi5 = pos("Selector 5: SO-50, multiple tracking (normal) of #1-#2", zero3);
  const auto multi4 = pos("Selector 4: ISS, multiple tracking (normal) of #1-#2", multi5);  // '-': no toggle
  const auto zero4 = pos("Selector 0: terminal mode", multi4);
  const auto single1 = pos("Selector 1: AO-07, single tracking", zero4);  // '+' from 0: toggles
  CHECK(single3 != std::string::npos);
  CHECK(zero1 != std::string::npos);
  CHECK(multi3 != std::string::npos);
  CHECK(multi2 != std::string::npos);
  CHECK(zero2 != std::string::npos);
  CHECK(single3b != std::string::npos);
  CHECK(zero3 != std::string::npos);
  CHECK(multi5 != std::string::npos);
  CHECK(multi4 != std::string::npos);
  CHECK(zero4 != std::string::npos);
  CHECK(single1 != std::string::npos);
  // In multiple tracking the LCD shows the AOS satellite (AO-27) with '!', whatever the selector.
  CHECK(pos("!AO-27  |Az", multi3) < multi2);
  CHECK(pos(" FO-29  |Az", single3b) < zero3);
  CHECK(f.tracker.mode() == tracker::Mode::single);
  REQUIRE(f.tracker.followed());
  CHECK(f.tracker.followed()->name == "AO-07");
  CHECK(pos("| LED off", single1) != std::string::npos);  // AO-07 is down
}

TEST_CASE("Standalone: priority sub-mode shows '&'; without two satellites there is no multiple tracking") {
  testing::MenuFixture f("03Q");
  f.model.priority_mode = true;
  f.term.timeouts_before_key = 1;
  standalone(f.term, *f.services, 3, no_terminal_mode);
  CHECK(f.term.output().find("multiple tracking (priority)") != std::string::npos);
  CHECK(f.term.output().find("&AO-27  |Az") != std::string::npos);
  CHECK(f.tracker.mode() == tracker::Mode::multi);
  CHECK(f.tracker.priority());

  testing::MenuFixture g("01Q");
  g.model.db.selected.resize(1);
  g.model.db.normalise();
  standalone(g.term, *g.services, 1, no_terminal_mode);
  CHECK(g.term.output().find("Multiple tracking needs two or more satellites") != std::string::npos);
  CHECK(g.term.output().find("Selector 1: AO-07, single tracking") != std::string::npos);
  CHECK(g.tracker.mode() == tracker::Mode::single);
}

TEST_CASE("Standalone: a position past the end of the list, Enter at 0 for the menus, input closing") {
  testing::MenuFixture f("9+0\r");
  f.model.db.selected.resize(9);
  f.model.db.normalise();
  int menus_started = 0;
  standalone(f.term, *f.services, 15, [&] { ++menus_started; });
  const std::string& out = f.term.output();
  CHECK(out.find("Selector 15: no satellite in the tracking list, tracking stopped") != std::string::npos);
  CHECK(out.find("|12:00:00        |No satellite #15| LED off") != std::string::npos);
  CHECK(out.find("Selector 9: ") != std::string::npos);
  CHECK(out.find("Selector 10: no satellite") != std::string::npos);
  CHECK(menus_started == 1);
  CHECK(count(out, "Selector 0: terminal mode") == 1);

  // Enter away from 0 does nothing; the end of input leaves standalone as the menus do.
  testing::MenuFixture g("\r5");
  int started = 0;
  CHECK_THROWS_AS(standalone(g.term, *g.services, 1, [&] { ++started; }), InputClosed);
  CHECK(started == 0);
  CHECK(g.tracker.followed()->name == "SO-50");
}
