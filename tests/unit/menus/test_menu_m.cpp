// Menu M (multiple tracking) and the tracker's multi-tracking rules, on the shipped database from
// the fixture's station (27.391 N, 128.657 E). The pass times below were found with
// orbit::find_passes from that station (horizon -2.0 deg); the tests re-check each one they rely
// on, so a change of the shipped elements fails loudly here instead of silently testing nothing.
//
// Tracking list: #1 AO-07  #2 AO-27  #3 FO-29  #4 ISS  #5 SO-50 ...
#include <doctest/doctest.h>

#include <utility>

#include "fixture.h"
#include "menus/realtime_display.h"
#include "orbit/passes.h"

using namespace tb;
using testing::count;
using orbit::from_civil;

namespace {

// The followed satellite's list number when it is AOS, else 0.
int aos_number(const tracker::Tracker& t) {
  const tracker::SatNow* f = t.followed();
  return (f && f->in_range) ? f->list_number : 0;
}

// The pass of list entry `number` containing t (checked, so the scenario is what it claims).
orbit::Pass pass_at(const testing::MenuFixture& f, int number, orbit::UtcTime t) {
  const int i = f.model.db.selected[static_cast<std::size_t>(number - 1)];
  const orbit::Sgp4 sgp4(f.model.db.satellites[static_cast<std::size_t>(i)].elements);
  const auto passes = orbit::find_passes(sgp4, f.model.station.observer(), orbit::add_minutes(t, -30.0),
                                         orbit::add_minutes(t, 30.0));
  for (const auto& p : passes)
    if (p.aos <= t && t <= p.los) return p;
  FAIL("list entry #" << number << " is not up at " << orbit::format_iso8601(t));
  return {};
}

// Changes of the AOS satellite while the tracker ticks once a second over [from, to].
std::vector<std::pair<orbit::UtcTime, int>> aos_changes(testing::MenuFixture& f, orbit::UtcTime from,
                                                        orbit::UtcTime to) {
  std::vector<std::pair<orbit::UtcTime, int>> changes;
  int last = -1;
  for (f.now = from; f.now <= to; f.now += std::chrono::seconds(1)) {
    f.tracker.tick();
    if (const int n = aos_number(f.tracker); n != last) {
      changes.emplace_back(f.now, n);
      last = n;
    }
  }
  return changes;
}

// Within two seconds (the tracker ticks once a second; find_passes is precise to 0.1 s).
bool near(orbit::UtcTime a, orbit::UtcTime b) {
  return std::chrono::abs(a - b) <= std::chrono::seconds(2);
}

}  // namespace

// ---- the tracker's rules (tracker::choose_multi and Tracker::tick) ----

TEST_CASE("choose_multi: normal keeps the current one while it is in range; priority takes the lowest") {
  using tracker::choose_multi;
  const std::vector<bool> none{false, false, false};
  const std::vector<bool> two_and_three{false, true, true};
  CHECK_FALSE(choose_multi(none, std::nullopt, false));
  CHECK_FALSE(choose_multi(none, 1, true));
  CHECK(choose_multi(two_and_three, std::nullopt, false) == 1u);  // tie: the lowest number
  CHECK(choose_multi(two_and_three, std::nullopt, true) == 1u);
  CHECK(choose_multi(two_and_three, 2u, false) == 2u);            // normal: stays
  CHECK(choose_multi(two_and_three, 2u, true) == 1u);             // priority: the lowest
  CHECK(choose_multi({true, false, true}, 1u, false) == 0u);      // current gone LOS: the lowest up
}

TEST_CASE("Multi tracking: two satellites AOS at once, the lowest list number is tracked, in both modes") {
  testing::MenuFixture f;
  f.model.db.multi_count = 3;
  const auto t = from_civil(2026, 5, 21, 12, 1, 0);
  pass_at(f, 2, t);  // AO-27 up
  pass_at(f, 3, t);  // FO-29 up
  for (const bool priority : {false, true}) {
    CAPTURE(priority);
    f.now = t;
    f.tracker.track_multi(priority);
    const tracker::Decision d = f.tracker.tick();
    CHECK(aos_number(f.tracker) == 2);
    CHECK(d.antenna == tracker::Decision::Antenna::point);
    REQUIRE(f.tracker.candidates().size() == 3);
    CHECK(f.tracker.candidates()[1].in_range);
    CHECK(f.tracker.candidates()[2].in_range);
  }
}

