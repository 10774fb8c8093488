// The attach socket's connections' output (attach_server.cpp's, internal): a bounded queue written
// asynchronously.
#pragma once
#include <poll.h>
#include <sys/types.h>
#include <sys/socket.h>
#include <unistd.h>

#include <boost/asio/local/stream_protocol.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/write.hpp>
#include <cerrno>
#include <chrono>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace tb::app {

namespace asio = boost::asio;

// A connection's output: a bounded queue written asynchronously. Over the bound the connection is
// closed: the station never waits for a reader.
struct Outbox : std::enable_shared_from_this<Outbox> {
  // Any stream: a client's socket, or the serial port of --tty.
  Outbox(asio::posix::stream_descriptor s, std::size_t limit) : sock(std::move(s)), limit(limit) {}
  asio::posix::stream_descriptor sock;
  std::size_t limit;
  std::string pending, inflight;
  bool writing = false, closed = false, overflowed = false, close_when_sent = false;

  bool send(std::string_view data) {
    if (closed) return false;
    if (pending.size() + inflight.size() + data.size() > limit) {
      overflowed = true;
      close();
      return false;
    }
    pending.append(data);
    kick();
    return true;
  }
  void kick() {
    if (writing || closed) return;
    if (pending.empty()) {
      if (close_when_sent) close();
      return;
    }
    inflight.swap(pending);
    pending.clear();
    writing = true;
    asio::async_write(sock, asio::buffer(inflight), [self = shared_from_this()](const boost::system::error_code& ec, std::size_t) {
      self->writing = false;
      self->inflight.clear();
      if (ec) self->close();
      else self->kick();
    });
  }
  void finish() {
    close_when_sent = true;
    kick();
  }
  // The station is stopping and its loop will not run again: what is queued is written now,
  // waiting at most `within` for a slow reader, then the connection is closed. A write under way
  // was tried at once when it started (asio writes speculatively), so what is queued follows it.
  void flush_now(std::chrono::milliseconds within) {
    const auto deadline = std::chrono::steady_clock::now() + within;
    std::size_t done = 0;
    while (!closed && done < pending.size()) {
      const ssize_t n = ::send(sock.native_handle(), pending.data() + done, pending.size() - done,
                               MSG_DONTWAIT | MSG_NOSIGNAL);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
        continue;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (n < 0 && errno == ENOTSOCK) {   // the serial port of --tty
        if (::write(sock.native_handle(), pending.data() + done, pending.size() - done) <= 0) break;
        continue;
      }
      if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) break;
      pollfd p{sock.native_handle(), POLLOUT, 0};
      if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    }
    pending.clear();
    close();
  }
  void close() {
    if (closed) return;
    closed = true;
    boost::system::error_code ec;
    ::shutdown(sock.native_handle(), SHUT_RDWR);  // (a serial port says ENOTSOCK: nothing to do)
    sock.close(ec);
  }
};

// The socket file: what bind_socket made (device, inode), so that only it is ever removed.
using SocketId = std::pair<dev_t, ino_t>;
// Binds and listens at `path` (the acceptor closed): a stale socket no process answers on is
// replaced; anything else there (a file, a folder, a link, a live station) is refused with a
// std::runtime_error naming the path and what is there, and left untouched.
SocketId bind_socket(boost::asio::local::stream_protocol::acceptor& acceptor, const std::string& path);
// Removes the socket at `path` if it is still the one made.
void remove_socket(const std::string& path, SocketId made);

}  // namespace tb::app
