// `trakbox attach`, `trakbox status` and `trakbox events`: the clients of the running station's
// socket (attach_server.h, docs/service.md).
#include "cli/attach_client.h"

#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <nlohmann/json.hpp>

#include "live/attach_server.h"
#include "live/station_socket.h"
#include "cli/options.h"
#include "live/status.h"
#include "util/json_limits.h"

namespace tb::app {
namespace {

std::vector<OptionSpec> client_specs(const std::string& command) {
  std::vector<OptionSpec> specs{
      {"help", "", "this list"},
      {"socket", "PATH", "the station's socket (default: STATE/" + std::string(kSocketFile) + " of --state or of the "
                         "default state directory, else the system service's " + std::string(kServiceSocket) + ")"},
      {"state", "DIR", "the state directory of the station (its socket is DIR/" + std::string(kSocketFile) + ")"},
  };
  if (command == "status") specs.push_back({"json", "", "the whole status document as JSON"});
  if (command == "attach") specs.push_back({"line", "", "plain lines even on a terminal"});
  if (command == "track")
    specs.push_back({"mode", "NAME", "in this mode of the satellite (SSB, CW, FT4, FM, APRS ...; docs/radio.md, "
                                     "\"Modes of a satellite\"): the radio goes to its spot; stored as its default"});
  return specs;
}

std::string help_text(const std::string& command) {
  std::string what;
  if (command == "standby" || command == "reserve")
    return "usage: trakbox " + command + (command == "standby" ? " on|off" : " START END [NOTE]") +
           " [--socket PATH | --state DIR]\n\n" +
           (command == "standby" ? "Standby on: the antenna parks (or stops), the radio is left alone, nothing tracks by itself and\n"
                                   "outside clients are refused, until standby off. Stored.\n"
                                 : "Reserves the station from START to END (ISO 8601 UTC, e.g. 2026-05-21T12:20:00Z): trakbox's\n"
                                   "tracking yields in that window, as to a SatNOGS observation. Stored.\n") +
           "\noptions:\n" + describe_options(client_specs(command));
  if (command == "track")
    return "usage: trakbox track SAT [--mode NAME] [--socket PATH | --state DIR]\n\n"
           "The running station tracks SAT alone (menu 1), its radio in the satellite's mode NAME when given.\n"
           "\noptions:\n" + describe_options(client_specs(command));
  if (command == "attach")
    what = "The TrakBox menus of the running station (the service, or a trakbox on another terminal) on this\n"
           "terminal: full screen on a terminal, plain lines otherwise. Ctrl-] detaches (the station goes on);\n"
           "when another terminal has the keyboard, Ctrl-T takes it over.\n";
  else if (command == "status")
    what = "What the running station is doing: tracking, antenna, radio, tracking list and next passes, element\n"
           "age, last save, problems. Exit status: 0 running and healthy, 1 running with problems, 3 not running.\n";
  else
    what = "The running station's events (aos, los, recording, elements, link-lost, link-back, save-failed, control) as JSON\n"
           "lines, until the station stops. Exit status: 0 when the station ended the stream, 3 not running.\n";
  return "usage: trakbox " + command + " [--socket PATH | --state DIR]" + (command == "status" ? " [--json]" : "") +
         (command == "attach" ? " [--line]" : "") + "\n\n" + what + "\noptions:\n" + describe_options(client_specs(command));
}

// Connects to the station's socket; -1 with a message naming the path when it cannot.
int connect_station(const std::string& path, const std::string& command, bool& not_running, bool quiet) {
  not_running = false;
  // Quiet: the caller only wants to know whether a station answers (`next` asking its clock).
  std::FILE* said = quiet ? nullptr : stderr;
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  if (fd < 0 || path.size() >= sizeof addr.sun_path) {
    if (said) std::fprintf(said, "trakbox %s: %s: not a usable socket path\n", command.c_str(), path.c_str());
    if (fd >= 0) ::close(fd);
    return -1;
  }
  std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    const int e = errno;
    ::close(fd);
    if (e == ENOENT || e == ECONNREFUSED) not_running = true;
    if (!said) return -1;
    if (e == ENOENT || e == ECONNREFUSED) {
      std::fprintf(said, "trakbox %s: no trakbox is running there (%s: %s)\n", command.c_str(), path.c_str(),
                   e == ENOENT ? "no such socket" : "nothing answers");
    } else if (e == EACCES) {
      std::fprintf(said,
                   "trakbox %s: %s: permission denied (the station's socket is for its user and the trakbox "
                   "group: docs/service.md)\n",
                   command.c_str(), path.c_str());
    } else {
      std::fprintf(said, "trakbox %s: %s: %s\n", command.c_str(), path.c_str(), std::strerror(e));
    }
    return -1;
  }
  return fd;
}

bool send_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::send(fd, data.data(), data.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

bool write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

struct ClientArgs {
  std::string socket;
  ParsedOptions options;
};

// The options of a client command; nullopt with the exit status in `code` when it ends here.
std::optional<ClientArgs> read_args(const std::string& command, const std::vector<std::string>& args, int& code) {
  const auto specs = client_specs(command);
  ParseOutcome parsed = parse_options(args, specs);
  if (parsed.error) {
    std::fprintf(stderr, "trakbox %s: %s (see trakbox %s --help)\n", command.c_str(), parsed.error->text().c_str(),
                 command.c_str());
    code = kExitUsage;
    return std::nullopt;
  }
  if (parsed.options.has("help")) {
    std::fputs(help_text(command).c_str(), stdout);
    code = kExitOk;
    return std::nullopt;
  }
  if (!parsed.options.positional().empty() || (parsed.options.has("socket") && parsed.options.has("state"))) {
    std::fprintf(stderr, "trakbox %s: %s (see trakbox %s --help)\n", command.c_str(),
                 parsed.options.positional().empty() ? "--socket: not with --state"
                                                     : ("unexpected argument '" + parsed.options.positional().front() + "'").c_str(),
                 command.c_str());
    code = kExitUsage;
    return std::nullopt;
  }
  ClientArgs a;
  if (const auto s = parsed.options.value("socket")) a.socket = *s;
  else if (const auto d = parsed.options.value("state")) a.socket = socket_for_state(*d);
  else a.socket = default_client_socket();
  a.options = std::move(parsed.options);
  return a;
}

// Everything the station sends until it closes.
std::optional<std::string> read_to_end(int fd) {
  std::string out;
  char buf[8192];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) return out;
    out.append(buf, static_cast<std::size_t>(n));
  }
}

