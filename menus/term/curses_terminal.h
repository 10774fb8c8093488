// Full-screen ncurses front end: the menus' text in a scrolling area, live blocks redrawn in place,
// a status line at the bottom, and (in realtime tracking) a polar sky plot and a world map.
#pragma once
#include <memory>

#include "menus/term/terminal.h"

namespace tb::term {

class CursesTerminal final : public Terminal {
 public:
  // Takes over the controlling terminal (stdin/stdout). Restores it on destruction.
  explicit CursesTerminal(WaitReadable wait);
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
  bool closed() const override { return false; }

 protected:
  int next_key(std::optional<Duration> timeout) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Pure drawing helpers (tested without a screen): a character grid for a polar sky plot and for an
// equirectangular world map with a ground track.
std::vector<std::string> draw_sky_plot(const Graphics& g, int width, int height);
std::vector<std::string> draw_world_map(const Graphics& g, int width, int height);

}  // namespace tb::term
