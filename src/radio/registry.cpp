#include "radio/registry.h"

#include <cstdio>

#include "radio/cat_links.h"
#include "radio/factory.h"
#include "radio/hamlib_radio.h"
#include "radio/simulated.h"

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

MakeRadio make_simulated(const RadioModel&, const RadioSpec&, const RadioConfig&, const DriverTiming&, RadioRole) {
  return {std::make_unique<SimulatedRadio>(), {}};
}

MakeRadio make_icom(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  return {make_icom_radio(spec.device, icom_options(m, spec, config, t, role), t.worker), {}};
}

MakeRadio make_kenwood(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  KenwoodOptions o = KenwoodOptions::from(config);
  if (m.form != SpecForm::device) {
    o.baud = spec.baud > 0 ? spec.baud : m.baud;
    o.reads = m.caps.reads;
    o.ctcss = m.caps.ctcss;
    o.model = std::string(m.label);
    o.one_link = role != RadioRole::both;
    if (m.satmode == SatCommand::kenwood_sa) {   // (:mainup is refused by parse_radio_spec)
      o.vfo_select = 'R';
      o.satellite_mode = role == RadioRole::both;
    }
  }
  return {make_kenwood_radio(spec.device, o, t.worker), {}};
}

MakeRadio make_ft736(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole) {
  YaesuOptions o = YaesuOptions::from(config);
  o.byte_gap = t.yaesu_byte_gap;
  if (m.form != SpecForm::device && spec.baud > 0) o.baud = spec.baud;
  return {make_yaesu_radio(spec.device, o, t.worker), {}};
}

MakeRadio make_ft8xx(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  Ft8xxOptions o;
  o.model = m.protocol == Protocol::ft847 ? Ft8xxOptions::Model::ft847 : Ft8xxOptions::Model::ft817;
  o.label = std::string(m.label.substr(m.label.find(' ') + 1));
  o.byte_gap = o.model == Ft8xxOptions::Model::ft817 ? t.ft817_byte_gap : t.yaesu_byte_gap;
  o.baud = spec.baud > 0 ? spec.baud : (m.form == SpecForm::device ? config.cat_baud : m.baud);
  o.satellite_mode = role == RadioRole::both;   // one of two radios: the main VFO alone
  return {make_ft8xx_radio(spec.device, o, t.worker), {}};
}

// yaesu:DEVICE: the FT-736 unless menu 6-7 (STATION.DAT line 4) names the FT-847.
MakeRadio make_yaesu_family(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  if (config.rig_model == RigModel::yaesu_847) return make_ft8xx(*find_radio_model("ft847"), spec, config, t, role);
  return make_ft736(m, spec, config, t, role);
}

MakeRadio make_cat(const RadioModel&, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  const char* family = nullptr;
  switch (config.rig) {
    case Rig::icom: family = "icom"; break;
    case Rig::kenwood: family = "kenwood"; break;
    case Rig::yaesu: family = "yaesu"; break;
    case Rig::none:
      return {nullptr, "--radio cat:" + spec.device + ": no CAT rig is configured (menu 6-7: choose Kenwood, Yaesu or Icom)"};
  }
  const RadioModel& m = *find_radio_model(family);
  return m.make(m, spec, config, t, role);
}

MakeRadio make_hamlib(const RadioModel&, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole) {
  if (hamlib_model_name(spec.model).empty())
    return {nullptr, "--radio hamlib:" + std::to_string(spec.model) + ": Hamlib has no rig model " +
                         std::to_string(spec.model) + " (see rigctl -l)"};
  return {make_hamlib_radio({spec.model, spec.device, spec.baud, spec.scheme}, t.worker), {}};
}

MakeRadio make_rigctld(const RadioModel&, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole) {
  return {make_hamlib_radio({2, spec.host + ":" + std::to_string(spec.port), 0, spec.scheme}, t.worker), {}};
}

