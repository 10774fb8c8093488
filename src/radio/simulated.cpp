#include "radio/simulated.h"

#include <utility>

namespace tb::radio {

SimulatedRadio::SimulatedRadio() {
  status_.connected = true;
  status_.connects = 1;
}

void SimulatedRadio::set_frequency(Link link, Hz hz) {
  std::lock_guard lock(mu_);
  if (status_.fault) {
    ++status_.failures;
    return;
  }
  (link == Link::downlink ? status_.downlink_hz : status_.uplink_hz) = hz;
  ++status_.delivered;
  record({RadioEvent::Kind::frequency, link, hz, Mode::none, {}});
}

void SimulatedRadio::set_mode(Link link, Mode mode) {
  if (mode == Mode::none) return;
  std::lock_guard lock(mu_);
  if (status_.fault) {
    ++status_.failures;
    return;
  }
  (link == Link::downlink ? status_.downlink_mode : status_.uplink_mode) = mode;
  ++status_.delivered;
  record({RadioEvent::Kind::mode, link, 0, mode, {}});
}

void SimulatedRadio::send_raw(std::string bytes) {
  std::lock_guard lock(mu_);
  if (status_.fault) {
    ++status_.failures;
    return;
  }
  ++status_.delivered;
  record({RadioEvent::Kind::raw, Link::downlink, 0, Mode::none, std::move(bytes)});
}

void SimulatedRadio::step(Link link, Hz delta) {
  std::lock_guard lock(mu_);
  auto& f = link == Link::downlink ? status_.downlink_hz : status_.uplink_hz;
  f = f.value_or(0) + delta;
  record({RadioEvent::Kind::step, link, delta, Mode::none, {}});
}

RadioStatus SimulatedRadio::status() const {
  std::lock_guard lock(mu_);
  return status_;
}

void SimulatedRadio::record(RadioEvent e) {
  if (history_.size() >= kHistoryLimit) history_.pop_front();
  history_.push_back(std::move(e));
}

std::vector<RadioEvent> SimulatedRadio::history() const {
  std::lock_guard lock(mu_);
  return {history_.begin(), history_.end()};
}

void SimulatedRadio::clear_history() {
  std::lock_guard lock(mu_);
  history_.clear();
}

std::optional<Hz> SimulatedRadio::frequency(Link link) const {
  std::lock_guard lock(mu_);
  return link == Link::downlink ? status_.downlink_hz : status_.uplink_hz;
}

std::optional<Mode> SimulatedRadio::mode(Link link) const {
  std::lock_guard lock(mu_);
  return link == Link::downlink ? status_.downlink_mode : status_.uplink_mode;
}

void SimulatedRadio::simulate_fault(std::string message) {
  std::lock_guard lock(mu_);
  status_.fault = true;
  status_.message = std::move(message);
}

void SimulatedRadio::clear_fault() {
  std::lock_guard lock(mu_);
  status_.fault = false;
  status_.message.clear();
}

}  // namespace tb::radio
