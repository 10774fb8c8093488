// Doppler: from the satellite's range rate to the frequencies the radios are tuned to.
// Pure: values in, values out; no clock, no I/O.
//
// The rules (docs/radio.md has the derivation):
//  - The frequency at the satellite is held constant on both links (the "one true rule"): the
//    satellite transmits F1 and must receive F2, whatever the geometry.
//  - Doppler is computed on the RF frequency, never on the converter IF.
//      downlink heard   f_rx = F1 * (1 - rr/c)
//      uplink sent      f_tx = F2 / (1 - rr/c)        rr in km/s, + receding, c = 299792.458
//  - The radio is tuned to RF + Doppler + offset; downlink Reverse (high-side LO) applies the
//    Doppler with the opposite sign: F1 - (f_rx - F1) + offset.
//  - The operator's RIT (+/-100 Hz steps, realtime + / - / 0) is added to the downlink at the
//    radio and carried through the pass until 0 or a new satellite.
//  - Uplink and downlink correction are enabled separately; a link that is off is not sent.
//  - CAT for the full orbit, or only at AOS (elevation >= -2.0 deg).
//  - What is sent is quantised to 10 Hz and sent when it moved at least the mode's Doppler step from
//    the last value sent (RadioConfig: SSB/CW 20 Hz, FM 100 Hz).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "radio/config.h"

namespace tb::radio {

inline constexpr double kSpeedOfLightKmS = 299792.458;
inline constexpr double kAosElevationDeg = -2.0;   // the manual's AOS rule
inline constexpr Hz kRitStepHz = 100;              // realtime '+' / '-'

inline bool at_aos(double elevation_deg) { return elevation_deg >= kAosElevationDeg; }

// Exact first principles, in Hz (double: 53 bits hold 10 GHz to well below 1 mHz).
double downlink_heard_hz(Hz sent_hz, double range_rate_km_s);    // F1 (1 - rr/c)
double uplink_send_hz(Hz wanted_at_sat_hz, double range_rate_km_s);  // F2 / (1 - rr/c)
// Round to the nearest multiple of step (halves away from zero). step > 0.
Hz quantise(double hz, Hz step = kTuningStepHz);

// The Doppler shown on the realtime display: heard - sent on the RF downlink, rounded to 1 Hz.
// Positive while the satellite approaches.
Hz downlink_doppler_hz(Hz downlink_hz, double range_rate_km_s);

// A linear transponder's passbands, for mapping uplink and downlink in the satellite's frame
// before Doppler (normal: up = up_low + (down - down_low); inverting: up = up_high - (...)).
struct LinearTransponder {
  Hz downlink_low_hz = 0, downlink_high_hz = 0;
  Hz uplink_low_hz = 0, uplink_high_hz = 0;
  bool inverting = true;
  Hz uplink_for(Hz downlink_hz) const;
  Hz downlink_for(Hz uplink_hz) const;
  bool downlink_inside(Hz hz) const { return hz >= downlink_low_hz && hz <= downlink_high_hz; }
  bool uplink_inside(Hz hz) const { return hz >= uplink_low_hz && hz <= uplink_high_hz; }
};
// The satellite's transponder when its record gives the passbands (SatelliteRadio::has_passbands).
std::optional<LinearTransponder> transponder_of(const SatelliteRadio& sat);

// Dial follow: how far the radio's frequency may stray from what trakbox last set before it counts
// as the operator's turn of the dial: two tuning steps (the radio's own rounding) plus the change of
// the Doppler correction over about a second (trakbox's next command may be in flight), rounded up.
Hz dial_tolerance_hz(double doppler_change_per_s_hz, Hz step = kTuningStepHz);
// The radio reads read_hz where trakbox last set last_set_hz: did the operator turn the dial?
inline bool dial_turned(Hz read_hz, Hz last_set_hz, Hz tolerance_hz) {
  const Hz d = read_hz - last_set_hz;
  return d > tolerance_hz || -d > tolerance_hz;
}

struct Corrections {
  bool uplink = true;
  DownlinkCorrection downlink = DownlinkCorrection::on;
  static Corrections from(const RadioConfig& c) { return {c.uplink_correction, c.downlink_correction}; }
};

// One evaluation of the rules. The radio frequencies are quantised to 10 Hz; a link whose RF
// frequency is not configured (0) has no value. A link whose correction is off still gets its
// nominal radio frequency here (RF + offset, + RIT for the downlink) for displays; whether it is
// sent is the Tuner's business.
struct Tuning {
  std::optional<Hz> downlink_radio_hz;
  std::optional<Hz> uplink_radio_hz;
  double downlink_doppler_hz = 0.0;   // RF: heard - F1 (0 without a downlink)
  double uplink_doppler_hz = 0.0;     // RF: sent - F2 (0 without an uplink)
};
Tuning compute_tuning(const SatelliteRadio& sat, const Corrections& corr, double range_rate_km_s,
                      Hz rit_hz = 0, Hz xit_hz = 0);

// The offsets an operator may set (the page, host mode): at most this far from the computed value.
inline constexpr Hz kMaxOffsetHz = 100'000;

// What to tell the radio on one tracking tick. Empty when nothing changed.
struct TuneCommands {
  std::optional<Hz> downlink_hz;
  std::optional<Hz> uplink_hz;
  std::optional<Mode> downlink_mode;   // sent before the frequency of the same link
  std::optional<Mode> uplink_mode;
  bool aos = false;                    // this tick is the AOS edge (or the first tick at AOS)
  // The other link's move after a turn of the dial (Tuner::settle) goes out before the turned
  // link's Doppler step, so that on a slow line it does not wait behind it.
  bool uplink_first = false;
  // Mic-click satellites with "automatic up pulse generation at AOS": the correction the pulses
  // must make at the radio (the radio was set to the nominal frequency by CAT, if at all).
  std::optional<Hz> aos_pulse_correction_hz;
  bool empty() const {
    return !downlink_hz && !uplink_hz && !downlink_mode && !uplink_mode &&
           !aos_pulse_correction_hz;
  }
};

// The stateful part: remembers the selected satellite, the operator's RIT and what was last sent,
// and decides what goes to the radio each tick.
//  - CAT satellites: every tick the policy allows, each enabled link is sent when its quantised
//    value differs from the last one sent. The mode goes out with a link's first frequency (and
//    again after each AOS edge). At each AOS edge what was sent is forgotten so the first command
//    at AOS is always sent (the operator may have turned the dial meanwhile).
//  - Mic-click satellites: frequencies by CAT once at the AOS edge if "frequency set CAT at AOS"
//    is on; with "automatic up pulses" on, the downlink is set to its nominal frequency and the
//    Doppler at AOS is left to the pulses (aos_pulse_correction_hz).
class Tuner {
 public:
  explicit Tuner(const RadioConfig& config = {});

