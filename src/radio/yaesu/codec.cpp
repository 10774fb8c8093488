#include "radio/yaesu/codec.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace tb::radio {

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
