// Satellite records and a radio configuration the Tuner tests share.
#pragma once
#include "radio/config.h"

namespace tbtest {

// RS-44 as data/freqmode.txt has it: an inverting linear transponder.
inline tb::radio::SatelliteRadio rs44() {
  tb::radio::SatelliteRadio s;
  s.downlink_hz = 435'640'000;
  s.uplink_hz = 145'965'000;
  s.downlink_mode = tb::radio::Mode::usb;
  s.uplink_mode = tb::radio::Mode::lsb;
  s.downlink_low_hz = 435'610'000;
  s.downlink_high_hz = 435'670'000;
  s.uplink_low_hz = 145'935'000;
  s.uplink_high_hz = 145'995'000;
  s.inverting = true;
  return s;
}

// The factory configuration with CAT for the full orbit (the tests tune at any elevation).
inline tb::radio::RadioConfig full_orbit() {
  tb::radio::RadioConfig c;
  c.cat_policy = tb::radio::CatPolicy::full_orbit;
  return c;
}

}  // namespace tbtest
