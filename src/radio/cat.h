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
// The frequency of a 05 (set), 03/00 (read / transceive) or 1C 03 (transmit frequency) frame.
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
// The VFO select: FN0; / FN1; on the TS-790/711/811, FR0; / FR1; on the TS-2000 (letter 'R').
std::string select_vfo(Vfo vfo, char letter = 'N');
std::string split(bool on);                         // SP1; / SP0;
inline std::string up() { return "UP;"; }
inline std::string down() { return "DN;"; }
inline std::string identify() { return "ID;"; }
// Read a VFO's frequency: FA; / FB; (the radio answers FA00435123450;).
std::string read_frequency(Vfo vfo);

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
// The radio's answers that mean "not done": ?; (wrong syntax, or not in the present state), E;
// (communication error), O; (processing not completed) -- the TS-2000 manual's general rules.
bool is_refusal(std::string_view command);

// The TS-2000's satellite mode, SA. SA; answers SA, the digits P1..P7 and the 8-character name of
// the satellite memory, then ';' (18 characters: Hamlib's kenwood_set_vfo). A set sends the seven
// digits (SatPC32's SA1010110; / SA0010000;). The digits, as Hamlib's ts2k.c (D. Edmons, 2002)
// and OscarWatch-Tracker's KenwoodCatCodec name them (docs/radio.md, "TS-2000 SA"):
//   P1 satellite mode on        P2 kept as found (SatPC32 and OscarWatch send 0)
//   P3 1: the uplink on Sub (Main receives: FA the downlink, FB the uplink), 0: on Main
//   P4 1: CTRL on Sub (MD, TN and TO then go to Sub), 0: CTRL on Main
//   P5 TRACE (the radio moves Sub with the Main dial)    P6 TRACE REV
//   P7 1: satellite memory channel, 0: VFO
struct Satellite {
  std::string digits = "0000000";   // P1..P7 as the radio gave them ('0' where an answer was short)
  bool on() const { return digits[0] == '1'; }
  bool operator==(const Satellite&) const = default;
};
inline std::string read_satellite() { return "SA;"; }
// "SA0010000        ;" (or Hamlib's short simulator answer "SA0;") -> digits; nullopt otherwise.
std::optional<Satellite> decode_satellite(std::string_view command);
std::string set_satellite(const Satellite& s);   // SA1010000;
// How trakbox runs the TS-2000 from the state it found: on, the uplink on Sub, TRACE off (trakbox
// moves the other link itself, at the Doppler pair, once the knob rests), VFO; CTRL on Main, or on
// Sub while a mode or tone goes to the uplink; P2 and P6 as found.
Satellite satellite_working(const Satellite& found, bool ctrl_on_sub);
// VFO select of the TS-2000 family outside satellite mode (Hamlib's FR; the TS-790's is FN).
inline std::string read_vfo() { return "FR;"; }
// CTCSS encoder (Hamlib's ts2000.c: TN with the 1-based number of the tone in the TS-2000's list of
// 38 tones and 1750 Hz, TN01 67.0 Hz; TO1 / TO0 the encoder). nullopt: a tone the radio has not.
std::optional<std::string> set_tone_number(int tenths_hz);
inline std::string tone(bool on) { return on ? "TO1;" : "TO0;"; }
inline std::string read_tone() { return "TO;"; }

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
