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

const char* to_string(Rig r) {
  switch (r) {
    case Rig::kenwood: return "KENWOOD";
    case Rig::yaesu: return "YAESU";
    case Rig::icom: return "ICOM";
    case Rig::none: break;
  }
  return "NONE";
}

}  // namespace tb::radio
