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
    o.reads_tx_1c03 = m.name == "ic9700";   // radios-2026.md: the IC-9700 reads its TX frequency so
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

constexpr RadioCaps kOneLink{1, false, false, false, 10};
constexpr RadioCaps kTwoLinks{2, false, false, false, 10};

// Which band transmits in satellite mode: IC-9700 Main receives and Sub transmits (Hamlib's
// icom_get_split_vfos); IC-9100, IC-910H and IC-821H Main transmits (Gpredict's "IC-910H: MAIN up /
// SUB down"; Hamlib's note that the IC-821H is the other way round from the IC-9700).
const RadioModel kModels[] = {
    {"sim", "trakbox simulated radio", SpecForm::none, Protocol::simulated, 0, 0, Link::uplink, SatCommand::none, false,
     {2, false, true, true, 1}, 0, "the default; records what it is told", make_simulated},
    // Today's families: menu 6-7 supplies addresses, speed and the Yaesu model.
    {"icom", "Icom CI-V (menu 6-7)", SpecForm::device, Protocol::icom, 0, 1200, Link::uplink, SatCommand::none, false,
     kTwoLinks, 0, "RX/TX addresses, band select and speed from menu 6-7", make_icom},
    {"kenwood", "Kenwood TS-790/711/811", SpecForm::device, Protocol::kenwood, 0, 4800, Link::uplink, SatCommand::none,
     false, kTwoLinks, 0, "downlink VFO A, uplink VFO B", make_kenwood},
    {"yaesu", "Yaesu FT-736 (FT-847 in menu 6-7)", SpecForm::device, Protocol::ft736, 0, 4800, Link::uplink,
     SatCommand::ft736, false, {2, true, false, false, 10}, 0, "the FT-847's own opcodes when STATION.DAT names YAESU_847",
     make_yaesu_family},
    {"cat", "the rig of menu 6-7", SpecForm::device, Protocol::cat, 0, 0, Link::uplink, SatCommand::none, false,
     kTwoLinks, 0, "icom, kenwood or yaesu as menu 6-7 chose", make_cat},
    // The satellite radios of 2026.
    {"ic9700", "Icom IC-9700", SpecForm::device_baud, Protocol::icom, 0xA2, 19200, Link::downlink, SatCommand::icom_16_5a,
     false, {2, true, true, true, 1}, 3081, "satellite mode 16 5A; Main down, Sub up; echo or not", make_icom},
    {"ic9100", "Icom IC-9100", SpecForm::device_baud, Protocol::icom, 0x7C, 19200, Link::uplink, SatCommand::icom_16_5a,
     false, {2, true, true, true, 1}, 3068, "satellite mode 16 5A; Main up, Sub down", make_icom},
    {"ic910h", "Icom IC-910H", SpecForm::device_baud, Protocol::icom, 0x60, 19200, Link::uplink, SatCommand::icom_1a_07,
     false, {2, true, true, false, 1}, 3044, "satellite mode 1A 07; Main up, Sub down", make_icom},
    {"ic821h", "Icom IC-821H", SpecForm::device_baud, Protocol::icom, 0x4C, 9600, Link::uplink, SatCommand::none, true,
     kTwoLinks, 3034, "4-byte frequencies; 07 D0/D1 before each command (Main up)", make_icom},
    {"ic275", "Icom IC-275", SpecForm::device_baud, Protocol::icom, 0x10, 1200, Link::uplink, SatCommand::none, false,
     kOneLink, 3004, "one band: pair it with --uplink-radio", make_icom},
    {"ic970", "Icom IC-970", SpecForm::device_baud, Protocol::icom, 0x2E, 1200, Link::uplink, SatCommand::none, false,
     kOneLink, 3035, "main band only (sub band select unconfirmed)", make_icom},
    {"ic705", "Icom IC-705", SpecForm::device_baud, Protocol::icom, 0xA4, 19200, Link::uplink, SatCommand::none, false,
     {1, false, true, true, 1}, 3085, "one link: pair it with --uplink-radio", make_icom},
    {"ts2000", "Kenwood TS-2000", SpecForm::device_baud, Protocol::kenwood, 0, 9600, Link::downlink,
     SatCommand::kenwood_sa, false, {2, true, true, true, 1}, 2014,
     "satellite mode SA: Main down (FA), Sub up (FB); TN/TO tone; read with FA;/FB;", make_kenwood},
    {"ts790", "Kenwood TS-790", SpecForm::device_baud, Protocol::kenwood, 0, 4800, Link::uplink, SatCommand::none,
     false, kTwoLinks, 2007, "VFO A down, B up", make_kenwood},
    {"ft847", "Yaesu FT-847", SpecForm::device_baud, Protocol::ft847, 0, 4800, Link::uplink, SatCommand::ft847, false,
     {2, true, true, true, 10}, 1001, "satellite mode 4E; SAT RX / SAT TX opcodes 11/21, read 13/23", make_ft8xx},
    {"ft817", "Yaesu FT-817", SpecForm::device_baud, Protocol::ft817, 0, 4800, Link::uplink, SatCommand::none, false,
     {1, false, true, true, 10}, 1020, "one link: a pair is --radio ft817:A --uplink-radio ft817:B", make_ft8xx},
    {"ft818", "Yaesu FT-818", SpecForm::device_baud, Protocol::ft817, 0, 4800, Link::uplink, SatCommand::none, false,
     {1, false, true, true, 10}, 1041, "as the FT-817", make_ft8xx},
    {"ft736", "Yaesu FT-736R", SpecForm::device_baud, Protocol::ft736, 0, 4800, Link::uplink, SatCommand::ft736, false,
     {2, true, false, false, 10}, 1010, "satellite mode 0E; never acknowledged, cannot be read", make_ft736},
    // Hamlib.
    {"hamlib", "any Hamlib backend", SpecForm::hamlib, Protocol::hamlib, 0, 0, Link::uplink, SatCommand::none, false,
     {2, false, true, true, 1}, 0, "MODEL: Hamlib's number or name (rigctl -l)", make_hamlib},
    {"rigctld", "a rigctld daemon (Hamlib NET rigctl)", SpecForm::rigctld, Protocol::rigctld, 0, 0, Link::uplink,
     SatCommand::none, false, {2, false, true, true, 1}, 2, "HOST 127.0.0.1, PORT 4532 by default", make_rigctld},
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
