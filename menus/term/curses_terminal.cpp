#include "menus/term/curses_terminal.h"

#include <algorithm>
#include <clocale>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <curses.h>
#include <numbers>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace tb::term {
namespace {

constexpr const char* kWorldMask[] = {
#include "menus/term/world_mask.inc"
};
constexpr int kMaskCols = 120;
constexpr int kMaskRows = 60;

bool land_at(double lat, double lon) {
  int row = static_cast<int>((90.0 - lat) / 3.0);
  int col = static_cast<int>((lon + 180.0) / 3.0);
  row = std::clamp(row, 0, kMaskRows - 1);
  col = ((col % kMaskCols) + kMaskCols) % kMaskCols;
  return kWorldMask[row][col] == '#';
}

void put(std::vector<std::string>& grid, int x, int y, char c) {
  if (y < 0 || y >= static_cast<int>(grid.size())) return;
  if (x < 0 || x >= static_cast<int>(grid[static_cast<std::size_t>(y)].size())) return;
  grid[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] = c;
}

}  // namespace

std::vector<std::string> draw_sky_plot(const Graphics& g, int width, int height) {
  std::vector<std::string> grid(static_cast<std::size_t>(std::max(height, 0)),
                                std::string(static_cast<std::size_t>(std::max(width, 0)), ' '));
  if (width < 11 || height < 7) return grid;
  const double cx = (width - 1) / 2.0, cy = (height - 1) / 2.0;
  const double rx = cx, ry = cy;
  constexpr double deg = std::numbers::pi / 180.0;
  auto to_xy = [&](double az, double el) {
    const double r = std::clamp((90.0 - el) / 90.0, 0.0, 1.0);
    return std::pair{static_cast<int>(std::lround(cx + r * rx * std::sin(az * deg))),
                     static_cast<int>(std::lround(cy - r * ry * std::cos(az * deg)))};
  };
  // Horizon and the 30/60 degree rings, every cell they pass through: a dot every 9 degrees of
  // azimuth read as scattered dots, not rings (issue 30 item 8).
  for (int a = 0; a < 360; ++a) {
    for (double el : {0.0, 30.0, 60.0}) {
      auto [x, y] = to_xy(a, el);
      put(grid, x, y, '.');
    }
  }
  put(grid, static_cast<int>(cx), 0, 'N');
  put(grid, static_cast<int>(cx), height - 1, 'S');
  put(grid, 0, static_cast<int>(cy), 'W');
  put(grid, width - 1, static_cast<int>(cy), 'E');
  put(grid, static_cast<int>(cx), static_cast<int>(cy), '+');
  for (const auto& p : g.pass_track) {
    if (p.el_deg < 0.0) continue;
    auto [x, y] = to_xy(p.az_deg, p.el_deg);
    put(grid, x, y, 'o');
  }
  if (!g.pass_track.empty()) {
    const auto& a = g.pass_track.front();
    auto [x, y] = to_xy(a.az_deg, std::max(a.el_deg, 0.0));
    put(grid, x, y, 'A');  // AOS
  }
  if (g.antenna) {
    auto [x, y] = to_xy(g.antenna->az_deg, std::max(g.antenna->el_deg, 0.0));
    put(grid, x, y, 'X');
  }
  if (g.satellite && g.satellite->el_deg >= -2.0) {
    auto [x, y] = to_xy(g.satellite->az_deg, std::max(g.satellite->el_deg, 0.0));
    put(grid, x, y, '@');
  }
  return grid;
}

const char* graphics_legend() { return "@ satellite  X antenna  o pass  A AOS  Q station"; }

std::vector<std::string> draw_world_map(const Graphics& g, int width, int height) {
  std::vector<std::string> grid(static_cast<std::size_t>(std::max(height, 0)),
                                std::string(static_cast<std::size_t>(std::max(width, 0)), ' '));
  if (width < 8 || height < 4) return grid;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double lat = 90.0 - (y + 0.5) * 180.0 / height;
      const double lon = -180.0 + (x + 0.5) * 360.0 / width;
      if (land_at(lat, lon)) put(grid, x, y, '#');
    }
  }
  auto to_xy = [&](double lat, double lon) {
    double l = std::fmod(lon + 180.0, 360.0);
    if (l < 0) l += 360.0;
    return std::pair{std::min(width - 1, static_cast<int>(l * width / 360.0)),
                     std::clamp(static_cast<int>((90.0 - lat) * height / 180.0), 0, height - 1)};
  };
  for (const auto& [lat, lon] : g.ground_track) {
    auto [x, y] = to_xy(lat, lon);
    put(grid, x, y, '.');
  }
  if (g.station) {
    auto [x, y] = to_xy(g.station->first, g.station->second);
    put(grid, x, y, 'Q');
  }
  if (g.sub_point) {
    auto [x, y] = to_xy(g.sub_point->first, g.sub_point->second);
    put(grid, x, y, '@');
  }
  return grid;
}

