// Two radios as one (--radio for the downlink, --uplink-radio for the uplink): the station, host
// mode and the menus keep talking to one RadioDriver with two links. The downlink radio carries the
// downlink on its own (current) VFO, the uplink radio the uplink on its own one: each is a plain
// single-link radio, so no split or Main/Sub handling is involved. Each reports its faults on its
// own: the status names which radio failed ("uplink radio: ..."), and each driver logs its own.
#pragma once
#include <memory>

#include "radio/driver.h"

namespace tb::radio {

class TwoRadios final : public RadioDriver {
 public:
  TwoRadios(std::unique_ptr<RadioDriver> downlink, std::unique_ptr<RadioDriver> uplink);

  std::string describe() const override;   // "downlink: ...; uplink: ..."
  void set_frequency(Link link, Hz radio_hz) override;
  void set_mode(Link link, Mode mode) override;
  void set_frequency_guarded(Link link, Hz radio_hz, Hz tolerance_hz) override;
  std::optional<Hz> take_dial_turn(Link link) override;
  std::chrono::milliseconds dial_turn_age(Link link) const override;
  void set_ctcss_tone(int tenths_hz) override;          // to the uplink radio
  void send_raw(std::string bytes) override;            // to the downlink radio (host mode S)
  void set_recording(Record what) override;             // to the downlink radio (the receiver)
  RadioStatus status() const override;
  bool wait_idle(std::chrono::milliseconds timeout) override;

  RadioDriver& downlink_radio() { return *down_; }
  // Takes the downlink radio out (the uplink radio is being replaced or removed).
  std::unique_ptr<RadioDriver> release_downlink() { return std::move(down_); }
  RadioDriver& uplink_radio() { return *up_; }

 private:
  RadioDriver& radio(Link l) { return l == Link::downlink ? *down_ : *up_; }
  std::unique_ptr<RadioDriver> down_, up_;
};

}  // namespace tb::radio