TEST_CASE("Multi tracking: normal mode stays until LOS, priority mode switches at once") {
  // 2026-05-22 from 12:45: SO-50 (#5) is up alone; FO-29 (#3) rises while SO-50 is still up; ISS
  // (#4) rises while FO-29 is still up; after the ISS, AO-27 (#2).
  testing::MenuFixture f;
  f.model.db.multi_count = 5;
  const auto so50 = pass_at(f, 5, from_civil(2026, 5, 22, 12, 45, 0));
  const auto fo29 = pass_at(f, 3, from_civil(2026, 5, 22, 12, 50, 0));
  const auto iss = pass_at(f, 4, from_civil(2026, 5, 22, 12, 59, 0));
  const auto ao27 = pass_at(f, 2, from_civil(2026, 5, 22, 13, 10, 0));
  REQUIRE(fo29.aos < so50.los);
  REQUIRE(iss.aos < fo29.los);
  REQUIRE(iss.los < ao27.aos);
  const auto from = from_civil(2026, 5, 22, 12, 45, 0);
  const auto to = from_civil(2026, 5, 22, 13, 10, 0);

  SUBCASE("normal") {
    f.tracker.track_multi(false);
    const auto c = aos_changes(f, from, to);
    REQUIRE(c.size() == 5);
    CHECK(c[0].second == 5);  // SO-50 ...
    CHECK(c[1].second == 3);  // ... until its LOS, although FO-29 rose long before
    CHECK(near(c[1].first, so50.los));
    CHECK(c[2].second == 4);  // FO-29 until its LOS, then the ISS (up since)
    CHECK(near(c[2].first, fo29.los));
    CHECK(c[3].second == 0);  // nobody up between the ISS and AO-27
    CHECK(near(c[3].first, iss.los));
    CHECK(c[4].second == 2);
    CHECK(near(c[4].first, ao27.aos));
  }
  SUBCASE("priority") {
    f.tracker.track_multi(true);
    const auto c = aos_changes(f, from, to);
    REQUIRE(c.size() == 5);
    CHECK(c[0].second == 5);
    CHECK(c[1].second == 3);  // FO-29 preempts SO-50 the second it is AOS
    CHECK(near(c[1].first, fo29.aos));
    CHECK(c[2].second == 4);  // the ISS (#4) does not preempt FO-29 (#3)
    CHECK(near(c[2].first, fo29.los));
    CHECK(c[3].second == 0);
    CHECK(c[4].second == 2);
    CHECK(near(c[4].first, ao27.aos));
  }
}

TEST_CASE("Multi tracking: nothing in view, nothing followed; the antenna waits at the next AOS") {
  testing::MenuFixture f;
  f.model.db.multi_count = 2;  // AO-07, AO-27: next AOS 19:49:04 (AO-07)
  f.now = from_civil(2026, 5, 21, 16, 30, 0);
  f.tracker.track_multi(false);
  CHECK(f.tracker.tick().antenna == tracker::Decision::Antenna::park);
  CHECK(f.tracker.followed() == nullptr);
  // Within five minutes of AO-07's AOS the antenna goes to the AOS azimuth; AO-07 is not AOS yet.
  f.now = from_civil(2026, 5, 21, 19, 46, 0);
  const tracker::Decision d = f.tracker.tick();
  CHECK(d.antenna == tracker::Decision::Antenna::preposition);
  REQUIRE(f.tracker.followed() != nullptr);
  CHECK(f.tracker.followed()->list_number == 1);
  CHECK_FALSE(f.tracker.followed()->in_range);
  CHECK(aos_number(f.tracker) == 0);
}

// ---- menu M ----

