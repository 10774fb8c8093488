// The scheduled element refresh's pure part (store/refresh.h): which sets replace which, the
// schedule, the sources an operator may name, and the state document's form.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "store/refresh.h"

using namespace tb;
using namespace tb::store;

namespace {

orbit::Elements set(int number, const std::string& name, double day, double raan = 10.0) {
  orbit::Elements e;
  e.catalog_number = number;
  e.name = name;
  e.epoch_year = 2026;
  e.epoch_day = day;
  e.raan_deg = raan;
  e.mean_motion_rev_per_day = 15.5;
  return e;
}

Database three() {
  Database db;
  db.satellites.push_back(Satellite{set(25544, "ISS", 141.0), {}, {}, {}});
  db.satellites.push_back(Satellite{set(7530, "AO-07", 141.0), {}, {}, {}});
  db.satellites.push_back(Satellite{set(800123456, "NEWSAT", 141.0), {}, {}, {}});
  db.selected = {0, 2};
  db.marked = 1;
  return db;
}

}  // namespace

TEST_CASE("A refresh replaces older sets of the same catalog number and keeps the database's names") {
  Database db = three();
  const std::vector<orbit::Elements> got = {
      set(25544, "ISS (ZARYA)", 145.5, 60.0),  // newer: taken, named ISS still
      set(7530, "OSCAR 7 (AO-7)", 141.0),      // same epoch: unchanged
      set(800123456, "NEWSAT", 140.0),         // older: the database's kept
      set(99999, "OTHER", 150.0),              // not in the database: not added
      set(25544, "ISS (ZARYA)", 144.0, 50.0),  // an older duplicate: the newer of the two counts
  };
  const RefreshReport r = apply_refresh(db, got);
  REQUIRE(r.updated.size() == 1);
  CHECK(r.updated[0].name == "ISS");
  CHECK(r.updated[0].catalog_number == 25544);
  CHECK(r.updated[0].old_epoch == orbit::from_year_day(2026, 141.0));
  CHECK(r.updated[0].new_epoch == orbit::from_year_day(2026, 145.5));
  CHECK(r.unchanged == 1);
  CHECK(r.older == 1);
  CHECK(r.not_in_database == 1);
  CHECK(db.satellites.size() == 3);
  CHECK(db.satellites[0].elements.name == "ISS");
  CHECK(db.satellites[0].elements.epoch_day == 145.5);
  CHECK(db.satellites[0].elements.raan_deg == 60.0);
  CHECK(db.satellites[2].elements.epoch_day == 141.0);
  CHECK(db.selected == std::vector<int>{0, 2});
  CHECK(db.marked == 1);
  CHECK(r.summary() == "1 updated (ISS 2026-05-25 12:00), 1 unchanged, 1 older than the database's, 1 not in the database");
}

TEST_CASE("Nothing to apply changes nothing") {
  Database db = three();
  const RefreshReport r = apply_refresh(db, {});
  CHECK(r.updated.empty());
  CHECK(r.summary() == "0 updated, 0 unchanged");
  CHECK(db.satellites[0].elements.epoch_day == 141.0);
}

