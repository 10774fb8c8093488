#include "radio/yaesu/newcat.h"
#include "radio/kenwood/codec.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace tb::radio::newcat {

namespace {

// The FT-991's 50 CTCSS tones in tenths of Hz, in the order of its CN numbers (the FT-991 CAT
// manual's CN table; Hamlib's common_ctcss_list).
constexpr int kTones[] = {670,  693,  719,  744,  770,  797,  825,  854,  885,  915,  948,  974,  1000,
                          1035, 1072, 1109, 1148, 1188, 1230, 1273, 1318, 1365, 1413, 1462, 1514, 1567,
                          1598, 1622, 1655, 1679, 1713, 1738, 1773, 1799, 1835, 1862, 1899, 1928, 1966,
                          1995, 2035, 2065, 2107, 2181, 2257, 2291, 2336, 2418, 2503, 2541};
static_assert(std::size(kTones) == 50);

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::string_view body(std::string_view answer) {   // without its ';'
  if (!answer.empty() && answer.back() == ';') answer.remove_suffix(1);
  return answer;
}

}  // namespace

std::string set_frequency(Vfo vfo, Hz hz) {
  require_frequency(hz, pow10(9), "Yaesu CAT (FA/FB, nine digits)");
  return fmt::format("{}{:09d};", vfo == Vfo::a ? "FA" : "FB", hz);
}

std::optional<Mode> mode_from_char(char c) {
  switch (c) {
    case '1': return Mode::lsb;
    case '2': return Mode::usb;
    case '3': case '7': return Mode::cw;
    case '4': case 'B': return Mode::fm;
    default: return std::nullopt;
  }
}

std::optional<std::string> set_mode(char band, Mode mode) {
  if (band != '0' && band != '1') throw std::invalid_argument(fmt::format("Yaesu CAT: MD band '{}' (0 or 1)", band));
  const auto c = kenwood::mode_digit(mode);  // the same MD codes as Kenwood's: LSB 1, USB 2, CW 3, FM 4
  if (!c) return std::nullopt;
  return fmt::format("MD{}{};", band, *c);
}

std::optional<std::string> set_tone(int tenths_hz) {
  const auto* it = std::find(std::begin(kTones), std::end(kTones), tenths_hz);
  if (it == std::end(kTones)) return std::nullopt;
  return fmt::format("CN00{:03d};CT02;", it - std::begin(kTones));
}

std::optional<Frequency> decode_frequency(std::string_view answer) {
  const std::string_view b = body(answer);
  if (b.size() != 11 || b[0] != 'F' || (b[1] != 'A' && b[1] != 'B') || !all_digits(b.substr(2))) return std::nullopt;
  Hz hz = 0;
  for (char c : b.substr(2)) hz = hz * 10 + (c - '0');
  return Frequency{b[1] == 'A' ? Vfo::a : Vfo::b, hz};
}

std::optional<Mode> decode_mode(std::string_view answer) {
  const std::string_view b = body(answer);
  if (b.size() != 4 || !b.starts_with("MD") || (b[2] != '0' && b[2] != '1')) return std::nullopt;
  return mode_from_char(b[3]);
}

std::optional<std::string> decode_id(std::string_view answer) {
  const std::string_view b = body(answer);
  if (b.size() != 6 || !b.starts_with("ID") || !all_digits(b.substr(2))) return std::nullopt;
  return std::string(b.substr(2));
}

}  // namespace tb::radio::newcat
