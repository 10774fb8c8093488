#include "radio/cat.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace tb::radio {

namespace {

std::uint64_t pow10(int n) {
  std::uint64_t p = 1;
  while (n-- > 0) p *= 10;
  return p;
}

void require_frequency(Hz hz, std::uint64_t limit, const char* what) {
  if (hz < 0 || static_cast<std::uint64_t>(hz) >= limit)
    throw std::invalid_argument(std::string(what) + ": frequency " + std::to_string(hz) +
                                " Hz out of range");
}

}  // namespace

std::string to_hex(std::span<const std::uint8_t> bytes) {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i) out.push_back(' ');
    out.push_back(digits[bytes[i] >> 4]);
    out.push_back(digits[bytes[i] & 0x0F]);
  }
  return out;
}

std::optional<Bytes> from_hex(std::string_view text) {
  Bytes out;
  int high = -1;
  for (char c : text) {
    if (c == ' ' || c == '\t') continue;
    int v;
    if (c >= '0' && c <= '9') v = c - '0';
    else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    else return std::nullopt;
    if (high < 0) {
      high = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(high << 4 | v));
      high = -1;
    }
  }
  if (high >= 0) return std::nullopt;
  return out;
}

Bytes bcd_little_endian(std::uint64_t value, int bytes) {
  Bytes out;
  for (int i = 0; i < bytes; ++i) {
    const int lo = static_cast<int>(value % 10);
    value /= 10;
    const int hi = static_cast<int>(value % 10);
    value /= 10;
    out.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
  }
  return out;
}

std::optional<std::uint64_t> decode_bcd_little_endian(std::span<const std::uint8_t> bytes) {
  std::uint64_t v = 0;
  for (std::size_t i = bytes.size(); i-- > 0;) {
    const int hi = bytes[i] >> 4, lo = bytes[i] & 0x0F;
    if (hi > 9 || lo > 9) return std::nullopt;
    v = v * 100 + static_cast<std::uint64_t>(hi * 10 + lo);
  }
  return v;
}

Bytes bcd_big_endian(std::uint64_t value, int bytes) {
  Bytes out = bcd_little_endian(value, bytes);
  std::reverse(out.begin(), out.end());
  return out;
}

std::optional<std::uint64_t> decode_bcd_big_endian(std::span<const std::uint8_t> bytes) {
  Bytes rev(bytes.rbegin(), bytes.rend());
  return decode_bcd_little_endian(rev);
}