volatile std::sig_atomic_t g_resized = 0;
void on_winch(int) { g_resized = 1; }

// The local terminal in raw mode for the session, restored however it ends.
struct RawTerminal {
  termios saved{};
  bool active = false;
  void enter() {
    if (::tcgetattr(STDIN_FILENO, &saved) != 0) return;
    termios raw = saved;
    ::cfmakeraw(&raw);
    if (::tcsetattr(STDIN_FILENO, TCSANOW, &raw) == 0) active = true;
  }
  ~RawTerminal() {
    if (active) ::tcsetattr(STDIN_FILENO, TCSANOW, &saved);
  }
};

std::pair<int, int> window_size() {
  winsize ws{};
  if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_row > 0 && ws.ws_col > 0) return {ws.ws_row, ws.ws_col};
  return {24, 80};
}

// Keyboard bytes as the socket carries them (a 0xFF byte doubled).
std::string frame_bytes(std::string_view keys) {
  std::string out;
  for (char c : keys) {
    out.push_back(c);
    if (static_cast<unsigned char>(c) == 0xFF) out.push_back(c);
  }
  return out;
}

// The session: keys to the station, its output to this terminal, until either side ends it.
int attach_session(int fd, bool raw_tty) {
  bool stdin_open = true;
  char buf[16384];
  for (;;) {
    if (g_resized) {
      g_resized = 0;
      const auto [rows, cols] = window_size();
      if (!send_all(fd, encode_window_size(rows, cols))) return kExitOk;
    }
    pollfd p[2] = {{fd, POLLIN, 0}, {STDIN_FILENO, static_cast<short>(stdin_open ? POLLIN : 0), 0}};
    if (::poll(p, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return kExitFailure;
    }
    if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n <= 0) return kExitOk;  // the station ended the session (detached, or it stopped)
      if (!write_all(STDOUT_FILENO, std::string_view(buf, static_cast<std::size_t>(n)))) return kExitFailure;
    }
    if (stdin_open && (p[1].revents & (POLLIN | POLLHUP | POLLERR))) {
      const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
      if (n <= 0) {
        // The end of a script's input: nothing more to say; the station's answers are still read.
        stdin_open = false;
        ::shutdown(fd, SHUT_WR);
        continue;
      }
      std::string_view keys(buf, static_cast<std::size_t>(n));
      const auto detach = keys.find(static_cast<char>(kDetachKey));
      if (raw_tty && detach != std::string_view::npos) {
        send_all(fd, frame_bytes(keys.substr(0, detach)));
        ::shutdown(fd, SHUT_WR);  // the station answers with its goodbye and closes
        stdin_open = false;
        continue;
      }
      if (!send_all(fd, frame_bytes(keys))) return kExitOk;
    }
  }
}

}  // namespace

