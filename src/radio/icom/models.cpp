// The Icom family: menu 6-7's CI-V form and the IC-9700, IC-9100, IC-910H, IC-821H, IC-275, IC-970, IC-705,
// IC-905, IC-7300, IC-7100, IC-706MKIIG: the registry's rows of this family (radio/registry.h) and the factories they name.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/icom/link.h"

namespace tb::radio {

namespace {

using std::chrono::milliseconds;

// The CI-V options of a registry model (its address for both links, its satellite mode and bands).
IcomOptions icom_options(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t,
                         RadioRole role) {
  IcomOptions o;
  if (m.form == SpecForm::device) {   // the family form: everything from menu 6-7
    o = IcomOptions::from(config);
  } else {
    o.rx_address = o.tx_address = m.civ_address;
    o.width = m.four_byte_frequency ? icom::FrequencyWidth::four_bytes : icom::FrequencyWidth::five_bytes;
    o.baud = spec.baud > 0 ? spec.baud : m.baud;
    o.reads = m.caps.reads;
    o.reads_tx_1c03 = m.caps.reads_tx_1c03;
    o.ctcss = m.caps.ctcss;
    o.model = std::string(m.label.substr(m.label.find(' ') + 1));
    o.bands.assign(m.bands.begin(), m.bands.end());
    o.xvtr_from = m.xvtr_from;
    o.transverter = spec.transverter;
    if (m.xvtr_from > 0) o.width = icom::FrequencyWidth::five_or_six;
    if (role == RadioRole::both && m.caps.links == 2) {
      o.main_link = spec.main_link.value_or(m.main_link);
      if (m.satmode == SatCommand::icom_16_5a) o.satellite_cmd = 0x16, o.satellite_sub = 0x5A;
      else if (m.satmode == SatCommand::icom_1a_07) o.satellite_cmd = 0x1A, o.satellite_sub = 0x07;
      else o.band_select = o.main_link == Link::uplink ? IcomBandSelect::main_tx_sub_rx : IcomBandSelect::none;
    }
  }
  o.echo_margin = t.icom_echo_margin;
  o.reply_timeout = t.icom_reply_timeout;
  return o;
}

MakeRadio make_icom(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  return {make_icom_radio(spec.device, icom_options(m, spec, config, t, role), t.worker), {}};
}

constexpr Hz MHz = 1000000;
// The bands each newer row tunes (its receive coverage; the manuals' specifications).
constexpr HzRange kIc905Bands[] = {{144 * MHz, 148 * MHz},   {420 * MHz, 450 * MHz},     {1240 * MHz, 1300 * MHz},
                                   {2300 * MHz, 2450 * MHz}, {5650 * MHz, 5925 * MHz},   {10000 * MHz, 10500 * MHz}};
constexpr HzRange kIc7300Bands[] = {{30 * MHz / 1000, 748 * MHz / 10}};
// IC-7100 and IC-706MKIIG: 0.03-199.999 MHz and 400-470 MHz (no 23 cm).
constexpr HzRange kHfVuBands[] = {{30 * MHz / 1000, 200 * MHz - 1}, {400 * MHz, 470 * MHz}};

}  // namespace

// Which band transmits in satellite mode: IC-9700 Main receives and Sub transmits (Hamlib's
// icom_get_split_vfos); IC-9100, IC-910H and IC-821H Main transmits (Gpredict's "IC-910H: MAIN up /
// SUB down"; Hamlib's note that the IC-821H is the other way round from the IC-9700).
std::span<const RadioModel> icom_rows() {
  static const RadioModel rows[] = {
      {.name = "icom", .label = "Icom CI-V (menu 6-7)", .protocol = Protocol::icom, .baud = 1200, .caps = {.links = 2},
       .note = "RX/TX addresses, band select and speed from menu 6-7", .make = make_icom},
      {.name = "ic9700", .label = "Icom IC-9700", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0xA2, .baud = 19200, .main_link = Link::downlink, .satmode = SatCommand::icom_16_5a,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true, .step_hz = 1, .reads_tx_1c03 = true},
       .hamlib_model = 3081, .note = "satellite mode 16 5A; Main down, Sub up; echo or not", .make = make_icom},
      {.name = "ic9100", .label = "Icom IC-9100", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x7C, .baud = 19200, .satmode = SatCommand::icom_16_5a,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 3068,
       .note = "satellite mode 16 5A; Main up, Sub down", .make = make_icom},
      {.name = "ic910h", .label = "Icom IC-910H", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x60, .baud = 19200, .satmode = SatCommand::icom_1a_07,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .step_hz = 1}, .hamlib_model = 3044,
       .note = "satellite mode 1A 07; Main up, Sub down", .make = make_icom},
      {.name = "ic821h", .label = "Icom IC-821H", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x4C, .baud = 9600, .four_byte_frequency = true, .caps = {.links = 2}, .hamlib_model = 3034,
       .note = "4-byte frequencies; 07 D0/D1 before each command (Main up)", .make = make_icom},
      {.name = "ic275", .label = "Icom IC-275", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x10, .baud = 1200, .caps = {}, .hamlib_model = 3004,
       .note = "one band: pair it with --uplink-radio", .make = make_icom},
      {.name = "ic970", .label = "Icom IC-970", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x2E, .baud = 1200, .caps = {}, .hamlib_model = 3035,
       .note = "main band only (sub band select unconfirmed)", .make = make_icom},
      {.name = "ic705", .label = "Icom IC-705", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0xA4, .baud = 19200, .caps = {.reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 3085,
       .note = "one link: pair it with --uplink-radio", .make = make_icom},
      {.name = "ic905", .label = "Icom IC-905", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0xAC, .baud = 115200, .main_link = Link::downlink, .satmode = SatCommand::icom_16_5a,
       .bands = kIc905Bands, .xvtr_from = 10000 * MHz,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true, .step_hz = 1},
       .note = "2 m to 5.7 GHz; 10 GHz (6-byte) with :xvtr; Main down, Sub up", .make = make_icom},
      {.name = "ic7300", .label = "Icom IC-7300", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x94, .baud = 115200, .bands = kIc7300Bands, .caps = {.reads = true, .ctcss = true, .step_hz = 1},
       .hamlib_model = 3073, .note = "HF/6 m, one link: AO-07 Mode A's 10 m downlink", .make = make_icom},
      {.name = "ic7100", .label = "Icom IC-7100", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x88, .baud = 19200, .bands = kHfVuBands, .caps = {.reads = true, .ctcss = true, .step_hz = 1},
       .hamlib_model = 3070, .note = "HF/6/2 m/70 cm, one link (one VFO per leg)", .make = make_icom},
      {.name = "ic706mkiig", .label = "Icom IC-706MKIIG", .form = SpecForm::device_baud, .protocol = Protocol::icom,
       .civ_address = 0x58, .baud = 19200, .bands = kHfVuBands, .caps = {.reads = true, .step_hz = 1},
       .hamlib_model = 3011, .note = "HF/6/2 m/70 cm, one link; no CTCSS trakbox sets", .make = make_icom},
  };
  return rows;
}

}  // namespace tb::radio
