#include <doctest/doctest.h>

#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "menus/common.h"
#include "menus/term/curses_terminal.h"
#include "menus/term/script_terminal.h"

using namespace tb;
using namespace tb::menus;

TEST_CASE("Line input: echo, backspace, CR LF counted once") {
  term::ScriptTerminal t("AB\bC\r\nX\n");
  CHECK(read_line(t) == "AC");
  CHECK(t.output() == "AB\b \bC\n");
  CHECK(read_line(t) == "X");
  CHECK_THROWS_AS(read_line(t), InputClosed);
}

TEST_CASE("Prompts keep the current value on Enter and repeat on bad input") {
  term::ScriptTerminal t("\rabc\r95\r-45.5\r");
  CHECK(edit_text(t, "Callsign", "NOCALL") == "NOCALL");
  CHECK(t.output() == "Callsign : NOCALL  \n");
  t.clear_output();
  CHECK(edit_number(t, "Latitude", 27.391, "+27.391", -90, 90) == -45.5);
  CHECK(t.output().find("'abc' is not a number") != std::string::npos);
  CHECK(t.output().find("95 is out of range: expected -90 to 90") != std::string::npos);
}

TEST_CASE("Y/N questions take one key") {
  term::ScriptTerminal t("yN");
  CHECK(ask_yes_no(t, "Are you sure ? [Y/N] ? "));
  CHECK(!ask_yes_no(t, "Again ? [Y/N] ? "));
  CHECK(t.output() == "Are you sure ? [Y/N] ? Y\nAgain ? [Y/N] ? N\n");
}

TEST_CASE("The manual's satellite list with the marker") {
  const std::vector<std::string> names = {"AO-10", "A-13S", "U-11",  "A-16",  "L-19",    "F-20",    "A-21", "W-18",
                                          "U-22A", "U-22B", "K-23A", "K-23B", "R-10/11", "R-12/13", "U-14"};
  const auto rows = format_satellite_list(names, 6);
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == " 1. AO-10       2. A-13S       3. U-11        4. A-16");
  CHECK(rows[1] == " 5. L-19        6. F-20        7.*A-21        8. W-18");
  CHECK(rows[3] == "13. R-10/11    14. R-12/13    15. U-14");
}

TEST_CASE("Choosing from the list: Enter takes the marked one, Q leaves") {
  const std::vector<std::string> names = {"AO-10", "A-13S", "U-11"};
  term::ScriptTerminal t("\r" "3\r" "9\r2\r" "q\r");
  CHECK(choose_satellite(t, "*** Tracking object satellite ***", names, 1) == 1);
  CHECK(choose_satellite(t, "x", names, 1) == 2);
  CHECK(choose_satellite(t, "x", names, 1) == 1);
  CHECK(t.output().find("Enter 1 to 3") != std::string::npos);
  CHECK(choose_satellite(t, "x", names, 1) == std::nullopt);
}

TEST_CASE("Clock input in the manual's [YY/MM/DD HH:MM:SS] form") {
  CHECK(parse_yymmdd_hhmmss("93/07/17 03:03:15") == orbit::from_civil(1993, 7, 17, 3, 3, 15));
  CHECK(parse_yymmdd_hhmmss("26/11/21 15:00:00") == orbit::from_civil(2026, 11, 21, 15));
  CHECK(parse_yymmdd_hhmmss("93/04/31 00:00:00") == std::nullopt);
  CHECK(parse_yymmdd_hhmmss("93/07/17") == std::nullopt);
  CHECK(parse_yymmdd_hhmmss("93/07/17 03:03:15 x") == std::nullopt);
  CHECK(format_date(orbit::from_civil(1993, 7, 17, 4, 6, 58)) == "1993/07/17");
  CHECK(format_time(orbit::from_civil(1993, 7, 17, 4, 6, 58)) == "04:06:58");
}

TEST_CASE("Uploads end at Ctrl-Z and keep line numbers") {
  term::ScriptTerminal t("line one\r\nline two\rline three\x1a");
  std::vector<std::string> lines;
  CHECK(t.read_upload([&](std::string_view l) { lines.emplace_back(l); }));
  CHECK(lines == std::vector<std::string>{"line one", "line two", "line three"});
  term::ScriptTerminal cut("no end\r");
  CHECK_FALSE(cut.read_upload([](std::string_view) {}));
}

TEST_CASE("Sky plot and world map drawings") {
  term::Graphics g;
  g.pass_track = {{90, 0}, {135, 45}, {180, 0}};
  g.satellite = term::SkyPoint{135, 45};
  g.antenna = term::SkyPoint{0, 90};
  const auto sky = term::draw_sky_plot(g, 21, 11);
  REQUIRE(sky.size() == 11);
  CHECK(sky[0][10] == 'N');
  CHECK(sky[5][10] == 'X');   // antenna at the zenith, the centre
  CHECK(sky[5][20] == 'A');   // AOS at east on the horizon
  g.station = std::pair{32.26, -110.78};
  g.sub_point = std::pair{0.0, 0.0};
  const auto map = term::draw_world_map(g, 72, 18);
  REQUIRE(map.size() == 18);
  CHECK(map[9][36] == '@');   // 0N 0E: the middle of the map
  CHECK(map[5][13] == 'Q');   // Tucson
  int land = 0;
  for (const auto& r : map) for (char c : r) land += c == '#';
  CHECK(land > 72 * 18 / 5);  // about a quarter of the Earth's surface shows as land
  CHECK(land < 72 * 18 / 2);
}

