// Yaesu's ASCII CAT of the FT-991/991A, FTX-1, FT-710 and FTdx10 (Hamlib calls the family
// "newcat"): two letters, parameters, ';'. Pure functions: values in, text out (and back); the
// strings of docs/radio.md ("CAT formats") are their unit tests (tests/unit/radio/test_newcat.cpp).
// Encoders throw std::invalid_argument for a value the format cannot carry; Mode::none has no
// command (the mode encoder returns nullopt). No function here makes ST (split): on the FTX-1 it
// puts the Sub VFO in TX state and freezes its frequency (Hamlib #1972), and trakbox never needs it.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "radio/bytes.h"

namespace tb::radio::newcat {

enum class Vfo { a, b };   // FA / FB: VFO-A (Main), VFO-B (Sub on the FTX-1)

// FA014250000; / FB145950000;: nine digits of Hz (0 .. 999 999 999).
std::string set_frequency(Vfo vfo, Hz hz);
inline std::string read_frequency(Vfo vfo) { return vfo == Vfo::a ? "FA;" : "FB;"; }
// MD0 / MD1 (Main / Sub) and the mode's character: LSB 1, USB 2, CW 3 (CW-U), FM 4.
std::optional<std::string> set_mode(char band, Mode mode);
std::optional<Mode> mode_from_char(char c);   // also CW-L 7 -> cw, FM-N B -> fm
inline std::string read_mode(char band) { return std::string("MD") + band + ";"; }
inline std::string identify() { return "ID;"; }
inline std::string copy_a_to_b() { return "AB;"; }          // VFO-A's frequency, mode and tone to VFO-B
inline std::string lock(bool on) { return on ? "LK1;" : "LK0;"; }   // the dial lock
// FT-991/991A CTCSS: the tone's number in the radio's list of 50 (67.0 Hz: 000) with CN00, then
// CT02 (tone encoder only); CT00 off. nullopt: a tone not in the list.
std::optional<std::string> set_tone(int tenths_hz);
inline std::string tone_off() { return "CT00;"; }

struct Frequency {
  Vfo vfo = Vfo::a;
  Hz hz = 0;
};
// "FA014250000;" (the ';' optional) -> {a, 14250000}; exactly nine digits.
std::optional<Frequency> decode_frequency(std::string_view answer);
// "MD02;" -> usb (either band); nullopt for a mode not ours.
std::optional<Mode> decode_mode(std::string_view answer);
// "ID0670;" -> "0670".
std::optional<std::string> decode_id(std::string_view answer);
// "?;": the radio did not take the command (unknown, or not in its present state).
inline bool is_refusal(std::string_view answer) { return answer == "?;" || answer == "?"; }

}  // namespace tb::radio::newcat
