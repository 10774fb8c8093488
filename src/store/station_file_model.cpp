#include "store/station_file_model.h"

#include <tuple>

#include "radio/freqmode.h"
#include "rotator/config.h"
#include "util/format.h"
#include "util/text.h"

namespace tb::store {

namespace {

// The later firmware's name of the configured rig (line 4).
std::string rig_name(const radio::RadioConfig& rc) {
  using radio::RigModel;
  switch (rc.rig) {
    case radio::Rig::icom: return "ICOM";
    case radio::Rig::kenwood: return rc.rig_model == RigModel::kenwood_711 ? "KENWOOD711" : "KENWOOD";
    case radio::Rig::yaesu:
      switch (rc.rig_model) {
        case RigModel::yaesu_847: return rc.ft736_wide_fm ? "YAESUw847" : "YAESU_847";
        case RigModel::yaesu_736: return rc.ft736_wide_fm ? "YAESUw736" : "YAESU_736";
        case RigModel::yaesu_other: return "YAESU_o";
        default: return "YAESU";  // the wide-FM filter of a YAESU without a model stays in the state
      }
    case radio::Rig::none: break;
  }
  return "NONE";
}

// Lines 1 to 3 as both firmwares write them; the later adds the COM speed to line 1 and F (flip
// mode) to line 2.
std::string lines_1_to_3(const Model& m, bool later) {
  const auto& st = m.station;
  const auto& r = m.rotator;
  return text::printf_string("1 %s %.3f %.3f %g %s", st.callsign.c_str(), st.lat_deg, st.lon_deg, st.height_m,
                             st.rotor_start == station::RotorStart::north ? "N" : "S") +
         (later ? " " + std::to_string(st.com_baud) : "") + "\n" +
         text::printf_string("2 %d %d %d %d", r.az_span.min, r.az_span.max, r.el_span.min, r.el_span.max) +
         (later && r.el_flip_allowed ? " F" : "") + "\n" +
         text::printf_string("3 %d %d %d %d\n", r.az_dead_band, r.el_dead_band, r.az_skew, r.el_skew);
}

// The limit switch and its range: the last five items of the 1994 line 5, the later line 7's.
std::string limit_items(const rotator::RotatorConfig& r) {
  return text::printf_string("%d %g %g %g %g", r.limits_enabled ? 1 : 0, r.az_limit_min, r.az_limit_max,
                             r.el_limit_min, r.el_limit_max);
}

}  // namespace

std::vector<std::string> apply_station_file(const StationFile& f, Model& m) {
  // What the lines carry, line by line; the rest of each configuration keeps its value.
  Model next = m;
  station::StationConfig& st = next.station;
  const station::StationConfig& fs = f.station;
  std::tie(st.callsign, st.lat_deg, st.lon_deg, st.height_m, st.rotor_start) =
      std::tie(fs.callsign, fs.lat_deg, fs.lon_deg, fs.height_m, fs.rotor_start);
  if (f.com_baud_given) st.com_baud = fs.com_baud;
  rotator::RotatorConfig& r = next.rotator;
  const rotator::RotatorConfig& fr = f.rotator;
  std::tie(r.az_span, r.el_span) = std::tie(fr.az_span, fr.el_span);
  // Flip mode says what the elevation span means (0..180 rather than 0..90), so it goes with the
  // span: a 1994 file's span is 0..90, whatever was set before.
  r.el_flip_allowed = f.later_firmware && fr.el_flip_allowed;
  std::tie(r.az_dead_band, r.el_dead_band, r.az_skew, r.el_skew) =
      std::tie(fr.az_dead_band, fr.el_dead_band, fr.az_skew, fr.el_skew);
  std::tie(r.parking_enabled, r.parking, r.limits_enabled, r.az_limit_min, r.az_limit_max, r.el_limit_min,
           r.el_limit_max) = std::tie(fr.parking_enabled, fr.parking, fr.limits_enabled, fr.az_limit_min,
                                      fr.az_limit_max, fr.el_limit_min, fr.el_limit_max);
  radio::RadioConfig& rc = next.radio;
  const radio::RadioConfig& frc = f.radio;
  std::tie(rc.rig, rc.rig_model, rc.cat_policy, rc.icom_rx_address, rc.icom_tx_address) =
      std::tie(frc.rig, frc.rig_model, frc.cat_policy, frc.icom_rx_address, frc.icom_tx_address);
  if (f.wide_fm_given) rc.ft736_wide_fm = frc.ft736_wide_fm;
  if (f.cat_baud_given) rc.cat_baud = frc.cat_baud;
  if (f.later_firmware) {
    r.stall_s = fr.stall_s;
    rc.mic_click.park_pulse_width_digit = frc.mic_click.park_pulse_width_digit;
    rc.mic_click.park_pulse_interval_digit = frc.mic_click.park_pulse_interval_digit;
    rc.parking = frc.parking;
    next.pass_events = f.pass_events;
    next.rotator_error_detection = f.rotator_error_detection;
  }
  auto problems = rotator::validate(r);
  if (problems.empty()) m = std::move(next);
  return problems;
}

std::string write_station_file(const Model& m) {
  const auto& r = m.rotator;
  const auto& rc = m.radio;
  return lines_1_to_3(m, false) +
         text::printf_string("4 %s %s %02X %02X\n", radio::to_string(rc.rig),
                             rc.cat_policy == radio::CatPolicy::full_orbit ? "F" : "A", rc.icom_rx_address,
                             rc.icom_tx_address) +
         text::printf_string("5 %d %g %g ", r.parking_enabled ? 1 : 0, r.parking.az, r.parking.el) + limit_items(r) +
         "\n";
}

std::string write_station_file_later(const Model& m) {
  const auto& r = m.rotator;
  const auto& rc = m.radio;
  std::string out = "; STATION.DAT of the later TrakBox firmware, written by trakbox\n" + lines_1_to_3(m, true);
  const int baud = radio::effective_cat_baud(rc);
  out += "4 " + rig_name(rc) + (rc.cat_policy == radio::CatPolicy::full_orbit ? " FULL" : " AOS") +
         text::printf_string(" %02X %02X %d\n", rc.icom_rx_address, rc.icom_tx_address, baud > 0 ? baud : 9600);
  std::string park = r.parking_enabled ? "1" : "0";
  if (rc.mic_click.park_pulse_width_digit >= 0) {
    park += std::to_string(rc.mic_click.park_pulse_width_digit);
    if (rc.mic_click.park_pulse_interval_digit >= 0) park += std::to_string(rc.mic_click.park_pulse_interval_digit);
  }
  out += text::printf_string("5 %s %g %g %g %g %g\n", park.c_str(), r.parking.az, r.parking.el,
                             m.pass_events.rotor_start_el_deg, m.pass_events.output_on_el_deg,
                             m.pass_events.output_off_el_deg);
  out += std::string("6 ") + (rc.parking.enabled ? "1" : "0") + (m.rotator_error_detection ? "1" : "0") + " " +
         radio::format_mhz(rc.parking.rx_hz) + " " + radio::format_mhz(rc.parking.tx_hz) + " " +
         text::lower(radio::to_string(rc.parking.rx_mode)) + " " + text::lower(radio::to_string(rc.parking.tx_mode)) +
         text::printf_string(" %g\n", r.stall_s);
  out += "7 " + limit_items(r) + "\n";
  return out;
}

}  // namespace tb::store