LivePlacement place_live_block(int live_row, int cursor_row, int cursor_col, int n, int height) {
  LivePlacement p;
  int y = live_row >= 0 ? live_row : cursor_row + (cursor_col != 0 ? 1 : 0);
  const int need = y + n + 1;  // the block, then a row of its own for the cursor
  if (need > height) {
    p.scroll = std::min(need - height, y);
    y -= p.scroll;
  }
  p.first_row = y;
  p.cursor_row = std::min(height - 1, y + n);
  return p;
}

struct CursesTerminal::Impl {
  WaitReadable wait;
  SCREEN* screen = nullptr;  // this terminal's screen (the others' may be current)
  void select() const {
    if (screen) set_term(screen);
  }
  WINDOW* text = nullptr;
  WINDOW* status = nullptr;
  int live_y = -1;
  int live_lines = 0;
  std::string status_text;
  bool colors = false;
  bool closed = false;  // Ctrl-C was typed
  bool too_small = false;  // the "terminal too small" message is on the screen

  void layout() {
    // A resize keeps what the text window shows (the prompt waiting in it above all).
    if (text && status && LINES > 1) {
      wresize(text, LINES - 1, COLS);
      wresize(status, 1, COLS);
      mvwin(status, LINES - 1, 0);
      live_y = -1;
      return;
    }
    if (text) delwin(text);
    if (status) delwin(status);
    text = newwin(LINES - 1, COLS, 0, 0);
    status = newwin(1, COLS, LINES - 1, 0);
    scrollok(text, TRUE);
    keypad(text, TRUE);
    nodelay(text, TRUE);
    live_y = -1;
  }
  void draw_status() {
    werase(status);
    wattron(status, A_REVERSE);
    mvwhline(status, 0, 0, ' ', COLS);
    mvwaddnstr(status, 0, 0, status_text.c_str(), COLS);
    wattroff(status, A_REVERSE);
    wnoutrefresh(status);
  }
};

CursesTerminal::CursesTerminal(WaitReadable wait) : impl_(std::make_unique<Impl>()) {
  impl_->wait = std::move(wait);
  std::setlocale(LC_ALL, "");
  // initscr's own screen, kept: it is selected again before each call when attached clients have
  // screens too. (initscr is newterm on $TERM, stdout and stdin, and exits with its message when
  // the terminal type is unknown: it is the fallback.)
  const char* term_type = std::getenv("TERM");
  impl_->screen = term_type ? newterm(term_type, stdout, stdin) : nullptr;
  if (!impl_->screen) initscr();
  raw();  // Ctrl-Z ends uploads here, it must not suspend the program
  noecho();
  nonl();
  curs_set(1);
  if (has_colors()) {
    start_color();
    use_default_colors();
    init_pair(1, COLOR_GREEN, -1);   // land
    init_pair(2, COLOR_YELLOW, -1);  // satellite, track
    init_pair(3, COLOR_CYAN, -1);    // antenna, station
    impl_->colors = true;
  }
  impl_->layout();
  impl_->draw_status();
  doupdate();
}

CursesTerminal::CursesTerminal(::screen* screen, int rows, int cols) : impl_(std::make_unique<Impl>()) {
  impl_->screen = screen;
  impl_->select();
  noecho();
  nonl();
  if (has_colors()) {
    start_color();
    use_default_colors();
    init_pair(1, COLOR_GREEN, -1);
    init_pair(2, COLOR_YELLOW, -1);
    init_pair(3, COLOR_CYAN, -1);
    impl_->colors = true;
  }
  resize(rows, cols);
}

::screen* new_screen(const std::string& term_type, std::FILE* out, std::FILE* in) {
  return newterm(term_type.c_str(), out, in);
}

CursesTerminal::~CursesTerminal() {
  impl_->select();
  if (impl_->text) delwin(impl_->text);
  if (impl_->status) delwin(impl_->status);
  endwin();
}

