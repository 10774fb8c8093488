// Icom CI-V frames (IC-271/275/375/471/475/970, 820H/821H/910H, IC-9700/9100/705).
// Pure functions: values in, bytes out (and back); the byte strings of docs/radio.md ("CAT formats")
// are their unit tests (tests/unit/radio/test_cat.cpp). Encoders throw std::invalid_argument for a
// value the format cannot carry; Mode::none has no command (the mode encoders return nullopt).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "radio/bytes.h"

namespace tb::radio {

namespace icom {

inline constexpr std::uint8_t kPreamble = 0xFE;
inline constexpr std::uint8_t kEnd = 0xFD;
inline constexpr std::uint8_t kController = 0xE0;   // the controller's own address
inline constexpr std::uint8_t kBroadcast = 0x00;    // TrakBox's default radio address
inline constexpr std::uint8_t kOk = 0xFB;
inline constexpr std::uint8_t kNg = 0xFA;
inline constexpr std::uint8_t kCollision = 0xFC;

inline constexpr std::uint8_t kCmdSetFrequency = 0x05;
inline constexpr std::uint8_t kCmdSetMode = 0x06;
inline constexpr std::uint8_t kCmdSelectVfo = 0x07;

// Default CI-V addresses.
inline constexpr std::uint8_t kIc271 = 0x20, kIc275 = 0x10, kIc375 = 0x12, kIc471 = 0x22,
                              kIc475 = 0x14, kIc970 = 0x2E, kIc820 = 0x42, kIc821 = 0x4C,
                              kIc910 = 0x60;

// 4: IC-820H/821H (no 100 MHz digit). five_or_six: the IC-905, whose 10 GHz band takes 6 bytes
// (12 digits, 100 GHz down to 1 Hz) and every band below it 5.
enum class FrequencyWidth { five_bytes, four_bytes, five_or_six };
inline constexpr Hz kSixBytesFrom = 10'000'000'000;   // five_or_six: 6 bytes from 10 GHz up
enum class Band { main, sub };
enum class Vfo { a, b };

// FE FE to from cmd data... FD
Bytes frame(std::uint8_t to, std::uint8_t from, std::uint8_t cmd, std::span<const std::uint8_t> data = {});
Bytes set_frequency(std::uint8_t to, Hz hz, FrequencyWidth width = FrequencyWidth::five_bytes,
                    std::uint8_t from = kController);
std::optional<Bytes> set_mode(std::uint8_t to, Mode mode, std::uint8_t from = kController);
Bytes select_band(std::uint8_t to, Band band, std::uint8_t from = kController);  // 07 D0 / 07 D1
Bytes select_vfo(std::uint8_t to, Vfo vfo, std::uint8_t from = kController);     // 07 00 / 07 01
// Read the selected band's frequency: 03 (the radio answers FE FE E0 <to> 03 <5 BCD> FD).
Bytes read_frequency(std::uint8_t to, std::uint8_t from = kController);
// Read the transmit frequency: 1C 03 (the answer: FE FE E0 <to> 1C 03 <5 BCD> FD).
Bytes read_transmit_frequency(std::uint8_t to, std::uint8_t from = kController);
// Satellite mode on/off: 16 5A 01|00 (IC-9700, IC-9100) or 1A 07 01|00 (IC-910H), cmd and sub given.
Bytes satellite_mode(std::uint8_t to, std::uint8_t cmd, std::uint8_t sub, bool on, std::uint8_t from = kController);
// CTCSS: 1B 00 <tone, 3 bytes BCD, tenths of Hz, most significant first> (67.0 Hz: 00 06 70), and
// the TONE function 16 42 01|00. Throws std::invalid_argument for a tone outside 0.1..999.9 Hz.
Bytes set_tone_frequency(std::uint8_t to, int tenths_hz, std::uint8_t from = kController);
Bytes tone_function(std::uint8_t to, bool on, std::uint8_t from = kController);

std::optional<std::uint8_t> mode_code(Mode mode);     // LSB 00, USB 01, CW 03, FM 05
std::optional<Mode> mode_from_code(std::uint8_t code);  // also CW-R 07 -> cw

struct Frame {
  std::uint8_t to = 0;
  std::uint8_t from = 0;
  std::uint8_t cmd = 0;
  Bytes data;              // sub-command and data, FD excluded
  bool operator==(const Frame&) const = default;
};
// Exactly one complete frame (FE FE ... FD); nullopt otherwise.
std::optional<Frame> decode_frame(std::span<const std::uint8_t> bytes);
// The frequency of a 05 (set), 03/00 (read / transceive) or 1C 03 (transmit frequency) frame:
// 4, 5 or 6 (IC-905, 10 GHz) BCD bytes.
std::optional<Hz> decode_frequency(const Frame& f);
std::optional<Mode> decode_mode(const Frame& f);

enum class Reply { ok, ng, collision, not_a_reply };
// FE FE E0 <radio> FB FD -> ok; ... FA FD -> ng; any FC byte (the bus jam code) -> collision.
Reply parse_reply(std::span<const std::uint8_t> bytes);

// Cuts a byte stream into frames. Bytes before a preamble are dropped (counted in skipped());
// a lone FC (jam) is returned as a one-byte "frame" so a collision is never missed.
class FrameReader {
 public:
  void feed(std::span<const std::uint8_t> bytes);
  std::optional<Bytes> next();
  std::size_t skipped() const { return skipped_; }
  void clear() { buf_.clear(); }

 private:
  Bytes buf_;
  std::size_t skipped_ = 0;
};

}  // namespace icom

}  // namespace tb::radio
