// What a Satrak unit keeps: a setting whose save failed (disk full, issue 14, defect 3) is not
// acknowledged: answered ERR,12 (internal), the change held in memory until the next start, queries
// still answered, and acknowledged again once a save succeeds; LOAD_IMAGE's state document,
// validated as a whole before it replaces anything; the settings' JSON.
#include <doctest/doctest.h>

#include "fixture.h"

#include <nlohmann/json.hpp>

#include "satrak/settings.h"
#include "store/state_file.h"

using namespace satrak_test;  // with std::chrono_literals and satrak::Error

TEST_CASE("A setting that could not be saved is answered ERR,12, not OK") {
  Acu acu(kT0);
  acu.save_error = "cannot write .trakbox-state.json.tmp-1: No space left on device";
  CHECK(acu.cmd("REDUCTION=,4000,4000") == err("REDUCTION=", Error::internal));
  CHECK(acu.cmd("REDUCTION?") == "REDUCTION?,4000,4000");  // in memory, as the log says
  CHECK(acu.cmd("GPS_SETTINGS=,0,41.02N,29.17E") == err("GPS_SETTINGS=", Error::internal));
  CHECK(acu.cmd("VERSION?").rfind("VERSION?,", 0) == 0);  // queries do not save and still answer
  const int failed_saves = acu.saves;
  CHECK(failed_saves >= 2);

  acu.save_error.reset();  // space again
  CHECK(acu.cmd("REDUCTION=,2000,2000") == "REDUCTION=,OK");
  CHECK(acu.saves == failed_saves + 1);
}

TEST_CASE("A refused command stays refused for its own reason when the disk is full too") {
  Acu acu(kT0);
  acu.save_error = "disk full";
  CHECK(acu.cmd("REDUCTION=,62.5,0") == err("REDUCTION=", Error::out_of_range));
}

TEST_CASE("LOAD_IMAGE: a state document, validated as a whole before it replaces anything") {
  Acu acu(kT0);
  CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,0");
  // An image made the way the program saves its state: the Model plus data["satrak"].
  store::Model m = acu.model;
  m.station.callsign = "IMAGE";
  m.station.lat_deg = 10.5;
  m.rotator.az_dead_band = 5;
  m.db.satellites.resize(3);
  m.db.normalise();
  satrak::Settings s;
  s.north_offset_deg = 7.5;
  s.tle_file = "amateur.txt";
  s.satellite = "AO-07";
  nlohmann::json data = store::to_json(m);
  data["satrak"] = satrak::to_json(s);
  {
    store::StateFile sf(acu.dir.path / "images");
    std::string e;
    REQUIRE(sf.save(data, e));
    fs::rename(sf.path(), acu.dir.path / "images" / "sysImage.json");
  }
  // Broken copies: bad checksum, bad field, not JSON.
  {
    auto doc = nlohmann::json::parse(read_file(acu.dir.path / "images" / "sysImage.json"));
    auto bad = doc;
    bad["data"]["station"]["callsign"] = "CHANGED";
    write_file(acu.dir.path / "images" / "badsum.json", bad.dump());
    auto bad2 = doc;
    bad2["data"]["satrak"]["north_offset_deg"] = 999;
    char sum[9];
    std::snprintf(sum, sizeof sum, "%08x", store::crc32(bad2["data"].dump()));
    bad2["checksum"] = sum;
    write_file(acu.dir.path / "images" / "badfield.json", bad2.dump());
    auto bad3 = doc;
    bad3["data"]["rotator"]["az_dead_band"] = -1;
    std::snprintf(sum, sizeof sum, "%08x", store::crc32(bad3["data"].dump()));
    bad3["checksum"] = sum;
    write_file(acu.dir.path / "images" / "badmodel.json", bad3.dump());
    write_file(acu.dir.path / "images" / "junk.json", "{not json");
  }
  const std::string callsign = acu.model.station.callsign;
  for (const char* f : {"badsum.json", "badfield.json", "badmodel.json", "junk.json"}) {
    CAPTURE(f);
    CHECK(acu.cmd(std::string("LOAD_IMAGE=,") + f) == "LOAD_IMAGE=,ERR,11");
    CHECK(acu.model.station.callsign == callsign);
    CHECK(acu.unit->settings().north_offset_deg == 0.0);
    CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,2");
  }
  CHECK(acu.cmd("LOAD_IMAGE=,none.json") == "LOAD_IMAGE=,ERR,9");
  CHECK(acu.saves == 0);

  CHECK(acu.cmd("LOAD_IMAGE=,sysImage.json") == "LOAD_IMAGE=,OK");
  CHECK(acu.cmd("LOAD_IMAGE?") == "LOAD_IMAGE?,1");
  CHECK(acu.model.station.callsign == "IMAGE");
  CHECK(acu.model.db.satellites.size() == 3);
  CHECK(acu.loop->rotator().config().az_dead_band == 5);  // the station runs on it
  CHECK(acu.unit->settings().north_offset_deg == 7.5);
  CHECK(acu.unit->elements()->catalog_number == 7530);
  CHECK(acu.cmd("GPS_SETTINGS?") == "GPS_SETTINGS?,0,10.5000N,110.7780W");
  CHECK(acu.saves == 1);
}

TEST_CASE("Settings JSON: round trip, and every bad field named") {
  satrak::Settings s;
  s.time_offset_ms = -1500;
  s.az_offset_deg = 1.25;
  s.window = satrak::TrackWindow{kT0, kT0 + 300s};
  s.auto_track = true;
  s.tle_file = "iridium.txt";
  s.satellite = "IRIDIUM 70 [+]";
  s.source = satrak::TleSource::ftp;
  s.ftp = {"10.0.1.2", "user", "secret", 2121, "iridium.txt", "IRIDIUM 70 [+]", 1.0, satrak::ErrorAction::stop_tracking};
  s.reduction_x = 4000;
  const auto j = satrak::to_json(s);
  CHECK(satrak::settings_from_json(j) == s);
  CHECK(satrak::settings_from_json(nlohmann::json::parse(j.dump())) == s);
  CHECK(satrak::settings_from_json(satrak::to_json(satrak::Settings{})) == satrak::Settings{});
  auto expect_throw = [&](const char* key, nlohmann::json value, const char* needle) {
    auto bad = j;
    bad[key] = std::move(value);
    try {
      satrak::settings_from_json(bad);
      FAIL("accepted " << key);
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
    }
  };
  expect_throw("north_offset_deg", 400, "satrak.north_offset_deg");
  expect_throw("tle_file", "../x", "satrak.tle_file");
  expect_throw("auto_track", 1, "satrak.auto_track");
  expect_throw("window", nlohmann::json{{"start", "2026-05-21T12:00:00Z"}, {"stop", "2026-05-21T11:00:00Z"}}, "satrak.window");
  expect_throw("satellite", "A,B", "satrak.satellite");
  auto missing = j;
  missing.erase("min_elevation_deg");
  CHECK_THROWS_WITH_AS(satrak::settings_from_json(missing), "satrak.min_elevation_deg: missing", std::runtime_error);
}
