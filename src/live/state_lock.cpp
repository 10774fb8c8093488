#include "live/state_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "util/text.h"

namespace tb::app {

LockHolder parse_lock_file(const std::string& text) {
  LockHolder h;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("pid ", 0) == 0) {
      if (const auto v = text::parse_integer<long>(std::string_view(line).substr(4))) h.pid = *v;
    } else if (line.rfind("socket ", 0) == 0) {
      h.socket = line.substr(7);
    }
  }
  return h;
}

std::optional<StateLock> StateLock::take(const std::filesystem::path& state_dir, LockHolder& holder,
                                         std::string& error) {
  const std::string path = (state_dir / "trakbox.lock").string();
  // Never through a link (issue 38): a link in the state directory would have its target truncated
  // and written. O_NOFOLLOW refuses a link with ELOOP; anything but a regular file is refused too.
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0600);
  if (fd < 0) {
    const int e = errno;
    error = e == ELOOP ? path + ": is a symbolic link; trakbox does not follow links in its state directory "
                                "(remove the link)"
                       : path + ": cannot open: " + std::strerror(e);
    return std::nullopt;
  }
  struct stat st{};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error = path + ": is not a regular file; remove it";
    ::close(fd);
    return std::nullopt;
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    if (e == EWOULDBLOCK) {
      std::string text(512, '\0');
      const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
      text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
      holder = parse_lock_file(text);
    } else {
      error = path + ": cannot lock: " + std::strerror(e);
    }
    ::close(fd);
    return std::nullopt;
  }
  StateLock lock(fd);
  lock.announce("");
  return lock;
}

void StateLock::announce(const std::string& socket_path) {
  if (fd_ < 0) return;
  std::string text = "pid " + std::to_string(::getpid()) + "\n";
  if (!socket_path.empty()) text += "socket " + socket_path + "\n";
  if (::ftruncate(fd_, 0) != 0) return;
  [[maybe_unused]] const ssize_t n = ::pwrite(fd_, text.data(), text.size(), 0);
}

StateLock::~StateLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace tb::app
