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
#include <csignal>
#include <sys/stat.h>
#include <unistd.h>

#include "util/format.h"
#include "util/json_limits.h"

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

std::string hex32(std::uint32_t v) { return text::printf_string("%08x", v); }

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

bool write_file_atomically(const fs::path& target, std::string_view text, std::string& error, unsigned mode) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const fs::path tmp = dir / ("." + target.filename().string() + kTempInfix + std::to_string(::getpid()));
  // Made new (O_EXCL), never through a link (issue 38): a link planted under the temporary name
  // would have had its target truncated and written. One left there (a crash, or planted) is
  // removed -- the name itself, never what it points to -- and the file made again.
  constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  int fd = ::open(tmp.c_str(), kFlags, static_cast<mode_t>(mode));
  if (fd < 0 && errno == EEXIST && ::unlink(tmp.c_str()) == 0) fd = ::open(tmp.c_str(), kFlags, static_cast<mode_t>(mode));
  if (fd < 0) {
    error = "cannot write " + tmp.string() + ": " + std::strerror(errno);
    return false;
  }
  // The mode of open() is filtered by the umask; the file gets exactly `mode`.
  const bool ok = ::fchmod(fd, static_cast<mode_t>(mode)) == 0 && write_all(fd, text) && ::fsync(fd) == 0;
  const int saved_errno = errno;
  ::close(fd);
  if (!ok) {
    ::unlink(tmp.c_str());
    error = "cannot write " + tmp.string() + ": " + std::strerror(saved_errno);
    return false;
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    error = "cannot replace " + target.string() + ": " + std::strerror(errno);
    ::unlink(tmp.c_str());
    return false;
  }
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return true;
}

std::vector<fs::path> remove_stale_temporaries(const fs::path& dir) {
  std::vector<fs::path> removed;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const auto at = name.rfind(kTempInfix);
    if (name.empty() || name.front() != '.' || at == std::string::npos) continue;
    const std::string pid_text = name.substr(at + std::string_view(kTempInfix).size());
    char* end_ptr = nullptr;
    const long pid = std::strtol(pid_text.c_str(), &end_ptr, 10);
    if (pid_text.empty() || *end_ptr != '\0' || pid <= 0) continue;
    // Another live process may be writing it; ours (this pid) cannot be: we have not saved yet.
    const bool alive = pid != ::getpid() && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    if (alive) continue;
    std::error_code rm;
    if (fs::remove(it->path(), rm)) removed.push_back(it->path());
  }
  return removed;
}

StateFile::StateFile(fs::path directory) : dir_(std::move(directory)) {}

LoadOutcome StateFile::load(bool read_only) const {
  LoadOutcome out;
  const fs::path file = path();
  auto corrupt = [&](std::string reason) {
    out.kind = LoadOutcome::Kind::corrupt;
    out.reason = std::move(reason);
    if (!read_only) out.kept_aside = store::keep_aside(file);
    out.data = nlohmann::json();
    return out;
  };
  // Opened without following a symbolic link: the state is a file of this directory, never
  // whatever a link points at (a link is kept aside like a corrupt file, its target untouched).
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) {
      out.kind = LoadOutcome::Kind::fresh;
      return out;
    }
    if (errno == ELOOP) return corrupt(file.string() + ": a symbolic link, not a file; not followed");
    return corrupt(file.string() + ": cannot open: " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return corrupt(file.string() + ": not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > kMaxBytes) {
    ::close(fd);
    return corrupt(file.string() + ": " + std::to_string(st.st_size) + " bytes, more than a state document may have (" +
                   std::to_string(kMaxBytes) + ")");
  }
  std::string text;
  text.resize(static_cast<std::size_t>(st.st_size));
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  text.resize(got);

  // Copying, comparing and dump() recurse once per level of nesting: a document nested deeper than
  // any trakbox writes is refused before it is parsed.
  std::string why;
  nlohmann::json doc = json_limits::parse_bounded<nlohmann::json>(text, why);
  if (why.starts_with("nested"))
    return corrupt(file.string() + ": nested more than " + std::to_string(json_limits::kMaxDepth) +
                   " levels deep, which no trakbox state document is");

  // Every member is checked for its type before it is read: a document of the wrong shape (say
  // {"format":{}}) is a corrupt file like any other, never an exception.
  if (doc.is_discarded() || !doc.is_object()) return corrupt(file.string() + ": not a JSON document");
  const auto format = doc.find("format");
  if (format == doc.end() || !format->is_string() || *format != "trakbox-state")
    return corrupt(file.string() + ": not a trakbox state file");
  const auto checksum = doc.find("checksum");
  const auto data = doc.find("data");
  if (data == doc.end() || checksum == doc.end() || !checksum->is_string())
    return corrupt(file.string() + ": data or checksum missing");
  if (!data->is_object()) return corrupt(file.string() + ": data is not an object");
  const std::string expected = checksum->get<std::string>();
  const std::string found = hex32(crc32(data->dump()));
  if (expected != found)
    return corrupt(file.string() + ": checksum " + found + " does not match the stored " + expected);
  out.kind = LoadOutcome::Kind::loaded;
  out.data = std::move(*data);
  return out;
}

bool StateFile::save(const nlohmann::json& data, std::string& error) const {
  std::error_code ec;
  if (!fs::exists(dir_, ec)) {
    fs::create_directories(dir_, ec);
    if (ec) {
      error = "cannot create state directory " + dir_.string() + ": " + ec.message();
      return false;
    }
    fs::permissions(dir_, fs::perms::owner_all, ec);  // 0700: it holds credentials
  }
  // Text from outside is made printable UTF-8 where it enters (util/safe_text.h); should any string
  // still not be UTF-8, it is written with U+FFFD for its bad bytes rather than the save throwing
  // (issue 38: one byte in an element file aborted every start). The checksum is of what is written.
  constexpr auto kReplace = nlohmann::json::error_handler_t::replace;
  const nlohmann::json clean = nlohmann::json::parse(data.dump(-1, ' ', false, kReplace));
  nlohmann::json doc;
  doc["format"] = "trakbox-state";
  doc["version"] = kVersion;
  doc["checksum"] = hex32(crc32(clean.dump()));
  doc["data"] = clean;
  return write_file_atomically(path(), doc.dump(2) + "\n", error, 0600);
}

std::vector<std::string> StateFile::tighten_permissions() const {
  std::vector<std::string> notes;
  std::error_code ec;
  const auto tighten = [&](const fs::path& p, fs::perms wanted) {
    // Never through a symbolic link: chmod would change the link's target. A linked state file is
    // kept aside by load(); a linked directory is the operator's choice, reported and left alone.
    const fs::file_status st = fs::symlink_status(p, ec);
    if (ec || !fs::exists(st)) return;
    if (fs::is_symlink(st)) {
      notes.push_back(p.string() + " is a symbolic link: its permissions were not checked or changed");
      return;
    }
    const fs::perms now = st.permissions() & fs::perms::all;
    if ((now & ~wanted) == fs::perms::none) return;
    fs::permissions(p, now & wanted, ec);
    char buf[96];
    std::snprintf(buf, sizeof buf, " was readable by others (mode %03o): now %03o",
                  static_cast<unsigned>(now), static_cast<unsigned>(now & wanted));
    notes.push_back(p.string() + buf + (ec ? " failed: " + ec.message() : std::string()));
  };
  tighten(dir_, fs::perms::owner_all);
  tighten(path(), fs::perms::owner_read | fs::perms::owner_write);
  return notes;
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
