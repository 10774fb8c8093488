#include "radio/config.h"

#include <cctype>

namespace tb::radio {

const char* to_string(Mode m) {
  switch (m) {
    case Mode::fm: return "FM";
    case Mode::lsb: return "LSB";
    case Mode::usb: return "USB";
    case Mode::cw: return "CW";
    case Mode::none: break;
  }
  return "None";
}

std::optional<Mode> parse_mode(std::string_view text) {
  std::string lower;
  for (char c : text) lower.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  if (lower == "fm") return Mode::fm;
  if (lower == "lsb") return Mode::lsb;
  if (lower == "usb") return Mode::usb;
  if (lower == "cw") return Mode::cw;
  if (lower == "none") return Mode::none;
  return std::nullopt;
}

const char* to_string(DopplerControl d) {
  return d == DopplerControl::mic_click ? "Mic-click" : "CAT";
}

const char* to_string(Record r) {
  switch (r) {
    case Record::audio: return "audio";
    case Record::iq: return "iq";
    case Record::off: break;
  }
  return "off";
}

const char* to_string(Rig r) {
  switch (r) {
    case Rig::kenwood: return "KENWOOD";
    case Rig::yaesu: return "YAESU";
    case Rig::icom: return "ICOM";
    case Rig::none: break;
  }
  return "NONE";
}

int standard_cat_baud(Rig r) {
  switch (r) {
    case Rig::icom: return 1200;
    case Rig::kenwood:
    case Rig::yaesu: return 4800;
    case Rig::none: break;
  }
  return 0;
}

int effective_cat_baud(const RadioConfig& c) { return c.cat_baud > 0 ? c.cat_baud : standard_cat_baud(c.rig); }

const char* to_string(RigModel m) {
  switch (m) {
    case RigModel::kenwood_711: return "TS-711";
    case RigModel::yaesu_other: return "other";
    case RigModel::yaesu_847: return "FT-847";
    case RigModel::yaesu_736: return "FT-736";
    case RigModel::generic: break;
  }
  return "";
}

const char* to_string(ReverseAssignment r) {
  switch (r) {
    case ReverseAssignment::icom_main_sub: return "ir";
    case ReverseAssignment::kenwood_vfo: return "kr";
    case ReverseAssignment::none: break;
  }
  return "";
}

bool SatelliteRadio::next_uplink() {
  if (alternate_uplinks_hz.empty() || !has_uplink()) return false;
  alternate_uplinks_hz.push_back(uplink_hz);
  uplink_hz = alternate_uplinks_hz.front();
  alternate_uplinks_hz.erase(alternate_uplinks_hz.begin());
  return true;
}

std::string mode_name_problem(std::string_view name) {
  if (name.empty()) return "a mode name is empty";
  if (name.size() > kMaxModeName) return "a mode name has at most " + std::to_string(kMaxModeName) + " characters";
  for (const char c : name) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' ||
                    c == '+' || c == '/' || c == '.' || c == '_';
    if (!ok) return "a mode name holds only letters, digits and - + / . _";
  }
  return {};
}

std::string default_mode_name(const SatelliteRadio& r) {
  switch (r.downlink_mode) {
    case Mode::usb:
    case Mode::lsb: return "SSB";
    case Mode::fm: return "FM";
    case Mode::cw: return "CW";
    case Mode::none: break;
  }
  return "default";
}

}  // namespace tb::radio
