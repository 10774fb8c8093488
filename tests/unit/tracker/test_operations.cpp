// StationOps: the operations every front end shares, on the simulated station and the shipped
// database (ISS is #1 of its tracking list; parking is off in the factory settings).
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "support/sim_station.h"
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR
#include "tracker/elements_refresh.h"
#include "tracker/operations.h"

using namespace tb;

namespace {

struct Ops : testing::StationFixture {
  Ops() { build_station(); }
  tracker::StationOps ops() { return tracker::StationOps(*station); }
  int index_of(const std::string& name) const {
    const auto i = model.db.find(name);
    REQUIRE(i.has_value());
    return *i;
  }
};

}  // namespace

TEST_CASE("StationOps: track by name, exact or ignoring case; unknown names refused with the name") {
  Ops f;
  const tracker::OpResult r = f.ops().track(" iss ");
  REQUIRE(r.ok());
  CHECK(f.tracker.mode() == tracker::Mode::single);
  f.step(std::chrono::milliseconds(100));
  REQUIRE(f.tracker.followed() != nullptr);
  CHECK(f.tracker.followed()->name == "ISS");
  CHECK(f.model.db.marked == f.model.db.list_number(f.index_of("ISS")) - 1);

  const store::Model before = f.model;
  const tracker::OpResult bad = f.ops().track("ISSS");
  REQUIRE_FALSE(bad.ok());
  CHECK(*bad.refusal == "unknown satellite 'ISSS'; did you mean ISS?");
  CHECK(f.tracker.followed()->name == "ISS");  // still tracking
  CHECK(f.model.db.selected == before.db.selected);

  // Bytes that are not printable ASCII are shown as '?' and long names cut.
  const tracker::OpResult odd = f.ops().track(std::string("A\x1b[2J\xff", 6));
  CHECK(*odd.refusal == "unknown satellite 'A?[2J?'");
  CHECK(f.ops().track(-1).refusal.value() == "no satellite -1 in the database");
}

TEST_CASE("StationOps: a list for multiple tracking moves to the front of the tracking list") {
  Ops f;
  const std::vector<int> old = f.model.db.selected;
  REQUIRE(old.size() >= 3);
  const std::string second = f.model.db.satellites[static_cast<std::size_t>(old[2])].name();
  const std::string first = f.model.db.satellites[static_cast<std::size_t>(old[1])].name();
  const tracker::OpResult r = f.ops().track_list({second, first}, true);
  REQUIRE(r.ok());
  CHECK(r.model_changed);
  CHECK(f.tracker.mode() == tracker::Mode::multi);
  CHECK(f.tracker.priority());
  CHECK(f.model.priority_mode);
  CHECK(f.model.db.multi_count == 2);
  CHECK(f.model.db.selected[0] == old[2]);
  CHECK(f.model.db.selected[1] == old[1]);
  CHECK(f.model.db.selected[2] == old[0]);
  CHECK(f.model.db.selected.size() == old.size());

  const store::Model before = f.model;
  CHECK(f.ops().track_list({first}, false).refusal.value() == "multiple tracking takes 2 to 5 satellites; 1 given");
  CHECK(f.ops().track_list({first, first}, false).refusal.value() == "satellite '" + first + "' is named twice");
  CHECK(f.ops().track_list({first, "NOPE"}, false).refusal.value() == "unknown satellite 'NOPE'");
  CHECK(f.model.db.selected == before.db.selected);
  CHECK(f.model.db.multi_count == 2);
}