TEST_CASE("Menu M: sub-mode prompt, LCD satellite, then the live table with '!' on the active one") {
  testing::MenuFixture f("N\r\rQ");
  f.model.db.multi_count = 3;
  f.now = from_civil(2026, 5, 21, 16, 30, 0);  // none of #1-#3 in view
  f.term.timeouts_before_key = 2;
  menus::menu_m_multiple_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("Normal or Priority mode ? [N/P] (Enter = N) N\n") != std::string::npos);
  CHECK(out.find("*** LCD display satellite ***") != std::string::npos);
  CHECK(out.find(" 1.!AO-07       2. AO-27       3. FO-29") != std::string::npos);
  CHECK(out.find("Multiple Tracking [2026/05/21] Normal mode") != std::string::npos);
  CHECK(out.find(menus::kMultiHeader1) != std::string::npos);
  CHECK(out.find(menus::kMultiHeader2) != std::string::npos);
  // The rows: nothing AOS, the LCD satellite (#1) marked, next AOS times from the tracker.
  REQUIRE(f.tracker.candidates().size() == 3);
  for (const auto& c : f.tracker.candidates()) {
    REQUIRE(c.pass);
    CHECK(out.find(menus::format_time(c.pass->aos)) != std::string::npos);
  }
  CHECK(out.find("  1.!AO-07  ") != std::string::npos);
  CHECK(out.find("  2. AO-27  ") != std::string::npos);
  CHECK(out.find("  3. FO-29  ") != std::string::npos);
  CHECK(out.find("19:49:0") != std::string::npos);  // AO-07's next AOS (19:49:04)
  CHECK(out.find("Rotor control ON   LCD |16:30:00!AO-07  |Az") != std::string::npos);
  CHECK(out.find("| LED off") != std::string::npos);
  CHECK(out.find("[Satellite:") == std::string::npos);  // no realtime display: nothing AOS
  CHECK_FALSE(f.model.priority_mode);
  CHECK(f.model.rotor_control);
  CHECK(f.tracker.mode() == tracker::Mode::multi);
  CHECK_FALSE(f.tracker.priority());
  CHECK(f.saves >= 1);
}

TEST_CASE("Menu M: priority mode marks with '&'; the choice is remembered; E toggles rotor control") {
  testing::MenuFixture f("P2\rEQ");
  f.now = from_civil(2026, 5, 21, 16, 30, 0);
  f.term.timeouts_before_key = 1;
  menus::menu_m_multiple_tracking(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find(" 1.&AO-07       2. AO-27") != std::string::npos);  // the last LCD choice marked
  CHECK(out.find("Priority mode") != std::string::npos);
  CHECK(out.find("  2.&AO-27  ") != std::string::npos);
  CHECK(out.find("LCD |16:30:00&AO-27  |") != std::string::npos);
  CHECK(f.model.priority_mode);
  CHECK(f.model.db.marked == 1);
  CHECK(f.tracker.priority());
  CHECK_FALSE(f.model.rotor_control);  // M switched it on, E off again

  // Next time Enter keeps priority mode and the LCD satellite.
  f.term.clear_output();
  f.term.feed("\r\rQ");
  menus::menu_m_multiple_tracking(f.term, *f.services);
  CHECK(f.term.output().find("Normal or Priority mode ? [N/P] (Enter = P) \n") != std::string::npos);
  CHECK(f.term.output().find(" 1. AO-07       2.&AO-27") != std::string::npos);
  CHECK(f.model.priority_mode);
  CHECK(f.model.rotor_control);
}

TEST_CASE("Menu M: Q at the prompts leaves without tracking") {
  testing::MenuFixture f("Q");
  menus::menu_m_multiple_tracking(f.term, *f.services);
  CHECK(f.tracker.mode() == tracker::Mode::off);
  testing::MenuFixture g("NQ\r");
  menus::menu_m_multiple_tracking(g.term, *g.services);
  CHECK(g.tracker.mode() == tracker::Mode::off);
}

