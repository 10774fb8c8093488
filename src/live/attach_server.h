// The running station on a local socket (docs/service.md): `trakbox attach` (the TrakBox menus on
// the attached terminal, several at once, one with the keyboard), `trakbox status` (the station's
// facts as JSON) and `trakbox events` (its events as JSON lines). An attach is answered "ok\n",
// then the session, or "refused: WHY\n". A Unix socket only, for its
// owner and group (0660): who may attach is who may open it; nothing here listens on a network.
//
// The menus run once, on the station's own event loop, against terminal(): what they write goes
// to every attached client (full screen through a curses screen of the client's terminal type and
// size, else plain lines), their keys come from the client that has the keyboard. A client whose
// output backs up past a bound is disconnected: a frozen terminal never stalls the station.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "menus/term/terminal.h"
#include "util/loop_fwd.h"

namespace tb::app {

// The keys of an attached terminal.
inline constexpr int kDetachKey = 0x1d;    // Ctrl-] (Ctrl-C detaches too)
inline constexpr int kTakeOverKey = 0x14;  // Ctrl-T
// What a client may have unsent before it is disconnected.
inline constexpr std::size_t kAttachOutputLimit = 256 * 1024;
// The caps on the socket's clients (issue 38; docs/reliability.md): over one, a newcomer is refused
// ("refused: ...", logged once a run) and the station goes on. Each attached client holds one
// descriptor (its socket; a full-screen client's curses screen adds a pipe, two descriptors, kept
// per terminal type for the next client), each subscriber and each connection still to say what it
// wants (at most 10 s) one.
inline constexpr std::size_t kMaxAttached = 16;
inline constexpr std::size_t kMaxSubscribers = 64;
inline constexpr std::size_t kMaxGreeting = 32;
inline constexpr std::size_t kMaxScreenTypes = 8;  // terminal types with a kept screen; others: lines

struct AttachServerOptions {
  std::string path;                           // the socket
  std::function<nlohmann::json()> status;     // the status document
  // "log {json}": the logbook's request (`trakbox log ...`, live/log_requests.h); its JSON reply is
  // given to the callback, at once or later from the loop (an import runs on a worker thread).
  std::function<void(const std::string&, std::function<void(std::string)>)> log;
  // `trakbox standby`, `trakbox reserve` (live/station_command.h): the request line in, the answer out.
  std::function<bool(const std::string&)> is_command;
  std::function<std::string(const std::string&)> command;
  // Whether the menus are offered (a trakbox whose menus are on its console answers status and
  // events, and tells an attach where its menus are).
  bool menus = true;
  std::size_t output_limit = kAttachOutputLimit;
};

class AttachServer {
 public:
  // Binds the socket (replacing a stale one no process answers on); throws std::runtime_error
  // naming the path when it cannot, or when a live station answers there.
  AttachServer(boost::asio::io_context& io, term::WaitReadable wait, AttachServerOptions options,
               spdlog::logger& log);
  ~AttachServer();  // closes every client and removes the socket
  AttachServer(const AttachServer&) = delete;
  AttachServer& operator=(const AttachServer&) = delete;

  // The menus' terminal: output to every attached client, keys from the one with the keyboard.
  term::Terminal& terminal();
  // One JSON line to every `trakbox events` client.
  void publish(const nlohmann::json& event);
  // The serial port of --tty (open, set up; taken over) as a client that stays: plain lines, its
  // keys like any client's (who: "/dev/ttyS0").
  void add_serial(int fd, const std::string& who);
  // Detaches the client that has the keyboard (the main menu's leave, when attached).
  void detach_keyboard();
  // Who is attached ("alice pts/3"), and who has the keyboard ("" for nobody).
  std::vector<std::string> attached() const;
  std::string keyboard() const;
  const std::string& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Input of an attached client: bytes, and 0xFF 'W' ROWS COLS (two bytes each, big-endian) for a
// window size; 0xFF 0xFF is a 0xFF byte.
struct ClientFrames {
  std::string bytes;               // keyboard bytes decoded
  std::vector<std::pair<int, int>> sizes;  // (rows, cols) in order
};
class FrameDecoder {
 public:
  ClientFrames feed(std::string_view data);

 private:
  std::string partial_;
};
std::string encode_window_size(int rows, int cols);

// What `attach {json}` asks for: each field optional, of its type, else the attach is refused with
// the reason in `error` naming the field ("'rows' must be an integer, found a string"). Text fields
// are made safe (util/safe_text.h); a terminal type is letters, digits and ". _ + -" (it names a
// terminfo file). Pure: fuzzed by tests/fuzz/fuzz_attach_hello.cpp.
struct AttachHello {
  std::string term;  // empty: plain lines
  std::string tty;   // the client's terminal, for "alice pts/3"
  long long rows = 24, cols = 80;  // as sent: the server clamps them to what it draws
  bool full_screen = false;
  bool crlf = false;
};
std::optional<AttachHello> parse_attach_hello(std::string_view text, std::string& error);
// Keys from a terminal's bytes: escape sequences (arrows, function keys) are dropped, a lone ESC
// stays ESC, DEL is Backspace.
std::vector<int> decode_keys(std::string_view bytes);

}  // namespace tb::app
