#include "radio/kenwood/codec.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace tb::radio {

namespace kenwood {

std::string set_frequency(Vfo vfo, Hz hz) {
  require_frequency(hz, pow10(11), "Kenwood");
  std::string digits = std::to_string(hz);
  digits.insert(0, 11 - digits.size(), '0');
  return std::string(vfo == Vfo::a ? "FA" : "FB") + digits + ";";
}

std::optional<char> mode_digit(Mode mode) {
  switch (mode) {
    case Mode::lsb: return '1';
    case Mode::usb: return '2';
    case Mode::cw: return '3';
    case Mode::fm: return '4';
    case Mode::none: break;
  }
  return std::nullopt;
}

std::optional<Mode> mode_from_digit(char d) {
  switch (d) {
    case '1': return Mode::lsb;
    case '2': return Mode::usb;
    case '3': case '7': return Mode::cw;
    case '4': return Mode::fm;
    default: return std::nullopt;
  }
}

std::optional<std::string> set_mode(Mode mode) {
  auto d = mode_digit(mode);
  if (!d) return std::nullopt;
  return std::string("MD") + *d + ";";
}

std::string select_vfo(Vfo vfo, char letter) { return std::string("F") + letter + (vfo == Vfo::a ? "0;" : "1;"); }
std::string read_frequency(Vfo vfo) { return vfo == Vfo::a ? "FA;" : "FB;"; }
std::string split(bool on) { return on ? "SP1;" : "SP0;"; }

std::optional<Frequency> decode_frequency(std::string_view c) {
  if (!c.empty() && c.back() == ';') c.remove_suffix(1);
  if (c.size() != 13 || c[0] != 'F' || (c[1] != 'A' && c[1] != 'B')) return std::nullopt;
  Frequency f;
  f.vfo = c[1] == 'A' ? Vfo::a : Vfo::b;
  for (char ch : c.substr(2)) {
    if (ch < '0' || ch > '9') return std::nullopt;
    f.hz = f.hz * 10 + (ch - '0');
  }
  return f;
}

std::optional<Mode> decode_mode(std::string_view c) {
  if (!c.empty() && c.back() == ';') c.remove_suffix(1);
  if (c.size() != 3 || c.substr(0, 2) != "MD") return std::nullopt;
  return mode_from_digit(c[2]);
}

std::vector<std::string> split_commands(std::string_view s, std::string* rest) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == ';') {
      out.emplace_back(s.substr(start, i + 1 - start));
      start = i + 1;
    }
  }
  if (rest) *rest = std::string(s.substr(start));
  return out;
}

bool is_refusal(std::string_view c) { return c == "?;" || c == "E;" || c == "O;"; }

std::optional<Satellite> decode_satellite(std::string_view c) {
  if (!c.empty() && c.back() == ';') c.remove_suffix(1);
  if (c.size() < 3 || c.size() > 17 || c.substr(0, 2) != "SA") return std::nullopt;
  Satellite s;
  const std::string_view digits = c.substr(2, 7);
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (digits[i] < '0' || digits[i] > '9') return std::nullopt;
    s.digits[i] = digits[i];
  }
  return s;
}

std::string set_satellite(const Satellite& s) { return "SA" + s.digits + ";"; }

Satellite satellite_working(const Satellite& found, bool ctrl_on_sub) {
  Satellite s = found;
  s.digits[0] = '1';                       // P1 on
  s.digits[2] = '1';                       // P3 the uplink on Sub
  s.digits[3] = ctrl_on_sub ? '1' : '0';   // P4 CTRL
  s.digits[4] = '0';                       // P5 TRACE off
  s.digits[6] = '0';                       // P7 VFO
  return s;
}

std::optional<std::string> set_tone_number(int tenths_hz) {
  static constexpr std::array<int, 39> kTones{
      670,  719,  744,  770,  797,  825,  854,  885,  915,  948,  974,  1000, 1035,
      1072, 1109, 1148, 1188, 1230, 1273, 1318, 1365, 1413, 1462, 1514, 1567, 1622,
      1679, 1738, 1799, 1862, 1928, 2035, 2107, 2181, 2257, 2336, 2418, 2503, 17500};
  for (std::size_t i = 0; i < kTones.size(); ++i) {
    if (kTones[i] != tenths_hz) continue;
    const std::string number = std::to_string(i + 1);
    return "TN" + std::string(2 - number.size(), '0') + number + ";";
  }
  return std::nullopt;
}

}  // namespace kenwood

}  // namespace tb::radio
