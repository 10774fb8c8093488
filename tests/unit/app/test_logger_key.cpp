// The logger's key file (live/logger_upload.h): the first line, trimmed; a refusal names the file
// and what is wrong; a file others may read is warned about.
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "live/logger_upload.h"

using tb::app::read_logger_key;
namespace fs = std::filesystem;

namespace {
struct KeyDir {
  fs::path dir = fs::temp_directory_path() / ("trakbox-logger-key-" + std::to_string(::getpid()));
  KeyDir() { fs::create_directories(dir); }
  ~KeyDir() { fs::remove_all(dir); }
  std::string file(const std::string& name, const std::string& text, mode_t mode) {
    const std::string p = (dir / name).string();
    std::ofstream(p) << text;
    ::chmod(p.c_str(), mode);
    return p;
  }
};
}  // namespace

TEST_CASE("The logger's key file") {
  KeyDir d;
  std::string key, warning;
  const std::string good = d.file("good", "  abc123KEY \nsecond line\n", 0600);
  CHECK_FALSE(read_logger_key(good, key, warning));
  CHECK(key == "abc123KEY");
  CHECK(warning.empty());
  const std::string open = d.file("open", "abc123KEY", 0644);
  CHECK_FALSE(read_logger_key(open, key, warning));
  CHECK(warning == "--logger-key-file " + open + ": others may read the logger's key (chmod 600 " + open + ")");
  CHECK(read_logger_key(d.file("empty", "\n", 0600), key, warning) ==
        "--logger-key-file " + (d.dir / "empty").string() + ": is empty: its first line is the logger's API key");
  const std::string missing = (d.dir / "missing").string();
  CHECK(read_logger_key(missing, key, warning) ==
        "--logger-key-file " + missing + ": cannot be read (No such file or directory)");
  CHECK(read_logger_key(d.dir.string(), key, warning) == "--logger-key-file " + d.dir.string() + ": is not a file");
}