// ---------------------------------------------------------------------------------------------
namespace icom {

Bytes frame(std::uint8_t to, std::uint8_t from, std::uint8_t cmd, std::span<const std::uint8_t> data) {
  Bytes out{kPreamble, kPreamble, to, from, cmd};
  out.insert(out.end(), data.begin(), data.end());
  out.push_back(kEnd);
  return out;
}

Bytes set_frequency(std::uint8_t to, Hz hz, FrequencyWidth width, std::uint8_t from) {
  require_frequency(hz, pow10(10), "Icom CI-V");
  const int n = width == FrequencyWidth::five_bytes ? 5 : 4;
  // The 4-byte form carries the low eight digits; the radio knows its own band.
  return frame(to, from, kCmdSetFrequency, bcd_little_endian(static_cast<std::uint64_t>(hz), n));
}

std::optional<std::uint8_t> mode_code(Mode mode) {
  switch (mode) {
    case Mode::lsb: return 0x00;
    case Mode::usb: return 0x01;
    case Mode::cw: return 0x03;
    case Mode::fm: return 0x05;
    case Mode::none: break;
  }
  return std::nullopt;
}

std::optional<Mode> mode_from_code(std::uint8_t code) {
  switch (code) {
    case 0x00: return Mode::lsb;
    case 0x01: return Mode::usb;
    case 0x03: case 0x07: return Mode::cw;
    case 0x05: return Mode::fm;
    default: return std::nullopt;
  }
}

std::optional<Bytes> set_mode(std::uint8_t to, Mode mode, std::uint8_t from) {
  auto code = mode_code(mode);
  if (!code) return std::nullopt;
  const std::uint8_t data[] = {*code};   // no filter byte: the radio keeps its filter
  return frame(to, from, kCmdSetMode, data);
}

Bytes select_band(std::uint8_t to, Band band, std::uint8_t from) {
  const std::uint8_t data[] = {static_cast<std::uint8_t>(band == Band::main ? 0xD0 : 0xD1)};
  return frame(to, from, kCmdSelectVfo, data);
}

Bytes select_vfo(std::uint8_t to, Vfo vfo, std::uint8_t from) {
  const std::uint8_t data[] = {static_cast<std::uint8_t>(vfo == Vfo::a ? 0x00 : 0x01)};
  return frame(to, from, kCmdSelectVfo, data);
}

Bytes read_frequency(std::uint8_t to, std::uint8_t from) { return frame(to, from, 0x03); }

Bytes read_transmit_frequency(std::uint8_t to, std::uint8_t from) {
  const std::uint8_t data[] = {0x03};
  return frame(to, from, 0x1C, data);
}

Bytes satellite_mode(std::uint8_t to, std::uint8_t cmd, std::uint8_t sub, bool on, std::uint8_t from) {
  const std::uint8_t data[] = {sub, static_cast<std::uint8_t>(on ? 0x01 : 0x00)};
  return frame(to, from, cmd, data);
}

Bytes set_tone_frequency(std::uint8_t to, int tenths_hz, std::uint8_t from) {
  if (tenths_hz <= 0 || tenths_hz > 9999) throw std::invalid_argument("CTCSS tone " + std::to_string(tenths_hz) + " (tenths of Hz) out of range");
  Bytes data{0x00};
  const Bytes bcd = bcd_big_endian(static_cast<std::uint64_t>(tenths_hz), 3);
  data.insert(data.end(), bcd.begin(), bcd.end());
  return frame(to, from, 0x1B, data);
}

Bytes tone_function(std::uint8_t to, bool on, std::uint8_t from) {
  const std::uint8_t data[] = {0x42, static_cast<std::uint8_t>(on ? 0x01 : 0x00)};
  return frame(to, from, 0x16, data);
}

std::optional<Frame> decode_frame(std::span<const std::uint8_t> b) {
  if (b.size() < 6 || b[0] != kPreamble || b[1] != kPreamble || b.back() != kEnd) return std::nullopt;
  for (std::size_t i = 2; i + 1 < b.size(); ++i)
    if (b[i] == kEnd || b[i] == kPreamble) return std::nullopt;
  Frame f;
  f.to = b[2];
  f.from = b[3];
  f.cmd = b[4];
  f.data.assign(b.begin() + 5, b.end() - 1);
  return f;
}

std::optional<Hz> decode_frequency(const Frame& f) {
  if (f.cmd == 0x1C && f.data.size() == 6 && f.data[0] == 0x03) {
    auto v = decode_bcd_little_endian(std::span(f.data).subspan(1));
    if (!v) return std::nullopt;
    return static_cast<Hz>(*v);
  }
  if (f.cmd != kCmdSetFrequency && f.cmd != 0x03 && f.cmd != 0x00) return std::nullopt;
  if (f.data.size() != 5 && f.data.size() != 4) return std::nullopt;
  auto v = decode_bcd_little_endian(f.data);
  if (!v) return std::nullopt;
  return static_cast<Hz>(*v);
}

std::optional<Mode> decode_mode(const Frame& f) {
  if ((f.cmd != kCmdSetMode && f.cmd != 0x04 && f.cmd != 0x01) || f.data.empty()) return std::nullopt;
  return mode_from_code(f.data[0]);
}

Reply parse_reply(std::span<const std::uint8_t> b) {
  if (std::find(b.begin(), b.end(), kCollision) != b.end()) return Reply::collision;
  auto f = decode_frame(b);
  if (!f || f->data.size() != 0) return Reply::not_a_reply;
  if (f->cmd == kOk) return Reply::ok;
  if (f->cmd == kNg) return Reply::ng;
  return Reply::not_a_reply;
}

void FrameReader::feed(std::span<const std::uint8_t> bytes) {
  buf_.insert(buf_.end(), bytes.begin(), bytes.end());
}

std::optional<Bytes> FrameReader::next() {
  while (!buf_.empty()) {
    if (buf_[0] == kCollision) {  // a jam code outside a frame
      buf_.erase(buf_.begin());
      return Bytes{kCollision};
    }
    if (buf_[0] != kPreamble) {
      buf_.erase(buf_.begin());
      ++skipped_;
      continue;
    }
    auto end = std::find(buf_.begin(), buf_.end(), kEnd);
    if (end == buf_.end()) return std::nullopt;  // incomplete
    Bytes f(buf_.begin(), end + 1);
    buf_.erase(buf_.begin(), end + 1);
    return f;
  }
  return std::nullopt;
}

}  // namespace icom

// ---------------------------------------------------------------------------------------------
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

