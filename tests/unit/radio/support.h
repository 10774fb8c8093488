// Test helpers for the radio tests: child processes (socat, rigctld), pseudo-terminal peers,
// free TCP ports, bounded waiting. POSIX only.
#pragma once
#include <doctest/doctest.h>
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "radio/cat.h"

extern char** environ;

namespace tbtest {

using namespace std::chrono_literals;
using Ms = std::chrono::milliseconds;

// The drivers log faults through spdlog; keep the test output clean.
inline const bool kQuietLogs = [] {
  spdlog::set_level(spdlog::level::off);
  return true;
}();

inline bool eventually(const std::function<bool()>& pred, Ms timeout = 5000ms) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(10ms);
  }
  return pred();
}

inline std::optional<std::string> which(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string p = path ? path : "/usr/bin:/bin";
  p += ":/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= p.size()) {
    std::size_t end = p.find(':', start);
    if (end == std::string::npos) end = p.size();
    std::string candidate = p.substr(start, end - start) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

// A child process; stderr optionally captured through a pipe. Killed (by its own pid) and
// reaped when destroyed.
class Child {
 public:
  Child(const std::vector<std::string>& argv, bool capture_stderr) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    int pipefd[2] = {-1, -1};
    if (capture_stderr && ::pipe(pipefd) == 0) {
      posix_spawn_file_actions_adddup2(&fa, pipefd[1], 2);
      posix_spawn_file_actions_addclose(&fa, pipefd[0]);
      posix_spawn_file_actions_addclose(&fa, pipefd[1]);
    } else {
      posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    }
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    if (::posix_spawnp(&pid_, args[0], &fa, nullptr, args.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&fa);
    if (pipefd[1] >= 0) ::close(pipefd[1]);
    err_fd_ = pipefd[0];
  }
  ~Child() { stop(); }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool started() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }

  // Reads stderr lines until pred(accumulated text) or the timeout.
  bool read_stderr_until(const std::function<bool(const std::string&)>& pred, Ms timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    char buf[512];
    while (!pred(err_text_)) {
      const auto left = std::chrono::duration_cast<Ms>(end - std::chrono::steady_clock::now());
      if (left <= 0ms || err_fd_ < 0) return false;
      pollfd p{err_fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) return false;
      const ssize_t n = ::read(err_fd_, buf, sizeof buf);
      if (n <= 0) return pred(err_text_);
      err_text_.append(buf, static_cast<std::size_t>(n));
    }
    return true;
  }
  const std::string& stderr_text() const { return err_text_; }

  void stop() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      int status = 0;
      for (int i = 0; i < 200; ++i) {
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
          pid_ = -1;
          break;
        }
        std::this_thread::sleep_for(10ms);
      }
      if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        pid_ = -1;
      }
    }
    if (err_fd_ >= 0) {
      ::close(err_fd_);
      err_fd_ = -1;
    }
  }

 private:
  pid_t pid_ = -1;
  int err_fd_ = -1;
  std::string err_text_;
};

// One end of a pty pair, opened raw and non-blocking.
class PtyEnd {
 public:
  explicit PtyEnd(const std::string& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ >= 0) {
      termios t{};
      if (::tcgetattr(fd_, &t) == 0) {
        ::cfmakeraw(&t);
        ::tcsetattr(fd_, TCSANOW, &t);
      }
    }
  }
  ~PtyEnd() {
    if (fd_ >= 0) ::close(fd_);
  }
  PtyEnd(const PtyEnd&) = delete;
  PtyEnd& operator=(const PtyEnd&) = delete;
  bool ok() const { return fd_ >= 0; }

  // Up to max bytes, waiting at most timeout for the first and then briefly for more.
  std::vector<std::uint8_t> read(std::size_t max, Ms timeout) {
    std::vector<std::uint8_t> out;
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (out.size() < max) {
      const auto left = std::chrono::duration_cast<Ms>(end - std::chrono::steady_clock::now());
      if (left <= 0ms) break;
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
      std::uint8_t buf[256];
      const ssize_t n = ::read(fd_, buf, std::min(sizeof buf, max - out.size()));
      if (n <= 0) break;
      out.insert(out.end(), buf, buf + n);
    }
    return out;
  }
  // Exactly n bytes, or fewer when the timeout passed.
  std::vector<std::uint8_t> read_exactly(std::size_t n, Ms timeout) { return read(n, timeout); }

  void write(const std::vector<std::uint8_t>& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else {
        pollfd p{fd_, POLLOUT, 0};
        if (::poll(&p, 1, 1000) <= 0) return;
      }
    }
  }

 private:
  int fd_ = -1;
};

