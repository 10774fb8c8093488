#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "store/state_file.h"

using namespace tb::store;
namespace fs = std::filesystem;

namespace {
struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "trakbox-test-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
};
std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
int count_corrupt(const fs::path& dir) {
  int n = 0;
  for (auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".corrupt-") != std::string::npos) ++n;
  return n;
}
}  // namespace

TEST_CASE("CRC-32 check value") {
  CHECK(crc32("123456789") == 0xCBF43926u);  // the standard CRC-32 (IEEE 802.3) check value
  CHECK(crc32("") == 0u);
}

TEST_CASE("No file is a fresh start; a save loads back") {
  TempDir d;
  StateFile f(d.path / "sub");
  CHECK(f.load().kind == LoadOutcome::Kind::fresh);
  nlohmann::json data = {{"station", {{"callsign", "WA7GXD"}, {"lat", 32.259}}}};
  std::string err;
  REQUIRE(f.save(data, err));
  const LoadOutcome o = f.load();
  CHECK(o.kind == LoadOutcome::Kind::loaded);
  CHECK(o.data == data);
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] auto& e : fs::directory_iterator(d.path / "sub")) ++files;
  CHECK(files == 1);
}

TEST_CASE("A changed byte fails the checksum: the file is kept aside, never overwritten") {
  TempDir d;
  StateFile f(d.path);
  std::string err;
  REQUIRE(f.save({{"callsign", "WA7GXD"}}, err));
  std::string text = read(f.path());
  const auto pos = text.find("WA7GXD");
  REQUIRE(pos != std::string::npos);
  text[pos] = 'X';
  std::ofstream(f.path()) << text;

  const LoadOutcome o = f.load();
  CHECK(o.kind == LoadOutcome::Kind::corrupt);
  CHECK(o.reason.find("checksum") != std::string::npos);
  CHECK(!fs::exists(f.path()));
  REQUIRE(fs::exists(o.kept_aside));
  CHECK(read(o.kept_aside) == text);

  // A second corruption in the same second gets its own name.
  std::ofstream(f.path()) << "{ not json";
  const LoadOutcome o2 = f.load();
  CHECK(o2.kind == LoadOutcome::Kind::corrupt);
  CHECK(o2.kept_aside != o.kept_aside);
  CHECK(count_corrupt(d.path) == 2);
  CHECK(read(o.kept_aside) == text);
}

TEST_CASE("Truncated and foreign files are corrupt") {
  TempDir d;
  StateFile f(d.path);
  std::string err;
  REQUIRE(f.save({{"a", 1}}, err));
  const std::string text = read(f.path());
  std::ofstream(f.path()) << text.substr(0, text.size() / 2);
  CHECK(f.load().kind == LoadOutcome::Kind::corrupt);
  std::ofstream(f.path()) << R"({"format": "something-else", "data": {}, "checksum": "0"})";
  CHECK(f.load().kind == LoadOutcome::Kind::corrupt);
  CHECK(count_corrupt(d.path) == 2);
}

TEST_CASE("A document of the wrong shape is corrupt, never an exception") {
  // Each is valid JSON; none may throw, each is kept aside and reported.
  const char* docs[] = {
      R"({"format":{}})",
      R"({"format":"trakbox-state","checksum":7,"data":{}})",
      R"({"format":"trakbox-state","checksum":"00000000","data":[]})",
      R"({"format":"trakbox-state","checksum":"00000000","data":"x"})",
      R"({"format":["trakbox-state"],"checksum":"x","data":{}})",
      R"({"format":null})",
      R"({"format":"trakbox-state","checksum":{},"data":null})",
      R"([])",
      R"("trakbox-state")",
      R"(12)",
  };
  for (const char* text : docs) {
    CAPTURE(text);
    TempDir dir;
    StateFile file(dir.path);
    { std::ofstream(file.path()) << text; }
    LoadOutcome got;
    CHECK_NOTHROW(got = file.load());
    CHECK(got.kind == LoadOutcome::Kind::corrupt);
    CHECK_FALSE(got.reason.empty());
    CHECK(read(got.kept_aside) == text);
    CHECK_FALSE(fs::exists(file.path()));
  }
}

