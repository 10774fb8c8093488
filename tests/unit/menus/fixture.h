// A whole simulated station for menu tests: the shipped database, a clock the test moves, the real
// tracker and station loop on the simulated rotator and radio, and a scripted terminal whose waits
// advance the clock and tick the station (as the event loop would).
#pragma once
#include <doctest/doctest.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

#include "menus/menus.h"
#include "menus/term/script_terminal.h"
#include <nlohmann/json.hpp>

#include "store/model.h"
#include "support/sim_station.h"

namespace tb::testing {

struct MenuFixture : StationFixture {
  explicit MenuFixture(std::string input = {}, orbit::UtcTime start = orbit::from_civil(2026, 5, 21, 12, 0, 0))
      : StationFixture(start), term(std::move(input)) {
    build();
    // Each wait of the terminal lets the timeout pass on the clock and ticks the station.
    term.on_wait = [this](std::optional<term::Duration> timeout) {
      now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
      station->tick();
    };
  }

  // (Re)builds the station around a simulated rotator with these mechanics (by default matching
  // the model's rotator settings), and the menus' services on it.
  void build(std::optional<rotator::SimulatedRotatorParams> params = std::nullopt) {
    build_station(params);
    // As the program wires it: every change the model's owner announces is saved.
    station->on_settings_changed([this] { ++saves; });
    owner.listen([this](const store::Notice& n) { changes.push_back(n.what); });
    services = std::make_unique<menus::Services>(menus::Services{model, clock, tracker, *station, [this]() -> std::optional<std::string> {
      ++saves;
      return std::nullopt;
    }, "test", {}});
  }

  std::unique_ptr<menus::Services> services;
  term::ScriptTerminal term;
  int saves = 0;
  std::vector<std::string> changes;  // what the owner announced, in order (each is saved)
};

// What a menu printed: whether it holds `what`, and how many times (overlapping ones too).
inline bool has(const std::string& text, std::string_view what) { return text.find(what) != std::string::npos; }
inline std::size_t count(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}
// The database part of the model as stored (JSON text), to compare a database before and after.
inline std::string db_json(const store::Model& m) { return store::to_json(m)["db"].dump(); }

// Each of `parts` is in what the menu printed (a check each, the part named when it fails).
inline void check_shows(const std::string& text, std::initializer_list<std::string_view> parts) {
  for (const std::string_view part : parts) {
    CAPTURE(part);
    CHECK(has(text, part));
  }
}

}  // namespace tb::testing
