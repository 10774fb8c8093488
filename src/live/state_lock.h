// One running trakbox per state directory: an exclusive lock (flock) on STATE_DIR/trakbox.lock,
// held for the life of the process. The lock file names the holder's pid and its control socket,
// so a second trakbox on the same state can say who holds it and attach to it instead of saving
// over it (docs/service.md).
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace tb::app {

struct LockHolder {
  long pid = 0;        // 0 when the file did not say
  std::string socket;  // the holder's control socket ("" when the file did not say)
};

class StateLock {
 public:
  // Takes the lock; on failure `holder` says who has it, or `error` why the file could not be used.
  static std::optional<StateLock> take(const std::filesystem::path& state_dir, LockHolder& holder, std::string& error);
  StateLock(StateLock&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  StateLock& operator=(StateLock&&) = delete;
  StateLock(const StateLock&) = delete;
  ~StateLock();
  // Records the control socket of this process in the lock file (for a second trakbox to read).
  void announce(const std::string& socket_path);

 private:
  explicit StateLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

// What a lock file says ("pid N\nsocket PATH\n").
LockHolder parse_lock_file(const std::string& text);

}  // namespace tb::app
