// What every radio driver shares (driver.h): the link names and sending a Tuner's commands.
#include "radio/driver.h"

namespace tb::radio {

const char* to_string(Link l) { return l == Link::downlink ? "downlink" : "uplink"; }

void apply(RadioDriver& radio, const TuneCommands& c, DialGuard guard) {
  auto frequency = [&](Link l, Hz hz, Hz tolerance) {
    if (tolerance > 0) radio.set_frequency_guarded(l, hz, tolerance);
    else radio.set_frequency(l, hz);
  };
  auto link = [&](Link l) {
    const bool down = l == Link::downlink;
    if (const auto& m = down ? c.downlink_mode : c.uplink_mode) radio.set_mode(l, *m);
    if (const auto& hz = down ? c.downlink_hz : c.uplink_hz) frequency(l, *hz, down ? guard.downlink_hz : guard.uplink_hz);
  };
  link(c.uplink_first ? Link::uplink : Link::downlink);
  link(c.uplink_first ? Link::downlink : Link::uplink);
}

}  // namespace tb::radio