  void set_config(const RadioConfig& config);
  const RadioConfig& config() const { return config_; }

  // A new satellite: forgets what was sent and the RIT. With its name, the correction remembered for
  // it and its downlink mode (RadioConfig::corrections) is applied as the RIT at once; with the name
  // of its mode too (issue 59), both corrections are the mode's ("RS-44 FT4").
  void select(const SatelliteRadio& sat, std::string_view name = {}, std::string_view mode = {});
  // The key of the correction remembered for the selected satellite ("SO-50 FM"), empty without a name.
  const std::string& correction_key() const { return correction_key_; }
  // Whether the RIT in force came from a remembered correction or was set this pass.
  bool correction_remembered() const { return !correction_key_.empty() && config_.corrections.contains(correction_key_); }
  const SatelliteRadio& satellite() const { return sat_; }

  // The operator stepped to another uplink channel of the same satellite: the uplink is sent
  // again on the next update; the downlink and the RIT stay.
  void set_uplink(Hz uplink_hz) {
    sat_.uplink_hz = uplink_hz;
    sent_up_.reset();
  }

  // The realtime + / - / 0 keys. On a linear transponder followed by the dial (dial_follow_active)
  // they move the spot itself, both links together, by 100 Hz (0 takes back what they added);
  // otherwise they are the manual's RIT on the downlink radio.
  void rit_up() { move_rit(kRitStepHz); }
  void rit_down() { move_rit(-kRitStepHz); }
  void rit_zero() { move_rit(-rit_hz_); }
  Hz rit_hz() const { return rit_hz_; }
  // The operator's offsets (the page's RX and TX, host mode's OFFSET): the RX offset is the RIT
  // above (on a transponder followed by the dial it moves the spot, as + / - do); the TX offset is
  // added to the uplink radio's frequency. Both are remembered per satellite and mode
  // (RadioConfig::corrections, tx_corrections); 0 forgets. |offset| <= kMaxOffsetHz (the caller checks).
  void set_offsets(std::optional<Hz> rx_hz, std::optional<Hz> tx_hz);
  Hz xit_hz() const { return xit_hz_; }
  // The key of the TX correction ("RS-44 USB": the uplink's mode), empty without a name.
  const std::string& tx_correction_key() const { return tx_correction_key_; }
  // A linear transponder's passband position: the downlink spot moves to downlink_spot_hz and the
  // uplink to its pair (the transponder's rule). False, nothing changed, without passbands or when
  // the spot is outside the downlink passband.
  bool set_spot(Hz downlink_spot_hz);
  // The uplink's CTCSS tone of the selected satellite (tenths of Hz, 0: none).
  void set_tone(int tenths_hz) { sat_.ctcss_tenths_hz = tenths_hz; }

