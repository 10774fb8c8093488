// The manual's example dialogues as data (tests/unit/menus/transcripts/*.txt), each replayed three
// times from the main menu: with CR, with LF and with CR LF for Enter (issue 18). Each replay must
// show the same screens (every "screen:" line, in order) and store the same result (every "state:"
// JSON pointer of the state document). docs/menus/transcripts.md lists the examples.
//
// File format, one item a line ('#' lines are comments):
//   keys: text typed, with <ENTER> for the Enter key and <CTRL-Z> for Ctrl-Z
//   screen: a piece of the output, in the order shown (blanks at the ends are kept)
//   state: /json/pointer = JSON value
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
      testing::MenuFixture f(typed(t.keys, enter));
      f.run(1);
      try {
        menus::main_menu(f.term, *f.services);
      } catch (const menus::InputClosed&) {
      } catch (const menus::cfg::Quit&) {
      }
      const std::string& out = f.term.output();
      std::size_t from = 0;
      for (const std::string& s : t.screens) {
        const auto at = out.find(s, from);
        CHECK_MESSAGE(at != std::string::npos, "screen '" << s << "' not shown (in order); output:\n" << out);
        if (at != std::string::npos) from = at + s.size();
      }
      const nlohmann::json doc = store::to_json(f.model);
      for (const auto& [pointer, want] : t.states) {
        const nlohmann::json::json_pointer ptr(pointer);
        REQUIRE_MESSAGE(doc.contains(ptr), "no " << pointer << " in the state document");
        CHECK_MESSAGE(doc.at(ptr) == want, pointer << " is " << doc.at(ptr).dump() << ", expected " << want.dump());
      }
      ++replays;
    }
  }
  MESSAGE(files.size() << " transcripts, " << replays << " replays");
}
