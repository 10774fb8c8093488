#include "store/state_file.h"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace tb::store {
namespace fs = std::filesystem;

std::uint32_t crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

namespace {

std::string hex32(std::uint32_t v) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", v);
  return buf;
}

}  // namespace

// Moves a bad file aside as NAME.corrupt-YYYYMMDDTHHMMSSZ[-N]; never overwrites anything.
fs::path keep_aside(const fs::path& file) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
  for (int n = 0; n < 1000; ++n) {
    fs::path target = file;
    target += std::string(".corrupt-") + stamp + (n ? "-" + std::to_string(n) : "");
    std::error_code ec;
    if (fs::exists(target, ec)) continue;
    // link + unlink never replaces an existing target (rename would).
    if (::link(file.c_str(), target.c_str()) == 0) {
      ::unlink(file.c_str());
      return target;
    }
    if (errno != EEXIST) break;
  }
  return {};
}

namespace {

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

StateFile::StateFile(fs::path directory) : dir_(std::move(directory)) {}

LoadOutcome StateFile::load() const {
  LoadOutcome out;
  const fs::path file = path();
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    out.kind = LoadOutcome::Kind::fresh;
    return out;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  in.close();
  const std::string text = ss.str();

  auto corrupt = [&](std::string reason) {
    out.kind = LoadOutcome::Kind::corrupt;
    out.reason = std::move(reason);
    out.kept_aside = store::keep_aside(file);
    out.data = nlohmann::json();
    return out;
  };

  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return corrupt(file.string() + ": not a JSON document");
  if (doc.value("format", "") != "trakbox-state") return corrupt(file.string() + ": not a trakbox state file");
  if (!doc.contains("data") || !doc.contains("checksum") || !doc["checksum"].is_string())
    return corrupt(file.string() + ": data or checksum missing");
  const std::string expected = doc["checksum"].get<std::string>();
  const std::string found = hex32(crc32(doc["data"].dump()));
  if (expected != found)
    return corrupt(file.string() + ": checksum " + found + " does not match the stored " + expected);
  out.kind = LoadOutcome::Kind::loaded;
  out.data = std::move(doc["data"]);
  return out;
}

bool StateFile::save(const nlohmann::json& data, std::string& error) const {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) {
    error = "cannot create state directory " + dir_.string() + ": " + ec.message();
    return false;
  }
  nlohmann::json doc;
  doc["format"] = "trakbox-state";
  doc["version"] = kVersion;
  doc["checksum"] = hex32(crc32(data.dump()));
  doc["data"] = data;
  const std::string text = doc.dump(2) + "\n";

  const fs::path tmp = dir_ / (std::string(".") + kFileName + ".tmp-" + std::to_string(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = "cannot write " + tmp.string() + ": " + std::strerror(errno);
    return false;
  }
  const bool ok = write_all(fd, text) && ::fsync(fd) == 0;
  const int saved_errno = errno;
  ::close(fd);
  if (!ok) {
    ::unlink(tmp.c_str());
    error = "cannot write " + tmp.string() + ": " + std::strerror(saved_errno);
    return false;
  }
  if (::rename(tmp.c_str(), path().c_str()) != 0) {
    error = "cannot replace " + path().string() + ": " + std::strerror(errno);
    ::unlink(tmp.c_str());
    return false;
  }
  const int dfd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return true;
}

fs::path StateFile::keep_aside() const {
  std::error_code ec;
  if (!fs::exists(path(), ec)) return {};
  return store::keep_aside(path());
}

fs::path default_state_directory() {
  if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return fs::path(x) / "trakbox";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".local" / "state" / "trakbox";
  return fs::path("trakbox-state");
}

}  // namespace tb::store
