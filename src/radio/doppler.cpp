#include "radio/doppler.h"

#include <cmath>
#include <utility>

namespace tb::radio {

double downlink_heard_hz(Hz sent_hz, double rr) {
  return static_cast<double>(sent_hz) * (1.0 - rr / kSpeedOfLightKmS);
}

double uplink_send_hz(Hz wanted_hz, double rr) {
  return static_cast<double>(wanted_hz) / (1.0 - rr / kSpeedOfLightKmS);
}

Hz quantise(double hz, Hz step) {
  const double s = static_cast<double>(step);
  return static_cast<Hz>(std::round(hz / s)) * step;
}

Hz downlink_doppler_hz(Hz downlink_hz, double rr) {
  return static_cast<Hz>(std::llround(downlink_heard_hz(downlink_hz, rr) -
                                      static_cast<double>(downlink_hz)));
}

Hz LinearTransponder::uplink_for(Hz down) const {
  return inverting ? uplink_high_hz - (down - downlink_low_hz) : uplink_low_hz + (down - downlink_low_hz);
}

Hz LinearTransponder::downlink_for(Hz up) const {
  return inverting ? downlink_low_hz + (uplink_high_hz - up) : downlink_low_hz + (up - uplink_low_hz);
}

std::optional<LinearTransponder> transponder_of(const SatelliteRadio& s) {
  if (!s.has_passbands()) return std::nullopt;
  return LinearTransponder{s.downlink_low_hz, s.downlink_high_hz, s.uplink_low_hz, s.uplink_high_hz, s.inverting};
}

Hz dial_tolerance_hz(double doppler_change_per_s_hz, Hz step) {
  return 2 * step + static_cast<Hz>(std::ceil(std::fabs(doppler_change_per_s_hz)));
}

Tuning compute_tuning(const SatelliteRadio& sat, const Corrections& corr, double rr, Hz rit_hz, Hz xit_hz) {
  Tuning t;
  if (sat.has_downlink()) {
    t.downlink_doppler_hz = downlink_heard_hz(sat.downlink_hz, rr) - static_cast<double>(sat.downlink_hz);
    double sign = 0.0;
    if (corr.downlink == DownlinkCorrection::on) sign = 1.0;
    if (corr.downlink == DownlinkCorrection::reverse) sign = -1.0;
    const double radio = static_cast<double>(sat.downlink_hz + sat.downlink_offset_hz + rit_hz) +
                         sign * t.downlink_doppler_hz;
    t.downlink_radio_hz = quantise(radio);
  }
  if (sat.has_uplink()) {
    t.uplink_doppler_hz = uplink_send_hz(sat.uplink_hz, rr) - static_cast<double>(sat.uplink_hz);
    const double radio = static_cast<double>(sat.uplink_hz + sat.uplink_offset_hz + xit_hz) +
                         (corr.uplink ? t.uplink_doppler_hz : 0.0);
    t.uplink_radio_hz = quantise(radio);
  }
  return t;
}

Tuner::Tuner(const RadioConfig& config) : config_(config) {}

void Tuner::set_config(const RadioConfig& config) {
  config_ = config;
  resend();
}

void Tuner::select(const SatelliteRadio& sat, std::string_view name, std::string_view mode) {
  sat_ = sat;
  rit_hz_ = 0;
  was_aos_.reset();
  resend();
  tuning_ = {};
  previous_tuning_ = {};
  updates_ = 0;
  waiting_.reset();
  correction_key_.clear();
  tx_correction_key_.clear();
  xit_hz_ = 0;
  if (name.empty()) return;
  correction_key_ = std::string(name) + " " + (mode.empty() ? std::string(to_string(sat.downlink_mode)) : std::string(mode));
  tx_correction_key_ = std::string(name) + " " + (mode.empty() ? std::string(to_string(sat.uplink_mode)) : std::string(mode));
  if (const auto it = config_.corrections.find(correction_key_); it != config_.corrections.end()) move_rit(it->second);
  if (const auto it = config_.tx_corrections.find(tx_correction_key_); it != config_.tx_corrections.end())
    xit_hz_ = it->second;
}

void Tuner::set_offsets(std::optional<Hz> rx_hz, std::optional<Hz> tx_hz) {
  if (rx_hz && *rx_hz != rit_hz_) move_rit(*rx_hz - rit_hz_);
  if (!tx_hz) return;
  xit_hz_ = *tx_hz;
  if (!tx_correction_key_.empty()) {
    if (xit_hz_ != 0) config_.tx_corrections[tx_correction_key_] = xit_hz_;
    else config_.tx_corrections.erase(tx_correction_key_);
  }
  sent_up_.reset();   // goes out at the next update whatever the Doppler step
}

bool Tuner::set_spot(Hz downlink_spot_hz) {
  const auto t = transponder_of(sat_);
  if (!t || !t->downlink_inside(downlink_spot_hz)) return false;
  sat_.downlink_hz = downlink_spot_hz;
  sat_.uplink_hz = t->uplink_for(downlink_spot_hz);
  waiting_.reset();
  sent_down_.reset();
  sent_up_.reset();
  return true;
}

Hz Tuner::doppler_step(Mode mode) const {
  const Hz step = mode == Mode::fm ? config_.doppler_step_fm_hz : config_.doppler_step_ssb_hz;
  return step > kTuningStepHz ? step : kTuningStepHz;
}

bool Tuner::dial_follow_active() const {
  return config_.dial_follow && sat_.doppler == DopplerControl::cat && sat_.has_passbands() &&
         sat_.has_downlink() && sat_.has_uplink();
}

void Tuner::move_rit(Hz delta) {
  rit_hz_ += delta;
  // The operator's correction for this satellite and mode: remembered for its next pass; 0 forgets.
  if (!correction_key_.empty()) {
    if (rit_hz_ != 0) config_.corrections[correction_key_] = rit_hz_;
    else config_.corrections.erase(correction_key_);
  }
  // A key press goes out at the next update whatever the Doppler step.
  sent_down_.reset();
  if (!dial_follow_active()) return;
  // On a transponder the keys move the spot: the downlink by delta, the uplink to its pair.
  sat_.downlink_hz += delta;
  sat_.uplink_hz = transponder_of(sat_)->uplink_for(sat_.downlink_hz);
  sent_up_.reset();
}

namespace {
bool near_band(Hz spot, Hz low, Hz high) {
  const Hz width = high - low;
  return spot >= low - width && spot <= high + width;
}
}  // namespace

bool Tuner::dial_downlink(Hz radio_hz, double rr) { return turn(true, radio_hz, rr, std::nullopt); }

bool Tuner::dial_uplink(Hz radio_hz, double rr) { return turn(false, radio_hz, rr, std::nullopt); }

bool Tuner::turn(bool downlink, Hz radio_hz, double rr, std::optional<double> now_s) {
  const auto t = transponder_of(sat_);
  Hz spot = 0;
  if (downlink) {
    // The radio: RF + sign * (RF (1 - rr/c) - RF) + offset + RIT = RF (1 - sign rr/c) + offset + RIT.
    double sign = 0.0;
    if (config_.downlink_correction == DownlinkCorrection::on) sign = 1.0;
    if (config_.downlink_correction == DownlinkCorrection::reverse) sign = -1.0;
    const Hz rit = dial_follow_active() ? 0 : rit_hz_;
    spot = static_cast<Hz>(std::llround(static_cast<double>(radio_hz - sat_.downlink_offset_hz - rit) /
                                        (1.0 - sign * rr / kSpeedOfLightKmS)));
    if (t && !near_band(spot, t->downlink_low_hz, t->downlink_high_hz)) return false;
    sat_.downlink_hz = spot;
  } else {
    // The radio: RF / (1 - rr/c) + offset with the uplink correction on, RF + offset without.
    const double factor = config_.uplink_correction ? 1.0 - rr / kSpeedOfLightKmS : 1.0;
    spot = static_cast<Hz>(std::llround(static_cast<double>(radio_hz - sat_.uplink_offset_hz - xit_hz_) * factor));
    if (t && !near_band(spot, t->uplink_low_hz, t->uplink_high_hz)) return false;
    sat_.uplink_hz = spot;
  }
  // The turned link's radio is where the operator put it: trakbox's next value starts from there.
  (downlink ? sent_down_ : sent_up_) = radio_hz;
  if (!now_s || config_.dial_rest_ms <= 0) {
    waiting_.reset();
    pair_from(downlink);
  } else {
    waiting_ = Waiting{downlink, *now_s};
  }
  return true;
}

void Tuner::pair_from(bool downlink) {
  const auto t = transponder_of(sat_);
  if (!t) return;
  if (downlink) {
    sat_.uplink_hz = t->uplink_for(sat_.downlink_hz);
    sent_up_.reset();   // the move goes out at once, whatever the Doppler step
    moved_uplink_ = true;
  } else {
    sat_.downlink_hz = t->downlink_for(sat_.uplink_hz);
    sent_down_.reset();
    moved_uplink_ = false;
  }
}

bool Tuner::settle(double now_s) {
  const auto due = settle_due_s();
  if (!due || now_s < *due) return false;
  const bool downlink = waiting_->downlink_turned;
  waiting_.reset();
  pair_from(downlink);
  return true;
}

std::optional<double> Tuner::settle_due_s() const {
  if (!waiting_) return std::nullopt;
  return waiting_->last_turn_s + config_.dial_rest_ms / 1000.0;
}

Tuner::Turn Tuner::dial_turn(std::optional<Hz> down, std::optional<Hz> up, double rr, double now_s) {
  if (down && up && sent_down_ && sent_up_) {
    // Both dials moved by the same amount at once: RIT/XIT (or the radio's own shift), not a knob.
    const Hz dd = *down - *sent_down_, du = *up - *sent_up_;
    const Hz slack = dial_tolerance_downlink_hz() + dial_tolerance_uplink_hz();
    if ((dd > 0) == (du > 0) && (dd - du <= slack && du - dd <= slack)) return Turn::rit_xit;
  }
  if (down) return turn(true, *down, rr, now_s) ? Turn::downlink : Turn::outside;
  if (up) return turn(false, *up, rr, now_s) ? Turn::uplink : Turn::outside;
  return Turn::none;
}

Hz Tuner::dial_tolerance_downlink_hz() const {
  if (updates_ < 2) return dial_tolerance_hz(0.0);
  return dial_tolerance_hz(tuning_.downlink_doppler_hz - previous_tuning_.downlink_doppler_hz);
}

Hz Tuner::dial_tolerance_uplink_hz() const {
  if (updates_ < 2) return dial_tolerance_hz(0.0);
  return dial_tolerance_hz(tuning_.uplink_doppler_hz - previous_tuning_.uplink_doppler_hz);
}

void Tuner::resend() {
  sent_down_.reset();
  sent_up_.reset();
  sent_down_mode_.reset();
  sent_up_mode_.reset();
}

TuneCommands Tuner::compute(double elevation_deg, double rr) {
  const Corrections corr = Corrections::from(config_);
  previous_tuning_ = tuning_;
  ++updates_;
  // On a followed transponder the + / - keys moved the spot itself (move_rit): no RIT on top.
  tuning_ = compute_tuning(sat_, corr, rr, dial_follow_active() ? 0 : rit_hz_, xit_hz_);

  TuneCommands cmd;
  const bool aos_now = at_aos(elevation_deg);
  const bool edge = aos_now && !was_aos_.value_or(false);
  was_aos_ = aos_now;
  cmd.aos = edge;
  if (edge) resend();

  const bool send_down = tuning_.downlink_radio_hz && corr.downlink != DownlinkCorrection::off;
  const bool send_up = tuning_.uplink_radio_hz && corr.uplink;

  auto emit = [&](std::optional<Hz> hz, std::optional<Hz>& sent, Mode mode,
                  std::optional<Mode>& sent_mode, std::optional<Hz>& out_hz,
                  std::optional<Mode>& out_mode) {
    // Sent when it moved the mode's Doppler step from the last value sent (a first value always).
    if (!hz || (sent && std::llabs(*sent - *hz) < doppler_step(mode))) return;
    if (mode != Mode::none && sent_mode != mode) {
      out_mode = mode;
      sent_mode = mode;
    }
    out_hz = *hz;
    sent = *hz;
  };

  if (sat_.doppler == DopplerControl::cat) {
    const bool allowed = config_.cat_policy == CatPolicy::full_orbit || aos_now;
    if (!allowed) return cmd;
    // While the knob rests (a turn seen, the other link not moved yet) neither link is written:
    // the turned dial is the operator's, and the other link is about to go to the new pair. The
    // line stays free to read the turned dial and to carry the move when the rest ends (on the
    // FT-847's 50 ms a byte, a Doppler write in the way held the move back by up to half a second).
    if (waiting_) return cmd;
    if (send_down)
      emit(tuning_.downlink_radio_hz, sent_down_, sat_.downlink_mode, sent_down_mode_,
           cmd.downlink_hz, cmd.downlink_mode);
    if (send_up)
      emit(tuning_.uplink_radio_hz, sent_up_, sat_.uplink_mode, sent_up_mode_, cmd.uplink_hz,
           cmd.uplink_mode);
    return cmd;
  }

  // Mic-click: one CAT command at AOS, then the pulses do the work.
  if (!edge) return cmd;
  const MicClickConfig& mc = config_.mic_click;
  std::optional<Hz> down = tuning_.downlink_radio_hz;
  if (mc.auto_up_at_aos && send_down) {
    const Tuning nominal = compute_tuning(sat_, Corrections{corr.uplink, DownlinkCorrection::off}, rr, rit_hz_, xit_hz_);
    cmd.aos_pulse_correction_hz = *tuning_.downlink_radio_hz - *nominal.downlink_radio_hz;
    down = nominal.downlink_radio_hz;
  }
  if (mc.cat_at_aos) {
    if (send_down)
      emit(down, sent_down_, sat_.downlink_mode, sent_down_mode_, cmd.downlink_hz, cmd.downlink_mode);
    if (send_up)
      emit(tuning_.uplink_radio_hz, sent_up_, sat_.uplink_mode, sent_up_mode_, cmd.uplink_hz,
           cmd.uplink_mode);
  }
  return cmd;
}

// The later firmware's additions around compute(): the radio parking of STATION.DAT line 6 and the
// FREQ.DAT `ir`/`kr` swap of the two radios (Icom main/sub) or VFOs (Kenwood).
TuneCommands Tuner::update(double elevation_deg, double rr) {
  const bool was_up = was_aos_.value_or(true);  // the first tick below the horizon parks too
  TuneCommands cmd = compute(elevation_deg, rr);
  const std::optional<bool> moved_uplink = std::exchange(moved_uplink_, std::nullopt);
  const RadioParking& park = config_.parking;
  if (park.enabled && !at_aos(elevation_deg)) {
    // From LOS to the next AOS the radios sit on the parking frequencies: one set of commands at
    // the LOS edge, nothing after it (the AOS edge sends the satellite's frequencies and modes again).
    TuneCommands out;
    if (was_up) {
      if (park.rx_mode != Mode::none) out.downlink_mode = park.rx_mode;
      if (park.rx_hz > 0) out.downlink_hz = park.rx_hz;
      if (park.tx_mode != Mode::none) out.uplink_mode = park.tx_mode;
      if (park.tx_hz > 0) out.uplink_hz = park.tx_hz;
      resend();
    }
    parked_ = true;
    return out;
  }
  parked_ = false;
  if (reversed()) {
    std::swap(cmd.downlink_hz, cmd.uplink_hz);
    std::swap(cmd.downlink_mode, cmd.uplink_mode);
  }
  // The link just moved goes first: the radio's uplink when it carries the one that moved.
  cmd.uplink_first = moved_uplink && *moved_uplink != reversed() && cmd.uplink_hz;
  return cmd;
}

bool Tuner::reversed() const {
  return (sat_.reverse == ReverseAssignment::icom_main_sub && config_.rig == Rig::icom) ||
         (sat_.reverse == ReverseAssignment::kenwood_vfo && config_.rig == Rig::kenwood);
}

}  // namespace tb::radio
