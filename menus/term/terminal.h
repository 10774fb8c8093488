// The small terminal interface every menu is written against. Two implementations: full-screen
// curses (curses_terminal.cpp) and plain lines for a serial line or a pipe (line_terminal.cpp).
//
// Menus are written like the manual reads: print a prompt, read the answer, act. While a menu waits
// for input, the terminal runs the program's event loop (timers, servers, the tracker), so tracking
// never stops because an operator is thinking.
#pragma once
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::term {

using Duration = std::chrono::steady_clock::duration;

// Special key codes returned by read_key (printable characters are returned as themselves).
inline constexpr int kTimeout = -1;     // no key within the timeout
inline constexpr int kEndOfInput = -2;  // the input closed (pipe ended, serial line gone)
inline constexpr int kEnter = '\r';
inline constexpr int kBackspace = 8;
inline constexpr int kCtrlZ = 26;
inline constexpr int kEscape = 27;

// What the full-screen front end may draw beside the text (ignored in line mode).
struct SkyPoint {
  double az_deg = 0.0;
  double el_deg = 0.0;
};
struct Graphics {
  std::vector<SkyPoint> pass_track;         // the current/next pass, AOS to LOS
  std::optional<SkyPoint> satellite;        // where the satellite is now (if up)
  std::optional<SkyPoint> antenna;          // where the antenna points
  std::vector<std::pair<double, double>> ground_track;  // (lat, lon) deg, next orbit
  std::optional<std::pair<double, double>> sub_point;   // (lat, lon) now
  std::optional<std::pair<double, double>> station;     // (lat, lon)
  std::string title;
};

// Runs the program's pending work while a terminal waits (installed by the application).
// wait(fd, timeout) returns true when fd became readable, false on timeout or when the loop did
// other work meanwhile (the caller looks again: a key may have come by the loop, the tick drew).
// No timeout: until input or work. It blocks in the loop's one wait; it never polls.
using WaitReadable = std::function<bool(int fd, std::optional<Duration> timeout)>;

class Terminal {
 public:
  virtual ~Terminal() = default;

  // ---- output ----
  virtual void write(std::string_view text) = 0;  // '\n' ends a line
  void line(std::string_view text = {}) {
    write(text);
    write("\n");
  }
  virtual void bell() = 0;
  virtual void clear() = 0;  // a new screen: curses clears, line mode starts a new line
  virtual void flush() = 0;

  // A live block (realtime display, monitor, schedule header...): curses redraws the lines in place
  // below the text written so far; line mode prints them once per update (no escape codes).
  virtual void live(const std::vector<std::string>& lines) = 0;
  virtual void end_live() = 0;

  // The status line (curses only): time, satellite, rotator and radio state.
  virtual void status(std::string_view text) = 0;
  // Pictures for the full-screen front end (sky plot, world map); line mode ignores them.
  virtual void graphics(const Graphics& g) = 0;
  virtual bool full_screen() const = 0;
  // Usable text width and height (line mode: 80 x 24).
  virtual int columns() const = 0;
  virtual int rows() const = 0;

  // ---- input (each pumps the event loop while it waits) ----
  // One key; kTimeout after timeout (none: wait for ever), kEndOfInput when input has closed.
  // Enter is always kEnter, whether the terminal sent CR, LF or CR LF (terminal.cpp).
  int read_key(std::optional<Duration> timeout = std::nullopt);
  // True when input has closed for good.
  virtual bool closed() const = 0;

  // Typed characters are echoed (what a terminal on a serial line expects); a program talking to
  // trakbox through a pipe may not want them back.
  void set_echo(bool on) { echo_ = on; }
  bool echo() const { return echo_; }

  // Esc at a line prompt: ignored (a control key) unless a menu asks for it, as menu 4 does, which
  // leaves unchanged on Esc (issue 30 item 10). While on, read_line returns "\x1b" for Esc.
  void set_escape_leaves(bool on) { escape_leaves_ = on; }
  bool escape_leaves() const { return escape_leaves_; }

  // A line, echoed as typed, Backspace/DEL edit, Enter (CR, LF or CRLF) ends it.
  // nullopt when input closed. Ctrl-Z alone returns "\x1a"; Esc, when escape_leaves(), "\x1b".
  std::optional<std::string> read_line(std::size_t max_length = 80);
  // The last read_line was typed with characters outside printable ASCII (a UTF-8 letter such as
  // 'a' with a grave): they are not in its text, so the prompt refuses the answer rather than keep
  // it mangled ("Paris" for "Pàris").
  bool last_line_had_non_ascii() const { return non_ascii_; }
  // A single key for [Y/N]-style questions: echoes it and a newline; upper-cased. With `accept`,
  // other keys are ignored; Enter returns '\r' (echoing a newline) when allow_enter, else it is
  // ignored. nullopt when input closed.
  std::optional<char> read_choice(std::string_view accept = {}, bool allow_enter = true);

  // An ASCII upload ending in Ctrl-Z (menus 3-3, 6-9): raw lines as received, each passed to
  // on_line (which may echo or report). Returns false if input closed before Ctrl-Z.
  // Lines longer than max_line are cut and reported through on_line with the cut text.
  bool read_upload(const std::function<void(std::string_view line)>& on_line, std::size_t max_line = 512);

 protected:
  // The implementation's raw key source.
  virtual int next_key(std::optional<Duration> timeout) = 0;

 private:
  std::vector<int> pending_;  // keys read ahead
  bool echo_ = true;
  bool escape_leaves_ = false;      // read_line returns "\x1b" for Esc
  bool non_ascii_ = false;          // the last read_line dropped bytes 128..255
  bool last_was_cr_ = false;        // the LF of a CR LF pair is dropped
  bool enter_ends_choice_ = false;  // the last key answered read_choice: an Enter now ends that answer
};

}  // namespace tb::term