TEST_CASE("Key questions ignore a bare Enter; an Enter after a Y/N answer ends that answer (issue 18)") {
  // "Y" and "Y<Enter>" answer the same, with CR, LF or CR LF for Enter: the Enter that follows a
  // single-key answer is never taken as the next answer.
  for (const char* enter : {"\r", "\n", "\r\n"}) {
    CAPTURE(enter);
    const std::string e = enter;
    term::ScriptTerminal t("Y" + e + e + "340" + e);  // Y<Enter>, <Enter> keeps the minimum
    CHECK(ask_yes_no(t, "Set Antenna rotation limit ? [Y/N] "));
    CHECK(edit_text(t, "Azimuth minmum value", "0.0") == "0.0");
    CHECK(edit_text(t, "Azimuth maximum value", "360.0") == "340");
    term::ScriptTerminal v("Y" + e + "10" + e + e);  // Y<Enter> 10<Enter>: the first value is 10
    CHECK(ask_yes_no(v, "Set Antenna rotation limit ? [Y/N] "));
    CHECK(edit_text(v, "Azimuth minmum value", "0.0") == "10");
    CHECK(edit_text(v, "Azimuth maximum value", "360.0") == "360.0");
    term::ScriptTerminal w("Y10" + e + e);  // Y without Enter: the same
    CHECK(ask_yes_no(w, "Set Antenna rotation limit ? [Y/N] "));
    CHECK(edit_text(w, "Azimuth minmum value", "0.0") == "10");
    CHECK(edit_text(w, "Azimuth maximum value", "360.0") == "360.0");
    // The manual's 3-3: "Are you sure ? [Y/N] ? Y <ENTER>" then "File format NASA/AMSAT (N/A) : N".
    term::ScriptTerminal u("Y" + e + "A");
    CHECK(ask_yes_no(u, "Are you sure ? [Y/N] ? "));
    CHECK(ask_key(u, "File format NASA/AMSAT (N/A) : ", "NA") == 'A');
    CHECK(u.output() == "Are you sure ? [Y/N] ? Y\nFile format NASA/AMSAT (N/A) : A\n");
  }
}

TEST_CASE("Full screen: a live block keeps a row of its own below it for what follows") {
  // A 39-row text window (40 rows less the status line), the cursor on its last row: the monitor
  // line of 6-6 goes there. The window scrolls one line so that the sub-menu printed after the
  // antenna arrived starts below the last position instead of over it.
  auto p = term::place_live_block(-1, 38, 0, 1, 39);
  CHECK(p.scroll == 1);
  CHECK(p.first_row == 37);
  CHECK(p.cursor_row == 38);
  // Redrawn in place afterwards: no further scrolling.
  p = term::place_live_block(37, 38, 0, 1, 39);
  CHECK(p.scroll == 0);
  CHECK(p.first_row == 37);
  CHECK(p.cursor_row == 38);
  // With room below, the block starts at the cursor's line (or the next one after a prompt).
  p = term::place_live_block(-1, 10, 0, 2, 39);
  CHECK((p.scroll == 0 && p.first_row == 10 && p.cursor_row == 12));
  p = term::place_live_block(-1, 10, 5, 2, 39);
  CHECK((p.scroll == 0 && p.first_row == 11 && p.cursor_row == 13));
  // A block that grows at the bottom scrolls by what it needs.
  p = term::place_live_block(36, 37, 0, 3, 39);
  CHECK((p.scroll == 1 && p.first_row == 35 && p.cursor_row == 38));
  // Taller than the window: from the top, cut at the bottom.
  p = term::place_live_block(-1, 20, 0, 50, 39);
  CHECK((p.scroll == 20 && p.first_row == 0 && p.cursor_row == 38));
}

TEST_CASE("Full screen: Ctrl-C typed right after Enter still ends the input") {
  // The CR of an Enter is followed by a short look for its LF; a Ctrl-C arriving then must not be
  // lost (trakbox would stay in the menus). The full-screen terminal runs on a pseudo-terminal in a
  // fresh copy of this program (exec'd, not only forked: other tests may have left threads).
  if (std::getenv("TB_TEST_CURSES_CTRL_C")) {
    int code = 1;
    {
      term::CursesTerminal t([](int fd, std::optional<term::Duration> timeout) {
        pollfd p{fd, POLLIN, 0};
        const int ms =
            timeout ? static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(*timeout).count()) : -1;
        return ::poll(&p, 1, ms) > 0;
      });
      const auto first = t.read_line();
      const auto second = t.read_line();
      code = first && *first == "6" && !second && t.closed() ? 0 : 2;
    }
    _exit(code);
  }
  std::vector<std::string> env_text{"TB_TEST_CURSES_CTRL_C=1", "TERM=xterm"};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "TERM=", 5) != 0) env_text.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::string arg0 = "unit_menus", filter = "-tc=*Ctrl-C typed right after Enter*";
  char* argv[] = {arg0.data(), filter.data(), nullptr};

  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::execve("/proc/self/exe", argv, envp.data());
    _exit(127);
  }
  // Once the screen is set up (raw mode), type 6, Enter and Ctrl-C in one go, as a fast typist or
  // a script does; the screen output is read (and not looked at) so that it never blocks.
  std::string shown;
  bool typed = false;
  int status = 0;
  pid_t done = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline) {
    pollfd p{master, POLLIN, 0};
    if (::poll(&p, 1, 50) > 0) {
      char buf[4096];
      const auto n = ::read(master, buf, sizeof buf);
      if (n > 0) shown.append(buf, static_cast<std::size_t>(n));
      else ::usleep(10000);
    }
    if (!typed && shown.find("\x1b[2J") != std::string::npos) {
      REQUIRE(::write(master, "6\r\x03", 3) == 3);
      typed = true;
    }
  }
  if (done == 0) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  ::close(master);
  CHECK(done == pid);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
}
