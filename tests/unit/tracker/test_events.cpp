// PassEventSource (tracker/events.h): the AOS and LOS events of the tracking list, stepped a second
// at a time as the station's ticks would, against the rises and sets Skyfield 1.45 finds for the
// shipped elements and the factory station (27.391 N, 128.657 E, 50 m) at -2.0 degrees:
//   ISS   rises 12:09:10.1, sets 12:15:37.1; AO-91 (up at 12:08:30) sets 12:17:34.0
// (sat.find_events(wgs84.latlon(27.391, 128.657, elevation_m=50), 12:08:30, 12:30, altitude_degrees=-2.0)).
#include <doctest/doctest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "station/clock.h"
#include "store/owner.h"
#include "support/shipped_model.h"
#include "tracker/events.h"
#include "tracker/tracker.h"

using namespace tb;

namespace {

int index_of(const store::Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.db.satellites.size(); ++i)
    if (m.db.satellites[i].elements.name == name) return static_cast<int>(i);
  FAIL("not in the shipped database: " << name);
  return -1;
}

orbit::UtcTime at(int h, int m, double s) {
  return orbit::from_civil(2026, 5, 21, h, m, 0) + std::chrono::microseconds(static_cast<long long>(s * 1e6));
}

struct Run {
  store::Model model = testing::shipped_model();
  station::ManualClock clock{at(12, 8, 30)};
  tracker::Tracker tracker{model, clock};
  std::vector<tracker::Event> events;
  explicit Run(std::vector<std::string> list) {
    model.db.selected.clear();
    for (const auto& n : list) model.db.selected.push_back(index_of(model, n));
  }
  // One step a second (or every `every`) from 12:08:30 to `until`.
  void step(tracker::PassEventSource& source, orbit::UtcTime until, std::chrono::seconds every = std::chrono::seconds(1)) {
    for (; clock.now() <= until; clock.set(clock.now() + every))
      for (auto& e : source.step(clock.now())) events.push_back(std::move(e));
  }
  const tracker::Event* find(const std::string& kind, const std::string& sat) const {
    for (const auto& e : events)
      if (e.kind == kind && e.satellite == sat) return &e;
    return nullptr;
  }
};

double seconds_between(orbit::UtcTime a, orbit::UtcTime b) {
  return std::chrono::duration<double>(a - b).count();
}

}  // namespace

TEST_CASE("AOS and LOS of the tracking list, at the first tick at or after each, once") {
  Run r({"ISS", "AO-91"});
  tracker::PassEventSource source(r.model, r.tracker);
  r.step(source, at(12, 20, 0));
  REQUIRE(r.events.size() == 4);
  // AO-91 is up at the start: its AOS is told at the first tick.
  const auto* ao91_aos = r.find("aos", "AO-91");
  REQUIRE(ao91_aos);
  CHECK(ao91_aos->time == at(12, 8, 30));
  CHECK(ao91_aos->pass->up_at_start);
  const auto* iss_aos = r.find("aos", "ISS");
  const auto* iss_los = r.find("los", "ISS");
  const auto* ao91_los = r.find("los", "AO-91");
  REQUIRE((iss_aos && iss_los && ao91_los));
  // Within the step (1 s) and the two programs' difference (Skyfield's frames, within 1.1 s here).
  CHECK(std::abs(seconds_between(iss_aos->time, at(12, 9, 10.1))) <= 1.5);
  CHECK(std::abs(seconds_between(iss_los->time, at(12, 15, 37.1))) <= 1.5);
  CHECK(std::abs(seconds_between(ao91_los->time, at(12, 17, 34.0))) <= 1.5);
  // The tick is the first at or after the pass's own AOS/LOS.
  CHECK(iss_aos->time >= iss_aos->pass->aos);
  CHECK(seconds_between(iss_aos->time, iss_aos->pass->aos) < 1.0);
  CHECK(iss_los->time >= iss_los->pass->los);
  CHECK(seconds_between(iss_los->time, iss_los->pass->los) < 1.0);
  CHECK(iss_aos->pass->max_el_deg == doctest::Approx(1.17).epsilon(0.02));
  CHECK(iss_aos->catalog_number == 25544);
  CHECK(iss_aos->list_number == 1);
  CHECK(iss_aos->downlink_hz == r.model.db.satellites[static_cast<std::size_t>(index_of(r.model, "ISS"))].radio.downlink_hz);
}

