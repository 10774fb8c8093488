// Kenwood CAT commands (TS-790/711/811, TS-2000).
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

}  // namespace tb::radio