  // Dial follow: on for a CAT satellite with passbands while RadioConfig::dial_follow is set.
  bool dial_follow_active() const;
  // The spot, in the satellite's frame (RF Hz at the satellite): where the links are now. It starts
  // at the record's F1/F2 and moves with the operator's dial and, on a transponder, the + / - keys.
  Hz downlink_spot_hz() const { return sat_.downlink_hz + (dial_follow_active() ? 0 : rit_hz_); }
  Hz uplink_spot_hz() const { return sat_.uplink_hz; }
  // The operator turned a link's dial to radio_hz (read back from the radio) at range rate rr: the
  // spot of that link becomes the satellite-frame frequency the radio now hears (or sends), the
  // other link moves to the paired spot of the transponder, and the next update sends from there.
  // A reading that puts the spot further than one passband width outside the passband is no turn
  // across the transponder (another band, a radio that reads another VFO): nothing changes, false.
  // These two take the turn as rested: the other link moves at once.
  bool dial_downlink(Hz radio_hz, double range_rate_km_s);
  bool dial_uplink(Hz radio_hz, double range_rate_km_s);

  // Operating practice: the readings of one tick (either or both links may have been turned), at
  // now_s (seconds on any steady clock). The turned link's spot follows the dial at once, so the
  // operator's frequency is never undone; the other link keeps its spot until the knob has rested
  // RadioConfig::dial_rest_ms (no further turn), then settle() moves it to the paired spot. Both links
  // moved together by the same amount is RIT/XIT (the IC-9700's RIT moves RX and TX in one report),
  // never a turn: nothing moves.
  enum class Turn { none, downlink, uplink, rit_xit, outside };
  Turn dial_turn(std::optional<Hz> downlink_read_hz, std::optional<Hz> uplink_read_hz, double range_rate_km_s,
                 double now_s);
  // Moves the waiting link once the knob has rested; true when it did.
  bool settle(double now_s);
  // When the waiting link will move (seconds on the caller's clock), nothing when none waits.
  std::optional<double> settle_due_s() const;
  // The Doppler step of a mode (RadioConfig::doppler_step_*): the least change sent.
  Hz doppler_step(Mode mode) const;
  // dial_tolerance_hz of a link for the last update's Doppler change (0 before two updates).
  Hz dial_tolerance_downlink_hz() const;
  Hz dial_tolerance_uplink_hz() const;

  // The commands of one tick. With radio parking on (RadioConfig::parking, the later firmware's
  // STATION.DAT line 6), from LOS (or a first tick below the horizon) to the next AOS the radios get
  // the parking frequencies and modes once and nothing else. With the satellite's FREQ.DAT `ir` on
  // an Icom rig, or `kr` on a Kenwood rig (menu 6-7), the two links swap radios (main/sub) or VFOs:
  // the downlink's commands go to the uplink's radio and the other way round.
  TuneCommands update(double elevation_deg, double range_rate_km_s);
  bool parked() const { return parked_; }    // the last update was between LOS and AOS, parking on
  bool reversed() const;                     // the links swap radios for this satellite and rig

  // Forget what was sent, e.g. after the radio link reconnected: the next update sends again.
  void resend();

  const Tuning& last_tuning() const { return tuning_; }
  std::optional<Hz> last_sent_downlink_hz() const { return sent_down_; }
  std::optional<Hz> last_sent_uplink_hz() const { return sent_up_; }

 private:
  TuneCommands compute(double elevation_deg, double range_rate_km_s);  // update() without the two above
  void move_rit(Hz delta_hz);
  // A turn of one link's dial: its spot follows; the other link's pairs now (rested) or at settle().
  bool turn(bool downlink, Hz radio_hz, double rr, std::optional<double> now_s);
  void pair_from(bool downlink);

  struct Waiting {
    bool downlink_turned;   // which knob was turned: the other link waits
    double last_turn_s;
  };
  std::optional<Waiting> waiting_;
  // Which link pair_from() just moved (true: the uplink, in the satellite's terms): it goes first at
  // the next update.
  std::optional<bool> moved_uplink_;
  std::string correction_key_;
  std::string tx_correction_key_;
  Hz xit_hz_ = 0;

  RadioConfig config_;
  SatelliteRadio sat_;
  bool parked_ = false;
  Hz rit_hz_ = 0;
  Tuning tuning_;
  Tuning previous_tuning_;          // the update before tuning_ (for the Doppler change)
  int updates_ = 0;                 // updates since select (the Doppler change needs two)
  std::optional<bool> was_aos_;
  std::optional<Hz> sent_down_, sent_up_;
  std::optional<Mode> sent_down_mode_, sent_up_mode_;
};

}  // namespace tb::radio