TEST_CASE("the lead moves the AOS event earlier, not the LOS") {
  Run r({"ISS"});
  tracker::PassEventSource source(r.model, r.tracker, std::chrono::seconds(30));
  r.step(source, at(12, 16, 0));
  const auto* aos = r.find("aos", "ISS");
  const auto* los = r.find("los", "ISS");
  REQUIRE((aos && los));
  CHECK(seconds_between(aos->pass->aos, aos->time) > 29.0);
  CHECK(seconds_between(aos->pass->aos, aos->time) <= 30.0);
  CHECK(los->time >= los->pass->los);
}

TEST_CASE("a satellite taken off the list is forgotten; one put on it is watched") {
  Run r({"AO-91"});
  tracker::PassEventSource source(r.model, r.tracker);
  r.step(source, at(12, 9, 0));
  CHECK(r.find("aos", "AO-91"));
  r.model.db.selected = {index_of(r.model, "ISS")};
  r.step(source, at(12, 20, 0));
  CHECK_FALSE(r.find("los", "AO-91"));  // no LOS for a satellite no longer watched
  CHECK(r.find("aos", "ISS"));
  CHECK(r.find("los", "ISS"));
}

TEST_CASE("a satellite that never sets (QO-100, geostationary, seen from Berlin) has its AOS and no LOS") {
  Run r({"QO-100"});
  r.model.station.lat_deg = 52.52;
  r.model.station.lon_deg = 13.40;
  tracker::PassEventSource source(r.model, r.tracker);
  r.step(source, at(12, 8, 30) + std::chrono::hours(24 * 5), std::chrono::seconds(60));
  REQUIRE(r.events.size() == 1);
  CHECK(r.events[0].kind == "aos");
  CHECK(r.events[0].time == at(12, 8, 30));
  // Its AOS event invents no LOS either (issue 39): the JSON's los is null, the hook's TRAKBOX_LOS empty.
  const auto j = tracker::to_json(r.events[0]);
  CHECK(j["los"].is_null());
  CHECK(j["aos"] == "2026-05-21T12:08:30.0Z");
  for (const auto& [name, value] : tracker::event_environment(r.events[0]))
    if (name == "TRAKBOX_LOS") CHECK(value.empty());
}

TEST_CASE("--event-min-el: no AOS and no LOS for a pass whose maximum stays under it (issue 39)") {
  // ISS's pass of 12:09-12:15 peaks at 1.17 deg (Skyfield: 1.17); AO-91's, already up, higher.
  SUBCASE("factory 0: the ISS pass rises, so it is told") {
    Run r({"ISS"});
    CHECK(r.model.event_min_el_deg == 0.0);
    tracker::PassEventSource source(r.model, r.tracker);
    r.step(source, at(12, 20, 0));
    CHECK(r.find("aos", "ISS"));
    CHECK(r.find("los", "ISS"));
  }
  SUBCASE("2 deg: the ISS pass is under it: no event at all; AO-91's is told") {
    Run r({"ISS", "AO-91"});
    r.model.event_min_el_deg = 2.0;
    tracker::PassEventSource source(r.model, r.tracker);
    r.step(source, at(12, 20, 0));
    CHECK_FALSE(r.find("aos", "ISS"));
    CHECK_FALSE(r.find("los", "ISS"));
    REQUIRE(r.find("aos", "AO-91"));
    CHECK(r.find("aos", "AO-91")->pass->max_el_deg >= 2.0);
    CHECK(r.find("los", "AO-91"));
  }
}

