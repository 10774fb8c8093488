// The station's radio during a linear-transponder pass (issue 17): the operator's turn of the
// downlink dial is kept and the uplink follows to the paired spot; with dial follow off trakbox
// puts the dial back, as before.
#include <doctest/doctest.h>

#include <cstdlib>

#include "support/sim_station.h"

using namespace tb;

namespace {

// RS-44 (#12 of the shipped database, inverting) a minute before its culmination of 10:58 UTC.
struct Rs44Pass : testing::StationFixture {
  explicit Rs44Pass(bool follow) : StationFixture(orbit::from_civil(2026, 5, 21, 10, 57, 0)) {
    model.radio.dial_follow = follow;
    build_station();
    tracker.track_single(rs44());
    run(3.0);
  }
  int rs44() const {
    for (std::size_t i = 0; i < model.db.satellites.size(); ++i)
      if (model.db.satellites[i].elements.name == "RS-44") return static_cast<int>(i);
    FAIL("RS-44 is not in the shipped database");
    return -1;
  }
  radio::Hz down() const { return *radio_sim->frequency(radio::Link::downlink); }
  radio::Hz up() const { return *radio_sim->frequency(radio::Link::uplink); }
};

}  // namespace

TEST_CASE("Station: the downlink dial turned +10 kHz on RS-44 stays, the uplink moves -10 kHz") {
  Rs44Pass p(true);
  REQUIRE(p.station->tuner().dial_follow_active());
  const radio::Hz d0 = p.down(), u0 = p.up();
  CHECK(std::llabs(d0 - 435'640'000) < 10'000);
  radio::Hz turned = d0 + 10'000;
  p.radio_sim->step(radio::Link::downlink, 10'000);
  p.run(3.0);
  // Three seconds of Doppler near culmination: under 300 Hz on the downlink, 100 Hz on the uplink.
  CHECK(std::llabs(p.down() - turned) < 300);
  CHECK(std::llabs(p.up() - (u0 - 10'000)) < 100);
  // The spot: the turned frequency in the satellite frame, within the 10 Hz rounding and one tick's Doppler.
  CHECK(std::llabs(p.station->tuner().downlink_spot_hz() - 435'650'000) <= 30);
  CHECK(p.station->tuner().uplink_spot_hz() == 145'995'000 - (p.station->tuner().downlink_spot_hz() - 435'610'000));
}

TEST_CASE("Station: with dial follow off the turn is undone at the next Doppler step") {
  Rs44Pass p(false);
  const radio::Hz d0 = p.down(), u0 = p.up();
  p.radio_sim->step(radio::Link::downlink, 10'000);
  p.run(3.0);
  CHECK(std::llabs(p.down() - d0) < 300);
  CHECK(std::llabs(p.up() - u0) < 100);
}

TEST_CASE("Station: with CAT only at AOS, choosing a satellite below the horizon presets the radio to it") {
  testing::StationFixture f(orbit::from_civil(2026, 5, 21, 12, 0, 0));
  f.model.radio.cat_policy = radio::CatPolicy::aos_only;
  f.build_station();
  const auto iss = f.model.db.find("ISS");
  REQUIRE(iss.has_value());
  f.tracker.track_single(*iss);
  f.step(std::chrono::milliseconds(100));
  REQUIRE(f.tracker.followed() != nullptr);
  REQUIRE(f.tracker.followed()->obs.look.el_deg < radio::kAosElevationDeg);   // below the horizon
  // ISS's 437.800 / 145.990 MHz FM (data/freqmode.txt), within its Doppler (under 11 kHz on 70 cm).
  REQUIRE(f.radio_sim->frequency(radio::Link::downlink).has_value());
  CHECK(std::llabs(*f.radio_sim->frequency(radio::Link::downlink) - 437'800'000) < 11'000);
  CHECK(std::llabs(*f.radio_sim->frequency(radio::Link::uplink) - 145'990'000) < 4'000);
  // Nothing more until AOS: a minute later the dial is where the preset put it.
  const radio::Hz preset = *f.radio_sim->frequency(radio::Link::downlink);
  f.run(60.0);
  CHECK(*f.radio_sim->frequency(radio::Link::downlink) == preset);
}
