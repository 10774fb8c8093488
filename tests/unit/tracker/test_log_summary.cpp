// The log's part of the status document (tracker/log_json.h's log_summary) on a simulated station:
// the logger's fields while one is configured, the queue counted from the logbook, the failing
// uploads as upload_problem; no logger, no such fields.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "support/sim_station.h"
#include "support/temp_logbook.h"
#include "tracker/log_json.h"
#include "tracker/operations.h"

using namespace tb;

namespace {
struct SummaryStation : testing::StationFixture, testing::TempLogbook {
  SummaryStation() {
    build_station();
    open_logbook(*station, "logsummary");
    station->tick();
  }
};
}  // namespace

TEST_CASE("log_summary: the logger while one is configured, its problem, the queue") {
  SummaryStation s;
  REQUIRE(s.logging.book);
  REQUIRE(tracker::StationOps(*s.station).track("RS-44").ok());
  s.run(1);
  tracker::LogOps ops(*s.station);
  nlohmann::json j = tracker::log_summary(ops);
  CHECK_FALSE(j.contains("logger"));
  s.logging.upload = true;
  s.logging.logger = tracker::LoggerStatus{"wavelog", "https://wl.example.org", "", "2026-05-21T12:00:01Z", {}, {}};
  tracker::LogRequest r;
  r.call = "W1AW";
  REQUIRE(ops.log(r).ok());
  j = tracker::log_summary(ops);
  CHECK(j["queue"] == 1);
  CHECK(j["logger"] == nlohmann::json{{"kind", "wavelog"}, {"url", "https://wl.example.org"}, {"queue", 1},
                                       {"last_upload", nullptr}, {"last_radio_post", "2026-05-21T12:00:01Z"},
                                       {"problem", nullptr}, {"radio_problem", nullptr}});
  CHECK_FALSE(j.contains("upload_problem"));
  s.logging.logger->problem = "QSO 1 (W1AW) not uploaded: HTTP 401: missing api key; next try in 30 s";
  j = tracker::log_summary(ops);
  CHECK(j["upload_problem"] == "QSO 1 (W1AW) not uploaded: HTTP 401: missing api key; next try in 30 s");
  CHECK(j["logger"]["problem"] == j["upload_problem"]);
}
