// PstRotator's UDP protocol (YO3DMU's PstRotator, the CSN Technologies S.A.T. box, SatDump's
// PstRotatorHandler, Hamlib's PSTRotator backend): one command a datagram, to UDP port 12000;
// replies and positions go back to the sender's address on the next port (12001).
//   <PST><AZIMUTH>173.0</AZIMUTH></PST>      aim the azimuth
//   <PST><ELEVATION>25.0</ELEVATION></PST>   aim the elevation
//   <PST><STOP>1</STOP></PST>                stop      <PST><PARK>1</PARK></PST>   park
//   <PST>AZ?</PST>  -> "AZ:297.0"            <PST>EL?</PST>  -> "EL:25.0"
// One datagram may carry several tags in one <PST> (<PST><AZIMUTH>..</AZIMUTH><ELEVATION>..
// </ELEVATION></PST>). Pure: the bytes both ways, and what a datagram says or why it is refused.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::rotator::pst {

inline constexpr int kCommandPort = 12000;   // where commands go; replies to the sender's next port
inline constexpr std::size_t kMaxDatagram = 512;

std::string set_azimuth(double az);
std::string set_elevation(double el);
std::string stop();
std::string park();
std::string ask_azimuth();      // "<PST>AZ?</PST>"
std::string ask_elevation();    // "<PST>EL?</PST>"
std::string azimuth_reply(double az);     // "AZ:297.0"
std::string elevation_reply(double el);   // "EL:25.0"

struct Command {
  enum class Kind { azimuth, elevation, stop, park, ask_azimuth, ask_elevation } kind;
  double value = 0.0;   // azimuth, elevation: degrees
};

struct Datagram {
  std::vector<Command> commands;   // in the order they came; empty when refused
  std::string error;               // why it was refused ("" when taken), visible text only
};
// A datagram to trakbox's PstRotator port: every tag known and well formed, or refused whole.
// Azimuth -360..720 (taken modulo 360 by the caller), elevation -90..180.
Datagram parse_command(std::string_view datagram);

// A reply from a PstRotator-speaking box: "AZ:297.0" / "EL:25.0" (also inside <PST>..</PST>, and
// with blanks or a CR LF); nothing when it is neither.
struct Reading {
  std::optional<double> az;
  std::optional<double> el;
};
Reading parse_reply(std::string_view datagram);

}  // namespace tb::rotator::pst
