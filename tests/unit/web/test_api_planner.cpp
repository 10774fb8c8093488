// The planner's GET /api/v1/passes (issue 47): several satellites or the tracking list, a minimum
// elevation, a bounded window, overlaps, a second station; and passes.ics. Checked against the
// pass search itself on the simulated station and the shipped data.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "orbit/pass_tools.h"
#include "support/sim_station.h"
#include "web/api.h"

using namespace tb;
using json = nlohmann::json;

namespace {

struct Planner : testing::StationFixture {
  Planner() : access(web::AccessOptions{}, nullptr) {
    build_station();
    api = std::make_unique<web::Api>(*station, access, web::ApiHooks{});
    run(0.2);
  }
  web::Response get(const std::string& target) {
    web::Request r;
    r.method = "GET";
    r.target = target;
    r.host = "127.0.0.1:8073";
    r.peer = "127.0.0.1";
    return api->handle(r, std::chrono::steady_clock::time_point(std::chrono::hours(1000)));
  }
  json get_json(const std::string& target) {
    const web::Response r = get(target);
    REQUIRE(r.status == 200);
    return json::parse(r.body);
  }
  std::vector<orbit::Pass> search(const std::string& name, double hours, double min_el) {
    orbit::PassOptions o;
    o.min_max_elevation_deg = min_el;
    const auto i = model.db.find(name);
    REQUIRE(i.has_value());
    // The passes up at some time of [from, from + hours), each whole (a low orbit's pass is shorter
    // than the half hour searched before): the planner's passes (issue 47).
    const orbit::UtcTime from = station->now();
    auto found = orbit::find_passes(*tracker.propagator(*i), model.station.observer(), orbit::add_minutes(from, -30.0),
                                    orbit::add_minutes(from, hours * 60), o);
    std::erase_if(found, [&](const orbit::Pass& p) { return p.los < from; });
    return found;
  }
  web::Access access;
  std::unique_ptr<web::Api> api;
};

}  // namespace

TEST_CASE("planner: SO-50, AO-91, RS-44 and ISS above 20 deg over 24 h, sorted, overlaps named both ways") {
  Planner p;
  const json j = p.get_json("/api/v1/passes?sat=SO-50,AO-91,RS-44,ISS&min_el=20&hours=24");
  std::size_t want = 0;
  for (const char* s : {"SO-50", "AO-91", "RS-44", "ISS"}) want += p.search(s, 24, 20).size();
  REQUIRE(j["passes"].size() == want);
  REQUIRE(want > 0);
  CHECK(j["min_el_deg"] == 20.0);
  const json& list = j["passes"];
  for (std::size_t k = 0; k < list.size(); ++k) {
    CHECK(list[k]["max_el_deg"].get<double>() >= 20.0);
    if (k) CHECK(list[k - 1]["aos"].get<std::string>() <= list[k]["aos"].get<std::string>());
    CHECK(list[k]["track"].size() == 17);
    for (const auto& o : list[k]["overlaps"]) {
      const auto other = o.get<std::size_t>();
      CHECK(list[other]["aos"].get<std::string>() < list[k]["los"].get<std::string>());
      CHECK(list[k]["aos"].get<std::string>() < list[other]["los"].get<std::string>());
      bool back = false;
      for (const auto& b : list[other]["overlaps"]) back = back || b.get<std::size_t>() == k;
      CHECK(back);
    }
  }
}

TEST_CASE("planner: no sat is the tracking list; only passes that rise; bounds refused with the value") {
  Planner p;
  const json j = p.get_json("/api/v1/passes?hours=12");
  std::size_t want = 0;
  for (const int i : p.model.db.selected)
    want += p.search(p.model.db.satellites[static_cast<std::size_t>(i)].name(), 12, 1e-9).size();
  CHECK(j["passes"].size() == want);
  for (const auto& pass : j["passes"]) CHECK(pass["max_el_deg"].get<double>() > 0.0);
  auto error_of = [&](const std::string& q) { return json::parse(p.get(q).body).at("error").get<std::string>(); };
  CHECK(error_of("/api/v1/passes?sat=ISS&hours=73") == "passes: hours '73': expected 1 to 72");
  CHECK(error_of("/api/v1/passes?sat=ISS&min_el=95") == "passes: min_el '95': expected 0 to 90 degrees");
  CHECK(error_of("/api/v1/passes?sat=ISS&with=nowhere") ==
        "passes: with 'nowhere': expected a Maidenhead locator (JN58td) or LAT,LON");
  CHECK(error_of("/api/v1/passes?sat=ISS,NOPE") == "unknown satellite 'NOPE'");
}

TEST_CASE("planner: with= keeps the times a second station sees it too; passes.ics is a calendar of the same") {
  Planner p;
  // The factory station is at 27.391 N 128.657 E; PM37 (Seoul, about 1,100 km away) shares many passes.
  const json alone = p.get_json("/api/v1/passes?sat=ISS&hours=24");
  const json both = p.get_json("/api/v1/passes?sat=ISS&hours=24&with=PM37");
  CHECK(both["with"] == "PM37");
  CHECK(both["passes"].size() <= alone["passes"].size());
  const web::Response ics = p.get("/api/v1/passes.ics?sat=ISS&hours=24");
  REQUIRE(ics.status == 200);
  CHECK(ics.content_type == "text/calendar; charset=utf-8");
  std::size_t events = 0;
  for (std::size_t at = ics.body.find("BEGIN:VEVENT"); at != std::string::npos; at = ics.body.find("BEGIN:VEVENT", at + 1))
    ++events;
  CHECK(events == alone["passes"].size());
  CHECK(p.get("/api/v1/passes.ics?sat=ISS&hours=100").status == 400);
}
