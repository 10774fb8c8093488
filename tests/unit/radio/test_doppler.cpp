#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "radio/doppler.h"

using namespace tb::radio;

namespace {

// Independent first-order Doppler, written from scratch for the cross-check:
// a source approaching at v sounds higher by f*v/c.
double first_order_shift(double f_hz, double range_rate_km_s) {
  const double c_m_s = 299792458.0;
  return -f_hz * (range_rate_km_s * 1000.0) / c_m_s;
}

// A satellite on a straight line past the station: closest approach d km at t = 0, speed v km/s.
// Range rate = v^2 t / r (+ receding).
double straight_line_range_rate(double t_s, double d_km = 500.0, double v_km_s = 7.6) {
  const double x = v_km_s * t_s;
  return v_km_s * x / std::sqrt(d_km * d_km + x * x);
}

SatelliteRadio iss_fm() {
  SatelliteRadio s;
  s.downlink_hz = 437'800'000;   // a 70 cm downlink
  s.uplink_hz = 145'990'000;
  s.downlink_mode = Mode::fm;
  s.uplink_mode = Mode::fm;
  return s;
}

}  // namespace

TEST_CASE("Doppler sign: approaching raises the downlink, the uplink is sent lower") {
  CHECK(downlink_heard_hz(435'000'000, -7.0) > 435'000'000.0);
  CHECK(downlink_heard_hz(435'000'000, 7.0) < 435'000'000.0);
  CHECK(uplink_send_hz(145'900'000, -7.0) < 145'900'000.0);
  CHECK(uplink_send_hz(145'900'000, 7.0) > 145'900'000.0);
  CHECK(downlink_doppler_hz(435'000'000, -7.0) > 0);
  // Sent uplink and heard downlink are exact inverses: what leaves the ground at
  // f/(1-rr/c) arrives at f.
  const double sent = uplink_send_hz(145'900'000, 6.5);
  CHECK(sent * (1.0 - 6.5 / kSpeedOfLightKmS) == doctest::Approx(145'900'000.0).epsilon(1e-15));
}

