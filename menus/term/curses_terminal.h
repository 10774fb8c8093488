// Full-screen ncurses front end: the menus' text in a scrolling area, live blocks redrawn in place,
// a status line at the bottom, and (in realtime tracking) a polar sky plot and a world map.
#pragma once
#include <cstdio>
#include <memory>
#include <string>

#include "menus/term/terminal.h"

struct screen;  // ncurses' SCREEN

namespace tb::term {

// The least screen the menus are drawn for; a smaller one shows "terminal too small" instead.
inline constexpr int kMinColumns = 80;
inline constexpr int kMinRows = 24;

class CursesTerminal final : public Terminal {
 public:
  // Takes over the controlling terminal (stdin/stdout). Restores it on destruction.
  explicit CursesTerminal(WaitReadable wait);
  // Output only, on a screen of the caller's (new_screen: an attached client's terminal,
  // live/attach_server.cpp); every call selects it first, so several can live in one process. The
  // screen stays the caller's: on destruction the windows go and the screen is left with endwin,
  // ready for another CursesTerminal. Keys come from elsewhere.
  CursesTerminal(::screen* screen, int rows, int cols);
  ~CursesTerminal() override;
  CursesTerminal(const CursesTerminal&) = delete;
  CursesTerminal& operator=(const CursesTerminal&) = delete;

  void write(std::string_view text) override;
  void bell() override;
  void clear() override;
  void flush() override;
  void live(const std::vector<std::string>& lines) override;
  void end_live() override;
  void status(std::string_view text) override;
  void graphics(const Graphics& g) override;
  bool full_screen() const override { return true; }
  int columns() const override;
  int rows() const override;
  // The terminal's size changed: the windows are laid out again (empty: the caller redraws).
  void resize(int rows, int cols);
  // True once Ctrl-C was typed: it ends the input for good (every later read sees the end).
  bool closed() const override;

 protected:
  int next_key(std::optional<Duration> timeout) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A screen of terminal type term_type writing to `out` (input `in` is never read); null when the
// type is unknown here. Screens are never deleted: ncurses 6.4's delscreen frees the windows of
// every screen, not only its own, so a caller keeps a screen for the next client of its type.
::screen* new_screen(const std::string& term_type, std::FILE* out, std::FILE* in);

// Pure drawing helpers (tested without a screen): a character grid for a polar sky plot and for an
// equirectangular world map with a ground track.
std::vector<std::string> draw_sky_plot(const Graphics& g, int width, int height);
std::vector<std::string> draw_world_map(const Graphics& g, int width, int height);
// The symbols of both pictures in one line, shown under the map (issue 30 item 8: they were
// explained only in docs).
const char* graphics_legend();

// Where a live block of n lines goes in a text window of `height` rows: below the cursor at
// (cursor_row, cursor_col) the first time (live_row < 0), then where it is (live_row). The window
// is scrolled first when needed so that the row after the block is on the screen: text written
// after the block goes there, and never over the block's last line (the last position of a live
// display stays readable above what follows).
struct LivePlacement {
  int scroll = 0;      // lines to scroll the window up first
  int first_row = 0;   // the block's first row, after scrolling
  int cursor_row = 0;  // where the cursor waits after drawing it
};
LivePlacement place_live_block(int live_row, int cursor_row, int cursor_col, int n, int height);

}  // namespace tb::term
