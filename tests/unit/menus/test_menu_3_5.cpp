// Menu 3-5, trakbox's own: the element sources, the refresh interval, a refresh now and its
// failure, and the SatNOGS transmitters taken into the freq/mode records.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "fixture.h"
#include "tracker/elements_refresh.h"
#include "radio/freqmode.h"

using namespace tb;
using testing::check_shows;
using testing::db_json;
using testing::has;

namespace {


}  // namespace

TEST_CASE("3-5 adds and deletes element sources, sets the interval, and refuses what cannot be used") {
  testing::MenuFixture f(
      "A\rceletrak.tle\r"                                                       // not a URL: refused
      "A\rhttps://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json\r"
      "A\r/srv/elements/extra.tle\r"
      "I\r1\r6\r"                                                               // 1 h refused, then 6
      "D\r3\rD\r1\r"                                                            // 3 is not listed; delete 1
      "R\rQ\r");
  menus::menu_3_5_refresh(f.term, *f.services);
  const std::string& out = f.term.output();
  check_shows(out, {
      "======= ELEMENT REFRESH =======\n No element source: the database is refreshed only by hand (3-3).\n"
      " Every 12.0 hours (at least 2).\n",
      "  Not added: 'celetrak.tle' is neither an http(s)://, ftp(s):// or file:/// URL nor an absolute file name",
      "  1 is out of range: expected 2 to 720",
      "  '3': enter a number from 1 to 2",
      " 1. /srv/elements/extra.tle\n Every 6.0 hours (at least 2).\n",
  });
  const store::RefreshSettings& r = f.model.refresh;
  REQUIRE(r.sources.size() == 1);
  CHECK(r.sources[0].url == "/srv/elements/extra.tle");
  CHECK(r.interval_hours == 6.0);
  // What was saved reads back the same.
  const auto back = store::model_from_json(store::to_json(f.model));
  CHECK(back.refresh.sources.size() == 1);
  CHECK(back.refresh.interval_hours == 6.0);
}

TEST_CASE("3-5 S merges the SatNOGS transmitters from a file into the modes, filling what the operator left empty") {
  const std::string list =
      (std::filesystem::temp_directory_path() / ("trakbox-satnogs-" + std::to_string(::getpid()) + ".json")).string();
  {
    std::ofstream out(list);
    out << R"([{"description":"Mode U/V linear","alive":true,"status":"active","type":"Transponder",
               "uplink_low":145935000,"uplink_high":145995000,"downlink_low":435610000,"downlink_high":435670000,
               "mode":"SSB","invert":true,"norad_cat_id":44909},
              {"description":"FM voice","alive":true,"status":"active","type":"Transceiver",
               "uplink_low":145990000,"downlink_low":437800000,"mode":"FM","invert":false,"norad_cat_id":25544}])";
  }
  testing::MenuFixture f;
  const int rs44 = *f.model.db.find("RS-44");
  f.model.db.satellites[static_cast<std::size_t>(rs44)].radio = {};  // the operator has nothing for RS-44
  const radio::SatelliteRadio iss_before = f.model.db.satellites[static_cast<std::size_t>(*f.model.db.find("ISS"))].radio;
  f.term.feed("S\r" + list + "\rN\rQ\r");
  menus::menu_3_5_refresh(f.term, *f.services);
  const std::string& out = f.term.output();
  // RS-44's chosen mode (SSB) emptied: each field filled from the list; the ISS's FM as shipped agrees.
  CHECK(has(out, "  RS-44 SSB downlink: 435.640 MHz from satnogs\n"));
  CHECK(has(out, "  RS-44 SSB passbands: 435.610-435.670 / 145.935-145.995 MHz from satnogs\n"));
  CHECK(has(out, "  RS-44 SSB inverting: inverting from satnogs\n"));
  CHECK(has(out, "  0 added, 6 updated, 0 conflicts (yours kept), 1 unchanged; 0 transmitters not alive or not active, not offered\n"));
  const radio::SatelliteRadio& r = f.model.db.satellites[static_cast<std::size_t>(rs44)].radio;
  CHECK(r.downlink_hz == 435'640'000);
  CHECK(r.uplink_mode == radio::Mode::lsb);
  CHECK(f.model.db.satellites[static_cast<std::size_t>(*f.model.db.find("ISS"))].radio == iss_before);
  CHECK(f.saves > 0);
  std::filesystem::remove(list);

  testing::MenuFixture g;
  const std::string before = db_json(g.model);
  g.term.feed("S\r/nonexistent/transmitters.json\rY\rQ\r");
  menus::menu_3_5_refresh(g.term, *g.services);
  CHECK(has(g.term.output(), "  Nothing changed: cannot read /nonexistent/transmitters.json\n"));
  CHECK(db_json(g.model) == before);
}

TEST_CASE("3-5 says a refresh running again together with the last one's failure (issue 39)") {
  testing::MenuFixture f;
  // The refresh posts its results to the loop: here a queue the test runs by hand.
  std::mutex mu;
  std::vector<std::function<void()>> posted;
  tracker::ElementsRefresh refresh(
      f.owner,
      [&](std::function<void()> fn) {
        std::lock_guard<std::mutex> lock(mu);
        posted.push_back(std::move(fn));
      },
      [] {});
  f.station->set_refresh(&refresh);
  f.model.refresh.sources = {store::RefreshSource{"file:///nonexistent/trakbox/amateur.tle", "", ""}};
  auto run_posted = [&] {
    for (int i = 0; i < 500; ++i) {
      std::vector<std::function<void()>> due;
      {
        std::lock_guard<std::mutex> lock(mu);
        due.swap(posted);
      }
      for (auto& fn : due) fn();
      if (!refresh.running()) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    FAIL("the refresh did not finish");
  };
  REQUIRE_FALSE(refresh.refresh_now(1'800'000'000));
  run_posted();
  REQUIRE(refresh.last_failed());
  REQUIRE_FALSE(refresh.refresh_now(1'800'000'100));
  REQUIRE(refresh.running());
  f.term.feed("Q\r");
  menus::menu_3_5_refresh(f.term, *f.services);
  CHECK(has(f.term.output(), " Refresh: running now; the last one FAILED "));
  CHECK_FALSE(has(f.term.output(), "Last refresh: running now"));
  run_posted();
  f.station->set_refresh(nullptr);
}