TEST_CASE("The schedule: never attempted, the interval, never under two hours, a clock that went back") {
  RefreshSettings s;
  CHECK_FALSE(refresh_due(s, 1'800'000'000));  // no source: never
  REQUIRE_FALSE(add_refresh_source(s, "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json"));
  CHECK(refresh_due(s, 1'800'000'000));  // never attempted
  s.last_attempt_unix = 1'800'000'000;
  CHECK_FALSE(refresh_due(s, 1'800'000'000 + 12 * 3600 - 1));
  CHECK(refresh_due(s, 1'800'000'000 + 12 * 3600));
  s.interval_hours = 0.5;  // only a hand-edited state could hold it: two hours still apply
  CHECK_FALSE(refresh_due(s, 1'800'000'000 + 2 * 3600 - 1));
  CHECK(refresh_due(s, 1'800'000'000 + 2 * 3600));
  CHECK(refresh_due(s, 1'700'000'000));  // the wall clock went back: try again
  // A failed attempt (a station started offline): again after half an hour, not the interval.
  s.interval_hours = 12.0;
  s.last_attempt_failed = true;
  CHECK(*seconds_until_refresh(s, 1'800'000'000 + 60) == 30 * 60 - 60);
  CHECK_FALSE(refresh_due(s, 1'800'000'000 + 30 * 60 - 1));
  CHECK(refresh_due(s, 1'800'000'000 + 30 * 60));
  s.last_attempt_failed = false;
  CHECK(*seconds_until_refresh(s, 1'800'000'000 + 3600) == 11 * 3600);
  CHECK(seconds_until_refresh(RefreshSettings{}, 1'800'000'000) == std::nullopt);
}

TEST_CASE("Refresh settings in the state file: the failed flag round-trips, and a file without it loads") {
  RefreshSettings s;
  REQUIRE_FALSE(add_refresh_source(s, "/srv/elements/amateur.tle"));
  s.last_attempt_unix = 1'800'000'000;
  s.last_attempt_failed = true;
  nlohmann::json j = to_json(s);
  CHECK(j["last_attempt_failed"] == true);
  CHECK(refresh_settings_from_json(j, "refresh").last_attempt_failed);
  j.erase("last_attempt_failed");   // written before the flag existed
  const RefreshSettings old = refresh_settings_from_json(j, "refresh");
  CHECK_FALSE(old.last_attempt_failed);
  CHECK(old.last_attempt_unix == 1'800'000'000);
  j["last_attempt_failed"] = "yes";
  CHECK_THROWS(refresh_settings_from_json(j, "refresh"));
}

TEST_CASE("Sources an operator may name, and the reasons for the others") {
  RefreshSettings s;
  CHECK_FALSE(add_refresh_source(s, "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json"));
  CHECK_FALSE(add_refresh_source(s, "/srv/elements/amateur.tle"));
  CHECK_FALSE(add_refresh_source(s, "file:///srv/elements/amateur.xml"));
  CHECK_FALSE(add_refresh_source(s, "/srv/elements/amateur.tle"));  // again: kept once
  CHECK(s.sources.size() == 3);
  CHECK(*add_refresh_source(s, "") == "no URL given");
  CHECK(*add_refresh_source(s, "amateur.tle") ==
        "'amateur.tle' is neither an http(s)://, ftp(s):// or file:/// URL nor an absolute file name");
  CHECK(add_refresh_source(s, "http://a b/")->find("blank") != std::string::npos);
  CHECK(add_refresh_source(s, "http://x/" + std::string(400, 'a'))->find("at most 400") != std::string::npos);
  for (int i = 0; s.sources.size() < kRefreshMaxSources; ++i) add_refresh_source(s, "/e/" + std::to_string(i));
  CHECK(*add_refresh_source(s, "/e/more") == "at most 8 element sources");
  CHECK_FALSE(check_refresh_interval(2.0));
  CHECK_FALSE(check_refresh_interval(720.0));
  CHECK(check_refresh_interval(1.5));
  CHECK(check_refresh_interval(721.0));
}

TEST_CASE("The state document's form reads back, and names a bad field") {
  RefreshSettings s;
  add_refresh_source(s, "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json");
  s.sources[0].etag = "\"v1\"";
  s.sources[0].last_modified = "Mon, 25 May 2026 12:00:00 GMT";
  s.interval_hours = 6;
  s.last_attempt_unix = 1'800'000'000;
  const RefreshSettings back = refresh_settings_from_json(to_json(s), "refresh");
  REQUIRE(back.sources.size() == 1);
  CHECK(back.sources[0].url == s.sources[0].url);
  CHECK(back.sources[0].etag == "\"v1\"");
  CHECK(back.sources[0].last_modified == s.sources[0].last_modified);
  CHECK(back.interval_hours == 6);
  CHECK(back.last_attempt_unix == 1'800'000'000);

  nlohmann::json j = to_json(s);
  j["interval_hours"] = 1;
  CHECK_THROWS_WITH(refresh_settings_from_json(j, "refresh"), doctest::Contains("refresh.interval_hours"));
  j = to_json(s);
  j["sources"][0]["url"] = "relative.tle";
  CHECK_THROWS_WITH(refresh_settings_from_json(j, "refresh"), doctest::Contains("refresh.sources[0].url"));
  j = to_json(s);
  j["sources"] = "x";
  CHECK_THROWS_WITH(refresh_settings_from_json(j, "refresh"), doctest::Contains("refresh.sources"));
}