// Which band transmits in satellite mode: IC-9700 Main receives and Sub transmits (Hamlib's
// icom_get_split_vfos); IC-9100, IC-910H and IC-821H Main transmits (Gpredict's "IC-910H: MAIN up /
// SUB down"; Hamlib's note that the IC-821H is the other way round from the IC-9700).
const RadioModel kModels[] = {
    {.name = "sim", .label = "trakbox simulated radio", .form = SpecForm::none,
     .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1}, .note = "the default; records what it is told",
     .make = make_simulated},
    // Today's families: menu 6-7 supplies addresses, speed and the Yaesu model.
    {.name = "icom", .label = "Icom CI-V (menu 6-7)", .protocol = Protocol::icom, .baud = 1200, .caps = {.links = 2},
     .note = "RX/TX addresses, band select and speed from menu 6-7", .make = make_icom},
    {.name = "kenwood", .label = "Kenwood TS-790/711/811", .protocol = Protocol::kenwood, .baud = 4800,
     .caps = {.links = 2}, .note = "downlink VFO A, uplink VFO B", .make = make_kenwood},
    {.name = "yaesu", .label = "Yaesu FT-736 (FT-847 in menu 6-7)", .protocol = Protocol::ft736, .baud = 4800,
     .satmode = SatCommand::ft736, .caps = {.links = 2, .satellite_mode = true},
     .note = "the FT-847's own opcodes when STATION.DAT names YAESU_847", .make = make_yaesu_family},
    {.name = "cat", .label = "the rig of menu 6-7", .protocol = Protocol::cat, .caps = {.links = 2},
     .note = "icom, kenwood or yaesu as menu 6-7 chose", .make = make_cat},
    // The satellite radios of 2026.
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
    {.name = "ts2000", .label = "Kenwood TS-2000", .form = SpecForm::device_baud, .protocol = Protocol::kenwood,
     .baud = 9600, .main_link = Link::downlink, .satmode = SatCommand::kenwood_sa,
     .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 2014,
     .note = "satellite mode SA: Main down (FA), Sub up (FB); TN/TO tone; read with FA;/FB;", .make = make_kenwood},
    {.name = "ts790", .label = "Kenwood TS-790", .form = SpecForm::device_baud, .protocol = Protocol::kenwood,
     .baud = 4800, .caps = {.links = 2}, .hamlib_model = 2007, .note = "VFO A down, B up", .make = make_kenwood},
    {.name = "ft847", .label = "Yaesu FT-847", .form = SpecForm::device_baud, .protocol = Protocol::ft847,
     .baud = 4800, .satmode = SatCommand::ft847,
     .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true}, .hamlib_model = 1001,
     .note = "satellite mode 4E; SAT RX / SAT TX opcodes 11/21, read 13/23", .make = make_ft8xx},
    {.name = "ft817", .label = "Yaesu FT-817", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
     .baud = 4800, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1020,
     .note = "one link: a pair is --radio ft817:A --uplink-radio ft817:B", .make = make_ft8xx},
    {.name = "ft818", .label = "Yaesu FT-818", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
     .baud = 4800, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1041, .note = "as the FT-817",
     .make = make_ft8xx},
    {.name = "ft736", .label = "Yaesu FT-736R", .form = SpecForm::device_baud, .protocol = Protocol::ft736,
     .baud = 4800, .satmode = SatCommand::ft736, .caps = {.links = 2, .satellite_mode = true}, .hamlib_model = 1010,
     .note = "satellite mode 0E; never acknowledged, cannot be read", .make = make_ft736},
    // Hamlib.
    {.name = "hamlib", .label = "any Hamlib backend", .form = SpecForm::hamlib, .protocol = Protocol::hamlib,
     .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1},
     .note = "MODEL: Hamlib's number or name (rigctl -l)", .make = make_hamlib},
    {.name = "rigctld", .label = "a rigctld daemon (Hamlib NET rigctl)", .form = SpecForm::rigctld,
     .protocol = Protocol::rigctld, .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1},
     .hamlib_model = 2, .note = "HOST 127.0.0.1, PORT 4532 by default", .make = make_rigctld},
};

}  // namespace

std::span<const RadioModel> radio_models() { return kModels; }

const RadioModel* find_radio_model(std::string_view name) {
  if (name == "simulated") name = "sim";
  for (const RadioModel& m : kModels)
    if (m.name == name) return &m;
  return nullptr;
}

const RadioModel* find_radio_model_by_hamlib(int hamlib_model) {
  if (hamlib_model <= 2) return nullptr;   // the dummy and NET rigctl are no radio
  for (const RadioModel& m : kModels)
    if (m.hamlib_model == hamlib_model) return &m;
  return nullptr;
}

std::string spec_form(const RadioModel& m) {
  const std::string n(m.name);
  switch (m.form) {
    case SpecForm::none: return n;
    case SpecForm::device: return n + ":DEVICE";
    case SpecForm::device_baud:
      return n + ":DEVICE[:BAUD]" + (m.caps.satellite_mode && m.protocol == Protocol::icom ? "[:maindown|:mainup]" : "");
    case SpecForm::hamlib: return n + ":MODEL:DEVICE[:BAUD][:split|:mainsub]";
    case SpecForm::rigctld: return n + "[:HOST[:PORT]][:split|:mainsub]";
  }
  return n;
}

std::string radio_model_names() {
  std::string out;
  for (const RadioModel& m : kModels) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

std::string radio_list_text() {
  std::string out = "radio spec                                   radio                              links sat read tone step  CI-V  baud hamlib  notes\n";
  char line[512];
  for (const RadioModel& m : kModels) {
    const std::string civ = m.civ_address ? [&] { char b[8]; std::snprintf(b, sizeof b, "%02Xh", m.civ_address); return std::string(b); }() : "-";
    const std::string form = spec_form(m);
    std::snprintf(line, sizeof line, "%-44s %-34s %5d %-3s %-4s %-4s %4lld %5s %5s %6s  %s\n", form.c_str(),
                  std::string(m.label).c_str(), m.caps.links, m.caps.satellite_mode ? "yes" : "no",
                  m.caps.reads ? "yes" : "no", m.caps.ctcss ? "yes" : "no", static_cast<long long>(m.caps.step_hz),
                  civ.c_str(), m.baud ? std::to_string(m.baud).c_str() : "-",
                  m.hamlib_model ? std::to_string(m.hamlib_model).c_str() : "-", std::string(m.note).c_str());
    out += line;
  }
  return out;
}

}  // namespace tb::radio