// ---------------------------------------------------------------------------------------------
namespace yaesu {

Command cat_on() { return {0x00, 0x00, 0x00, 0x00, kOpCatOn}; }
Command cat_off() { return {0x80, 0x80, 0x80, 0x80, kOpCatOff}; }
Command sat_mode_on() { return {0x00, 0x00, 0x00, 0x00, kOpSatOn}; }
Command sat_mode_off() { return {0x00, 0x00, 0x00, 0x00, kOpSatOff}; }

std::uint8_t frequency_opcode(Target t) {
  switch (t) {
    case Target::sat_rx: return 0x1E;
    case Target::sat_tx: return 0x2E;
    case Target::main: break;
  }
  return 0x01;
}

std::uint8_t mode_opcode(Target t) {
  switch (t) {
    case Target::sat_rx: return 0x17;
    case Target::sat_tx: return 0x27;
    case Target::main: break;
  }
  return 0x07;
}

Command set_frequency(Target t, Hz hz) {
  if (hz < 0) throw std::invalid_argument("FT-736: negative frequency");
  const std::uint64_t tens = static_cast<std::uint64_t>((hz + 5) / 10);
  const bool band_1200 = tens >= 120000000 && tens < 130000000;
  if (tens >= 100000000 && !band_1200)
    throw std::invalid_argument("FT-736: frequency " + std::to_string(hz) +
                                " Hz out of range (below 1000 MHz or 1200-1300 MHz)");
  Bytes d = bcd_big_endian(tens, 4);   // the low eight digits
  if (band_1200) d[0] = static_cast<std::uint8_t>(0xC0 | (d[0] & 0x0F));
  return {d[0], d[1], d[2], d[3], frequency_opcode(t)};
}

std::optional<std::uint8_t> mode_code(Mode mode, bool narrow_fm) {
  switch (mode) {
    case Mode::lsb: return 0x00;
    case Mode::usb: return 0x01;
    case Mode::cw: return 0x02;
    case Mode::fm: return narrow_fm ? 0x88 : 0x08;
    case Mode::none: break;
  }
  return std::nullopt;
}

std::optional<Command> set_mode(Target t, Mode mode, bool narrow_fm) {
  auto code = mode_code(mode, narrow_fm);
  if (!code) return std::nullopt;
  return Command{*code, 0x00, 0x00, 0x00, mode_opcode(t)};
}

std::optional<Hz> decode_frequency_digits(std::span<const std::uint8_t, 4> p) {
  std::array<std::uint8_t, 4> d{p[0], p[1], p[2], p[3]};
  std::uint64_t extra = 0;
  if ((d[0] >> 4) == 0xC) {  // 1.2 GHz band: "C" stands for "12"
    d[0] = static_cast<std::uint8_t>(0x20 | (d[0] & 0x0F));
    extra = 100000000;
  }
  auto v = decode_bcd_big_endian(d);
  if (!v) return std::nullopt;
  return static_cast<Hz>((*v + extra) * 10);
}

Decoded decode(const Command& c) {
  Decoded d;
  const std::uint8_t op = c[4];
  if (c == cat_on()) { d.kind = Decoded::Kind::cat_on; return d; }
  if (c == cat_off()) { d.kind = Decoded::Kind::cat_off; return d; }
  if (op == kOpSatOn) { d.kind = Decoded::Kind::sat_on; return d; }
  if (op == kOpSatOff) { d.kind = Decoded::Kind::sat_off; return d; }
  for (Target t : {Target::main, Target::sat_rx, Target::sat_tx}) {
    if (op == frequency_opcode(t)) {
      auto hz = decode_frequency_digits(std::span<const std::uint8_t, 4>(c.data(), 4));
      if (!hz) return d;
      d.kind = Decoded::Kind::frequency;
      d.target = t;
      d.hz = *hz;
      return d;
    }
    if (op == mode_opcode(t)) {
      d.kind = Decoded::Kind::mode;
      d.target = t;
      d.mode_code = c[0];
      switch (c[0]) {
        case 0x00: d.mode = Mode::lsb; break;
        case 0x01: d.mode = Mode::usb; break;
        case 0x02: case 0x82: d.mode = Mode::cw; break;
        case 0x08: case 0x88: d.mode = Mode::fm; break;
        default: break;
      }
      return d;
    }
  }
  return d;
}

}  // namespace yaesu

// ---------------------------------------------------------------------------------------------
namespace {

// 8 BCD digits of 10 Hz, most significant first, for the FT-847 and FT-817 (below 1 GHz).
yaesu::Command yaesu_frequency(Hz hz, std::uint8_t op, const char* what) {
  if (hz < 0) throw std::invalid_argument(std::string(what) + ": negative frequency");
  const std::uint64_t tens = static_cast<std::uint64_t>((hz + 5) / 10);
  if (tens >= 100000000)
    throw std::invalid_argument(std::string(what) + ": frequency " + std::to_string(hz) + " Hz out of range (below 1000 MHz)");
  const Bytes d = bcd_big_endian(tens, 4);
  return {d[0], d[1], d[2], d[3], op};
}

std::optional<Hz> yaesu_read_answer(std::span<const std::uint8_t> a) {
  if (a.size() != 5) return std::nullopt;
  auto v = decode_bcd_big_endian(a.first(4));
  if (!v) return std::nullopt;
  return static_cast<Hz>(*v * 10);
}

std::uint8_t vfo_nibble(yaesu::Target t) {
  switch (t) {
    case yaesu::Target::sat_rx: return 0x10;
    case yaesu::Target::sat_tx: return 0x20;
    case yaesu::Target::main: break;
  }
  return 0x00;
}

}  // namespace

