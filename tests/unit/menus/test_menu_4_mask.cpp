// Menu 4's horizon mask (issue 57): shown briefly, typed on one line in the reader's forms or
// `none`, a malformed one said with the reader's sentence and asked again, committed with the rest
// of menu 4; a parking position below the mask said loudly in menus 4 and 6-4, never moved.
#include <doctest/doctest.h>

#include "fixture.h"
#include "menus/6_configuration.h"

using namespace tb;

TEST_CASE("Menu 4 takes a horizon mask on one line; a bad one is said and asked again, nothing stored") {
  testing::MenuFixture f("\r\r\r\r\r\r0 0; 190 25; 400 0\r0 0 190 25 230 0 360\r");
  menus::menu_4_station_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(out.find("Horizon mask       : none  0 0; 190 25; 400 0") != std::string::npos);
  CHECK(out.find("  horizon mask pair 3: azimuth 400 is outside 0..360; not changed") != std::string::npos);
  CHECK(f.model.station.horizon_mask == "0 0 190 25 230 0 360");
  CHECK(out.find("Horizon mask: stepped, 3 steps, 0.0..25.0 deg") != std::string::npos);
  CHECK(out.find("WARNING") == std::string::npos);  // parking is off
  CHECK(f.saves == 1);
  std::size_t from = 0;
  for (std::size_t nl; (nl = out.find('\n', from)) != std::string::npos; from = nl + 1)
    if (out.substr(from, nl - from).find("ask") != std::string::npos) CHECK(nl - from <= 80);  // the mask's lines
}

TEST_CASE("Menu 4 shows the mask there is; Enter keeps it, none clears it") {
  testing::MenuFixture f("\r\r\r\r\r\r\r");
  f.model.station.horizon_mask = "0 5; 214 25; 263 5";
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.term.output().find("  now 0 5; 214 25; 263 5\n") != std::string::npos);
  CHECK(f.term.output().find("Horizon mask       : interpolated, 3 points, 5.0..25.0 deg") != std::string::npos);
  CHECK(f.model.station.horizon_mask == "0 5; 214 25; 263 5");
  testing::MenuFixture g("\r\r\r\r\r\rNONE\r");
  g.model.station.horizon_mask = "0 5; 214 25; 263 5";
  menus::menu_4_station_elements(g.term, *g.services);
  CHECK(g.model.station.horizon_mask.empty());
  CHECK(g.term.output().find("Horizon mask: none") != std::string::npos);
}

TEST_CASE("Menus 4 and 6-4 say when the parking position points into the mask, and keep it") {
  testing::MenuFixture f("\r\r\r\r\r\r0 0 190 25 230 0 360\r");
  f.model.rotator.parking_enabled = true;
  f.model.rotator.parking = {200.0, 0.0};
  menus::menu_4_station_elements(f.term, *f.services);
  CHECK(f.term.output().find("WARNING: parking at azimuth 200.0, elevation 0.0 points into the horizon mask\n"
                             "(25.0 there) (menu 6-4 sets the parking position)") != std::string::npos);
  CHECK(f.model.rotator.parking == rotator::AzEl{200.0, 0.0});
  // 6-4: parking moved out of the roof's reach, then back into it.
  auto before = f.term.output().size();
  f.term.feed("Y240\r0\rN");
  menus::menu_6_4_parking_limits(f.term, *f.services);
  CHECK(f.model.rotator.parking.az == 240.0);
  CHECK(f.term.output().find("WARNING", before) == std::string::npos);
  before = f.term.output().size();
  f.term.feed("Y210\r0\rN");
  menus::menu_6_4_parking_limits(f.term, *f.services);
  CHECK(f.model.rotator.parking.az == 210.0);
  CHECK(f.term.output().find("WARNING: parking at azimuth 210.0, elevation 0.0 points into the horizon mask\n"
                             "  (25.0 there) (menu 4 sets the mask)",
                             before) != std::string::npos);
}
