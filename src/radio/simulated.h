// The simulated radio (trakbox's default): it does what it is told at once and records everything,
// so displays can show the radio and tests can read back what the tracker sent.
#pragma once
#include <cstddef>
#include <deque>
#include <mutex>
#include <vector>

#include "radio/driver.h"

namespace tb::radio {

struct RadioEvent {
  enum class Kind { frequency, mode, raw, step };
  Kind kind = Kind::frequency;
  Link link = Link::downlink;
  Hz hz = 0;                // frequency: the new value; step: the change (mic-click pulse)
  Mode mode = Mode::none;   // mode
  std::string raw;          // raw
  bool operator==(const RadioEvent&) const = default;
};

class SimulatedRadio final : public RadioDriver {
 public:
  SimulatedRadio();

  std::string describe() const override { return "simulated radio"; }
  void set_frequency(Link link, Hz radio_hz) override;
  void set_mode(Link link, Mode mode) override;
  // It can be read back: step() is the operator's dial that dial follow sees.
  void set_frequency_guarded(Link link, Hz radio_hz, Hz tolerance_hz) override;
  std::optional<Hz> take_dial_turn(Link link) override;
  void send_raw(std::string bytes) override;
  RadioStatus status() const override;
  bool wait_idle(std::chrono::milliseconds) override { return true; }

  // The operator's dial, or a mic-click pulse: moves the link by delta (recorded as a step).
  void step(Link link, Hz delta_hz);

  // The latest kHistoryLimit events, oldest first (older ones are dropped: a radio tuned with
  // Doppler every second for days must not grow without bound).
  static constexpr std::size_t kHistoryLimit = 4096;
  std::vector<RadioEvent> history() const;
  void clear_history();
  std::optional<Hz> frequency(Link link) const;
  std::optional<Mode> mode(Link link) const;

  // Pretend the radio fails (for displays and tests); commands are then not taken.
  void simulate_fault(std::string message);
  void clear_fault();

 private:
  mutable std::mutex mu_;
  RadioStatus status_;
  std::deque<RadioEvent> history_;
  void record(RadioEvent e);  // under mu_
  std::optional<Hz> accepted_[2];    // what was last set per link (status_ holds the dial)
  std::optional<Hz> turned_[2];      // a turn of the dial seen by a guarded set, not yet taken
};

}  // namespace tb::radio
