// What rotctld and rigctld have in common: one command a line, short ("P") or long ("\set_pos")
// names, the Default Protocol (data lines, or "RPRT n") and the Extended Response Protocol
// (a '+' or other punctuation before the command: "set_pos: 90 45", "Key: value" lines, "RPRT n").
// Transport-free: a line in, reply text out. docs/hamlib-endpoints.md has the formats.
#pragma once
#include "util/text.h"
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tb::netctl {

// Hamlib's error numbers (hamlib/rig.h, enum rig_errcode_e) that trakbox answers with; "RPRT"
// carries them negated ("RPRT -1").
enum class Error : int {
  none = 0,
  invalid = 1,         // RIG_EINVAL: argument missing, extra, malformed or outside the protocol's range
  io = 6,              // RIG_EIO: the device is not answering (link down, no reading yet)
  protocol = 8,        // RIG_EPROTO: line too long
  rejected = 9,        // RIG_ERJCTED: trakbox refuses now (rotor control off, parking off, tracking)
  not_available = 11,  // RIG_ENAVAIL: a command trakbox does not offer
  bad_vfo = 16,        // RIG_EVFO: a VFO trakbox has no link for
  security = 19,       // RIG_ESECURITY: the endpoint wants its secret first (\password)
};
// "RPRT -1"
std::string rprt(Error e);

// The longest line taken (bytes, newline excluded). Hamlib's own lines are under 100 bytes.
inline constexpr std::size_t kMaxLineLength = 1024;

// One request line, split.
struct Request {
  char separator = 0;             // 0: Default Protocol; else the Extended Response separator
  std::string name;               // "P", "set_pos" (long names without the backslash)
  bool long_name = false;
  std::vector<std::string> args;  // whitespace-separated
  bool extended() const { return separator != 0; }
};
// Nothing for a blank line or a comment ('#').
std::optional<Request> parse_request(std::string_view line);

// What a command produced: its values (in order, each a key and a value) or an error.
struct Outcome {
  Error error = Error::none;
  std::vector<std::pair<std::string, std::string>> values;
  static Outcome fail(Error e) { return Outcome{e, {}}; }
  Outcome& add(std::string key, std::string value) {
    values.emplace_back(std::move(key), std::move(value));
    return *this;
  }
};

// The reply text. A "get" command answers its values one a line in the Default Protocol and
// "RPRT n" only on error; a "set" answers "RPRT n" (after its values, if it has any, as the
// "M ?" lists do). Extended: "long_name: args", "Key: value" records (a value with an empty key is
// sent as it is), "RPRT n", the records ended by the separator and the whole by a newline.
std::string format_reply(const Request& r, std::string_view long_name, bool get, const Outcome& o);

// What the server sends back for a line, and whether it then closes the connection.
struct Reply {
  std::string text;    // empty: nothing to send
  bool close = false;  // q / Q: send text, then close
};

// Why a connection is refused at accept.
enum class Refusal {
  not_allowed,  // its address is not in --allow
  busy,         // every connection (or every one its address may hold) is taken
  locked_out,   // its address gave too many wrong secrets
};

// What a LineServer drives: one call a line, in order, on the event loop.
class LineHandler {
 public:
  virtual ~LineHandler() = default;
  // One line without its line end.
  virtual Reply handle(std::string_view line) = 0;
  // A line longer than the server's max_line (discarded up to its line end).
  virtual Reply overlong() const = 0;
  // Who sends the line handle() gets next ("127.0.0.1:51234"), and a client that has gone: what it
  // held of the station is handed back (tracker/control.h).
  virtual void client_line(const std::string& peer) { (void)peer; }
  virtual void client_left(const std::string& peer) { (void)peer; }
  // Sent to each client as it connects (empty: nothing).
  virtual std::string greeting() const { return {}; }
  // Sent to a client refused at accept, in the protocol's words, for the reason given (empty: just
  // closed).
  virtual std::string refusal(Refusal why) const {
    (void)why;
    return {};
  }

  // Authentication, when the endpoint has a shared secret (ServerOptions::secret): until a client
  // has given it, each line goes to gate() instead of handle(). A line is the protocol's password
  // command (with the secret it carries), a line allowed without it (the handshake a client sends
  // first, quitting), or refused.
  struct Gate {
    enum class Kind { refused, allowed, password } kind = Kind::refused;
    std::string password;
  };
  virtual Gate gate(std::string_view line) const {
    (void)line;
    return {};
  }
  // The reply to the password command (right or wrong), and to a refused line.
  virtual std::string auth_reply(bool ok) const { return ok ? "OK\n" : "ERROR\n"; }
  virtual std::string auth_required() const { return "ERROR\n"; }
};

// The Hamlib line protocols (rotctld, rigctld).
class LineProtocol : public LineHandler {
 public:
  // One line without its newline (a trailing '\r' is ignored).
  Reply handle(std::string_view line) override;
  std::string refusal(Refusal why) const override;  // "RPRT -9" (rejected) whatever the reason
  // Hamlib's rigctld: "\password SECRET" answers RPRT 0, or RPRT -1 when wrong; before it only
  // \chk_vfo, \dump_state and quitting work, anything else is answered RPRT -19 (RIG_ESECURITY).
  Gate gate(std::string_view line) const override;
  std::string auth_reply(bool ok) const override;
  std::string auth_required() const override;
  // A line longer than kMaxLineLength (the server discards it up to its newline): RPRT -8.
  Reply overlong() const override;

 protected:
  struct Command {
    int id = 0;
    char short_name = 0;         // 0: long name only
    std::string_view long_name;
    bool get = false;
  };
  // The command table, and what each command does (args already split; the count unchecked).
  virtual const std::vector<Command>& commands() const = 0;
  virtual Outcome execute(int id, const std::vector<std::string>& args) = 0;
};

// Strict number parsing for arguments: the whole token, finite.
using text::parse_double;
using text::parse_integer;
// printf("%.2f")
std::string fixed2(double v);
// Control characters replaced by spaces, so a value always fits on its line.
std::string one_line(std::string s);

}  // namespace tb::netctl
