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
  const fs::path mine = dir.path / (".trakbox-state.json.tmp-" + std::to_string(::getpid()));
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