int attach_to(const std::string& socket_path, bool line) {
  bool not_running = false;
  const int fd = connect_station(socket_path, "attach", not_running, false);
  if (fd < 0) return not_running ? kStatusNotRunning : kExitFailure;
  const bool tty = ::isatty(STDIN_FILENO) && ::isatty(STDOUT_FILENO);
  const char* term = std::getenv("TERM");
  const bool full = tty && !line && term && *term && std::string(term) != "dumb";
  const auto [rows, cols] = window_size();
  nlohmann::json hello{{"full_screen", full}, {"crlf", tty}, {"rows", rows}, {"cols", cols}};
  if (term) hello["term"] = term;
  if (const char* name = tty ? ::ttyname(STDIN_FILENO) : nullptr) hello["tty"] = name;
  if (!send_all(fd, "attach " + hello.dump() + "\n")) {
    ::close(fd);
    return kExitFailure;
  }
  // "ok", then the session; else why not.
  std::string answer;
  for (char c = 0; answer.size() < 1024;) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 10000) <= 0 || ::read(fd, &c, 1) != 1 || c == '\n') break;
    answer.push_back(c);
  }
  if (answer != "ok") {
    std::fprintf(stderr, "trakbox attach: %s\n",
                 answer.rfind("refused: ", 0) == 0 ? answer.substr(9).c_str()
                                                   : ("no answer from the station on " + socket_path).c_str());
    ::close(fd);
    return kExitFailure;
  }
  int code = kExitOk;
  {
    RawTerminal raw;
    if (tty) raw.enter();
    struct sigaction sa{};
    sa.sa_handler = on_winch;
    ::sigaction(SIGWINCH, &sa, nullptr);
    code = attach_session(fd, tty);
  }
  ::close(fd);
  if (tty) std::fputs("\n", stdout);
  return code;
}

int run_attach(const std::vector<std::string>& args) {
  int code = kExitOk;
  const auto a = read_args("attach", args, code);
  if (!a) return code;
  return attach_to(a->socket, a->options.has("line"));
}

// The options of `command`, a connection to the station, and the request sent; -1 with the exit
// status in `code` when it ends here.
int request(const std::string& command, const std::vector<std::string>& args, std::optional<ClientArgs>& a, int& code) {
  code = kExitOk;
  a = read_args(command, args, code);
  if (!a) return -1;
  bool not_running = false;
  const int fd = connect_station(a->socket, command, not_running, false);
  code = not_running ? kStatusNotRunning : kExitFailure;
  if (fd < 0) return -1;
  if (!send_all(fd, command + "\n")) {
    std::fprintf(stderr, "trakbox %s: %s: the station closed the connection\n", command.c_str(), a->socket.c_str());
    ::close(fd);
    return -1;
  }
  return fd;
}

