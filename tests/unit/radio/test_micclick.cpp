// Mic-click: the closed loop of menu 6-8 watched closing on a simulated discriminator.
#include <doctest/doctest.h>

#include <cmath>

#include "radio/doppler.h"
#include "radio/micclick.h"
#include "radio/simulated.h"

using namespace tb::radio;

TEST_CASE("Mic-click factory values are the manual's") {
  MicClickConfig c;
  CHECK(c.centre_adc == 550);
  CHECK(c.reference_adc == 560);
  CHECK(c.span() == 10);
  CHECK(c.step_hz == 100);
  CHECK(c.polarity == PulsePolarity::normal);
  RadioConfig r;
  CHECK(r.rig == Rig::none);
  CHECK(r.icom_rx_address == 0x00);
  CHECK(r.icom_tx_address == 0x00);
  CHECK(r.cat_policy == CatPolicy::aos_only);
}

TEST_CASE("Pulses outside the span only; polarity swaps them") {
  SimulatedPulseOutput out;
  MicClickConfig c;   // centre 550, reference 560: span 10
  MicClick mc(c, out);
  CHECK_FALSE(mc.step(550));
  CHECK_FALSE(mc.step(560));
  CHECK_FALSE(mc.step(540));
  CHECK(mc.step(561) == Pulse::up);
  CHECK(mc.step(539) == Pulse::down);
  CHECK(out.pulses() == std::vector<Pulse>{Pulse::up, Pulse::down});
  c.polarity = PulsePolarity::reverse;
  mc.set_config(c);
  CHECK(mc.step(700) == Pulse::down);
  CHECK(mc.step(0) == Pulse::up);
  // The manual's example entries: centre 525, reference 500 (below the centre works the same).
  c = {};
  c.centre_adc = 525;
  c.reference_adc = 500;
  c.step_hz = 50;
  mc.set_config(c);
  CHECK(c.span() == 25);
  CHECK_FALSE(mc.step(549));
  CHECK(mc.step(551) == Pulse::up);
  CHECK(mc.decide(400) == Pulse::down);
  CHECK(mc.net_pulses() == 1);   // up, down, down, up, up
}

TEST_CASE("Measure reports the ADC value against the centre") {
  SimulatedPulseOutput out;
  MicClick mc({}, out);
  auto m = mc.measure(548);
  CHECK(m.locked);
  CHECK(m.error == -2);
  CHECK(m.text() == "ADC3=  548 center 550 span 10: locked");
  CHECK(mc.measure(700).text() == "ADC3=  700 center 550 span 10: above");
  CHECK(mc.measure(12).text() == "ADC3=   12 center 550 span 10: below");
  CHECK(out.pulses().empty());   // measuring sends nothing
}

TEST_CASE("Simulated discriminator: linear in the capture range, silent outside, clamped") {
  SimulatedDiscriminator d;   // centre 550, 40 counts/kHz, capture 5 kHz
  CHECK(d.read(435'000'000, 435'000'000) == 550);
  CHECK(d.read(435'001'000, 435'000'000) == 590);
  CHECK(d.read(434'999'000, 435'000'000) == 510);
  CHECK(d.read(435'010'000, 435'000'000) == 550);   // out of capture: nothing heard
  d.counts_per_khz = 400;
  CHECK(d.read(435'004'000, 435'000'000) == 1023);
  CHECK(d.read(434'996'000, 435'000'000) == 0);
  d.inverted = true;
  CHECK(d.read(434'999'900, 435'000'000) == 590);
}

