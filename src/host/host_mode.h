// Host mode (menu 7): the command interpreter, free of any transport. A line goes in, reply lines
// come out, and a flag says Q was given. Menu 7 runs it on the operator's terminal; the same
// interpreter can serve stdio, a serial line or TCP (the transport prints greeting(), then kPrompt
// after every reply, and stops at quit).
//
//   AZxxx ELxxx   point the antenna (degrees; AZ220 EL45, any spacing)       no reply ("LIMIT ..." if clamped)
//   MUxxx MDxxx   uplink / downlink mode: FM, LSB, USB or CW                  no reply
//   FUxxxxxxxx    uplink frequency in 10 Hz units (FU14595000 = 145.950 MHz)  no reply
//   FDxxxxxxxx    downlink frequency in 10 Hz units                           no reply
//   Sxxx          the rest of the line to the radio as it is (\xHH a byte)    no reply
//   ?A            where the antenna points                                    "AZ220.0 EL45.0"
//   ?             the command list                                            lines
//   Q             quit (back to the main menu)                                no reply, quit
//   RF            refresh the elements now (trakbox's own; menu 3-5)         "REFRESH STARTED"
//   ?R            the last element refresh (trakbox's own)                    "REFRESH OK 3 updated ..."
//
// A command that cannot be carried out is answered by one line "ERROR <command>: <what was wrong,
// what is expected>" and changes nothing. Commands are case-insensitive (the string of S is sent as
// typed). Every command that moves the antenna or talks to the radio stops trakbox's own tracking
// first, so the host program and the tracker never fight; ?A and ? do not. The rotor control
// switch (the E key) is respected: with it off AZ/EL is refused. docs/host-mode.md has the details.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "radio/config.h"

#include "tracker/operations.h"

namespace tb::tracker { class StationLoop; }

namespace tb::host {

inline constexpr std::string_view kBanner = "TrakBox host mode.";
inline constexpr std::string_view kCommandLine = "Command:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,?A,?";
inline constexpr std::string_view kPrompt = "TrakBox>>";

struct Reply {
  std::vector<std::string> lines;  // without line ends
  bool ok = true;                  // false: refused, lines holds the one "ERROR ..." line
  bool quit = false;               // Q: leave host mode

  // A refusal: the one line "ERROR " + text.
  static Reply error(std::string text) { return Reply{{"ERROR " + std::move(text)}, false}; }
};

// The pieces of a command line, parsed (for the interpreter and for tests).
struct AzElArgs {
  double az = 0.0;
  double el = 0.0;
};
// "AZ220 EL45", "az 220.5 el 45", "AZ220EL45", "AZ220_EL45": the part after nothing else. Either the
// angles or the error text ("expected AZxxx ELxxx ...", "azimuth 400 out of range ...").
struct AzElParse {
  std::optional<AzElArgs> args;
  std::string error;
};
AzElParse parse_az_el(std::string_view line);

// "14595000" (10 Hz units) -> 145950000 Hz; nullopt unless 1 to 9 digits and not zero.
std::optional<radio::Hz> parse_ten_hz(std::string_view digits);
// "TX;" as is; "\xFE\xFE" bytes; "\\" a backslash. nullopt on a malformed escape.
std::optional<std::string> unescape(std::string_view text);
// "AZ220.0 EL45.0": the reply to ?A (one decimal, azimuth [0, 360)).
std::string format_antenna(double az_deg, double el_deg);

class Interpreter {
 public:
  explicit Interpreter(tracker::StationLoop& station);

  // What is said on entry: the banner and the command line (the prompt follows).
  static std::vector<std::string> greeting();
  // The help of '?'.
  static std::vector<std::string> help();

  // One command line (without its CR; surrounding blanks are ignored; an empty line does nothing).
  Reply execute(std::string_view line);

 private:
  // One command of the table (host_mode.cpp): its word, how a line matches it, its `?` line ("" for
  // a second form listed with the first) and what it runs.
  struct Command {
    enum class Match { exact, prefix, word };
    std::string_view word;
    Match match;
    std::string_view help;
    std::function<Reply(Interpreter&, std::string_view upper_line, std::string_view line)> run;
  };
  static const std::vector<Command>& commands();
  Reply standby(bool on);
  Reply az_el(std::string_view line);
  Reply mode(std::string_view cmd, std::string_view arg);
  Reply frequency(std::string_view cmd, std::string_view arg);
  Reply raw(std::string_view arg);
  Reply antenna();
  Reply refresh_now();
  Reply refresh_status();
  Reply control();
  Reply radio_outcome(std::string_view cmd);
  // The radio asked for as menu 1's keys ask (tracker/control.h): refused in standby; when an
  // outside client (rigctld) holds it, done when the same command comes again at once. Nothing when
  // granted (host mode then holds the radio, and status says so).
  std::optional<Reply> ask_radio(std::string_view cmd);
  std::string line_;  // the command line being executed (its repetition is the confirmation)
  // trakbox's tuning commands (host_tuning.cpp): PB passband spot, OR/OT offsets, CT tone, ?T.
  std::optional<Reply> tuning(std::string_view upper_line, std::string_view line);
  Reply station(std::string_view arg);   // QTH
  Reply sat_mode(std::string_view arg);  // MODE: the tuned satellite's modes, one chosen

  tracker::StationLoop& station_;
  // Host mode acts as the operator "host" (tracker/control.h). A move refused because an outside
  // client or a reservation holds the antenna is done when the same command comes again at once:
  // the second command is the confirmation.
  std::string unconfirmed_;
  tracker::StationOps ops(bool confirmed = false) const {
    return tracker::StationOps(station_, {tracker::HolderKind::host, "host"}, confirmed);
  }
};

}  // namespace tb::host
