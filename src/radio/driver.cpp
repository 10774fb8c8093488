// What every radio driver shares (driver.h): the link names and sending a Tuner's commands.
#include "radio/driver.h"

namespace tb::radio {

const char* to_string(Link l) { return l == Link::downlink ? "downlink" : "uplink"; }

void apply(RadioDriver& radio, const TuneCommands& c, DialGuard guard) {
  auto frequency = [&](Link l, Hz hz, Hz tolerance) {
    if (tolerance > 0) radio.set_frequency_guarded(l, hz, tolerance);
    else radio.set_frequency(l, hz);
  };
  if (c.downlink_mode) radio.set_mode(Link::downlink, *c.downlink_mode);
  if (c.downlink_hz) frequency(Link::downlink, *c.downlink_hz, guard.downlink_hz);
  if (c.uplink_mode) radio.set_mode(Link::uplink, *c.uplink_mode);
  if (c.uplink_hz) frequency(Link::uplink, *c.uplink_hz, guard.uplink_hz);
}

}  // namespace tb::radio