int CursesTerminal::columns() const {
  impl_->select();
  return COLS;
}
int CursesTerminal::rows() const {
  impl_->select();
  return LINES - 1;
}

void CursesTerminal::resize(int rows, int cols) {
  impl_->select();
  resize_term(rows, cols);
  impl_->layout();
  clearok(curscr, TRUE);
  flush();
}

void CursesTerminal::write(std::string_view text) {
  impl_->select();
  for (char c : text) {
    if (c == '\a') {
      beep();
      continue;
    }
    waddch(impl_->text, static_cast<chtype>(static_cast<unsigned char>(c)));
  }
}

void CursesTerminal::bell() {
  impl_->select();
  beep();
}

void CursesTerminal::clear() {
  impl_->select();
  werase(impl_->text);
  wmove(impl_->text, 0, 0);
  impl_->live_y = -1;
  impl_->live_lines = 0;
}

void CursesTerminal::flush() {
  impl_->select();
  // Under 80x24 the menus and the realtime display would wrap mid-word: one message instead, and
  // the screen as it was once the terminal is large enough again (issue 39). Keys still go to the
  // prompt that waits; nothing is lost.
  if (COLS < kMinColumns || LINES < kMinRows) {
    impl_->too_small = true;
    WINDOW* all = newwin(LINES, COLS, 0, 0);
    if (!all) return;
    char msg[96];
    std::snprintf(msg, sizeof msg, "terminal too small (needs %dx%d, is %dx%d): make it larger", kMinColumns, kMinRows,
                  COLS, LINES);
    werase(all);
    wmove(all, 0, 0);
    waddnstr(all, msg, -1);  // wrapped by curses if even this does not fit
    wnoutrefresh(all);
    doupdate();
    delwin(all);
    return;
  }
  if (impl_->too_small) {
    impl_->too_small = false;
    clearok(curscr, TRUE);
    touchwin(impl_->text);
  }
  wnoutrefresh(impl_->text);
  impl_->draw_status();
  wnoutrefresh(impl_->text);  // leave the cursor in the text window
  doupdate();
}

void CursesTerminal::live(const std::vector<std::string>& lines) {
  impl_->select();
  WINDOW* w = impl_->text;
  const int h = getmaxy(w);
  const int n = static_cast<int>(lines.size());
  const LivePlacement p = place_live_block(impl_->live_y, getcury(w), getcurx(w), n, h);
  if (p.scroll > 0) wscrl(w, p.scroll);
  impl_->live_y = p.first_row;
  for (int i = 0; i < n && impl_->live_y + i < h; ++i) {
    wmove(w, impl_->live_y + i, 0);
    wclrtoeol(w);
    waddnstr(w, lines[static_cast<std::size_t>(i)].c_str(), COLS - 1);
  }
  impl_->live_lines = n;
  wmove(w, p.cursor_row, 0);
  flush();
}

void CursesTerminal::end_live() {
  impl_->select();
  if (impl_->live_y >= 0) {
    wmove(impl_->text, std::min(getmaxy(impl_->text) - 1, impl_->live_y + impl_->live_lines), 0);
  }
  impl_->live_y = -1;
  impl_->live_lines = 0;
  flush();
}

void CursesTerminal::status(std::string_view text) {
  impl_->select();
  impl_->status_text.assign(text);
  impl_->draw_status();
  wnoutrefresh(impl_->text);
  doupdate();
}

