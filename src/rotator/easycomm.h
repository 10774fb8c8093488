// Easycomm II and III (WiSP's text by G7UPN, Easycomm III by A. Schultze, as Hamlib's easycomm
// backend carries them): the SatNOGS rotator firmware (III, 19200 baud), SARCNET and the REF
// interfaces (II), K3NG's controller. The codec is pure: the bytes trakbox sends, and what a line
// from the controller says. The bytes are Hamlib's (`rotctl -m 202` / `-m 204`) for the three
// commands trakbox uses:
//   set position  "AZ%.1f EL%.1f\n"   (no reply)
//   read position "AZ EL \n"          -> "AZaaa.a ELeee.e" (any blanks between, up to "\n")
//   stop          "SA SE \n"          (no reply; the SatNOGS firmware answers the position)
// and the controller may send a line of its own at any time: "ALxxx", an alarm (Easycomm II).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "rotator/config.h"

namespace tb::rotator::easycomm {

enum class Version { two = 2, three = 3 };

// The serial speed unless the spec gives one: 19200 for Easycomm III (the SatNOGS firmware's
// BAUDRATE), 9600 for Easycomm II.
constexpr int default_baud(Version v) { return v == Version::three ? 19200 : 9600; }
// Hamlib's model number of the same protocol (rotctl -m): 202 Easycomm II, 204 Easycomm III.
constexpr int hamlib_model(Version v) { return v == Version::three ? 204 : 202; }

std::string set_position(AzEl p);
std::string read_position();
std::string stop();

// One line from the controller (its "\r" / "\n" taken off).
struct Line {
  enum class Kind {
    position,   // "AZ123.4 EL45.6": where the antenna is
    alarm,      // "AL...": the controller reports a fault; text is the whole line
    other,      // an echo, a version, a value trakbox did not ask for: ignored
    bad,        // "AZ..." that is not a position: text says what is wrong
  } kind = Kind::other;
  AzEl position;
  std::string text;
};
Line parse_line(std::string_view line);

}  // namespace tb::rotator::easycomm
