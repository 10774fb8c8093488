// What every radio driver shares (driver.h): the link names and sending a Tuner's commands.
#include "radio/driver.h"

namespace tb::radio {

const char* to_string(Link l) { return l == Link::downlink ? "downlink" : "uplink"; }

void apply(RadioDriver& radio, const TuneCommands& c) {
  if (c.downlink_mode) radio.set_mode(Link::downlink, *c.downlink_mode);
  if (c.downlink_hz) radio.set_frequency(Link::downlink, *c.downlink_hz);
  if (c.uplink_mode) radio.set_mode(Link::uplink, *c.uplink_mode);
  if (c.uplink_hz) radio.set_frequency(Link::uplink, *c.uplink_hz);
}

}  // namespace tb::radio