namespace ft847 {

Command cat_on() { return {0x00, 0x00, 0x00, 0x00, 0x00}; }
Command cat_off() { return {0x00, 0x00, 0x00, 0x00, 0x80}; }
Command sat_mode_on() { return {0x00, 0x00, 0x00, 0x00, 0x4E}; }
Command sat_mode_off() { return {0x00, 0x00, 0x00, 0x00, 0x8E}; }

Command set_frequency(Target t, Hz hz) {
  return yaesu_frequency(hz, static_cast<std::uint8_t>(vfo_nibble(t) | 0x01), "FT-847");
}

std::optional<Command> set_mode(Target t, Mode mode) {
  auto code = yaesu::mode_code(mode);
  if (!code) return std::nullopt;
  return Command{*code, 0x00, 0x00, 0x00, static_cast<std::uint8_t>(vfo_nibble(t) | 0x07)};
}

Command read(Target t) { return {0x00, 0x00, 0x00, 0x00, static_cast<std::uint8_t>(vfo_nibble(t) | 0x03)}; }

std::optional<Hz> decode_read(std::span<const std::uint8_t> answer) { return yaesu_read_answer(answer); }

std::optional<Command> set_tone(Target t, int tenths_hz) {
  // The FT-847's 39 tones and its CAT code for each (Hamlib ft847.c, ft847_ctcss_list / _cat).
  static constexpr int kTones[] = {670,  693,  719,  744,  770,  797,  825,  854,  885,  915,  948,  974,  1000,
                                   1035, 1072, 1109, 1148, 1188, 1230, 1273, 1318, 1365, 1413, 1462, 1514, 1567,
                                   1622, 1679, 1738, 1799, 1862, 1928, 2035, 2107, 2181, 2257, 2336, 2418, 2503};
  static constexpr std::uint8_t kCodes[] = {
      0x3F, 0x39, 0x1F, 0x3E, 0x0F, 0x3D, 0x1E, 0x3C, 0x0E, 0x3B, 0x1D, 0x3A, 0x0D, 0x1C, 0x0C, 0x1B, 0x0B, 0x1A, 0x0A, 0x19,
      0x09, 0x18, 0x08, 0x17, 0x07, 0x16, 0x06, 0x15, 0x05, 0x14, 0x04, 0x13, 0x03, 0x12, 0x02, 0x11, 0x01, 0x10, 0x00};
  static_assert(std::size(kTones) == std::size(kCodes));
  for (std::size_t i = 0; i < std::size(kTones); ++i)
    if (kTones[i] == tenths_hz) return Command{kCodes[i], 0x00, 0x00, 0x00, static_cast<std::uint8_t>(vfo_nibble(t) | 0x0B)};
  return std::nullopt;
}

Command tone_encoder(Target t, bool on) {
  return {static_cast<std::uint8_t>(on ? 0x4A : 0x8A), 0x00, 0x00, 0x00, static_cast<std::uint8_t>(vfo_nibble(t) | 0x0A)};
}

}  // namespace ft847

namespace ft817 {

Command set_frequency(Hz hz) { return yaesu_frequency(hz, 0x01, "FT-817"); }

std::optional<Command> set_mode(Mode mode) {
  auto code = yaesu::mode_code(mode);
  if (!code) return std::nullopt;
  return Command{*code, 0x00, 0x00, 0x00, 0x07};
}

Command read() { return {0x00, 0x00, 0x00, 0x00, 0x03}; }

std::optional<Hz> decode_read(std::span<const std::uint8_t> answer) { return yaesu_read_answer(answer); }

Command set_tone(int tenths_hz) {
  if (tenths_hz <= 0 || tenths_hz > 9999) throw std::invalid_argument("FT-817: CTCSS tone out of range");
  const Bytes d = bcd_big_endian(static_cast<std::uint64_t>(tenths_hz), 2);
  return {d[0], d[1], d[0], d[1], 0x0B};
}

Command tone_encoder(bool on) { return {static_cast<std::uint8_t>(on ? 0x4A : 0x8A), 0x00, 0x00, 0x00, 0x0A}; }

}  // namespace ft817

}  // namespace tb::radio