// socat -d -d pty,raw,echo=0 pty,raw,echo=0: two linked ptys, announced on stderr. Each is also
// given a symlink in a private folder, which socat removes when it ends: a pty number the kernel
// hands to someone else afterwards can never be mistaken for our cable.
class PtyPair {
 public:
  PtyPair() {
    auto socat = which("socat");
    if (!socat) return;
    char tmpl[] = "/tmp/tb_radio_pty.XXXXXX";
    if (!::mkdtemp(tmpl)) return;
    dir_ = tmpl;
    const std::string a = dir_ + "/radio", b = dir_ + "/peer";
    child_.emplace(std::vector<std::string>{*socat, "-d", "-d", "pty,raw,echo=0,link=" + a,
                                            "pty,raw,echo=0,link=" + b},
                   true);
    if (!child_->started()) return;
    const bool ready = child_->read_stderr_until(
        [&](const std::string& text) {
          return text.find("starting data transfer loop") != std::string::npos;
        },
        5000ms);
    if (ready && ::access(a.c_str(), F_OK) == 0 && ::access(b.c_str(), F_OK) == 0) paths_ = {a, b};
  }
  ~PtyPair() {
    child_.reset();
    if (!dir_.empty()) {
      ::unlink((dir_ + "/radio").c_str());
      ::unlink((dir_ + "/peer").c_str());
      ::rmdir(dir_.c_str());
    }
  }
  PtyPair(const PtyPair&) = delete;
  PtyPair& operator=(const PtyPair&) = delete;
  bool ok() const { return paths_.size() >= 2; }
  const std::string& radio_side() const { return paths_.at(0); }   // the driver opens this
  const std::string& test_side() const { return paths_.at(1); }    // the "radio" reads here

 private:
  std::string dir_;
  std::optional<Child> child_;
  std::vector<std::string> paths_;
};

inline int free_tcp_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t len = sizeof a;
  int port = 0;
  if (::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
      ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &len) == 0)
    port = ntohs(a.sin_port);
  ::close(s);
  return port;
}

inline bool tcp_connectable(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(s);
  return ok;
}

// One line-oriented exchange with a TCP server: sends text, returns what arrives until the
// peer has said `lines` lines or the timeout.
inline std::string tcp_exchange_once(int port, const std::string& text, int lines, Ms timeout) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  std::string out;
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
      ::send(s, text.data(), text.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(text.size())) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::count(out.begin(), out.end(), '\n') < lines) {
      const auto left = std::chrono::duration_cast<Ms>(end - std::chrono::steady_clock::now());
      pollfd p{s, POLLIN, 0};
      if (left <= 0ms || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
      char buf[256];
      const ssize_t n = ::recv(s, buf, sizeof buf, 0);
      if (n <= 0) break;
      out.append(buf, static_cast<std::size_t>(n));
    }
  }
  ::close(s);
  return out;
}

// Sends `text` on a fresh connection and reads `lines` lines back. Hamlib 4.5's rigctld now and
// then resets a connection at once (about 1 in 150 in a quick loop, more under load): a reply that
// did not come at all is asked for again, up to three times.
inline std::string tcp_exchange(int port, const std::string& text, int lines, Ms timeout = 2000ms) {
  std::string out;
  for (int attempt = 0; attempt < 3 && out.empty(); ++attempt) {
    if (attempt) std::this_thread::sleep_for(50ms);
    out = tcp_exchange_once(port, text, lines, timeout);
  }
  return out;
}

// Runs a command, returns its standard output (the command's own exit status is ignored).
inline std::string run_capture(const std::string& command) {
  std::string out;
  if (FILE* f = ::popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, f)) out += buf;
    ::pclose(f);
  }
  return out;
}

// socat makes the pty pairs the serial tests run on; without it they are skipped with a message.
inline bool have_socat() {
  if (which("socat")) return true;
  MESSAGE("socat not installed: serial CAT pty tests skipped");
  return false;
}

// The radio's side of a CI-V line: reads the pty until stop, cuts what comes into frames (a lone
// jam code too) and hands each to on_frame, on the calling thread (a responder's own thread).
template <typename OnFrame>
void read_civ_frames(PtyEnd& end, const std::atomic<bool>& stop, OnFrame on_frame) {
  tb::radio::icom::FrameReader reader;
  while (!stop) {
    auto bytes = end.read(256, 20ms);
    if (bytes.empty()) continue;
    reader.feed(bytes);
    while (auto f = reader.next()) on_frame(*f);
  }
}

}  // namespace tbtest
