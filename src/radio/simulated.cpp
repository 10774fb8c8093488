#include "radio/simulated.h"

#include <utility>

namespace tb::radio {

SimulatedRadio::SimulatedRadio() {
  status_.connected = true;
  status_.connects = 1;
  status_.reads_downlink = status_.reads_uplink = true;
}

void SimulatedRadio::set_frequency_guarded(Link link, Hz hz, Hz tolerance) {
  {
    std::lock_guard lock(mu_);
    const std::optional<Hz> dial = link == Link::downlink ? status_.downlink_hz : status_.uplink_hz;
    std::optional<Hz>& accepted = accepted_[link_index(link)];
    if (tolerance > 0 && dial && accepted && dial_turned(*dial, *accepted, tolerance)) {
      turned_[link_index(link)] = *dial;
      accepted = *dial;
      return;
    }
    if (tolerance > 0 && turned_[link_index(link)]) return;   // a turn not yet taken: not undone
  }
  set_frequency(link, hz);
}

std::optional<Hz> SimulatedRadio::take_dial_turn(Link link) {
  std::lock_guard lock(mu_);
  return std::exchange(turned_[link_index(link)], std::nullopt);
}

void SimulatedRadio::set_frequency(Link link, Hz hz) {
  std::lock_guard lock(mu_);
  if (status_.fault) {
    ++status_.failures;
    return;
  }
  (link == Link::downlink ? status_.downlink_hz : status_.uplink_hz) = hz;
  (link == Link::downlink ? status_.downlink_read_hz : status_.uplink_read_hz) = hz;
  accepted_[link_index(link)] = hz;
  turned_[link_index(link)].reset();
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
  (link == Link::downlink ? status_.downlink_read_hz : status_.uplink_read_hz) = f;
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