TEST_CASE("AOS pre-correction: round(correction / step) pulses, up while approaching") {
  SimulatedRadio radio;
  radio.set_downlink_frequency(437'025'000);
  SimulatedPulseOutput out(100, &radio);
  MicClick mc({}, out);
  CHECK(mc.pre_correct(10'157) == 102);
  CHECK(out.net_steps() == 102);
  CHECK(radio.frequency(Link::downlink) == 437'035'200);
  CHECK(mc.pre_correct(-249) == -2);
  CHECK(mc.net_correction_hz() == 10'000);
  CHECK(mc.pre_correct(40) == 0);
}

namespace {

struct PassResult {
  int first_lock_tick = -1;
  int locked_ticks = 0;
  int ticks = 0;
  Hz worst_residual_after_lock = 0;
  Hz final_residual = 0;
};

// A pass of AO-16 (437.025 MHz PSK downlink, mic-click): range rate from -6.5 km/s at AOS to
// +6.5 km/s at LOS over ten minutes, the loop read five times a second.
// The operator's dial starts on the nominal frequency.
PassResult run_pass(const RadioConfig& cfg, SimulatedDiscriminator disc, bool pre_correct) {
  SatelliteRadio sat;
  sat.downlink_hz = 437'025'000;
  sat.uplink_hz = 145'940'000;
  sat.downlink_mode = Mode::usb;
  sat.uplink_mode = Mode::fm;
  sat.doppler = DopplerControl::mic_click;

  SimulatedRadio radio;
  radio.set_downlink_frequency(sat.downlink_hz);
  SimulatedPulseOutput out(cfg.mic_click.step_hz, &radio);
  MicClick mc(cfg.mic_click, out);
  RadioConfig tcfg = cfg;
  tcfg.mic_click.auto_up_at_aos = pre_correct;
  Tuner tuner(tcfg);
  tuner.select(sat);

  PassResult r;
  const int seconds = 600;
  bool locked_once = false;
  for (int tick = 0; tick <= seconds * 5; ++tick) {
    const double t = tick / 5.0;
    const double rr = -6.5 + 13.0 * t / seconds;
    if (tick % 5 == 0) {   // the tracker's once-a-second tick
      const auto cmds = tuner.update(10.0, rr);
      apply(radio, cmds);
      if (cmds.aos_pulse_correction_hz) mc.pre_correct(*cmds.aos_pulse_correction_hz);
    }
    const Hz signal = std::llround(downlink_heard_hz(sat.downlink_hz, rr));
    const Hz tuned = *radio.frequency(Link::downlink);
    mc.step(disc.read(signal, tuned));
    const Hz residual = signal - *radio.frequency(Link::downlink);
    ++r.ticks;
    const bool in_span = std::abs(disc.read(signal, *radio.frequency(Link::downlink)) - disc.centre_adc) <=
                         cfg.mic_click.span() && std::llabs(residual) < disc.capture_hz;
    if (in_span) {
      if (r.first_lock_tick < 0) r.first_lock_tick = tick;
      ++r.locked_ticks;
      locked_once = true;
    }
    if (locked_once) r.worst_residual_after_lock = std::max<Hz>(r.worst_residual_after_lock, std::llabs(residual));
    r.final_residual = residual;
  }
  return r;
}

}  // namespace

TEST_CASE("The loop closes: CAT at AOS, pre-correction pulses, then it follows the Doppler") {
  RadioConfig cfg;
  cfg.mic_click.cat_at_aos = true;
  SimulatedDiscriminator disc;
  const PassResult r = run_pass(cfg, disc, true);
  // Pre-corrected to within a step, then held within the dead span (10 counts = 250 Hz) plus one
  // step all pass long while the Doppler sweeps through 19 kHz.
  CHECK(r.locked_ticks > r.ticks * 95 / 100);
  CHECK(r.worst_residual_after_lock <= 250 + 100);
  CHECK(std::llabs(r.final_residual) <= 350);
}

TEST_CASE("Without pre-correction or CAT the AOS Doppler is outside the capture range") {
  RadioConfig cfg;
  SimulatedDiscriminator disc;
  // CAT at AOS without pulses: the CAT command carries the Doppler, so it locks at once.
  cfg.mic_click.cat_at_aos = true;
  const PassResult cat = run_pass(cfg, disc, false);
  CHECK(cat.first_lock_tick == 0);
  CHECK(cat.locked_ticks > cat.ticks * 95 / 100);
  // Neither: the radio stays on the nominal frequency, 14 kHz from the signal; the modem hears
  // nothing until the Doppler has swept to within the capture range near closest approach.
  cfg.mic_click.cat_at_aos = false;
  const PassResult none = run_pass(cfg, disc, false);
  CHECK(none.first_lock_tick > 5 * 120);
  CHECK(none.locked_ticks < none.ticks * 75 / 100);
  // Pulses alone (no CAT): the pre-correction lands it in the capture range at AOS.
  const PassResult pulses = run_pass(cfg, disc, true);
  CHECK(pulses.first_lock_tick == 0);
}

TEST_CASE("Wrong polarity runs away; Reverse fixes an inverted discriminator") {
  RadioConfig cfg;
  SimulatedDiscriminator inverted;
  inverted.inverted = true;
  const PassResult wrong = run_pass(cfg, inverted, true);
  CHECK(wrong.locked_ticks < wrong.ticks / 10);
  cfg.mic_click.polarity = PulsePolarity::reverse;
  const PassResult right = run_pass(cfg, inverted, true);
  CHECK(right.locked_ticks > right.ticks * 95 / 100);
}
