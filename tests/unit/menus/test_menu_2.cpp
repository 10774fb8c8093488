// Menu 2: Display Schedule — the manual's transcript on the shipped satellites, rows checked against
// SGP4 + observe computed here, paging, the start-time forms, the time step, a failed propagation.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "fixture.h"
#include "orbit/observe.h"
#include "orbit/passes.h"

using namespace tb;
using testing::count;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Table rows: lines that start with a date.
std::vector<std::string> rows_of(const std::string& text) {
  std::vector<std::string> rows;
  for (const auto& l : lines_of(text))
    if (l.size() > 20 && l[4] == '/' && l[7] == '/' && l[13] == ':' && l.find("Starting") == std::string::npos)
      rows.push_back(l);
  return rows;
}

// The row for satellite db_index at t, computed here from the elements (not through the menus).
std::string expected_row(const testing::MenuFixture& f, int db_index, orbit::UtcTime t) {
  const auto& sat = f.model.db.satellites[static_cast<std::size_t>(db_index)];
  const orbit::Sgp4 sgp4(sat.elements);
  const orbit::Observation o = orbit::observe(sgp4, f.model.station.observer(), t);
  REQUIRE(o.ok());
  const double doppler =
      sat.radio.downlink_hz > 0 ? orbit::doppler_shift_hz(double(sat.radio.downlink_hz), o.look.range_rate_km_s) : 0.0;
  const auto c = orbit::to_civil(t);
  char el[16];
  std::snprintf(el, sizeof el, "%4.1f", o.look.el_deg);
  char buf[160];
  std::snprintf(buf, sizeof buf, "%04d/%02d/%02d %02d:%02d:%02d %6.1f/%-5s %5.1f %+7ld", c.year, c.month, c.day, c.hour,
                c.minute, static_cast<int>(c.second), o.look.az_deg, el, std::floor(o.phase256), std::lround(doppler));
  return buf;
}

}  // namespace