void CursesTerminal::graphics(const Graphics& g) {
  impl_->select();
  WINDOW* w = impl_->text;
  const int top = (impl_->live_y >= 0 ? impl_->live_y + impl_->live_lines : getcury(w)) + 1;
  // The window's last row stays empty: writing its last cell would scroll a scrolling window.
  const int height = getmaxy(w) - top - 1;
  if (height < 7) return;
  const int sky_h = height;
  const int sky_w = std::min(2 * sky_h + 1, COLS / 3);
  const int map_w = std::min(COLS - sky_w - 3, 2 * (height - 2) * 2);
  const auto sky = draw_sky_plot(g, sky_w, sky_h);
  const auto map = draw_world_map(g, map_w, height - 2);  // its last row: the legend
  const int cy = getcury(w), cx = getcurx(w);
  for (int y = 0; y < height; ++y) {
    wmove(w, top + y, 0);
    wclrtoeol(w);
    for (int x = 0; x < sky_w; ++x) {
      const char c = sky[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      int attr = 0;
      if (impl_->colors && (c == '@' || c == 'o' || c == 'A')) attr = COLOR_PAIR(2) | A_BOLD;
      if (impl_->colors && c == 'X') attr = COLOR_PAIR(3) | A_BOLD;
      mvwaddch(w, top + y, x, static_cast<chtype>(c) | static_cast<chtype>(attr));
    }
    if (y == 0 && !g.title.empty()) mvwaddnstr(w, top, sky_w + 3, g.title.c_str(), map_w);
    if (y == height - 1 && COLS - sky_w - 4 > 0) mvwaddnstr(w, top + y, sky_w + 3, graphics_legend(), COLS - sky_w - 4);
    if (y >= 1 && y < height - 1 && map_w >= 8) {
      const auto& row = map[static_cast<std::size_t>(y - 1)];
      for (int x = 0; x < map_w; ++x) {
        const char c = row[static_cast<std::size_t>(x)];
        int attr = 0;
        if (impl_->colors && c == '#') attr = COLOR_PAIR(1) | A_DIM;
        if (impl_->colors && (c == '@' || c == '.')) attr = COLOR_PAIR(2) | A_BOLD;
        if (impl_->colors && c == 'Q') attr = COLOR_PAIR(3) | A_BOLD;
        mvwaddch(w, top + y, sky_w + 3 + x, static_cast<chtype>(c) | static_cast<chtype>(attr));
      }
    }
  }
  wmove(w, cy, cx);
  flush();
}

// Whether the terminal's input has hung up: poll(2) reports POLLHUP, POLLERR or POLLNVAL on it (the
// other end of a pseudo-terminal closed, the serial line's carrier dropped).
static bool input_hung_up() {
  pollfd p{STDIN_FILENO, POLLIN, 0};
  if (::poll(&p, 1, 0) != 1) return false;
  if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) return true;
  return false;
}

bool CursesTerminal::closed() const { return impl_->closed; }

int CursesTerminal::next_key(std::optional<Duration> timeout) {
  flush();
  if (!impl_->wait) return kEndOfInput;  // an output-only screen: its keys come from elsewhere
  if (impl_->closed) return kEndOfInput;
  const auto deadline = timeout ? std::optional(std::chrono::steady_clock::now() + *timeout) : std::nullopt;
  for (;;) {
    impl_->select();
    // The terminal's size as the kernel has it: ncurses' own SIGWINCH handling has been seen to miss
    // a resize while the loop waits (issue 39), so the screen is laid out again here when it changed.
    if (winsize ws{}; ::ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_row > 0 && ws.ws_col > 0 &&
                      (ws.ws_row != LINES || ws.ws_col != COLS)) {
      resize_term(ws.ws_row, ws.ws_col);
      impl_->layout();
      clearok(curscr, TRUE);
      flush();
    }
    const int ch = wgetch(impl_->text);
    if (ch == ERR && impl_->wait && input_hung_up()) {
      // The terminal went away (its window closed, the SSH link dropped): wgetch says ERR as it does
      // for "no key yet", so the kernel is asked. Leaving as Ctrl-C does saves the state and stops
      // the rotator; looping on would spin on an end of file that is always readable.
      impl_->closed = true;
      return kEndOfInput;
    }
    if (ch != ERR) {
      switch (ch) {
        case KEY_RESIZE:
          impl_->layout();
          clearok(curscr, TRUE);
          flush();
          continue;
        case KEY_BACKSPACE:
        case KEY_DC: return kBackspace;
        case KEY_ENTER:
        case '\n': return kEnter;
        case 3:  // Ctrl-C leaves trakbox (raw mode delivers it as a key); it stays the end of input,
                 // also when a read that only looked ahead (the LF after a CR) was the one to see it
          impl_->closed = true;
          return kEndOfInput;
        default:
          if (ch >= 0 && ch < 256) return ch;
          continue;  // function keys the menus do not use
      }
    }
    // The wait returns after any work of the loop too (the tick, once a second at most): a resize
    // is seen (above) within a tick while no key comes, without a wake-up of its own.
    std::optional<Duration> left;
    if (deadline) {
      const auto now = std::chrono::steady_clock::now();
      if (now >= *deadline) return kTimeout;
      left = *deadline - now;
    }
    if (impl_->wait) impl_->wait(STDIN_FILENO, left);
  }
}

}  // namespace tb::term