TEST_CASE("StationOps: go_to clamps, says so, takes rotor control; out of range refused") {
  Ops f;
  f.model.rotor_control = false;
  f.station->set_rotor_control(false);
  const tracker::OpResult r = f.ops().go_to(120.0, 30.0);
  REQUIRE(r.ok());
  CHECK(f.model.rotor_control);
  CHECK(r.model_changed);
  REQUIRE(r.commanded.has_value());
  CHECK(r.commanded->az == doctest::Approx(120.0).epsilon(0.01));
  CHECK(r.commanded->el == doctest::Approx(30.0).epsilon(0.01));
  f.run(60.0);
  CHECK(std::abs(f.truth().az - 120.0) < testing::kAzTol);
  CHECK(std::abs(f.truth().el - 30.0) < testing::kElTol);

  CHECK(f.ops().go_to(361.0, 10.0).refusal.value() == "azimuth 361 out of range: expected 0 to 360");
  CHECK(f.ops().go_to(10.0, -1.0).refusal.value() == "elevation -1 out of range: expected 0 to 90");
  CHECK(f.ops().go_to(std::nan(""), 10.0).refusal.value() == "azimuth nan out of range: expected 0 to 360");

  // Elevation limits of 10..80 (menu 6-3): the antenna is sent to 80, and the note says so.
  f.model.rotator.limits_enabled = true;
  f.model.rotator.el_limit_min = 10.0;
  f.model.rotator.el_limit_max = 80.0;
  f.station->reconfigure();
  const tracker::OpResult high = f.ops().go_to(120.0, 89.0);
  REQUIRE(high.ok());
  CHECK(high.commanded->el == doctest::Approx(80.0).epsilon(0.01));
  CHECK(high.note == "limited to AZ120.0 EL80.0");
}

TEST_CASE("StationOps: park is refused while parking is off, then parks and stops tracking") {
  Ops f;
  f.model.rotator.parking_enabled = false;
  f.station->reconfigure();
  REQUIRE(f.ops().track("ISS").ok());
  CHECK(f.ops().park().refusal.value() == "parking is off (menu 6-4 sets the parking position)");
  CHECK(f.tracker.mode() == tracker::Mode::single);

  f.model.rotator.parking_enabled = true;
  f.model.rotator.parking = rotator::AzEl{200.0, 10.0};
  f.station->reconfigure();
  REQUIRE(f.ops().park().ok());
  CHECK(f.tracker.mode() == tracker::Mode::off);
  CHECK(f.model.rotor_control);
  f.run(90.0);
  CHECK(std::abs(f.truth().az - 200.0) < testing::kAzTol);
  CHECK(std::abs(f.truth().el - 10.0) < testing::kElTol);
}

TEST_CASE("StationOps: stop, rotor control and Doppler") {
  Ops f;
  REQUIRE(f.ops().track("ISS").ok());
  REQUIRE(f.ops().stop().ok());
  // Stop stops the rotator only (issue 44): the choice stays for the radio's Doppler, and the menus
  // hold the antenna until the operator chooses what to track again.
  CHECK(f.tracker.mode() == tracker::Mode::single);
  CHECK(f.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::menus);
  CHECK(f.station->control().tracking_drives(tracker::Resource::radio));
  REQUIRE(f.ops().track("ISS").ok());
  CHECK(f.station->control().tracking_drives(tracker::Resource::antenna));

  CHECK(f.ops().rotor_control(true).ok());
  CHECK(f.model.rotor_control);
  CHECK_FALSE(f.ops().rotor_control(true).model_changed);
  CHECK(f.ops().rotor_control(false).model_changed);
  CHECK_FALSE(f.model.rotor_control);

  CHECK(f.ops().doppler(false).ok());
  CHECK_FALSE(f.station->doppler());
  CHECK(f.ops().doppler(true).ok());
  CHECK(f.station->doppler());
  // No refresh in this station: the refusal says so.
  CHECK(f.ops().refresh_elements(0).refusal.value() ==
        "this trakbox has no element refresh (it runs only with the station)");
}

