// util/secret.h: the endpoints' shared secrets.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "util/secret.h"

using namespace tb;

TEST_CASE("secrets compare equal only when every byte and the length match") {
  CHECK(secret::equal("hunter2", "hunter2"));
  CHECK_FALSE(secret::equal("hunter3", "hunter2"));
  CHECK_FALSE(secret::equal("hunter", "hunter2"));
  CHECK_FALSE(secret::equal("hunter22", "hunter2"));
  CHECK_FALSE(secret::equal("", "hunter2"));
  CHECK_FALSE(secret::equal(std::string("hunter2\0", 8), "hunter2"));
}

namespace {
std::string write_temp(const std::string& text, mode_t mode) {
  char path[] = "/tmp/tb_secret_XXXXXX";
  const int fd = ::mkstemp(path);
  REQUIRE(fd >= 0);
  ::close(fd);
  std::ofstream(path, std::ios::binary) << text;
  ::chmod(path, mode);
  return path;
}
}  // namespace

TEST_CASE("a secret file: the first line, checked, with a warning when others may read it") {
  std::string error, warning;
  const std::string good = write_temp("s3cret-Pass\nsecond line\n", 0600);
  CHECK(secret::read_file(good, error, warning) == "s3cret-Pass");
  CHECK(warning.empty());
  const std::string crlf = write_temp("abc\r\n", 0644);
  CHECK(secret::read_file(crlf, error, warning) == "abc");
  CHECK(warning == crlf + " can be read by other users (chmod 600 it)");
  for (const std::string& bad : {std::string("\n"), std::string("two words\n"), std::string(300, 'x')}) {
    const std::string p = write_temp(bad, 0600);
    error.clear();
    CHECK_FALSE(secret::read_file(p, error, warning));
    CHECK(error.rfind(p + ": ", 0) == 0);
    std::remove(p.c_str());
  }
  error.clear();
  CHECK_FALSE(secret::read_file("/nonexistent/secret", error, warning));
  CHECK(error == "/nonexistent/secret: cannot be read");
  std::remove(good.c_str());
  std::remove(crlf.c_str());
}