TEST_CASE("Menu 2: the manual's example — pick #2, a start time, a 60-minute step, a screenful, Q") {
  testing::MenuFixture f("2\r26/05/21 15:09:03\r60\r0\rQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("     *** Tracking object satellite ***\n 1.*AO-07") != std::string::npos);
  CHECK(out.find("     Select :2\n") != std::string::npos);
  CHECK(out.find("2026/05/21 12:00:00 Starting Day/Time ? [YY/MM/DD HH:MM:SS] Day of the Year [T] >26/05/21 15:09:03\n"
                 "Time Step Min [1]:60\nSec [0]:0\n") != std::string::npos);
  CHECK(out.find("DATE       TIME      AZ/EL       Phase Doppler\n") != std::string::npos);
  CHECK(out.find("        - 'Q' for abort 'S' for scroll") != std::string::npos);
  CHECK(count(out, "DATE       TIME") == 1);

  // A screenful: 24 rows less the header and the prompt; each row as computed here.
  const auto rows = rows_of(out);
  REQUIRE(rows.size() == 22);
  const int iso = f.model.db.selected[1];
  CHECK(f.model.db.satellites[static_cast<std::size_t>(iso)].name() == "AO-27");
  for (int k = 0; k < 22; ++k) {
    const auto t = orbit::from_civil(2026, 5, 21, 15, 9, 3) + std::chrono::hours(k);
    CHECK(rows[static_cast<std::size_t>(k)] == expected_row(f, iso, t));
    // And the tracker agrees on what the columns hold.
    const auto n = f.tracker.observe(iso, t);
    REQUIRE(n);
    char azel[32];
    std::snprintf(azel, sizeof azel, "%.1f/", n->obs.look.az_deg);
    CHECK(rows[static_cast<std::size_t>(k)].find(azel) != std::string::npos);
  }
  CHECK(rows.front().substr(0, 20) == "2026/05/21 15:09:03 ");
  CHECK(rows.back().substr(0, 20) == "2026/05/22 12:09:03 ");
  // The antennas are not moved and nothing starts tracking.
  CHECK(f.tracker.mode() == tracker::Mode::off);
  CHECK_FALSE(f.model.rotor_control);
  CHECK(f.saves == 0);
}

TEST_CASE("Menu 2: the row layout follows the header's columns") {
  testing::MenuFixture f("\r26/05/21 12:00:00\r\r\rQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const auto rows = rows_of(f.term.output());
  REQUIRE(!rows.empty());
  const std::string header = "DATE       TIME      AZ/EL       Phase Doppler";
  const std::string& r = rows.front();
  CHECK(r.size() == header.size());
  CHECK(r[26] == '/');  // azimuth right-aligned before the '/', under "AZ/EL"
  CHECK(r.substr(0, 20) == "2026/05/21 12:00:00 ");
  // Phase ends under "Phase", Doppler (signed Hz) ends under "Doppler".
  CHECK(r[37] != ' ');
  CHECK((r[39] == ' ' || r[39] == '+' || r[39] == '-'));
  CHECK(r.find_first_of("+-", 38) != std::string::npos);
}

TEST_CASE("Menu 2: S shows the next screenful, Q returns") {
  testing::MenuFixture f("1\r26/05/21 12:00:00\r\r30\rSSQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(count(out, "DATE       TIME      AZ/EL       Phase Doppler") == 3);
  CHECK(count(out, "- 'Q' for abort 'S' for scroll") == 3);
  const auto rows = rows_of(out);
  REQUIRE(rows.size() == 66);
  // Step 1 min 30 s, continuous across the pages.
  for (int k = 0; k < 66; ++k)
    CHECK(rows[static_cast<std::size_t>(k)] ==
          expected_row(f, 0, orbit::from_civil(2026, 5, 21, 12, 0, 0) + std::chrono::seconds(90 * k)));
}

TEST_CASE("Menu 2: other keys at the page prompt are ignored; Q alone ends") {
  testing::MenuFixture f("1\r26/05/21 12:00:00\r\r\rxQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  CHECK(count(f.term.output(), "- 'Q' for abort 'S' for scroll") == 2);
  CHECK(rows_of(f.term.output()).size() == 22);
}

TEST_CASE("Menu 2: Enter starts now with a 1 minute step") {
  testing::MenuFixture f("\r\r\r\rQ");
  f.now = orbit::from_civil(2026, 5, 21, 12, 0, 0) + std::chrono::milliseconds(400);
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("     Select :\n") != std::string::npos);  // Enter: the marked one (#1, AO-07)
  CHECK(out.find("2026/05/21 12:00:00 Starting Day/Time ?") != std::string::npos);
  const auto rows = rows_of(out);
  REQUIRE(rows.size() == 22);
  CHECK(rows[0] == expected_row(f, 0, orbit::from_civil(2026, 5, 21, 12, 0, 0)));
  CHECK(rows[1] == expected_row(f, 0, orbit::from_civil(2026, 5, 21, 12, 1, 0)));
}

TEST_CASE("Menu 2: the day-of-year form (T), in the clock's year; the manual's 564.17270 is refused") {
  // 141.5 is 21 May 2026, 12:00:00; .17270 of a day is 04:08:41.
  testing::MenuFixture f("\r564.17270\r141.17270\r\r\rQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("day 564.17270 is not in 2026: expected 1 to 365.99999") != std::string::npos);
  CHECK(count(out, "Starting Day/Time ?") == 2);
  const auto rows = rows_of(out);
  REQUIRE(!rows.empty());
  CHECK(rows[0].substr(0, 19) == "2026/05/21 04:08:41");

  testing::MenuFixture g("\r2026/05/21 12:00:00\r\r\rQ");  // the four-digit year the prompt shows
  menus::menu_2_display_schedule(g.term, *g.services);
  CHECK(rows_of(g.term.output()).at(0).substr(0, 19) == "2026/05/21 12:00:00");

  testing::MenuFixture h("\r26/13/01 00:00:00\rsoon\r1\r\r\rQ");
  menus::menu_2_display_schedule(h.term, *h.services);
  CHECK(h.term.output().find("'26/13/01 00:00:00' is not a date and time") != std::string::npos);
  CHECK(h.term.output().find("'soon' is not understood") != std::string::npos);
  CHECK(rows_of(h.term.output()).at(0).substr(0, 19) == "2026/01/01 00:00:00");
}

TEST_CASE("Menu 2: a zero time step is refused; bad numbers are asked again") {
  testing::MenuFixture f("\r26/05/21 12:00:00\r0\r0\rx\r0\r61\r45\rQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("The time step must be at least 1 second.") != std::string::npos);
  CHECK(out.find("'x': expected a whole number from 0 to 10080") != std::string::npos);
  CHECK(out.find("'61': expected a whole number from 0 to 59") != std::string::npos);
  const auto rows = rows_of(out);
  REQUIRE(rows.size() == 22);
  CHECK(rows[1].substr(11, 8) == "12:00:45");
}

TEST_CASE("Menu 2: Doppler is on F1; +0 without a downlink frequency") {
  testing::MenuFixture f("\r26/05/21 12:00:00\r\r\rQ");
  f.model.db.satellites[0].radio.downlink_hz = 0;
  menus::menu_2_display_schedule(f.term, *f.services);
  for (const auto& r : rows_of(f.term.output())) CHECK(r.substr(r.size() - 7) == "     +0");
}

TEST_CASE("Menu 2: a propagation failure ends the table with one line naming the error") {
  // ISS (#4) with an absurd drag term decays within days.
  testing::MenuFixture f("4\r26/05/21 12:00:00\r1440\r\rQ");
  const int iss = f.model.db.selected[3];
  f.model.db.satellites[static_cast<std::size_t>(iss)].elements.bstar = 0.9;
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string& out = f.term.output();
  const auto lines = lines_of(out);
  REQUIRE(!lines.empty());
  CHECK(lines.back().find("no position: ") != std::string::npos);
  CHECK(lines.back().find("(SGP4 error ") != std::string::npos);
  CHECK(lines.back().find("end of the schedule") != std::string::npos);
  CHECK(rows_of(out).size() < 22);
  CHECK(out.find("'Q' for abort") == std::string::npos);  // the table ended: no page prompt
}

TEST_CASE("Menu 2: Q at the list returns at once; input closing throws") {
  testing::MenuFixture f("Q\r");
  menus::menu_2_display_schedule(f.term, *f.services);
  CHECK(f.term.output().find("Starting Day/Time") == std::string::npos);

  testing::MenuFixture g("1\r26/05/21 12:00:00\r\r\r");
  CHECK_THROWS_AS(menus::menu_2_display_schedule(g.term, *g.services), menus::InputClosed);
}

namespace {

// The ISS's pass at or after `from` as the orbit layer finds it (orbit::next_pass, checked against
// Skyfield in tests/unit/orbit), in the words of menu 2's P.
std::string expected_pass_line(const testing::MenuFixture& f, orbit::UtcTime from) {
  const int iss = f.model.db.selected[3];
  const auto& sat = f.model.db.satellites[static_cast<std::size_t>(iss)];
  REQUIRE(sat.name() == "ISS");
  const orbit::Sgp4 sgp4(sat.elements);
  orbit::PassOptions po;
  po.precision_s = 1.0;
  const auto p = orbit::next_pass(sgp4, f.model.station.observer(), from, 1.0, po);
  REQUIRE(p);
  char buf[200];
  const auto hms = [](orbit::UtcTime t) {
    const auto c = orbit::to_civil(t);
    char b[16];
    std::snprintf(b, sizeof b, "%02d:%02d:%02d", c.hour, c.minute, static_cast<int>(c.second));
    return std::string(b);
  };
  std::snprintf(buf, sizeof buf, "ISS: pass 2026/05/21 AOS %s az %.1f, max el %.1f at %s az %.1f, LOS %s az %.1f",
                hms(p->aos).c_str(), p->aos_az_deg, p->max_el_deg, hms(p->tca).c_str(), p->tca_az_deg,
                hms(p->los).c_str(), p->los_az_deg);
  return buf;
}

}  // namespace

TEST_CASE("Menu 2: P at the prompt says the page's pass: the next one, or the one in progress from its AOS") {
  // From 12:00 the next pass (AOS 12:09:09); from 12:12, in the middle of it, the same pass.
  for (const char* start : {"26/05/21 12:00:00", "26/05/21 12:12:00"}) {
    testing::MenuFixture f(std::string("4\r") + start + "\r1\r0\rPQ");
    menus::menu_2_display_schedule(f.term, *f.services);
    const std::string line = "        - 'Q' for abort 'S' for scroll P\n  " +
                             expected_pass_line(f, orbit::from_civil(2026, 5, 21, 12, 0, 0)) + "\n";
    CHECK(f.term.output().find(line) != std::string::npos);
    CHECK(f.term.output().find("AOS 12:09:09") != std::string::npos);
    CHECK(f.term.graphics_count() == 0);   // line mode: words only
  }
  // From 12:20, after its LOS: the next pass.
  testing::MenuFixture f("4\r26/05/21 12:20:00\r1\r0\rPQ");
  menus::menu_2_display_schedule(f.term, *f.services);
  const std::string next = expected_pass_line(f, orbit::from_civil(2026, 5, 21, 12, 20, 0));
  CHECK(next.find("AOS 12:09:09") == std::string::npos);
  CHECK(f.term.output().find("  " + next + "\n") != std::string::npos);
}

TEST_CASE("Menu 2: P on a full screen draws the pass's sky plot until a key, then the page again") {
  testing::MenuFixture f("4\r26/05/21 12:00:00\r1\r0\rP Q");
  f.term.set_full_screen(true);
  menus::menu_2_display_schedule(f.term, *f.services);
  REQUIRE(f.term.graphics_count() == 1);
  const term::Graphics& g = f.term.last_graphics();
  CHECK(g.title == "ISS  pass 12:09:09-12:15:35");
  REQUIRE(g.pass_track.size() > 10);
  const std::string said = expected_pass_line(f, orbit::from_civil(2026, 5, 21, 12, 0, 0));
  double aos_az = 0.0;
  REQUIRE(std::sscanf(said.c_str() + said.find(" az ") + 4, "%lf", &aos_az) == 1);
  CHECK(std::abs(g.pass_track.front().az_deg - aos_az) < 0.5);   // the track starts at AOS
  CHECK(std::abs(g.pass_track.front().el_deg - orbit::kAosThresholdDeg) < 0.05);   // at the AOS elevation
  const std::string& out = f.term.output();
  CHECK(out.find(said + "\n        - any key to return to the schedule ") != std::string::npos);
  CHECK(count(out, "DATE       TIME") == 2);   // the page shown again after the key
  CHECK_FALSE(f.term.graphics_shown());        // and the plot cleared away
}