TEST_CASE("Menu M: the realtime display takes over at AOS and the table is back after LOS") {
  // Multi tracking of #1 AO-07 and #2 AO-27: AO-27 alone from 13:38:13 to 13:53:49, AO-07 alone
  // from 19:49:04 to 20:04:07 (#1 is also the display's fallback: its LOS must still end the display).
  struct Case {
    int number;
    const char* name;
    orbit::UtcTime during;
  };
  for (const Case c : {Case{2, "AO-27", from_civil(2026, 5, 21, 13, 45, 0)},
                       Case{1, "AO-07", from_civil(2026, 5, 21, 19, 56, 0)}}) {
    const std::string name = c.name;
    CAPTURE(name);
    testing::MenuFixture f("N\r\rQ");
    f.model.db.multi_count = 2;
    const auto pass = pass_at(f, c.number, c.during);
    f.now = pass.aos - std::chrono::seconds(20);
    // The clock runs a second a wait; a minute into the pass it jumps to 15 s before LOS.
    const auto jump_at = pass.aos + std::chrono::seconds(60);
    const auto jump_to = pass.los - std::chrono::seconds(15);
    std::optional<rotator::AzEl> antenna_in_pass;
    std::optional<orbit::LookAngles> satellite_in_pass;
    f.term.on_wait = [&](std::optional<term::Duration> timeout) {
      f.now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
      if (f.now >= jump_at && f.now < jump_to) {
        antenna_in_pass = f.station->antenna();
        if (f.tracker.followed()) satellite_in_pass = f.tracker.followed()->obs.look;
        f.now = jump_to;
      }
      f.station->tick();
    };
    f.term.timeouts_before_key = 20 + 60 + 15 + 20;  // table, pass, its end, table again
    menus::menu_m_multiple_tracking(f.term, *f.services);
    const std::string& out = f.term.output();
    const std::string row = "  " + std::to_string(c.number) + ".!" + name + "  ";
    const auto first_table = out.find("Multiple Tracking [2026/05/21] Normal mode");
    const auto realtime = out.find("[Satellite:!" + name + "]");
    const auto second_table = out.find("Multiple Tracking [2026/05/21] Normal mode", first_table + 1);
    REQUIRE(first_table != std::string::npos);
    REQUIRE(realtime != std::string::npos);
    REQUIRE(second_table != std::string::npos);
    CHECK(first_table < realtime);
    CHECK(realtime < second_table);
    CHECK(out.find("============ Realtime Tracking [2026/05/21]") != std::string::npos);
    CHECK(count(out, "[Satellite:") == 1);
    // Before AOS the satellite is the one waited for (marked) and its AOS time is shown.
    CHECK(out.find(row) < realtime);
    CHECK(out.find(menus::format_time(pass.aos).substr(0, 7)) < realtime);
    // The realtime rows show AOS steady (rotor control on).
    CHECK(out.find("  AOS\n", realtime) < second_table);
    // After LOS: the table live again, nobody AOS (the '!' is back on the LCD satellite, #1).
    CHECK(out.find("  2. AO-27  ", second_table) != std::string::npos);
    CHECK(out.find("  1.!AO-07  ", second_table) != std::string::npos);
    CHECK(out.find("AOS now", second_table) == std::string::npos);
    CHECK(aos_number(f.tracker) == 0);
    // The antenna was on the satellite a minute into the pass (rotor control on in M).
    REQUIRE(antenna_in_pass);
    REQUIRE(satellite_in_pass);
    CHECK(std::abs(antenna_in_pass->az - satellite_in_pass->az_deg) < 6.0);
    CHECK(std::abs(antenna_in_pass->el - std::max(0.0, satellite_in_pass->el_deg)) < 6.0);
  }
}

