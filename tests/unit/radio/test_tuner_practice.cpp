// Operating practice in the Tuner (issue 28): the other link moves once the knob has rested, RIT/XIT
// is never a turn, Doppler steps per mode, and the correction remembered per satellite and mode.
// Expected values are worked by hand from the formulas of docs/radio.md: heard F (1 - rr/c), sent
// F / (1 - rr/c), c = 299792.458 km/s, rounded to 10 Hz.
#include <doctest/doctest.h>

#include "radio/config.h"
#include "radio/doppler.h"
#include "satellites.h"

using namespace tb::radio;
using tbtest::full_orbit;
using tbtest::rs44;

namespace {

SatelliteRadio so50() {   // data/freqmode.txt: FM, 67.0 Hz tone
  SatelliteRadio s;
  s.downlink_hz = 436'795'000;
  s.uplink_hz = 145'850'000;
  s.downlink_mode = Mode::fm;
  s.uplink_mode = Mode::fm;
  s.ctcss_tenths_hz = 670;
  return s;
}

}  // namespace

TEST_CASE("Knob rest: the turned link follows the dial at once, the other link moves after 1 s without a turn") {
  Tuner t(full_orbit());
  t.select(rs44());
  const auto first = t.update(30.0, 0.0);
  REQUIRE(*first.downlink_hz == 435'640'000);
  REQUIRE(*first.uplink_hz == 145'965'000);
  CHECK_FALSE(t.settle_due_s());

  // At 10.0 s the operator has turned the downlink to 435.650 MHz: its spot moves, the uplink waits.
  CHECK(t.dial_turn(435'650'000, std::nullopt, 0.0, 10.0) == Tuner::Turn::downlink);
  CHECK(t.downlink_spot_hz() == 435'650'000);
  CHECK(t.uplink_spot_hz() == 145'965'000);
  CHECK(*t.settle_due_s() == doctest::Approx(11.0));
  const auto during = t.update(30.0, 0.0);
  CHECK_FALSE(during.downlink_hz);   // the radio is where the operator put it
  CHECK_FALSE(during.uplink_hz);     // the uplink has not moved yet
  // Still turning at 10.6 s (435.652 MHz): the rest starts again.
  CHECK(t.dial_turn(435'652'000, std::nullopt, 0.0, 10.6) == Tuner::Turn::downlink);
  CHECK_FALSE(t.settle(11.5));
  CHECK(t.uplink_spot_hz() == 145'965'000);
  CHECK(*t.settle_due_s() == doctest::Approx(11.6));
  // Rested: the uplink goes to the pair of 435.652 MHz on the inverting transponder, 145.953 MHz.
  CHECK(t.settle(11.6));
  CHECK(t.uplink_spot_hz() == 145'953'000);
  CHECK_FALSE(t.settle_due_s());
  const auto after = t.update(30.0, 0.0);
  CHECK_FALSE(after.downlink_hz);
  CHECK(*after.uplink_hz == 145'953'000);
}

TEST_CASE("Knob rest: neither link is written while the knob rests; then the other link's move goes first") {
  Tuner t(full_orbit());
  t.select(rs44());
  t.update(30.0, 0.0);
  CHECK(t.dial_turn(435'650'000, std::nullopt, 0.0, 10.0) == Tuner::Turn::downlink);
  // Approaching at 3 km/s: the downlink's Doppler moved 4.4 kHz, the uplink's 1.5 kHz. Nothing is
  // written during the rest: the downlink dial is the operator's, the uplink is about to jump.
  const auto during = t.update(30.0, -3.0);
  CHECK_FALSE(during.downlink_hz);
  CHECK_FALSE(during.uplink_hz);
  REQUIRE(t.settle(11.0));
  const auto after = t.update(30.0, -3.0);
  REQUIRE(after.uplink_hz);
  REQUIRE(after.downlink_hz);     // the downlink's Doppler step from where the operator put it
  CHECK(after.uplink_first);      // the move does not wait behind it on a slow line
  const auto next = t.update(30.0, -3.01);
  CHECK_FALSE(next.uplink_first);
  // The uplink dial turned: the downlink moves, and it goes first anyway.
  CHECK(t.dial_turn(std::nullopt, 145'950'000, -3.01, 20.0) == Tuner::Turn::uplink);
  REQUIRE(t.settle(21.0));
  const auto down_moved = t.update(30.0, -3.02);
  REQUIRE(down_moved.downlink_hz);
  CHECK_FALSE(down_moved.uplink_first);
}

TEST_CASE("Knob rest: settable; 0 moves the other link at once") {
  RadioConfig c = full_orbit();
  c.dial_rest_ms = 2500;
  Tuner t(c);
  t.select(rs44());
  t.update(30.0, 0.0);
  t.dial_turn(std::nullopt, 145'960'000, 0.0, 100.0);   // the uplink dial, 5 kHz down
  CHECK(t.uplink_spot_hz() == 145'960'000);
  CHECK(t.downlink_spot_hz() == 435'640'000);
  CHECK_FALSE(t.settle(102.4));
  CHECK(t.settle(102.5));
  CHECK(t.downlink_spot_hz() == 435'645'000);   // inverting: 5 kHz up

  c.dial_rest_ms = 0;
  t.set_config(c);
  t.update(30.0, 0.0);
  t.dial_turn(435'650'000, std::nullopt, 0.0, 200.0);
  CHECK(t.uplink_spot_hz() == 145'955'000);
  CHECK_FALSE(t.settle_due_s());
}