TEST_CASE("Doppler is about +/-10 kHz on 435 MHz for a low pass, matching first order") {
  for (double rr : {-7.0, -3.5, 0.0, 3.5, 7.0}) {
    const double exact = downlink_heard_hz(435'000'000, rr) - 435'000'000.0;
    CHECK(std::fabs(exact - first_order_shift(435e6, rr)) < 1.0);   // second order < 1 Hz
    const double up = uplink_send_hz(435'000'000, rr) - 435'000'000.0;
    CHECK(std::fabs(up + first_order_shift(435e6, rr)) < 1.0);
  }
  CHECK(downlink_doppler_hz(435'000'000, 7.0) == -10157);
  CHECK(downlink_doppler_hz(435'000'000, -7.0) == 10157);
  CHECK(std::abs(downlink_doppler_hz(435'000'000, 7.0)) > 9'500);
  CHECK(std::abs(downlink_doppler_hz(435'000'000, 7.0)) < 10'500);
}

TEST_CASE("Doppler goes through zero at closest approach") {
  CHECK(straight_line_range_rate(0.0) == 0.0);
  CHECK(downlink_doppler_hz(435'000'000, straight_line_range_rate(0.0)) == 0);
  const Tuning at_tca = compute_tuning(iss_fm(), {}, straight_line_range_rate(0.0));
  CHECK(at_tca.downlink_radio_hz == 437'800'000);
  CHECK(at_tca.uplink_radio_hz == 145'990'000);
  // Before: approaching, positive; after: receding, negative; monotonic through the pass.
  double previous = 1e9;
  for (int t = -600; t <= 600; t += 30) {
    const Hz d = downlink_doppler_hz(435'000'000, straight_line_range_rate(t));
    if (t < 0) CHECK(d > 0);
    if (t > 0) CHECK(d < 0);
    CHECK(d <= previous);
    previous = static_cast<double>(d);
  }
}

TEST_CASE("Quantised to 10 Hz, halves away from zero") {
  CHECK(quantise(435'123'444.9) == 435'123'440);
  CHECK(quantise(435'123'445.0) == 435'123'450);
  CHECK(quantise(-24'025.0) == -24'030);
  CHECK(quantise(-24'024.9) == -24'020);
  CHECK(quantise(1234.0, 100) == 1200);
}

TEST_CASE("Radio = RF + Doppler + offset; Doppler on the RF (AO-13 mode S)") {
  SatelliteRadio s;
  s.downlink_hz = 2'400'730'000;
  s.downlink_offset_hz = -2'256'000'000;
  s.uplink_hz = 435'620'000;
  const double rr = 3.0;
  const Tuning still = compute_tuning(s, {}, 0.0);
  CHECK(still.downlink_radio_hz == 144'730'000);   // the 2-metre frequency at the radio
  const Tuning t = compute_tuning(s, {}, rr);
  const double d_rf = first_order_shift(2'400'730'000.0, rr);   // about -24 kHz
  CHECK(t.downlink_doppler_hz == doctest::Approx(d_rf).epsilon(1e-6));
  CHECK(*t.downlink_radio_hz == quantise(144'730'000.0 + t.downlink_doppler_hz));
  CHECK(std::abs(*t.downlink_radio_hz - (144'730'000 - 24'024)) <= 10);
  // Not the IF: Doppler on 144.730 MHz would be only about 1.4 kHz.
  CHECK(std::abs(*t.downlink_radio_hz - 144'730'000) > 20'000);
  CHECK(*t.uplink_radio_hz == quantise(uplink_send_hz(435'620'000, rr)));
}

TEST_CASE("Downlink Reverse (high-side LO) turns the correction round") {
  SatelliteRadio s;
  s.downlink_hz = 2'400'730'000;
  s.downlink_offset_hz = -2'256'000'000;
  const double rr = -5.0;  // approaching: RF heard higher
  const Tuning normal = compute_tuning(s, {true, DownlinkCorrection::on}, rr);
  const Tuning reverse = compute_tuning(s, {true, DownlinkCorrection::reverse}, rr);
  const Tuning off = compute_tuning(s, {true, DownlinkCorrection::off}, rr);
  CHECK(*off.downlink_radio_hz == 144'730'000);
  CHECK(*normal.downlink_radio_hz > 144'730'000);
  CHECK(*reverse.downlink_radio_hz < 144'730'000);
  CHECK(*normal.downlink_radio_hz - 144'730'000 == 144'730'000 - *reverse.downlink_radio_hz);
}

TEST_CASE("Uplink and downlink corrections are separate") {
  const SatelliteRadio s = iss_fm();
  const Tuning t = compute_tuning(s, {false, DownlinkCorrection::on}, 6.0);
  CHECK(*t.uplink_radio_hz == 145'990'000);
  CHECK(*t.downlink_radio_hz != 437'800'000);
  // Unconfigured links have no frequency at all.
  SatelliteRadio none;
  const Tuning n = compute_tuning(none, {}, 6.0);
  CHECK_FALSE(n.downlink_radio_hz);
  CHECK_FALSE(n.uplink_radio_hz);
}

TEST_CASE("Linear transponder mapping in the satellite frame") {
  LinearTransponder inv{435'800'000, 435'900'000, 145'900'000, 146'000'000, true};
  CHECK(inv.uplink_for(435'850'000) == 145'950'000);
  CHECK(inv.uplink_for(435'800'000) == 146'000'000);
  CHECK(inv.downlink_for(146'000'000) == 435'800'000);
  LinearTransponder norm{435'800'000, 435'900'000, 145'900'000, 146'000'000, false};
  CHECK(norm.uplink_for(435'810'000) == 145'910'000);
  CHECK(norm.downlink_for(145'910'000) == 435'810'000);
}

TEST_CASE("Tuner: sends on change only, modes with the first frequency") {
  RadioConfig cfg;
  cfg.cat_policy = CatPolicy::full_orbit;
  Tuner tuner(cfg);
  tuner.select(iss_fm());
  auto c1 = tuner.update(10.0, -5.0);
  REQUIRE(c1.downlink_hz);
  REQUIRE(c1.uplink_hz);
  CHECK(c1.downlink_mode == Mode::fm);
  CHECK(c1.uplink_mode == Mode::fm);
  CHECK(c1.aos);
  CHECK(*c1.downlink_hz == quantise(downlink_heard_hz(437'800'000, -5.0)));
  // A change of range rate too small to move either link by 10 Hz: nothing to send.
  auto c2 = tuner.update(10.1, -5.0 + 1e-6);
  CHECK(c2.empty());
  // 0.1 km/s moves the FM uplink 48.7 Hz, under the FM Doppler step of 100 Hz: only the downlink
  // (146 Hz) goes.
  auto c2b = tuner.update(11.0, -4.9);
  CHECK(c2b.downlink_hz);
  CHECK_FALSE(c2b.uplink_hz);
  // A bigger change: both links, no modes this time.
  auto c3 = tuner.update(11.0, -4.7);
  CHECK(c3.downlink_hz);
  CHECK(c3.uplink_hz);
  CHECK_FALSE(c3.downlink_mode);
  CHECK_FALSE(c3.uplink_mode);
  CHECK(tuner.last_sent_downlink_hz() == c3.downlink_hz);
  // Over a pass, every command differs from the previous one and each is a multiple of 10 Hz.
  std::vector<Hz> sent;
  tuner.select(iss_fm());
  for (int t = -300; t <= 300; ++t) {
    auto c = tuner.update(20.0, straight_line_range_rate(t));
    if (c.downlink_hz) sent.push_back(*c.downlink_hz);
  }
  REQUIRE(sent.size() > 100);
  for (std::size_t i = 0; i < sent.size(); ++i) {
    CHECK(sent[i] % 10 == 0);
    if (i) CHECK(std::llabs(sent[i] - sent[i - 1]) >= 100);   // the FM Doppler step
  }
  // resend() after a reconnect: the value of now goes out again, with the mode.
  tuner.resend();
  auto again = tuner.update(20.0, straight_line_range_rate(300));
  CHECK(again.downlink_hz == quantise(downlink_heard_hz(437'800'000, straight_line_range_rate(300))));
  CHECK(again.downlink_mode == Mode::fm);
}

TEST_CASE("Tuner: RIT steps of 100 Hz on the downlink, carried through the pass") {
  RadioConfig cfg;
  cfg.cat_policy = CatPolicy::full_orbit;
  Tuner tuner(cfg);
  tuner.select(iss_fm());
  const auto base = tuner.update(30.0, 2.0);
  tuner.rit_up();
  tuner.rit_up();
  CHECK(tuner.rit_hz() == 200);
  const auto c = tuner.update(30.0, 2.0);
  CHECK(*c.downlink_hz == *base.downlink_hz + 200);
  CHECK_FALSE(c.uplink_hz);   // the uplink does not move with RIT
  // Later in the pass the RIT is still there.
  const auto later = tuner.update(20.0, 4.0);
  CHECK(*later.downlink_hz ==
        quantise(downlink_heard_hz(437'800'000, 4.0)) + 200);
  tuner.rit_down();
  CHECK(*tuner.update(20.0, 4.0).downlink_hz == quantise(downlink_heard_hz(437'800'000, 4.0)) + 100);
  tuner.rit_zero();
  CHECK(*tuner.update(20.0, 4.0).downlink_hz == quantise(downlink_heard_hz(437'800'000, 4.0)));
  tuner.rit_down();
  tuner.select(iss_fm());   // a new satellite forgets the RIT
  CHECK(tuner.rit_hz() == 0);
}

TEST_CASE("Tuner: AOS-only policy (elevation >= -2.0 deg)") {
  RadioConfig cfg;
  cfg.cat_policy = CatPolicy::aos_only;
  Tuner tuner(cfg);
  tuner.select(iss_fm());
  CHECK(tuner.update(-10.0, -7.0).empty());
  CHECK(tuner.update(-2.01, -7.0).empty());
  // The display still gets the computed values.
  CHECK(tuner.last_tuning().downlink_radio_hz);
  auto aos = tuner.update(-2.0, -7.0);
  CHECK(aos.aos);
  CHECK(aos.downlink_hz);
  CHECK(aos.downlink_mode == Mode::fm);
  CHECK_FALSE(tuner.update(5.0, -6.0).aos);
  CHECK(tuner.update(-3.0, 7.0).empty());   // LOS: nothing more
  // Next AOS: sent again even though the value is the one last sent.
  auto next = tuner.update(-1.0, -6.0);
  CHECK(next.aos);
  CHECK(next.downlink_hz);
  // Full orbit: sent below the horizon too.
  cfg.cat_policy = CatPolicy::full_orbit;
  tuner.set_config(cfg);
  CHECK(tuner.update(-40.0, 3.0).downlink_hz);
}

TEST_CASE("Tuner: a link whose correction is off is not sent") {
  RadioConfig cfg;
  cfg.cat_policy = CatPolicy::full_orbit;
  cfg.uplink_correction = false;
  Tuner tuner(cfg);
  tuner.select(iss_fm());
  auto c = tuner.update(10.0, 1.0);
  CHECK(c.downlink_hz);
  CHECK_FALSE(c.uplink_hz);
  CHECK_FALSE(c.uplink_mode);
  cfg.uplink_correction = true;
  cfg.downlink_correction = DownlinkCorrection::off;
  tuner.set_config(cfg);
  c = tuner.update(10.0, 1.0);
  CHECK_FALSE(c.downlink_hz);
  CHECK(c.uplink_hz);
  // Nothing configured: nothing computed, nothing sent.
  tuner.select(SatelliteRadio{});
  CHECK(tuner.update(10.0, 1.0).empty());
}

TEST_CASE("Tuner: mic-click satellites get one CAT command at AOS") {
  SatelliteRadio s = iss_fm();
  s.doppler = DopplerControl::mic_click;
  RadioConfig cfg;
  cfg.cat_policy = CatPolicy::full_orbit;
  cfg.mic_click.cat_at_aos = true;
  cfg.mic_click.auto_up_at_aos = false;
  Tuner tuner(cfg);
  tuner.select(s);
  CHECK(tuner.update(-5.0, -7.0).empty());   // mic-click: nothing before AOS, even full orbit
  auto aos = tuner.update(-1.5, -7.0);
  CHECK(aos.aos);
  CHECK(*aos.downlink_hz == quantise(downlink_heard_hz(437'800'000, -7.0)));
  CHECK(aos.uplink_hz);
  CHECK_FALSE(aos.aos_pulse_correction_hz);
  CHECK(tuner.update(10.0, -6.0).empty());   // then nothing: the pulses do the work

  // With automatic up pulses: the radio is set to the nominal frequency and the pulses carry the
  // AOS Doppler (positive while approaching).
  cfg.mic_click.auto_up_at_aos = true;
  tuner.set_config(cfg);
  tuner.select(s);
  auto aos2 = tuner.update(0.0, -7.0);
  CHECK(*aos2.downlink_hz == 437'800'000);
  REQUIRE(aos2.aos_pulse_correction_hz);
  CHECK(*aos2.aos_pulse_correction_hz == quantise(downlink_heard_hz(437'800'000, -7.0)) - 437'800'000);
  CHECK(*aos2.aos_pulse_correction_hz > 10'000);

  // Without "frequency set by CAT at AOS": pulses only.
  cfg.mic_click.cat_at_aos = false;
  tuner.set_config(cfg);
  tuner.select(s);
  auto aos3 = tuner.update(0.0, -7.0);
  CHECK_FALSE(aos3.downlink_hz);
  CHECK_FALSE(aos3.uplink_hz);
  CHECK(aos3.aos_pulse_correction_hz);
}
