// One client attached to the station's menus (attach_server.cpp's, internal): who it is, its
// outbox, the screen the menus are drawn on for it (a curses screen of its terminal's type on a
// pipe this side drains into the outbox, or plain lines), the keys it sent; and the pool of curses
// screens kept for the next client of a type.
#pragma once
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "live/attach_internal.h"
#include "live/attach_server.h"
#include "menus/term/terminal.h"
#include "util/loop_fwd.h"

struct screen;  // ncurses' SCREEN

namespace tb::term {
class CursesTerminal;
}

namespace tb::app {

// A curses screen on a pipe this side drains, kept for the next client of its terminal type
// (curses_terminal.h: screens are never deleted).
struct ScreenSlot {
  std::string type;
  ::screen* screen = nullptr;
  FILE* out = nullptr;
  FILE* in = nullptr;
  int pipe_rd = -1;
};

// The screens made so far: those no client uses, and how many terminal types have one.
struct ScreenPool {
  std::vector<ScreenSlot> kept;
  std::size_t types = 0;
};

struct Member {
  int id = 0;
  std::string who;
  std::shared_ptr<Outbox> out;
  std::unique_ptr<term::Terminal> screen;
  term::CursesTerminal* curses = nullptr;  // screen, when full screen
  ScreenSlot slot;                         // its curses screen and the pipe of its output
  ScreenPool* pool = nullptr;              // where the slot goes back
  FrameDecoder frames;
  std::deque<int> keys;
  std::array<char, 4096> rbuf{};
  bool gone = false;
  bool permanent = false;  // the serial port of --tty: no detaching, and a lost port is only logged
  bool input_ended = false;  // a script's input ended: it detaches once the menus took its keys
  std::string farewell = "\r\n[detached from trakbox: the station goes on]\r\n";  // the session's last words
  std::string told;  // the keyboard note last given to a line client
  std::chrono::steady_clock::time_point told_at{};

  // The menus as plain lines into the outbox (a LineTerminal's output rules; crlf: "\r\n").
  void open_lines(bool crlf);
  // A curses screen of the client's type (one kept in the pool, else a new one, at most
  // kMaxScreenTypes types); false, nothing changed, when the client is to get plain lines (an
  // unknown type, too many types: logged).
  bool open_screen(ScreenPool& from, const std::string& term_type, int rows, int cols, spdlog::logger& log);
  // What the curses screen wrote, to the client.
  void drain();
  // The client's terminal given back as it was, the farewell sent, the screen back in the pool.
  ~Member();
};

// Who is at the other end: the user of the peer's credentials and the terminal it says it has
// ("alice pts/3").
std::string peer_name(int fd, const std::string& tty);

}  // namespace tb::app
