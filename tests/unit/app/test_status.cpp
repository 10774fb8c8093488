// The status document's text and problems (live/status.h) from documents written here by hand: a
// satellite always up has no LOS to print, a "pass" that never rises says so, stale elements are a
// problem, the station is named (issue 39).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "live/status.h"

using namespace tb;
using nlohmann::json;

namespace {
json document() {
  return json{{"schema", app::kStatusSchema},
              {"running", true},
              {"pid", 42},
              {"version", "test"},
              {"service", true},
              {"state_dir", "/var/lib/trakbox"},
              {"time", "2026-05-21T12:00:00.000000Z"},
              {"clock_rate", 1.0},
              {"station",
               {{"callsign", "F4ABC"}, {"lat_deg", 48.8566}, {"lon_deg", 2.3522}, {"height_m", 35.0},
                {"locator", "JN18eu"}, {"position_from_gps", false}}},
              {"tracking",
               {{"mode", "single"},
                {"priority", false},
                {"followed", "QO-100"},
                {"satellites",
                 json::array({{{"name", "QO-100"},
                               {"list_number", 1},
                               {"in_range", true},
                               {"az_deg", 160.0},
                               {"el_deg", 29.5},
                               {"pass",
                                {{"aos", "2026-05-21T12:00:00Z"},
                                 {"tca", "2026-05-21T20:00:00Z"},
                                 {"los", nullptr},
                                 {"max_el_deg", 29.6},
                                 {"in_progress", true},
                                 {"always_up", true},
                                 {"rises", true}}}}})}}},
              {"antenna",
               {{"rotor_control", true}, {"link", "ok"}, {"position", nullptr}, {"action", "point"}, {"target", nullptr}}},
              {"radios", json::array()},
              {"tracking_list",
               json::array({{{"number", 1},
                             {"name", "FO-29"},
                             {"element_age_days", 190.8},
                             {"elements_stale", true},
                             {"next_pass",
                              {{"aos", "2026-05-21T13:00:00Z"},
                               {"los", "2026-05-21T13:04:00Z"},
                               {"max_el_deg", -1.4},
                               {"always_up", false},
                               {"rises", false}}}}})},
              {"elements_refresh", {{"sources", 1}, {"last_result", ""}, {"last_failed", false}}},
              {"save", {{"last_saved", nullptr}, {"failure", nullptr}}},
              {"servers", json::array()},
              {"attached", json::array()},
              {"keyboard", nullptr},
              {"problems", json::array()}};
}
}  // namespace

TEST_CASE("status text: the station, an always-up satellite without LOS, a pass that never rises (issue 39)") {
  const std::string text = app::format_status(document());
  CHECK(text.find("  station   F4ABC 48.8566, 2.3522, 35 m, JN18eu\n") != std::string::npos);
  CHECK(text.find("#1 QO-100 az 160.0 el 29.5  always up (no AOS or LOS), el 29.6\n") != std::string::npos);
  CHECK(text.find("next pass 2026-05-21T13:00:00Z - 2026-05-21T13:04:00Z max -1.4 (never rises)") != std::string::npos);
}

TEST_CASE("status problems: a tracked satellite on elements past its orbit's age is one (issue 39)") {
  json d = document();
  CHECK(app::status_problems(d).empty());  // FO-29's stale set is listed, not tracked
  d["tracking"]["satellites"][0]["name"] = "FO-29";
  const auto problems = app::status_problems(d);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] == "elements of 1 tracked satellite(s) too old (up to 190.8 days): refresh them (menu 3-5, "
                       "--elements-url)");
  d["tracking_list"][0]["elements_stale"] = false;
  CHECK(app::status_problems(d).empty());
}

TEST_CASE("status: the logger's line, and its failing uploads a problem (issue 45)") {
  json d = document();
  d["log"] = {{"open", true}, {"count", 3}, {"queue", 1},
              {"last", {{"id", 3}, {"call", "G4XYZ"}, {"sat_name", "ISS"}, {"time_on", "2026-05-21T13:50:00Z"}}},
              {"logger", {{"kind", "cloudlog"}, {"url", "https://log.example.org"}, {"queue", 1},
                          {"last_upload", "2026-05-21T13:49:00Z"}, {"last_radio_post", nullptr},
                          {"problem", nullptr}, {"radio_problem", nullptr}}}};
  const std::string text = app::format_status(d);
  CHECK(text.find("  log       3 QSO(s), last G4XYZ ISS 2026-05-21T13:50:00Z, 1 to upload\n") != std::string::npos);
  CHECK(text.find("  logger    cloudlog https://log.example.org, last upload 2026-05-21T13:49:00Z, radio posted "
                  "never\n") != std::string::npos);
  CHECK(app::status_problems(d).empty());
  d["log"]["upload_problem"] = "QSO 3 (G4XYZ) not uploaded: HTTP 500: an empty reply; next try in 60 s";
  const auto problems = app::status_problems(d);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] == "logger: QSO 3 (G4XYZ) not uploaded: HTTP 500: an empty reply; next try in 60 s");
}

TEST_CASE("status: a parking position in the horizon mask is a problem, said in the text (issue 57)") {
  json d = document();
  d["antenna"]["parking_into_mask"] = nullptr;
  CHECK(app::status_problems(d).empty());
  const std::string w = "parking at azimuth 230.0, elevation 0.0 points into the horizon mask (25.0 there)";
  d["antenna"]["parking_into_mask"] = w;
  const auto problems = app::status_problems(d);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0] == w);
  d["problems"] = problems;
  d["healthy"] = false;
  CHECK(app::format_status(d).find("  PROBLEM   " + w) != std::string::npos);
}
