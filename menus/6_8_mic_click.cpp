// 6-8: Mic click configuration. S sets the ADC3 centre and reference, the radio's step and the three
// AOS/polarity answers; M shows the live ADC3 reading against the configured centre and span.
#include <cstdio>

#include "menus/6_configuration.h"
#include "radio/doppler.h"
#include "radio/micclick.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

int simulated_adc3(const Services& s) {
  const radio::SimulatedDiscriminator disc;  // the modem's own centre, slope and capture range
  if (s.tracker.mode() == tracker::Mode::off) return disc.centre_adc;
  const tracker::SatNow* f = s.tracker.followed();
  if (!f || !f->obs.ok() || f->obs.look.el_deg < 0.0) return disc.centre_adc;  // nothing heard
  if (tracker::body_target(f->db_index)) return disc.centre_adc;  // the Sun or the Moon: no downlink
  const radio::SatelliteRadio& sat = s.model.db.satellites[static_cast<std::size_t>(f->db_index)].radio;
  if (!sat.has_downlink()) return disc.centre_adc;
  // Where the downlink arrives at the radio: Doppler-shifted RF plus the converter offset (a
  // high-side local oscillator turns the shift round), no RIT: that is the operator's.
  const radio::Corrections arrive{true, s.model.radio.downlink_correction == radio::DownlinkCorrection::reverse
                                            ? radio::DownlinkCorrection::reverse
                                            : radio::DownlinkCorrection::on};
  const radio::Tuning at = radio::compute_tuning(sat, arrive, f->obs.look.range_rate_km_s);
  const auto tuned = s.station.radio().status().downlink_hz;
  if (!at.downlink_radio_hz || !tuned) return disc.centre_adc;
  return disc.read(*at.downlink_radio_hz, *tuned);
}

void menu_6_8_mic_click(term::Terminal& t, Services& s) {
  const char how = cfg::ask_choice(t, "Set new value or Measure ADC value ? [S/M] ", "SM");
  if (how == 'M') {
    t.line("ADC3 value (any key to stop)");
    std::string shown;
    radio::SimulatedPulseOutput no_pulses;  // measuring only: nothing is sent
    for (;;) {
      const radio::MicClick loop(s.model.radio.mic_click, no_pulses);
      const radio::MicClickMeasure m = loop.measure(simulated_adc3(s));
      const std::string text = m.text();
      if (text != shown) {
        t.live({text});
        shown = text;
      }
      const int k = t.read_key(cfg::kLiveInterval);
      if (k == term::kEndOfInput) throw InputClosed{};
      if (k != term::kTimeout) break;
    }
    t.end_live();
    return;
  }
  radio::MicClickConfig c = s.model.radio.mic_click;
  c.centre_adc = static_cast<int>(cfg::ask_number(t, "Modem locked center ADC value: " + std::to_string(c.centre_adc) + "  ",
                                                  c.centre_adc, 0, radio::kAdcMax, true));
  for (;;) {
    c.reference_adc = static_cast<int>(cfg::ask_number(t, "Reference ADC value : " + std::to_string(c.reference_adc) + "  ",
                                                       c.reference_adc, 0, radio::kAdcMax, true));
    if (c.reference_adc != c.centre_adc) break;
    t.line("  The reference must differ from the center: their difference is the span left alone");
  }
  c.step_hz = static_cast<radio::Hz>(
      cfg::ask_number(t, "Enter Step Frequency [Hz]: ", static_cast<double>(c.step_hz), 1, 100000, true));
  c.cat_at_aos = cfg::ask_choice(t, "Frequency set CAT command at AOS ? [Y/N] ", "YN") == 'Y';
  c.auto_up_at_aos = cfg::ask_choice(t, "Automatic up pulse generation at AOS ? [Y/N] ", "YN") == 'Y';
  c.polarity = cfg::ask_choice(t, "Polarity of step pulse, Normal/Reverse? [N/R] ", "NR") == 'R'
                   ? radio::PulsePolarity::reverse
                   : radio::PulsePolarity::normal;
  (void)commit(t, s, store::bit(store::Area::radio), "menu 6-8", [&](store::Model& m) { m.radio.mic_click = c; });
}

}  // namespace tb::menus
