// The later firmware's radio items the Tuner acts on: radio parking after LOS (STATION.DAT line 6),
// the FREQ.DAT `ir`/`kr` swap of the two radios or VFOs, and the CAT port speed (line 4).
#include <doctest/doctest.h>

#include <tuple>
#include <utility>

#include "radio/icom/link.h"
#include "radio/kenwood/link.h"
#include "radio/yaesu/link.h"
#include "radio/config.h"
#include "radio/doppler.h"

using namespace tb::radio;

namespace {

// FO-29-like linear transponder, CAT, no Doppler (range rate 0) so the numbers are the nominal ones.
SatelliteRadio linear() {
  SatelliteRadio s;
  std::tie(s.downlink_mode, s.uplink_mode) = std::pair(Mode::usb, Mode::lsb);
  std::tie(s.downlink_hz, s.uplink_hz) = std::pair<Hz, Hz>(435'850'000, 145'950'000);
  return s;
}

RadioConfig parking_config() {
  RadioConfig c;
  c.cat_policy = CatPolicy::full_orbit;   // parking must win over Full-orbit Doppler below the horizon
  c.parking = {true, 145'800'000, 145'990'000, Mode::fm, Mode::fm};
  return c;
}

}  // namespace

TEST_CASE("Radio parking: the parking frequencies once at LOS, nothing until AOS, then the satellite again") {
  Tuner t(parking_config());
  t.select(linear());
  const auto up = t.update(20.0, 0.0);
  REQUIRE(up.downlink_hz);
  CHECK(*up.downlink_hz == 435'850'000);
  CHECK(*up.uplink_hz == 145'950'000);
  CHECK_FALSE(t.parked());

  const auto los = t.update(-2.5, 0.0);   // below the AOS rule's -2.0 deg
  REQUIRE(los.downlink_hz);
  CHECK(*los.downlink_hz == 145'800'000);
  CHECK(*los.downlink_mode == Mode::fm);
  CHECK(*los.uplink_hz == 145'990'000);
  CHECK(*los.uplink_mode == Mode::fm);
  CHECK(t.parked());
  CHECK(t.update(-10.0, 3.0).empty());     // parked: Full-orbit Doppler does not move the radio
  CHECK(t.update(-30.0, 5.0).empty());

  const auto aos = t.update(-1.0, 0.0);
  CHECK(aos.aos);
  CHECK(*aos.downlink_hz == 435'850'000);
  CHECK(*aos.downlink_mode == Mode::usb);   // the satellite's modes again after the parking modes
  CHECK(*aos.uplink_mode == Mode::lsb);
  CHECK_FALSE(t.parked());
}

TEST_CASE("Radio parking: a first tick below the horizon parks; a zero frequency or mode None is not sent") {
  RadioConfig c = parking_config();
  c.parking.tx_hz = 0;
  c.parking.rx_mode = Mode::none;
  Tuner t(c);
  t.select(linear());
  const auto first = t.update(-20.0, 1.0);
  CHECK(*first.downlink_hz == 145'800'000);
  CHECK_FALSE(first.downlink_mode);
  CHECK_FALSE(first.uplink_hz);
  CHECK(*first.uplink_mode == Mode::fm);
}

TEST_CASE("Radio parking off: below the horizon the policy decides, as before") {
  RadioConfig c = parking_config();
  c.parking.enabled = false;
  Tuner t(c);
  t.select(linear());
  const auto below = t.update(-20.0, 0.0);
  CHECK(*below.downlink_hz == 435'850'000);   // Full orbit: Doppler below the horizon too
  CHECK_FALSE(t.parked());
}

TEST_CASE("FREQ.DAT ir on an Icom rig swaps main and sub; on a Kenwood rig it does nothing") {
  SatelliteRadio s = linear();
  s.reverse = ReverseAssignment::icom_main_sub;
  RadioConfig c;
  c.rig = Rig::icom;
  c.cat_policy = CatPolicy::full_orbit;
  Tuner icom(c);
  icom.select(s);
  CHECK(icom.reversed());
  const auto swapped = icom.update(10.0, 0.0);
  CHECK(*swapped.downlink_hz == 145'950'000);      // the downlink's radio gets the uplink
  CHECK(*swapped.downlink_mode == Mode::lsb);
  CHECK(*swapped.uplink_hz == 435'850'000);
  CHECK(*swapped.uplink_mode == Mode::usb);
  CHECK(*icom.last_sent_downlink_hz() == 435'850'000);  // the Tuner's own links keep their meaning
  CHECK_FALSE(swapped.uplink_first);                    // an ordinary update: downlink radio first

  c.rig = Rig::kenwood;
  Tuner kenwood(c);
  kenwood.select(s);
  CHECK_FALSE(kenwood.reversed());
  CHECK(*kenwood.update(10.0, 0.0).downlink_hz == 435'850'000);

  s.reverse = ReverseAssignment::kenwood_vfo;
  kenwood.select(s);
  CHECK(kenwood.reversed());
  CHECK(*kenwood.update(10.0, 0.0).downlink_hz == 145'950'000);
}

TEST_CASE("CAT port speed: the configured one, else the rig's standard") {
  RadioConfig c;
  CHECK(c.cat_baud == 0);
  CHECK(effective_cat_baud(c) == 0);   // no rig
  c.rig = Rig::icom;
  CHECK(effective_cat_baud(c) == 1200);
  c.rig = Rig::kenwood;
  CHECK(effective_cat_baud(c) == 4800);
  c.rig = Rig::yaesu;
  CHECK(effective_cat_baud(c) == 4800);
  c.cat_baud = 19200;
  CHECK(effective_cat_baud(c) == 19200);
  CHECK(IcomOptions::from(c).baud == 19200);
  CHECK(KenwoodOptions::from(c).baud == 19200);
  CHECK(YaesuOptions::from(c).baud == 19200);
}
