#include "radio/flex/codec.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>

#include "util/text.h"

namespace tb::radio::flex {

namespace {

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::optional<std::uint32_t> hex32(std::string_view s) {
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) s.remove_prefix(2);
  if (s.empty() || s.size() > 8) return std::nullopt;
  std::uint32_t v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 16);
  if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

// "1" / "0" as a boolean field's value.
std::optional<bool> flag(std::string_view v) {
  if (v == "1") return true;
  if (v == "0") return false;
  return std::nullopt;
}

}  // namespace

std::string mhz(Hz hz) {
  // 0 .. 99 999.999999 MHz: every band a FlexRadio or its transverters tune.
  if (hz < 0 || hz >= 100'000'000'000) throw std::invalid_argument(fmt::format("frequency {} Hz out of range for SmartSDR", hz));
  return fmt::format("{}.{:06}", hz / 1'000'000, hz % 1'000'000);
}

std::string command(std::uint32_t seq, std::string_view body) { return fmt::format("C{}|{}\n", seq, body); }

std::string tune(int slice, Hz hz) { return fmt::format("slice tune {} {}", slice, mhz(hz)); }

std::optional<std::string> mode_name(Mode mode) {
  switch (mode) {
    case Mode::usb: return "USB";
    case Mode::lsb: return "LSB";
    case Mode::cw: return "CW";
    case Mode::fm: return "FM";
    case Mode::none: break;
  }
  return std::nullopt;
}

std::optional<Mode> mode_from_name(std::string_view name) {
  const std::string n = text::upper(name);
  if (n == "USB") return Mode::usb;
  if (n == "LSB") return Mode::lsb;
  if (n == "CW") return Mode::cw;
  if (n == "FM" || n == "NFM" || n == "DFM") return Mode::fm;
  return std::nullopt;
}

std::optional<std::string> set_mode(int slice, Mode mode) {
  const auto name = mode_name(mode);
  if (!name) return std::nullopt;
  return fmt::format("slice set {} mode={}", slice, *name);
}

std::string create(Hz hz, Mode mode) {
  std::string out = "slice create freq=" + mhz(hz);
  if (const auto name = mode_name(mode)) out += " mode=" + *name;
  return out;
}

std::string set_tx(int slice) { return fmt::format("slice set {} tx=1", slice); }

std::string set_tone(int slice, int tenths_hz) {
  if (tenths_hz <= 0) return fmt::format("slice set {} fm_tone_mode=OFF", slice);
  return fmt::format("slice set {} fm_tone_mode=CTCSS_TX fm_tone_value={}.{}", slice, tenths_hz / 10, tenths_hz % 10);
}

std::optional<Hz> decode_mhz(std::string_view text) {
  const auto dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
  if (!all_digits(whole) || whole.size() > 5 || (dot != std::string_view::npos && !all_digits(frac))) return std::nullopt;
  // Beyond 1 Hz: rounded half up on the seventh decimal, the rest ignored.
  const bool round_up = frac.size() > 6 && frac[6] >= '5';
  if (frac.size() > 6) frac = frac.substr(0, 6);
  Hz hz = *text::parse_integer<Hz>(whole) * 1'000'000;
  Hz scale = 100'000;
  for (char c : frac) {
    hz += (c - '0') * scale;
    scale /= 10;
  }
  return hz + (round_up ? 1 : 0);
}

std::optional<Reply> decode_reply(std::string_view line) {
  if (line.size() < 2 || line[0] != 'R') return std::nullopt;
  const auto bar1 = line.find('|');
  if (bar1 == std::string_view::npos) return std::nullopt;
  const auto bar2 = line.find('|', bar1 + 1);
  const std::string_view seq = line.substr(1, bar1 - 1);
  const std::string_view status = line.substr(bar1 + 1, bar2 == std::string_view::npos ? std::string_view::npos : bar2 - bar1 - 1);
  const auto s = hex32(status);
  if (!all_digits(seq) || !s) return std::nullopt;
  const auto n = text::parse_integer<std::uint32_t>(seq);
  if (!n) return std::nullopt;
  Reply r{*n, *s, bar2 == std::string_view::npos ? std::string{} : std::string(line.substr(bar2 + 1))};
  // A debug part after a third '|' is not data.
  if (const auto bar3 = r.data.find('|'); bar3 != std::string::npos) r.data.erase(bar3);
  return r;
}

std::string error_text(std::uint32_t status) {
  switch (status) {
    case 0x50000001: return "50000001 unable to get foundation receiver assignment";
    case 0x50000003: return "50000003 license check failed";
    case 0x50000004: return "50000004 slice parameter error";
    case 0x50000005: return "50000005 wrong number or type of parameters";
    case 0x5000000D: return "5000000D incorrect slice receiver";
    case 0x50000016: return "50000016 malformed command";
    case 0x5000002C: return "5000002C incorrect number of parameters";
    case 0x5000002D: return "5000002D bad field";
    case 0x50000032: return "50000032 bad mode";
    default: break;
  }
  return fmt::format("error {:08X}", status);
}

std::optional<SliceStatus> decode_slice_status(std::string_view line) {
  if (line.size() < 2 || line[0] != 'S') return std::nullopt;
  const auto bar = line.find('|');
  if (bar == std::string_view::npos) return std::nullopt;
  const auto handle = hex32(line.substr(1, bar - 1));
  if (!handle) return std::nullopt;
  const auto words = text::split(line.substr(bar + 1), ' ');
  if (words.size() < 2 || words[0] != "slice") return std::nullopt;
  const auto index = text::parse_integer<int>(words[1]);
  if (!all_digits(words[1]) || !index) return std::nullopt;
  SliceStatus s{*handle, *index, {}, {}, {}, {}};
  for (std::size_t i = 2; i < words.size(); ++i) {
    const auto eq = words[i].find('=');
    if (eq == std::string_view::npos) continue;
    const std::string_view key = words[i].substr(0, eq), value = words[i].substr(eq + 1);
    if (key == "RF_frequency") s.hz = decode_mhz(value);
    else if (key == "mode") s.mode = mode_from_name(value);
    else if (key == "tx") s.tx = flag(value);
    else if (key == "in_use") s.in_use = flag(value);
  }
  return s;
}

std::optional<std::string> decode_version(std::string_view line) {
  if (line.size() < 2 || line[0] != 'V') return std::nullopt;
  const auto parts = text::split(line.substr(1), '.');
  if (parts.size() != 4 || !std::all_of(parts.begin(), parts.end(), all_digits)) return std::nullopt;
  return std::string(line.substr(1));
}

std::optional<std::uint32_t> decode_handle(std::string_view line) {
  if (line.size() < 2 || line[0] != 'H') return std::nullopt;
  return hex32(line.substr(1));
}

std::optional<std::vector<int>> decode_slice_list(std::string_view data) {
  std::vector<int> out;
  for (std::string_view w : text::split(data, ' ')) {
    if (w.empty()) continue;
    const auto n = text::parse_integer<int>(w);
    if (!all_digits(w) || !n) return std::nullopt;
    out.push_back(*n);
  }
  return out;
}

}  // namespace tb::radio::flex
