#include "radio/icom/codec.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace tb::radio {

namespace icom {

Bytes frame(std::uint8_t to, std::uint8_t from, std::uint8_t cmd, std::span<const std::uint8_t> data) {
  Bytes out{kPreamble, kPreamble, to, from, cmd};
  out.insert(out.end(), data.begin(), data.end());
  out.push_back(kEnd);
  return out;
}

Bytes set_frequency(std::uint8_t to, Hz hz, FrequencyWidth width, std::uint8_t from) {
  if (width == FrequencyWidth::five_or_six) {
    require_frequency(hz, pow10(12), "Icom CI-V (IC-905)");
    const int n = hz >= kSixBytesFrom ? 6 : 5;
    return frame(to, from, kCmdSetFrequency, bcd_little_endian(static_cast<std::uint64_t>(hz), n));
  }
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
  if (f.cmd == 0x1C && (f.data.size() == 6 || f.data.size() == 7) && f.data[0] == 0x03) {
    auto v = decode_bcd_little_endian(std::span(f.data).subspan(1));
    if (!v) return std::nullopt;
    return static_cast<Hz>(*v);
  }
  if (f.cmd != kCmdSetFrequency && f.cmd != 0x03 && f.cmd != 0x00) return std::nullopt;
  if (f.data.size() < 4 || f.data.size() > 6) return std::nullopt;
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

}  // namespace tb::radio
