// A plain loopback TCP client with bounded waits, for the server tests.
#pragma once
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <functional>
#include <string>

namespace nettest {

using namespace std::chrono_literals;

// A plain loopback TCP client with bounded waits.
class RawClient {
 public:
  explicit RawClient(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(port);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
      ::close(fd_);
      fd_ = -1;
    }
    if (fd_ >= 0) ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
  }
  ~RawClient() { close(); }
  bool ok() const { return fd_ >= 0; }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  void set_receive_buffer(int bytes) { ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof bytes); }
  // Sends what the socket takes now; the count sent, -1 when the connection is gone.
  long send_some(const std::string& s) {
    const ssize_t n = ::send(fd_, s.data(), s.size(), MSG_NOSIGNAL);
    if (n < 0) return (errno == EAGAIN || errno == EWOULDBLOCK) ? 0 : -1;
    return n;
  }
  bool send_all(const std::string& s, std::chrono::milliseconds limit = 5s) {
    const auto end = std::chrono::steady_clock::now() + limit;
    std::size_t done = 0;
    while (done < s.size()) {
      const long n = send_some(s.substr(done));
      if (n < 0) return false;
      done += static_cast<std::size_t>(n);
      if (done < s.size()) {
        if (std::chrono::steady_clock::now() > end) return false;
        pollfd p{fd_, POLLOUT, 0};
        ::poll(&p, 1, 20);
      }
    }
    return true;
  }
  void shutdown_write() { ::shutdown(fd_, SHUT_WR); }
  // Reads until `pred(received)` holds, the peer closes, or the limit passes.
  bool read_until(const std::function<bool(const std::string&)>& pred, std::chrono::milliseconds limit = 5s) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!pred(in_)) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0 || eof_) return pred(in_);
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 50))) <= 0) continue;
      char buf[8192];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)) eof_ = true;
      if (n > 0) in_.append(buf, static_cast<std::size_t>(n));
    }
    return true;
  }
  // One request, the reply up to the line that ends it.
  std::string ask(const std::string& line, std::size_t reply_lines = 1) {
    in_.clear();
    if (!send_all(line + "\n")) return "<send failed>";
    read_until([&](const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')) >= reply_lines; });
    std::string r;
    r.swap(in_);
    return r;
  }
  // Sends bytes as they are; the reply up to (and with) the first `end` after them.
  std::string exchange(const std::string& bytes, const std::string& end) {
    in_.clear();
    if (!send_all(bytes)) return "<send failed>";
    read_until([&](const std::string& s) { return s.find(end) != std::string::npos; });
    std::string r;
    r.swap(in_);
    return r;
  }
  bool closed_by_peer(std::chrono::milliseconds limit = 5s) {
    read_until([](const std::string&) { return false; }, limit);
    return eof_;
  }
  const std::string& received() const { return in_; }

 private:
  int fd_ = -1;
  std::string in_;
  bool eof_ = false;
};

}  // namespace nettest