TEST_CASE("The state document is written 0600 in a directory created 0700; looser ones are tightened") {
  TempDir dir;
  const fs::path sub = dir.path / "state";
  StateFile file(sub);
  std::string err;
  REQUIRE(file.save(nlohmann::json{{"x", 1}}, err));
  CHECK((fs::status(sub).permissions() & fs::perms::all) == fs::perms::owner_all);
  CHECK((fs::status(file.path()).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write));
  CHECK(file.tighten_permissions().empty());

  fs::permissions(sub, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(file.path(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                                   fs::perms::others_read);
  const auto notes = file.tighten_permissions();
  REQUIRE(notes.size() == 2);
  CHECK(notes[0].find("mode 755") != std::string::npos);
  CHECK(notes[1].find("mode 644") != std::string::npos);
  CHECK((fs::status(sub).permissions() & fs::perms::all) == fs::perms::owner_all);
  CHECK((fs::status(file.path()).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write));
  // A save over a looser file still leaves 0600 (the umask does not widen it either).
  fs::permissions(file.path(), fs::perms::all);
  REQUIRE(file.save(nlohmann::json{{"x", 2}}, err));
  CHECK((fs::status(file.path()).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write));
}

TEST_CASE("Temporary files of saves that were killed are removed; a live process's are not") {
  TempDir dir;
  // A pid that cannot be running: above the kernel's maximum.
  const fs::path dead = dir.path / ".trakbox-state.json.tmp-999999999";
  const fs::path mine = dir.path / (".trakbox-state.json" + std::string(kTempInfix) + std::to_string(::getpid()));
  const fs::path live = dir.path / ".trakbox-state.json.tmp-1";  // init is always running
  const fs::path other = dir.path / "notes.tmp-12";               // not ours: no leading dot
  for (const auto& p : {dead, mine, live, other}) std::ofstream(p) << "{";
  const auto removed = remove_stale_temporaries(dir.path);
  CHECK(removed.size() == 2);
  CHECK_FALSE(fs::exists(dead));
  CHECK_FALSE(fs::exists(mine));
  CHECK(fs::exists(live));
  CHECK(fs::exists(other));
}

// Issue 33, defect 1: a checksum-valid state file nested 100,000 objects deep crashed trakbox at
// every start (dump() recursing once per level) and was never kept aside. The checksum below is the
// CRC-32 of the nested data as nlohmann::json dumps it, computed here without recursion.
TEST_CASE("A state file nested deeper than any trakbox writes is kept aside, not parsed into a crash") {
  TempDir d;
  StateFile f(d.path);
  for (const bool arrays : {false, true}) {
    constexpr int kLevels = 100000;
    std::string data;
    for (int i = 0; i < kLevels; ++i) data += arrays ? "[" : "{\"a\":";
    data += "1";
    for (int i = 0; i < kLevels; ++i) data += arrays ? "]" : "}";
    if (arrays) data = "{\"a\":" + data + "}";
    char crc[9];
    std::snprintf(crc, sizeof crc, "%08x", crc32(data));
    {
      std::ofstream out(f.path());
      out << "{\"checksum\":\"" << crc << "\",\"data\":" << data << ",\"format\":\"trakbox-state\",\"version\":1}";
    }
    const LoadOutcome o = f.load();
    CHECK(o.kind == LoadOutcome::Kind::corrupt);
    CHECK(o.reason.find("nested more than 64 levels") != std::string::npos);
    CHECK(!o.kept_aside.empty());
    CHECK(fs::exists(o.kept_aside));
    CHECK(!fs::exists(f.path()));
  }
  CHECK(count_corrupt(d.path) == 2);
  // 64 levels is still a document (the limit is inclusive).
  std::string data;
  for (int i = 0; i < 63; ++i) data += "{\"a\":";
  data += "1";
  for (int i = 0; i < 63; ++i) data += "}";
  std::string err;
  REQUIRE(f.save(nlohmann::json::parse(data), err));
  CHECK(f.load().kind == LoadOutcome::Kind::loaded);
}

TEST_CASE("A state file larger than a state document may be is refused before it is read") {
  TempDir d;
  StateFile f(d.path);
  {
    std::ofstream out(f.path());
    out << "{\"format\":\"trakbox-state\",\"data\":{\"x\":\"";
  }
  fs::resize_file(f.path(), StateFile::kMaxBytes + 1);  // sparse: no 64 MiB written
  const LoadOutcome o = f.load();
  CHECK(o.kind == LoadOutcome::Kind::corrupt);
  CHECK(o.reason.find(std::to_string(StateFile::kMaxBytes + 1) + " bytes, more than a state document may have") !=
        std::string::npos);
  CHECK(fs::exists(o.kept_aside));
}

// Issue 33, defect 5: a state file that is a symbolic link is never followed: not read, its target's
// mode never changed; the link is kept aside and defaults apply.
TEST_CASE("A symbolic link in place of the state file or directory is not followed") {
  TempDir d;
  const fs::path target = d.path / "elsewhere.json";
  {
    std::ofstream out(target);
    out << "{}";
  }
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
  const fs::path state = d.path / "state";
  fs::create_directory(state);
  fs::permissions(state, fs::perms::owner_all);
  StateFile f(state);
  fs::create_symlink(target, f.path());
  const auto notes = f.tighten_permissions();
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("is a symbolic link: its permissions were not checked or changed") != std::string::npos);
  CHECK((fs::status(target).permissions() & fs::perms::others_read) == fs::perms::others_read);  // untouched
  const LoadOutcome o = f.load();
  CHECK(o.kind == LoadOutcome::Kind::corrupt);
  CHECK(o.reason.find("a symbolic link, not a file; not followed") != std::string::npos);
  CHECK(fs::is_symlink(fs::symlink_status(o.kept_aside)));  // the link moved aside, as a link
  CHECK(read(target) == "{}");
  // A later save writes a real file where the link was.
  std::string err;
  REQUIRE(f.save(nlohmann::json::object(), err));
  CHECK(!fs::is_symlink(fs::symlink_status(f.path())));
  CHECK(read(target) == "{}");
}

// Issue 38, crash 2: a string that is not UTF-8 made dump() throw type_error.316 in the save, at
// every start. The save writes U+FFFD for the bad bytes, and what it wrote loads back.
TEST_CASE("A save never throws on a string that is not UTF-8") {
  TempDir d;
  StateFile f(d.path);
  const nlohmann::json data = {{"db", {{{"name", "IS\xff\xfeS"}}}}};
  std::string err;
  REQUIRE(f.save(data, err));
  const LoadOutcome o = f.load();
  REQUIRE(o.kind == LoadOutcome::Kind::loaded);
  CHECK(o.data["db"][0]["name"] == "IS\xEF\xBF\xBD\xEF\xBF\xBDS");
}

// Issue 38: every path trakbox creates in a directory is checked first. A link planted under the
// save's temporary name is removed, never written through.
TEST_CASE("A save never writes through a link planted under its temporary name") {
  TempDir d;
  TempDir elsewhere;
  const fs::path target = elsewhere.path / "victim.txt";
  { std::ofstream(target) << "keep me\n"; }
  StateFile f(d.path);
  fs::create_symlink(target, d.path / (".trakbox-state.json" + std::string(kTempInfix) + std::to_string(::getpid())));
  std::string err;
  REQUIRE(f.save(nlohmann::json{{"a", 1}}, err));
  CHECK(read(target) == "keep me\n");
  CHECK(f.load().kind == LoadOutcome::Kind::loaded);
}
