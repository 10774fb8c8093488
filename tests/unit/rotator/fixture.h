// The rotator Controller on a SimulatedRotator, with a ManualClock the test moves: the closed loop
// the controller and property tests drive. Logging is off.
#pragma once
#include <spdlog/spdlog.h>

#include <chrono>
#include <functional>
#include <memory>

#include "rotator/controller.h"
#include "rotator/simulated.h"

namespace rotator_test {

// Degrees per ADC count of the default span (360 deg over 1023 counts in azimuth, 90 over 511 in
// elevation): what one count of the model moves.
inline constexpr double kAzCount = 360.0 / 1023.0, kElCount = 90.0 / 511.0;

struct Rig {
  tb::station::ManualClock clock;
  tb::rotator::SimulatedRotator* sim = nullptr;
  std::unique_ptr<tb::rotator::Controller> ctl;

  // The antenna starts at `at` (rotator coordinates); the rotator's mechanics are `p`; the clock
  // starts at `t0`. The controller has taken its first reading.
  explicit Rig(tb::rotator::RotatorConfig c = {}, tb::station::RotorStart start = tb::station::RotorStart::north,
               tb::rotator::RotatorPosition at = {0, 0},
               tb::rotator::SimulatedRotatorParams p = tb::rotator::SimulatedRotatorParams{},
               tb::orbit::UtcTime t0 = tb::orbit::from_civil(2026, 3, 1, 12))
      : clock(t0) {
    spdlog::set_level(spdlog::level::off);
    p.start = at;
    auto s = std::make_unique<tb::rotator::SimulatedRotator>(clock, p);
    sim = s.get();
    ctl = std::make_unique<tb::rotator::Controller>(c, start, std::move(s));
    ctl->tick(clock.now());
  }
  // Ticks every `step` for up to `limit`, calling each(…) after every tick; returns the time taken
  // to get on target (or limit when it never did).
  std::chrono::milliseconds run(std::chrono::milliseconds limit,
                                std::chrono::milliseconds step = std::chrono::milliseconds(100),
                                const std::function<void()>& each = {}) {
    for (std::chrono::milliseconds t{0}; t < limit; t += step) {
      clock.advance(step);
      ctl->tick(clock.now());
      if (each) each();
      if (ctl->status().on_target) return t + step;
    }
    return limit;
  }
  void idle(std::chrono::milliseconds d, std::chrono::milliseconds step = std::chrono::milliseconds(100)) {
    for (std::chrono::milliseconds t{0}; t < d; t += step) {
      clock.advance(step);
      ctl->tick(clock.now());
    }
  }
};

}  // namespace rotator_test
