// Yaesu 5-byte CAT commands: FT-736 (yaesu::), FT-847 (ft847::), FT-817/818 (ft817::).
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

namespace yaesu {

using Command = std::array<std::uint8_t, 5>;   // P1 P2 P3 P4 OP, never acknowledged

enum class Target { main, sat_rx, sat_tx };

inline constexpr std::uint8_t kOpCatOn = 0x00;
inline constexpr std::uint8_t kOpSatOn = 0x0E;
inline constexpr std::uint8_t kOpSatOff = 0x8E;
inline constexpr std::uint8_t kOpCatOff = 0x80;

Command cat_on();          // 00 00 00 00 00
Command cat_off();         // 80 80 80 80 80
Command sat_mode_on();     // 00 00 00 00 0E
Command sat_mode_off();    // 00 00 00 00 8E

std::uint8_t frequency_opcode(Target t);   // 01 / 1E / 2E
std::uint8_t mode_opcode(Target t);        // 07 / 17 / 27

// 8 BCD digits of 10 Hz, most significant first; 1.2 GHz band: leading "1" dropped and the first
// nibble becomes C. Hz are rounded to the nearest 10 Hz. Valid: 0 .. 999.99999 MHz and
// 1200 .. 1299.99999 MHz.
Command set_frequency(Target t, Hz hz);
// LSB 00, USB 01, CW 02, FM 08; narrow_fm selects FM-N (88) instead of FM (08).
std::optional<Command> set_mode(Target t, Mode mode, bool narrow_fm = false);
std::optional<std::uint8_t> mode_code(Mode mode, bool narrow_fm = false);

struct Decoded {
  enum class Kind { cat_on, cat_off, sat_on, sat_off, frequency, mode, unknown };
  Kind kind = Kind::unknown;
  Target target = Target::main;
  Hz hz = 0;                       // frequency
  std::uint8_t mode_code = 0;      // mode
  std::optional<Mode> mode;        // mode, when it maps to one of ours (FM-N -> fm)
};
Decoded decode(const Command& c);
std::optional<Hz> decode_frequency_digits(std::span<const std::uint8_t, 4> p);

}  // namespace yaesu

// ---------------------------------------------------------------------------------------------
// Yaesu FT-847 (Hamlib's ft847.c): 5-byte commands like the FT-736 but its own opcodes. The low
// nibble is the command, the high nibble the VFO: main 0x, satellite RX 1x, satellite TX 2x.
namespace ft847 {

using Command = yaesu::Command;
using Target = yaesu::Target;

Command cat_on();        // 00 00 00 00 00
Command cat_off();       // 00 00 00 00 80
Command sat_mode_on();   // 00 00 00 00 4E
Command sat_mode_off();  // 00 00 00 00 8E
// 8 BCD digits of 10 Hz, most significant first (below 1 GHz); opcode 01 / 11 / 21.
Command set_frequency(Target t, Hz hz);
// LSB 00, USB 01, CW 02, FM 08 in P1; opcode 07 / 17 / 27.
std::optional<Command> set_mode(Target t, Mode mode);
// Read frequency and mode: 00 00 00 00 03 / 13 / 23; the radio answers 4 BCD bytes and the mode.
Command read(Target t);
// The answer's frequency (and mode, when it is one of ours).
std::optional<Hz> decode_read(std::span<const std::uint8_t> answer);
// CTCSS tone: the radio's own code for one of its 39 tones in P1, opcode 0B / 1B / 2B; nullopt for
// a tone it does not have. Encoder on: 4A 00 00 00 0A / 1A / 2A; off: 8A ... .
std::optional<Command> set_tone(Target t, int tenths_hz);
Command tone_encoder(Target t, bool on);

}  // namespace ft847

// ---------------------------------------------------------------------------------------------
// Yaesu FT-817/818 (Hamlib's ft817.c): one VFO, 5-byte commands; never send 00 (that is LOCK ON).
namespace ft817 {

using Command = yaesu::Command;

Command set_frequency(Hz hz);                  // 8 BCD digits of 10 Hz + 01
std::optional<Command> set_mode(Mode mode);    // LSB 00, USB 01, CW 02, FM 08 + 07
Command read();                                // 00 00 00 00 03 -> 4 BCD bytes + mode
std::optional<Hz> decode_read(std::span<const std::uint8_t> answer);
// Tone as 4 BCD digits of tenths twice (67.0 Hz: 06 70 06 70 0B), then encoder on 4A 00 00 00 0A;
// off: 8A 00 00 00 0A.
Command set_tone(int tenths_hz);
Command tone_encoder(bool on);

}  // namespace ft817

}  // namespace tb::radio
