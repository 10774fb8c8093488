#include "rotator/serial_line.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tb::rotator {

namespace {

using Clock = std::chrono::steady_clock;

speed_t speed_of(int baud) {
  switch (baud) {
    case 1200: return B1200;
    case 2400: return B2400;
    case 4800: return B4800;
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    default: return B0;
  }
}

int left_ms(Clock::time_point until) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

}  // namespace

bool SerialLine::open(const std::string& device, int baud, std::string& error) {
  close();
  const speed_t speed = speed_of(baud);
  if (speed == B0) {
    error = std::to_string(baud) + " baud is not a speed this line takes (1200..115200)";
    return false;
  }
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error = "cannot open " + device + ": " + std::strerror(errno);
    return false;
  }
  termios t{};
  if (::tcgetattr(fd, &t) != 0) {
    error = device + " is not a serial port: " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  ::cfmakeraw(&t);
  t.c_cflag &= ~(CSTOPB | CRTSCTS | PARENB);
  t.c_cflag |= CLOCAL | CREAD | CS8;
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  if (::tcsetattr(fd, TCSANOW, &t) != 0) {
    error = "cannot set " + device + " to " + std::to_string(baud) + " 8N1: " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  ::tcflush(fd, TCIOFLUSH);
  fd_ = fd;
  inbuf_.clear();
  return true;
}

void SerialLine::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  inbuf_.clear();
}

bool SerialLine::write(std::string_view bytes, std::chrono::milliseconds timeout, std::string& error) {
  const auto until = Clock::now() + timeout;
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n > 0) {
      bytes.remove_prefix(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      error = std::string("cannot write: ") + std::strerror(errno);
      return false;
    }
    pollfd p{fd_, POLLOUT, 0};
    if (::poll(&p, 1, left_ms(until)) <= 0) {
      error = "cannot write: timed out";
      return false;
    }
  }
  return true;
}

std::optional<std::string> SerialLine::read_line(std::chrono::milliseconds timeout, std::string& error) {
  const auto until = Clock::now() + timeout;
  while (true) {
    if (const auto nl = inbuf_.find('\n'); nl != std::string::npos) {
      std::string line = inbuf_.substr(0, nl);
      inbuf_.erase(0, nl + 1);
      while (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (inbuf_.size() > 4096) inbuf_.clear();   // a line that never ends is noise
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, left_ms(until));
    if (r == 0) return std::nullopt;
    if (r < 0 && errno == EINTR) continue;
    if (r < 0 || (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) {
      error = "the port hung up";
      return std::nullopt;
    }
    char buf[256];
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n > 0) inbuf_.append(buf, static_cast<std::size_t>(n));
    else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
      error = "the port hung up";
      return std::nullopt;
    }
  }
}

void SerialLine::discard_input() noexcept {
  inbuf_.clear();
  if (fd_ >= 0) ::tcflush(fd_, TCIFLUSH);
}

}  // namespace tb::rotator
