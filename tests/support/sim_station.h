// A StationLoop on simulated hardware, wired as the program wires a real one: a SimulatedRotator
// behind the rotator Controller and a SimulatedRadio; and StationFixture, a whole such station on
// the shipped data with a clock the test moves by hand. Header-only; the including test program
// links tb_tracker (and what it pulls in).
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <optional>

#include "radio/simulated.h"
#include "rotator/adc_model.h"
#include "rotator/controller.h"
#include "rotator/simulated.h"
#include "station/clock.h"
#include "support/shipped_model.h"
#include "tracker/station_loop.h"

namespace tb::testing {

struct SimulatedStation {
  std::unique_ptr<tracker::StationLoop> loop;
  rotator::SimulatedRotator* rotator = nullptr;  // owned by the loop's controller
  radio::SimulatedRadio* radio = nullptr;        // owned by the loop
};

// A test's direct hand on the model its owner keeps: the fixtures set the state up as a test needs
// it (and call reconfigure() when the station must see it), bypassing the checks and the notices
// that every front end of the program goes through (store/owner.h). Tests only.
inline store::Model& setup_model(store::ModelOwner& owner) { return const_cast<store::Model&>(owner.model()); }

// The loop on `owner`'s model; the rotator's mechanics are `params`, by default matching the
// model's rotator settings.
inline SimulatedStation simulated_station(store::ModelOwner& owner, const station::Clock& clock, tracker::Tracker& tracker,
                                          std::optional<rotator::SimulatedRotatorParams> params = std::nullopt) {
  const store::Model& model = owner.model();
  SimulatedStation s;
  auto rot = std::make_unique<rotator::SimulatedRotator>(
      clock, params ? *params : rotator::SimulatedRotatorParams::matching(model.rotator));
  s.rotator = rot.get();
  auto controller = std::make_unique<rotator::Controller>(model.rotator, model.station.rotor_start, std::move(rot));
  auto rad = std::make_unique<radio::SimulatedRadio>();
  s.radio = rad.get();
  s.loop = std::make_unique<tracker::StationLoop>(owner, clock, tracker, std::move(controller), std::move(rad));
  return s;
}

// Where the simulated rotator truly points: compass azimuth and elevation.
inline rotator::AzEl true_compass(rotator::SimulatedRotator& sim, station::RotorStart start) {
  const auto p = sim.true_position();
  return {rotator::wrap360(p.az_travel + rotator::rotor_start_deg(start)), p.el};
}

// Dead band plus one count of ADC flooring, in degrees (factory span: 360/1023 and 90/511 a count).
inline constexpr double kAzTol = 4 * 360.0 / 1023;
inline constexpr double kElTol = 2 * 90.0 / 511;

// The shipped data, the factory settings, a RealTimeClock reading `now`, the real tracker, and a
// simulated station loop (once build_station() has made it): what the menu and host-mode fixtures
// build on.
struct StationFixture {
  explicit StationFixture(orbit::UtcTime start = orbit::from_civil(2026, 5, 21, 12, 0, 0))
      : StationFixture(start, shipped_model()) {}
  // The same on a model of the test's own.
  StationFixture(orbit::UtcTime start, store::Model m)
      : now(start), owner(std::move(m)), clock([this] { return now; }), tracker(model, clock) {}
  StationFixture(const StationFixture&) = delete;
  StationFixture& operator=(const StationFixture&) = delete;

  // (Re)builds the station loop around a simulated rotator with these mechanics (by default
  // matching the model's rotator settings).
  void build_station(std::optional<rotator::SimulatedRotatorParams> params = std::nullopt) {
    SimulatedStation sim = simulated_station(owner, clock, tracker, params);
    rotator_sim = sim.rotator;
    radio_sim = sim.radio;
    station = std::move(sim.loop);
  }

  // The simulated rotator's true compass azimuth and elevation.
  rotator::AzEl truth() { return true_compass(*rotator_sim, model.station.rotor_start); }

  // Lets `dt` pass on the clock, then the station ticks, as the event loop would.
  void step(std::chrono::milliseconds dt) {
    now += dt;
    station->tick();
  }

  // Lets `seconds` pass on the clock, ticking the station every 100 ms; `each` runs after each tick.
  void run(double seconds, const std::function<void()>& each = {}) {
    for (int i = 0; i < static_cast<int>(seconds * 10); ++i) {
      step(std::chrono::milliseconds(100));
      if (each) each();
    }
  }

  orbit::UtcTime now;
  store::ModelOwner owner;                    // the station's one door, as in the program
  store::Model& model = setup_model(owner);  // the test's hand on it for setting up
  station::RealTimeClock clock;
  tracker::Tracker tracker;
  rotator::SimulatedRotator* rotator_sim = nullptr;
  radio::SimulatedRadio* radio_sim = nullptr;
  std::unique_ptr<tracker::StationLoop> station;
};

}  // namespace tb::testing
