#include "radio/two_radios.h"

#include <algorithm>

namespace tb::radio {

// Each radio carries its link on its own (current) VFO: the driver's downlink link.
TwoRadios::TwoRadios(std::unique_ptr<RadioDriver> downlink, std::unique_ptr<RadioDriver> uplink)
    : down_(std::move(downlink)), up_(std::move(uplink)) {
  up_->carries_for_station(Link::uplink);
}

std::string TwoRadios::describe() const {
  return "downlink: " + down_->describe() + "; uplink: " + up_->describe();
}

void TwoRadios::set_frequency(Link l, Hz hz) { radio(l).set_frequency(Link::downlink, hz); }

void TwoRadios::set_mode(Link l, Mode m) { radio(l).set_mode(Link::downlink, m); }

void TwoRadios::set_frequency_guarded(Link l, Hz hz, Hz tolerance) {
  radio(l).set_frequency_guarded(Link::downlink, hz, tolerance);
}

std::optional<Hz> TwoRadios::take_dial_turn(Link l) { return radio(l).take_dial_turn(Link::downlink); }

std::chrono::milliseconds TwoRadios::dial_turn_age(Link l) const {
  return (l == Link::downlink ? *down_ : *up_).dial_turn_age(Link::downlink);
}

void TwoRadios::set_ctcss_tone(int tenths_hz) { up_->set_ctcss_tone(tenths_hz); }

void TwoRadios::send_raw(std::string bytes) { down_->send_raw(std::move(bytes)); }

void TwoRadios::set_recording(Record what) { down_->set_recording(what); }

RadioStatus TwoRadios::status() const {
  const RadioStatus d = down_->status(), u = up_->status();
  RadioStatus s;
  s.connected = d.connected && u.connected;
  s.fault = d.fault || u.fault;
  if (d.fault) s.message = "downlink radio: " + d.message;
  if (u.fault) s.message += (d.fault ? "; " : "") + std::string("uplink radio: ") + u.message;
  s.downlink_hz = d.downlink_hz;
  s.uplink_hz = u.downlink_hz;
  s.downlink_mode = d.downlink_mode;
  s.uplink_mode = u.downlink_mode;
  s.delivered = d.delivered + u.delivered;
  s.failures = d.failures + u.failures;
  s.connects = d.connects + u.connects;
  s.pending = d.pending + u.pending;
  s.reads_downlink = d.reads_downlink;
  s.reads_uplink = u.reads_downlink;
  s.downlink_read_hz = d.downlink_read_hz;
  s.uplink_read_hz = u.downlink_read_hz;
  s.recorder = d.recorder;
  return s;
}

bool TwoRadios::wait_idle(std::chrono::milliseconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  const bool a = down_->wait_idle(timeout);
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
  return up_->wait_idle(std::max(left, std::chrono::milliseconds(0))) && a;
}

}  // namespace tb::radio
