// The logbook's endpoints (web/api_log.h) through web::Api on the simulated station: a QSO from the
// pass, the refusals (4xx with a sentence naming the field), edit and delete, the ADIF export.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "logbook/adif.h"
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

namespace {
// A streamed reply's body, its pieces joined (as the server sends them); the largest piece.
std::pair<std::string, std::size_t> drain(const web::Response& r) {
  REQUIRE(r.stream);
  std::string body;
  std::size_t largest = 0;
  for (int guard = 0; guard < 100000; ++guard) {
    const std::string piece = r.stream();
    if (piece.empty()) break;
    largest = std::max(largest, piece.size());
    body += piece;
  }
  return {body, largest};
}
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
  const std::string body = drain(r).first;
  CHECK(body.find("<PROGRAMVERSION:3>9.9 <CREATED_TIMESTAMP:15>20261201 214420 <EOH>") != std::string::npos);
  CHECK(body.find("<MODE:3>SSB <BAND:2>2m <FREQ:10>145.965000 <BAND_RX:4>70cm <FREQ_RX:10>435.640000 "
                    "<PROP_MODE:3>SAT <SAT_NAME:5>RS-44 <SAT_MODE:3>V/U") != std::string::npos);
}

TEST_CASE("web: GET /api/v1/log gives a page and the cursor of the next; the ADIF comes in pages (issue 56, item 4)") {
  LogWeb w;
  REQUIRE(tracker::StationOps(*w.station).track("RS-44").ok());
  w.run(1);
  std::vector<logbook::Qso> many;
  for (int i = 0; i < 1203; ++i) {
    tracker::LogRequest ask;
    ask.call = "K1ABC";
    logbook::Qso q = tracker::LogOps(*w.station).fill(ask).qso;
    q.call = "K" + std::to_string(i % 10) + "A" + std::string(1, static_cast<char>('A' + i % 26)) +
             std::string(1, static_cast<char>('A' + i / 26 % 26));
    q.time_on += i / 3;  // three at each second: pages end inside a second
    q.station_call = "JA6ABC";  // the factory's NOCALL would warn once a QSO
    many.push_back(q);
  }
  REQUIRE(w.logging.book->import(many).added == 1203);
  auto r = w.request("GET", "/api/v1/log");
  REQUIRE(r.status == 200);
  json j = json::parse(r.body);
  CHECK(j["qsos"].size() == 500);  // the default page, not the whole log
  CHECK(j["limit"] == 500);
  CHECK(j["summary"]["count"] == 1203);
  std::vector<std::int64_t> ids;
  std::size_t pages = 0;
  std::string target = "/api/v1/log?limit=1000";
  for (;;) {
    r = w.request("GET", target);
    REQUIRE(r.status == 200);
    j = json::parse(r.body);
    ++pages;
    CHECK(j["qsos"].size() <= 1000);
    for (const auto& q : j["qsos"]) ids.push_back(q["id"].get<std::int64_t>());
    if (j["next"].is_null()) break;
    target = "/api/v1/log?limit=1000&after=" + j["next"].get<std::string>();
  }
  CHECK(pages == 2);
  REQUIRE(ids.size() == 1203);
  for (std::size_t i = 0; i < ids.size(); ++i) CHECK(ids[i] == static_cast<std::int64_t>(i + 1));
  CHECK(w.request("GET", "/api/v1/log?limit=1001").status == 400);
  CHECK(w.request("GET", "/api/v1/log?limit=0").status == 400);
  CHECK(w.request("GET", "/api/v1/log?after=12").status == 400);
  // The export: the same log in pieces of at most a page, joined equal to write_adif's whole export.
  r = w.request("GET", "/api/v1/log.adi");
  REQUIRE(r.status == 200);
  CHECK(r.body.empty());
  const auto [adif, largest] = drain(r);
  CHECK(adif == logbook::write_adif(w.logging.book->list(0), "9.9", 1796161460).text);
  CHECK(largest < 500 * 1024);
  CHECK(r.trailers().at(0) == std::pair<std::string, std::string>{"X-Trakbox-Warnings", "0"});
}