std::optional<std::string> station_request(const std::string& socket, const std::string& command,
                                           const std::string& line, bool& not_running, bool quiet) {
  const int fd = connect_station(socket, command, not_running, quiet);
  if (fd < 0) return std::nullopt;
  if (!send_all(fd, line + "\n")) {
    std::fprintf(stderr, "trakbox %s: %s: the station closed the connection\n", command.c_str(), socket.c_str());
    ::close(fd);
    return std::nullopt;
  }
  auto text = read_to_end(fd);
  ::close(fd);
  return text;
}

int run_status(const std::vector<std::string>& args) {
  std::optional<ClientArgs> a;
  int code = kExitOk;
  const int fd = request("status", args, a, code);
  if (fd < 0) {
    // --json always prints a document, for a script reading stdout (issue 39): not running.
    if (a && a->options.has("json") && code == kStatusNotRunning)
      std::fputs((nlohmann::json{{"schema", kStatusSchema}, {"running", false}, {"socket", a->socket}, {"healthy", false}}
                      .dump(2) +
                  "\n")
                     .c_str(),
                 stdout);
    return code;
  }
  const auto text = read_to_end(fd);
  ::close(fd);
  std::string why;
  const nlohmann::json doc = text ? json_limits::parse_bounded<nlohmann::json>(*text, why) : nlohmann::json();
  if (!doc.is_object() || !doc.contains("antenna")) {
    std::fprintf(stderr, "trakbox status: %s: no status from the station%s\n", a->socket.c_str(),
                 text && !text->empty() ? (" (it said: " + text->substr(0, 200) + ")").c_str() : "");
    return kExitFailure;
  }
  if (a->options.has("json")) std::fputs((doc.dump(2) + "\n").c_str(), stdout);
  else std::fputs(format_status(doc).c_str(), stdout);
  return doc.value("healthy", false) ? kStatusHealthy : kStatusUnhealthy;
}

int run_station_command(const std::string& command, const std::vector<std::string>& args) {
  // The command's words first (a note may have several), then the options.
  std::vector<std::string> words, opts;
  for (const std::string& s : args) (s.rfind("--", 0) == 0 || !opts.empty() ? opts : words).push_back(s);
  int code = kExitOk;
  const auto a = read_args(command, opts, code);
  if (!a) return code;
  if (words.empty()) {
    std::fprintf(stderr, "trakbox %s: %s (see trakbox %s --help)\n", command.c_str(),
                 command == "standby" ? "expected on or off"
                 : command == "track" ? "expected SAT"
                                      : "expected START END [NOTE]",
                 command.c_str());
    return kExitUsage;
  }
  std::string line = command;
  if (const auto mode = a->options.value("mode")) line += " --mode " + *mode;
  for (const std::string& w : words) line += " " + w;
  bool not_running = false;
  const int fd = connect_station(a->socket, command, not_running, false);
  if (fd < 0) return not_running ? kStatusNotRunning : kExitFailure;
  if (!send_all(fd, line + "\n")) {
    ::close(fd);
    return kExitFailure;
  }
  const auto text = read_to_end(fd);
  ::close(fd);
  const std::string answer = text ? *text : std::string();
  std::fputs(answer.c_str(), answer.rfind("ok:", 0) == 0 ? stdout : stderr);
  return answer.rfind("ok:", 0) == 0 ? kExitOk : kExitFailure;
}

int run_events(const std::vector<std::string>& args) {
  std::optional<ClientArgs> a;
  int code = kExitOk;
  const int fd = request("events", args, a, code);
  if (fd < 0) return code;
  char buf[8192];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (std::fwrite(buf, 1, static_cast<std::size_t>(n), stdout) != static_cast<std::size_t>(n)) break;
    std::fflush(stdout);
  }
  ::close(fd);
  return kExitOk;
}

}  // namespace tb::app