TEST_CASE("Menu M: priority mode drops a satellite for a higher-priority one; normal mode does not") {
  // 2026-05-22: SO-50 (#5) up from 12:44:39; FO-29 (#3) rises at 12:47:27.
  for (const bool priority : {false, true}) {
    CAPTURE(priority);
    testing::MenuFixture f(priority ? "P\r\rQ" : "N\r\rQ");
    f.model.db.multi_count = 5;
    const auto fo29 = pass_at(f, 3, from_civil(2026, 5, 22, 12, 50, 0));
    pass_at(f, 5, fo29.aos);
    f.now = fo29.aos - std::chrono::seconds(30);
    f.term.timeouts_before_key = 60;
    menus::menu_m_multiple_tracking(f.term, *f.services);
    const std::string& out = f.term.output();
    const char m = priority ? '&' : '!';
    const auto so50 = out.find(std::string("[Satellite:") + m + "SO-50]");
    const auto fo = out.find(std::string("[Satellite:") + m + "FO-29]");
    REQUIRE(so50 != std::string::npos);
    CHECK(count(out, "Multiple Tracking [") == 0);  // AOS from the start: no table at all
    if (priority) {
      REQUIRE(fo != std::string::npos);
      CHECK(so50 < fo);
      CHECK(f.tracker.followed()->name == "FO-29");
    } else {
      CHECK(fo == std::string::npos);
      CHECK(f.tracker.followed()->name == "SO-50");
    }
  }
}

TEST_CASE("The multi table row") {
  tracker::SatNow n;
  n.list_number = 2;
  n.name = "AO-27";
  n.obs.time = from_civil(2026, 5, 21, 13, 38, 20);
  n.obs.look = {133.2, -1.52, 3012.4, 0.0};
  n.in_range = true;
  CHECK(menus::format_multi_row(n, '!') == "  2.!AO-27       133.20   -1.52   3012.4  AOS  AOS now");
  {
    // Its whole pass in progress: when it rose and the whole pass's maximum, within 80 columns.
    tracker::SatNow up = n;
    orbit::Pass whole;
    whole.aos = from_civil(2026, 5, 21, 13, 31, 2);
    whole.los = from_civil(2026, 5, 21, 13, 45, 40);
    whole.max_el_deg = 45.24;
    up.pass = whole;
    const std::string row = menus::format_multi_row(up, '!');
    CHECK(row == "  2.!AO-27       133.20   -1.52   3012.4  AOS  AOS now (13:31:02, max 45.2)");
    CHECK(row.size() < 80);
    up.pass->up_at_start = true;   // the rest of it from a search inside it: no AOS to tell
    CHECK(menus::format_multi_row(up, '!') == "  2.!AO-27       133.20   -1.52   3012.4  AOS  AOS now");
  }
  n.in_range = false;
  n.obs.look.el_deg = -20.0;
  orbit::Pass p;
  p.aos = from_civil(2026, 5, 21, 15, 2, 7);
  n.pass = p;
  CHECK(menus::format_multi_row(n, ' ') == "  2. AO-27       133.20  -20.00   3012.4       15:02:07");
  // An AOS on another UTC day than the row's time carries its date (issue 47).
  n.pass->aos = from_civil(2026, 5, 22, 0, 4, 5);
  CHECK(menus::format_multi_row(n, ' ') == "  2. AO-27       133.20  -20.00   3012.4       2026/05/22 00:04:05");
  CHECK(menus::aos_text(from_civil(2026, 5, 21, 23, 59, 59), from_civil(2026, 5, 21, 0, 0, 0)) == "23:59:59");
  CHECK(menus::aos_text(from_civil(2026, 6, 1, 0, 0, 0), from_civil(2026, 5, 31, 23, 59, 59)) == "2026/06/01 00:00:00");
  CHECK(menus::format_multi_row(n, ' ').size() <= 79);
  n.pass->aos = p.aos;
  n.pass.reset();
  CHECK(menus::format_multi_row(n, '&') == "  2.&AO-27       133.20  -20.00   3012.4       none in 24h");
  // The headers line up with the row's columns.
  const std::string row = menus::format_multi_row(n, ' ');
  CHECK(std::string(menus::kMultiHeader1).find("Azim.") + 5 == row.find("133.20") + 6);
  CHECK(std::string(menus::kMultiHeader2).find("Km") + 2 == row.find("3012.4") + 6);
}
