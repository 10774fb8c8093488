// CAT wire formats of the radios TrakBox drives: Icom CI-V, Kenwood TS-790/711/811, Yaesu FT-736.
// Pure functions: values in, bytes out (and back). The byte strings in
// /work/shared/reference/cat-protocols.md are the unit tests of this file.
//
// Encoders throw std::invalid_argument for a value the format cannot carry (a negative frequency,
// one with too many digits, an FT-736 frequency between 1.0 and 1.2 GHz); the drivers turn that into
// a fault message. Mode::none has no command: the mode encoders return nullopt for it.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "radio/config.h"

namespace tb::radio {

using Bytes = std::vector<std::uint8_t>;

// "FE FE 10 E0 05 00 00 95 45 01 FD" (upper-case hex, one space between bytes).
std::string to_hex(std::span<const std::uint8_t> bytes);
// The reverse; spaces optional ("FEFE..." works). nullopt on a bad digit or an odd count.
std::optional<Bytes> from_hex(std::string_view text);

// Packed BCD, least significant byte first, low digit in the low nibble (Icom).
Bytes bcd_little_endian(std::uint64_t value, int bytes);
std::optional<std::uint64_t> decode_bcd_little_endian(std::span<const std::uint8_t> bytes);
// Packed BCD, most significant byte first (Yaesu). Keeps the low 2*bytes digits.
Bytes bcd_big_endian(std::uint64_t value, int bytes);
std::optional<std::uint64_t> decode_bcd_big_endian(std::span<const std::uint8_t> bytes);

// ---------------------------------------------------------------------------------------------
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

enum class FrequencyWidth { five_bytes, four_bytes };  // 4: IC-820H/821H (no 100 MHz digit)
enum class Band { main, sub };
enum class Vfo { a, b };

// FE FE to from cmd data... FD
Bytes frame(std::uint8_t to, std::uint8_t from, std::uint8_t cmd, std::span<const std::uint8_t> data = {});
Bytes set_frequency(std::uint8_t to, Hz hz, FrequencyWidth width = FrequencyWidth::five_bytes,
                    std::uint8_t from = kController);
std::optional<Bytes> set_mode(std::uint8_t to, Mode mode, std::uint8_t from = kController);
Bytes select_band(std::uint8_t to, Band band, std::uint8_t from = kController);  // 07 D0 / 07 D1
Bytes select_vfo(std::uint8_t to, Vfo vfo, std::uint8_t from = kController);     // 07 00 / 07 01

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
// The frequency of a 05 (set) or 03/00 (read / transceive) frame.
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

// ---------------------------------------------------------------------------------------------
namespace kenwood {

enum class Vfo { a, b };

std::string set_frequency(Vfo vfo, Hz hz);          // FA00435123450;
std::optional<std::string> set_mode(Mode mode);     // MD2;
std::string select_vfo(Vfo vfo);                    // FN0; / FN1;
std::string split(bool on);                         // SP1; / SP0;
inline std::string up() { return "UP;"; }
inline std::string down() { return "DN;"; }
inline std::string identify() { return "ID;"; }

std::optional<char> mode_digit(Mode mode);          // 1 LSB, 2 USB, 3 CW, 4 FM
std::optional<Mode> mode_from_digit(char digit);    // also 7 CW-R -> cw

// "FA00435123450;" -> {FA, 435123450}. The command may lack its ';'.
struct Frequency {
  Vfo vfo = Vfo::a;
  Hz hz = 0;
};
std::optional<Frequency> decode_frequency(std::string_view command);
std::optional<Mode> decode_mode(std::string_view command);
// Splits a stream at ';' (each command keeps its ';'); an unterminated tail is left in rest.
std::vector<std::string> split_commands(std::string_view stream, std::string* rest = nullptr);

}  // namespace kenwood

// ---------------------------------------------------------------------------------------------
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

}  // namespace tb::radio
