// The logbook's endpoints (web/api_log.h) through web::Api on the simulated station: a QSO from the
// pass, the refusals (4xx with a sentence naming the field), edit and delete, the ADIF export.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/sim_station.h"
#include "support/temp_logbook.h"
#include "test_paths.h"
#include "tracker/log_ops.h"
#include "tracker/operations.h"
#include "web/api.h"

using namespace tb;
using json = nlohmann::json;

namespace {
struct LogWeb : testing::StationFixture, testing::TempLogbook {
  web::Access access{web::AccessOptions{}, nullptr};
  std::unique_ptr<web::Api> api;
  LogWeb() {
    build_station();
    open_logbook(*station, "weblog");
    web::ApiHooks hooks;
    hooks.status = [] { return json{{"running", true}, {"version", "9.9"}}; };
    hooks.wall_now_unix = [] { return std::int64_t{1796161460}; };
    api = std::make_unique<web::Api>(*station, access, hooks);
    station->tick();
  }
  web::Response request(const std::string& method, const std::string& target, const std::string& body = "") {
    web::Request r;
    r.method = method;
    r.target = target;
    r.host = "127.0.0.1:8073";
    r.peer = "127.0.0.1";
    r.content_type = "application/json";
    r.body = body;
    return api->handle(r, std::chrono::steady_clock::time_point(std::chrono::hours(1000)));
  }
};
}  // namespace

TEST_CASE("web: POST /api/v1/log stores the pass's QSO; GET lists it; edit keeps a version; delete marks") {
  LogWeb w;
  REQUIRE(tracker::StationOps(*w.station).track("ISS").ok());
  w.run(1);
  auto r = w.request("POST", "/api/v1/log", R"({"call":"w1aw","grid":"fn31","rst_sent":"59"})");
  REQUIRE(r.status == 200);
  json j = json::parse(r.body);
  CHECK(j["qso"]["call"] == "W1AW");
  CHECK(j["qso"]["sat_name"] == "ISS");
  CHECK(j["qso"]["lotw_name"] == "ARISS");
  CHECK(j["qso"]["uplink_hz"] == 145990000);
  CHECK(j["qso"]["downlink_hz"] == 437800000);
  CHECK(j["qso"]["sat_mode"] == "V/U");
  CHECK(j["qso"]["time_on"] == "2026-05-21T12:00:01Z");
  CHECK(j["qso"]["source"] == "web");
  CHECK(w.logging.book->count() == 1);

  r = w.request("POST", "/api/v1/log", R"({"call":"W1AW","grid":"FN3"})");
  CHECK(r.status == 409);
  CHECK(json::parse(r.body)["error"].get<std::string>().rfind("grid: 'FN3'", 0) == 0);
  r = w.request("POST", "/api/v1/log", R"({"call":42})");
  CHECK(r.status == 400);
  CHECK(json::parse(r.body)["error"] == "call: a string is expected");
  r = w.request("POST", "/api/v1/log", R"({"call":"W1AW","time_on":"yesterday"})");
  CHECK(r.status == 400);
  CHECK(json::parse(r.body)["error"] == "time_on: 'yesterday' is not a UTC time (2026-12-01T21:44:20Z)");
  CHECK(w.logging.book->count() == 1);

  r = w.request("GET", "/api/v1/log?since=2026-05-21");
  REQUIRE(r.status == 200);
  j = json::parse(r.body);
  CHECK(j["qsos"].size() == 1);
  CHECK(j["summary"]["count"] == 1);
  CHECK(w.request("GET", "/api/v1/log?since=2026-05-22").body.find("\"qsos\":[]") != std::string::npos);
  CHECK(w.request("GET", "/api/v1/log?since=May").status == 400);
  CHECK(json::parse(w.request("GET", "/api/v1/log?since=today").body)["qsos"].size() == 1);  // the station's day

  r = w.request("POST", "/api/v1/log/edit", R"({"id":1,"grid":"FN42"})");
  REQUIRE(r.status == 200);
  CHECK(json::parse(r.body)["qso"]["version"] == 2);
  CHECK(w.logging.book->versions(1).at(0).grid == "FN31");
  CHECK(w.request("POST", "/api/v1/log/edit", R"({"id":7,"grid":"FN42"})").status == 404);
  CHECK(w.request("POST", "/api/v1/log/delete", R"({"id":"1"})").status == 400);
  CHECK(w.request("POST", "/api/v1/log/delete", R"({"id":1})").status == 200);
  CHECK(w.logging.book->count() == 0);
}

TEST_CASE("web: GET /api/v1/log.adi is the ADIF export with TQSL's name and the uplink in BAND/FREQ") {
  LogWeb w;
  REQUIRE(tracker::StationOps(*w.station).track("RS-44").ok());
  w.run(1);
  REQUIRE(w.request("POST", "/api/v1/log", R"({"call":"K1JT"})").status == 200);
  const auto r = w.request("GET", "/api/v1/log.adi");
  REQUIRE(r.status == 200);
  CHECK(r.content_type == "text/plain; charset=us-ascii");
  CHECK(r.body.find("<PROGRAMVERSION:3>9.9 <CREATED_TIMESTAMP:15>20261201 214420 <EOH>") != std::string::npos);
  CHECK(r.body.find("<MODE:3>SSB <BAND:2>2m <FREQ:10>145.965000 <BAND_RX:4>70cm <FREQ_RX:10>435.640000 "
                    "<PROP_MODE:3>SAT <SAT_NAME:5>RS-44 <SAT_MODE:3>V/U") != std::string::npos);
}