TEST_CASE("a pass hours ahead is searched once, not at every step") {
  // AO-07's next pass after 12:08:30 is hours away; ISS's is a minute away. A minute of steps
  // searches each once (the station ticks every second: a search a tick was 8 searches a second
  // for the shipped list).
  Run r({"AO-07", "ISS"});
  tracker::PassEventSource source(r.model, r.tracker);
  r.step(source, at(12, 9, 30));
  CHECK(source.searches() == 2);
  CHECK(r.find("aos", "ISS"));
  CHECK_FALSE(r.find("aos", "AO-07"));
}

TEST_CASE("the clock set back: the passes not yet told are searched again, and told again") {
  Run r({"ISS"});
  tracker::PassEventSource source(r.model, r.tracker);
  r.step(source, at(12, 20, 0));
  REQUIRE(r.find("los", "ISS"));
  const std::size_t searched = source.searches();
  r.events.clear();
  r.clock.set(at(12, 8, 30));  // menu 5: back before the ISS pass
  r.step(source, at(12, 20, 0));
  CHECK(source.searches() > searched);
  const auto* aos = r.find("aos", "ISS");
  REQUIRE(aos);
  CHECK(std::abs(seconds_between(aos->time, at(12, 9, 10.1))) <= 1.5);
  CHECK(r.find("los", "ISS"));
}

TEST_CASE("an event's JSON line and environment") {
  tracker::Event e;
  e.kind = "link-lost";
  e.time = at(12, 0, 1.5);
  e.detail = "rotator: no reply";
  const auto j = tracker::to_json(e);
  CHECK(j.dump() == R"({"detail":"rotator: no reply","event":"link-lost","time":"2026-05-21T12:00:01.500Z"})");
  const auto env = tracker::event_environment(e);
  CHECK(env.front() == std::pair<std::string, std::string>{"TRAKBOX_EVENT", "link-lost"});
  CHECK(env.back().first == "TRAKBOX_EVENT_JSON");
  CHECK(env.back().second == j.dump());
}

TEST_CASE("the station moves: the next AOS event is the new place's, not the old place's pass (issue 55)") {
  // Every user of "the next pass" asks the station's one cache (tracker/pass_memo.h), keyed by the
  // place: after a move through the model's owner the events watch the new place's pass.
  auto run = [](bool move) {
    store::ModelOwner owner(testing::shipped_model());
    const_cast<store::Model&>(owner.model()).db.selected = {index_of(owner.model(), "ISS")};  // the test's list
    station::ManualClock clock{at(12, 0, 0)};
    tracker::Tracker tracker{owner.model(), clock};
    tracker::PassEventSource source(owner.model(), tracker);
    std::vector<tracker::Event> told;
    for (; clock.now() <= at(12, 20, 0); clock.set(clock.now() + std::chrono::seconds(1))) {
      for (auto& e : source.step(clock.now())) told.push_back(std::move(e));
      if (move && clock.now() == at(12, 0, 1)) {  // to Tucson: ISS is over the other side of the world
        REQUIRE(owner.set_position(32.259, -110.778, 842.0, store::Origin::web).changed);
      }
    }
    return std::pair{told, source.searches()};
  };
  const auto [stay, stayed_searches] = run(false);
  REQUIRE(stay.size() == 2);  // the factory station: AOS 12:09:10, LOS 12:15:37 (Skyfield)
  CHECK(stay[0].kind == "aos");
  CHECK(std::abs(seconds_between(stay[0].time, at(12, 9, 10.1))) < 1.5);
  const auto [moved, searched] = run(true);
  CHECK(moved.empty());  // the old place's AOS is not told
  CHECK(searched >= 2);  // searched again for the new place
  CHECK(stayed_searches >= 1);
}