TEST_CASE("RIT/XIT is never a turn: both links moved together by the same amount leave the spots") {
  Tuner t(full_orbit());
  t.select(rs44());
  t.update(30.0, 0.0);   // sent 435,640,000 / 145,965,000
  // The IC-9700's RIT report: RX and TX both 11 kHz up.
  CHECK(t.dial_turn(435'651'000, 145'976'000, 0.0, 5.0) == Tuner::Turn::rit_xit);
  CHECK(t.downlink_spot_hz() == 435'640'000);
  CHECK(t.uplink_spot_hz() == 145'965'000);
  CHECK_FALSE(t.settle_due_s());
  // 11,000 and 11,030 Hz: within the two links' tolerances (20 + 20 Hz) of the same amount, still RIT.
  CHECK(t.dial_turn(435'651'000, 145'976'030, 0.0, 6.0) == Tuner::Turn::rit_xit);
  // The two dials in opposite directions (as the inverting pair would be) are a turn of the
  // downlink knob, which leads.
  CHECK(t.dial_turn(435'650'000, 145'955'000, 0.0, 7.0) == Tuner::Turn::downlink);
  CHECK(t.downlink_spot_hz() == 435'650'000);
}

TEST_CASE("Doppler steps per mode: SSB/CW 20 Hz, FM 100 Hz, settable") {
  Tuner t(full_orbit());
  t.select(rs44());
  CHECK(t.doppler_step(Mode::usb) == 20);
  CHECK(t.doppler_step(Mode::cw) == 20);
  CHECK(t.doppler_step(Mode::none) == 20);
  CHECK(t.doppler_step(Mode::fm) == 100);
  CHECK(*t.update(30.0, 0.0).downlink_hz == 435'640'000);
  // rr -0.010 km/s: heard 435,640,014.5 -> 435,640,010, 10 Hz: under the SSB step.
  CHECK_FALSE(t.update(30.0, -0.010).downlink_hz);
  // rr -0.014: 435,640,020.3 -> 435,640,020: sent.
  CHECK(*t.update(30.0, -0.014).downlink_hz == 435'640'020);

  Tuner f(full_orbit());
  f.select(so50());
  const auto first = f.update(30.0, 0.0);
  CHECK(*first.downlink_hz == 436'795'000);
  CHECK(*first.uplink_hz == 145'850'000);
  // rr -0.05: downlink 436,795,072.8 -> ...070 (70 Hz), uplink 145,849,975.7 -> ...980: neither.
  CHECK(f.update(30.0, -0.05).empty());
  // rr -0.07: downlink 436,795,102.0 -> ...100: sent; uplink ...970 (30 Hz): not.
  const auto moved = f.update(30.0, -0.07);
  CHECK(*moved.downlink_hz == 436'795'100);
  CHECK_FALSE(moved.uplink_hz);

  RadioConfig c = full_orbit();
  c.doppler_step_fm_hz = 500;
  c.doppler_step_ssb_hz = 5;   // below the tuning step: the 10 Hz step stands
  Tuner g(c);
  CHECK(g.doppler_step(Mode::lsb) == 10);
  g.select(so50());
  g.update(30.0, -0.07);
  // An FM step of 500 Hz holds the Doppler, but the operator's key goes out at once.
  CHECK(g.update(30.0, 0.0).empty());
  g.rit_up();
  CHECK(*g.update(30.0, 0.0).downlink_hz == 436'795'100);   // 436,795,000 + 100 Hz of RIT
}

TEST_CASE("The correction found for a satellite and mode is remembered, applied at its next pass, 0 forgets it") {
  Tuner t(full_orbit());
  t.select(so50(), "SO-50");
  CHECK(t.correction_key() == "SO-50 FM");
  CHECK_FALSE(t.correction_remembered());
  t.update(30.0, 0.0);
  t.rit_up();
  t.rit_up();
  t.rit_up();
  CHECK(t.config().corrections.at("SO-50 FM") == 300);
  CHECK(t.correction_remembered());
  CHECK(*t.update(30.0, 0.0).downlink_hz == 436'795'300);

  // Another satellite: no correction; SO-50 again: +300 Hz from the start.
  t.select(rs44(), "RS-44");
  CHECK(t.rit_hz() == 0);
  CHECK(t.correction_key() == "RS-44 USB");
  t.select(so50(), "SO-50");
  CHECK(t.rit_hz() == 300);
  CHECK(t.correction_remembered());
  const auto next_pass = t.update(30.0, -0.07);
  CHECK(*next_pass.downlink_hz == 436'795'400);   // 436,795,100 with its Doppler, + 300
  CHECK(*next_pass.uplink_hz == 145'849'970);     // the uplink does not carry the downlink's correction

  t.rit_zero();
  CHECK(t.config().corrections.empty());
  t.select(so50(), "SO-50");
  CHECK(t.rit_hz() == 0);
  // Without a name nothing is remembered.
  t.select(so50());
  t.rit_down();
  CHECK(t.config().corrections.empty());
}
