// A whole simulated station for menu tests: the shipped database, a clock the test moves, the real
// tracker and station loop on the simulated rotator and radio, and a scripted terminal whose waits
// advance the clock and tick the station (as the event loop would).
#pragma once
#include <memory>

#include "menus/menus.h"
#include "menus/term/script_terminal.h"
#include "support/shipped_model.h"
#include "radio/simulated.h"
#include "rotator/simulated.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::testing {

struct MenuFixture {
  explicit MenuFixture(std::string input = {}, orbit::UtcTime start = orbit::from_civil(2026, 5, 21, 12, 0, 0))
      : now(start), model(shipped_model()), clock([this] { return now; }), tracker(model, clock),
        term(std::move(input)) {
    auto sim = std::make_unique<rotator::SimulatedRotator>(clock, rotator::SimulatedRotatorParams::matching(model.rotator));
    rotator_sim = sim.get();
    auto controller = std::make_unique<rotator::Controller>(model.rotator, model.station.rotor_start, std::move(sim));
    auto rad = std::make_unique<radio::SimulatedRadio>();
    radio_sim = rad.get();
    station = std::make_unique<tracker::StationLoop>(model, clock, tracker, std::move(controller), std::move(rad));
    services = std::make_unique<menus::Services>(menus::Services{model, clock, tracker, *station, [this]() -> std::optional<std::string> {
      ++saves;
      return std::nullopt;
    }, "test"});
    // Each wait of the terminal lets the timeout pass on the clock and ticks the station.
    term.on_wait = [this](std::optional<term::Duration> timeout) {
      now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
      station->tick();
    };
  }

  orbit::UtcTime now;
  store::Model model;
  station::RealTimeClock clock;
  tracker::Tracker tracker;
  rotator::SimulatedRotator* rotator_sim = nullptr;
  radio::SimulatedRadio* radio_sim = nullptr;
  std::unique_ptr<tracker::StationLoop> station;
  std::unique_ptr<menus::Services> services;
  term::ScriptTerminal term;
  int saves = 0;
};

}  // namespace tb::testing