TEST_CASE("StationOps: a manual element refresh at most once per 10 minutes of station time per source") {
  Ops f;
  std::mutex mu;
  std::vector<std::function<void()>> posted;  // the download's results, run here as the loop would
  tracker::ElementsRefresh refresh(
      f.owner,
      [&](std::function<void()> fn) {
        std::lock_guard<std::mutex> lock(mu);
        posted.push_back(std::move(fn));
      },
      [] {});
  f.model.refresh.sources = {{"file://" TRAKBOX_SOURCE_DIR "/data/amateur.tle", "", ""}};
  refresh.set_station_clock(&f.clock);
  f.station->set_refresh(&refresh);
  auto finish = [&] {
    for (int i = 0; i < 500 && refresh.running(); ++i) {
      std::vector<std::function<void()>> run;
      {
        std::lock_guard<std::mutex> lock(mu);
        run.swap(posted);
      }
      for (auto& fn : run) fn();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    REQUIRE_FALSE(refresh.running());
  };
  f.step(std::chrono::milliseconds(100));  // the station's time: 12:00:00.1
  REQUIRE(f.ops().refresh_elements(0).ok());
  finish();
  const tracker::OpResult again = f.ops().refresh_elements(0);
  REQUIRE_FALSE(again.ok());
  CHECK(*again.refusal ==
        "the elements were refreshed less than 10 minutes ago: the next manual refresh at 12:10:00 UTC, in 600 s");
  f.step(std::chrono::seconds(599));
  CHECK(*f.ops().refresh_elements(0).refusal ==
        "the elements were refreshed less than 10 minutes ago: the next manual refresh at 12:10:00 UTC, in 1 s");
  f.step(std::chrono::seconds(1));
  CHECK(f.ops().refresh_elements(0).ok());
  finish();
  // A new source has not been asked for: it may come, the old one still may not.
  f.model.refresh.sources.push_back({"file://" TRAKBOX_SOURCE_DIR "/data/amateur.tle?b", "", ""});
  CHECK_FALSE(f.ops().refresh_elements(0).ok());
  f.station->set_refresh(nullptr);
}

TEST_CASE("StationOps: a list that pushes satellites out of a full tracking list names them (issue 46)") {
  Ops f;
  REQUIRE(f.model.db.satellites.size() >= 17);
  f.model.db.selected.clear();
  for (int i = 0; i < 15; ++i) f.model.db.selected.push_back(i);
  const std::string a = f.model.db.satellites[15].name(), b = f.model.db.satellites[16].name();
  const tracker::OpResult r = f.ops().track_list({a, b}, false);
  REQUIRE(r.ok());
  CHECK(f.model.db.selected.size() == 15);
  CHECK(f.model.db.selected[0] == 15);
  CHECK(f.model.db.selected[1] == 16);
  CHECK(r.note == "multiple tracking (normal) of #1-#2; the tracking list holds 15: " + f.model.db.satellites[13].name() +
                      ", " + f.model.db.satellites[14].name() + " left it");
}

TEST_CASE("StationOps: Stop stops the rotator only; the radio keeps its Doppler (issue 44)") {
  Ops f;
  f.now = orbit::from_civil(2026, 5, 21, 12, 10, 0);  // ISS is up (12:09:10 to 12:15:37 at -2 deg)
  REQUIRE(f.ops().track("ISS").ok());
  f.run(5.0);
  const auto before = f.radio_sim->frequency(radio::Link::downlink);
  REQUIRE(f.ops().stop().ok());
  CHECK_FALSE(f.station->rotator().status().target);
  f.run(60.0);
  CHECK(f.radio_sim->frequency(radio::Link::downlink) != before);  // still tuned for Doppler
  CHECK(f.tracker.mode() == tracker::Mode::single);
  // Doppler off: the radio is left where it is.
  REQUIRE(f.ops().doppler(false).ok());
  const auto held = f.radio_sim->frequency(radio::Link::downlink);
  f.run(60.0);
  CHECK(f.radio_sim->frequency(radio::Link::downlink) == held);
}

TEST_CASE("Tracking parks between passes: the aim is the parking position, not the decision's 0/0") {
  Ops f;
  f.model.rotator.parking_enabled = true;
  f.model.rotator.parking = rotator::AzEl{200.0, 10.0};
  f.station->reconfigure();
  REQUIRE(f.ops().track("ISS").ok());
  f.run(2.0);
  REQUIRE(f.tracker.last_decision().antenna == tracker::Decision::Antenna::park);  // noon: the ISS is not up
  const auto aim = f.station->aim();
  CHECK(std::string(aim.action) == "park");
  REQUIRE(aim.target);
  CHECK(aim.target->az == doctest::Approx(200.0));
  CHECK(aim.target->el == doctest::Approx(10.0));
}
