// The manual's example dialogues as data (tests/unit/menus/transcripts/*.txt), each replayed three
// times from the main menu: with CR, with LF and with CR LF for Enter (issue 18). Each replay must
// show the same screens (every "screen:" line, in order) and store the same result (every "state:"
// JSON pointer of the state document). docs/menus/transcripts.md lists the examples. The examples
// that do not replay as printed are in transcripts-failing/, which this runner does not read.
//
// File format, one item a line ('#' lines are comments):
//   keys: text typed, with <ENTER> for the Enter key and <CTRL-Z> for Ctrl-Z
//   screen: a piece of the output, in the order shown (blanks at the ends are kept)
//   state: /json/pointer = JSON value
// and two optional settings for the whole replay:
//   timeouts: N   live displays (timed reads) see N timeouts before each key, the clock moving by each
//                 timeout (ScriptTerminal::timeouts_before_key; 0 when absent)
//   sign-on: yes  the sign-on banner is shown before the main menu, as at power-on
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fixture.h"
#include "menus/6_configuration.h"
#include "menus/common.h"
#include "store/model.h"

using namespace tb;

namespace {

struct Transcript {
  std::string name;
  std::string keys;  // with <ENTER> and <CTRL-Z> tokens
  std::vector<std::string> screens;
  std::vector<std::pair<std::string, nlohmann::json>> states;
  int timeouts = 0;
  bool sign_on = false;
};

Transcript read_transcript(const std::filesystem::path& p) {
  Transcript t;
  t.name = p.filename().string();
  std::ifstream in(p);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    REQUIRE_MESSAGE(colon != std::string::npos, p.string() << ":" << n << ": expected 'keys:', 'screen:' or 'state:'");
    const std::string key = line.substr(0, colon);
    std::string value = line.substr(colon + 1);
    if (!value.empty() && value[0] == ' ') value.erase(0, 1);
    if (key == "keys") {
      t.keys += value;
    } else if (key == "screen") {
      t.screens.push_back(value);
    } else if (key == "state") {
      const auto eq = value.find(" = ");
      REQUIRE_MESSAGE(eq != std::string::npos, p.string() << ":" << n << ": expected 'state: /pointer = value'");
      t.states.emplace_back(value.substr(0, eq), nlohmann::json::parse(value.substr(eq + 3)));
    } else if (key == "timeouts") {
      t.timeouts = std::stoi(value);
      REQUIRE_MESSAGE(t.timeouts >= 0, p.string() << ":" << n << ": expected 'timeouts: N' with N >= 0");
    } else if (key == "sign-on") {
      REQUIRE_MESSAGE((value == "yes" || value == "no"), p.string() << ":" << n << ": expected 'sign-on: yes' or 'no'");
      t.sign_on = value == "yes";
    } else {
      FAIL(p.string() << ":" << n << ": unknown item '" << key << "'");
    }
  }
  return t;
}

std::string typed(std::string keys, const std::string& enter) {
  for (const auto& [token, bytes] : {std::pair<std::string, std::string>{"<ENTER>", enter}, {"<CTRL-Z>", "\x1a"}}) {
    for (std::size_t at; (at = keys.find(token)) != std::string::npos;) keys.replace(at, token.size(), bytes);
  }
  return keys;
}

std::vector<std::filesystem::path> transcript_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(TRAKBOX_SOURCE_DIR) / "tests/unit/menus/transcripts"))
    if (e.path().extension() == ".txt") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// One replay of a transcript from the main menu with this Enter; the output and the state document.
struct Replay {
  std::string output;
  nlohmann::json state;
};

Replay replay(const Transcript& t, const std::string& enter) {
  testing::MenuFixture f(typed(t.keys, enter));
  f.term.timeouts_before_key = t.timeouts;
  f.run(1);
  try {
    if (t.sign_on) menus::sign_on(f.term, *f.services);
    menus::main_menu(f.term, *f.services);
  } catch (const menus::InputClosed&) {
  } catch (const menus::cfg::Quit&) {
  }
  return {f.term.output(), store::to_json(f.model)};
}

}  // namespace

TEST_CASE("The manual's example dialogues reach the same screens and state with CR, LF and CR LF") {
  const auto files = transcript_files();
  REQUIRE(files.size() >= 8);
  int replays = 0;
  for (const auto& file : files) {
    const Transcript t = read_transcript(file);
    for (const std::string enter : {"\r", "\n", "\r\n"}) {
      CAPTURE(t.name);
      const std::string ending = enter == "\r" ? "CR" : enter == "\n" ? "LF" : "CR LF";
      CAPTURE(ending);
      const Replay r = replay(t, enter);
      const std::string& out = r.output;
      std::size_t from = 0;
      for (const std::string& s : t.screens) {
        const auto at = out.find(s, from);
        CHECK_MESSAGE(at != std::string::npos, "screen '" << s << "' not shown (in order); output:\n" << out);
        if (at != std::string::npos) from = at + s.size();
      }
      for (const auto& [pointer, want] : t.states) {
        const nlohmann::json::json_pointer ptr(pointer);
        REQUIRE_MESSAGE(r.state.contains(ptr), "no " << pointer << " in the state document");
        CHECK_MESSAGE(r.state.at(ptr) == want, pointer << " is " << r.state.at(ptr).dump() << ", expected " << want.dump());
      }
      ++replays;
    }
  }
  MESSAGE(files.size() << " transcripts, " << replays << " replays");
}

TEST_CASE("Transcript settings: 'timeouts: N' lets a live display tick N times before each key; 'sign-on: yes' "
          "shows the banner") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "trakbox_transcript_settings";
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return read_transcript(dir / name);
  };
  // The realtime display prints a row per second: with 'timeouts: 3' the rows before Q are
  // 12:00:01 .. 12:00:04, without it only the first.
  const Transcript plain = write("plain.txt", "keys: 1<ENTER><ENTER>Q\n");
  const Transcript ticking = write("ticking.txt", "# comment\ntimeouts: 3\nkeys: 1<ENTER><ENTER>Q\n");
  CHECK(plain.timeouts == 0);
  CHECK(ticking.timeouts == 3);
  const std::string slow = replay(ticking, "\r").output;
  const std::string fast = replay(plain, "\r").output;
  CHECK(slow.find("12:00:04  ") != std::string::npos);
  CHECK(fast.find("12:00:01  ") != std::string::npos);
  CHECK(fast.find("12:00:02  ") == std::string::npos);
  // The banner only when asked for; the main menu follows it.
  const Transcript banner = write("banner.txt", "sign-on: yes\nkeys: Q<ENTER>\n");
  CHECK(banner.sign_on);
  CHECK(!plain.sign_on);
  const std::string with = replay(banner, "\r").output;
  CHECK(with.find("TrakBox 8052 v3.10a") < with.find("----- MAIN MENU -----"));
  CHECK(replay(plain, "\r").output.find("TrakBox 8052 v3.10a") == std::string::npos);
  std::filesystem::remove_all(dir);
}
