#include "menus/term/line_terminal.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace tb::term {

bool valid_terminal_baud(int baud) {
  return baud == 1200 || baud == 2400 || baud == 4800 || baud == 9600 || baud == 19200;
}

namespace {
speed_t to_speed(int baud) {
  switch (baud) {
    case 1200: return B1200;
    case 2400: return B2400;
    case 4800: return B4800;
    case 19200: return B19200;
    default: return B9600;
  }
}
}  // namespace

LineTerminal::LineTerminal(int in_fd, int out_fd, WaitReadable wait, bool crlf, bool owns_fds)
    : LineOutput(crlf), in_(in_fd), out_(out_fd), wait_(std::move(wait)), owns_(owns_fds) {}

LineTerminal::~LineTerminal() {
  flush();
  if (owns_) {
    ::close(in_);
    if (out_ != in_) ::close(out_);
  }
}

int LineTerminal::open_serial_fd(const std::string& device, int baud, std::string& error) {
  if (!valid_terminal_baud(baud)) {
    error = "--baud " + std::to_string(baud) + ": expected 1200, 2400, 4800, 9600 or 19200";
    return -1;
  }
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    error = "--tty " + device + ": cannot open: " + std::strerror(errno);
    return -1;
  }
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    error = "--tty " + device + ": not a serial line: " + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CSIZE | CRTSCTS);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;  // 8N1, no modem control
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, to_speed(baud));
  ::cfsetospeed(&tio, to_speed(baud));
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    error = "--tty " + device + ": cannot set " + std::to_string(baud) + " 8N1: " + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  return fd;
}

std::unique_ptr<LineTerminal> LineTerminal::open_serial(const std::string& device, int baud, WaitReadable wait,
                                                        std::string& error) {
  const int fd = open_serial_fd(device, baud, error);
  if (fd < 0) return nullptr;
  return std::make_unique<LineTerminal>(fd, fd, std::move(wait), true, true);
}

void LineTerminal::emit(std::string_view bytes) {
  out_buf_.append(bytes);
  if (out_buf_.size() > 4096) flush();
}

void LineTerminal::flush() {
  std::size_t done = 0;
  while (done < out_buf_.size() && !write_failed_) {
    const ssize_t n = ::write(out_, out_buf_.data() + done, out_buf_.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && errno == EAGAIN) {
      if (wait_) wait_(-1, std::chrono::milliseconds(5));
    } else {
      write_failed_ = true;  // the other side went away: behave as closed input
      closed_ = true;
    }
  }
  out_buf_.clear();
}

int LineTerminal::next_key(std::optional<Duration> timeout) {
  flush();
  if (closed_) return kEndOfInput;
  if (in_pos_ < in_len_) return in_buf_[in_pos_++];
  const auto deadline = timeout ? std::optional(std::chrono::steady_clock::now() + *timeout) : std::nullopt;
  for (;;) {
    std::optional<Duration> left;
    if (deadline) {
      const auto now = std::chrono::steady_clock::now();
      if (now >= *deadline) left = Duration::zero();
      else left = *deadline - now;
    }
    const bool ready = wait_ ? wait_(in_, left) : true;
    if (!ready) {
      if (deadline && std::chrono::steady_clock::now() >= *deadline) return kTimeout;
      continue;
    }
    const ssize_t n = ::read(in_, in_buf_, sizeof in_buf_);
    if (n > 0) {
      in_len_ = static_cast<std::size_t>(n);
      in_pos_ = 0;
      return in_buf_[in_pos_++];
    }
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    closed_ = true;
    return kEndOfInput;
  }
}

}  // namespace tb::term
