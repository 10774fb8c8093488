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
