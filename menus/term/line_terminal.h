// Plain lines for a serial line (a dumb terminal or a terminal program) or a pipe: no escape codes,
// typed characters echoed back, live displays printed as one line per update.
#pragma once
#include <memory>
#include <string>

#include "menus/term/terminal.h"

namespace tb::term {

class LineTerminal final : public Terminal {
 public:
  // in_fd/out_fd are not closed by the terminal unless owns_fds. crlf: send "\r\n" for '\n'
  // (what a serial terminal expects); a pipe gets plain "\n".
  LineTerminal(int in_fd, int out_fd, WaitReadable wait, bool crlf, bool owns_fds = false);
  ~LineTerminal() override;

  // Opens a serial device at 8N1 and the given rate (1200 to 19200). On failure returns null and
  // sets error to a one-line reason naming the device.
  static std::unique_ptr<LineTerminal> open_serial(const std::string& device, int baud, WaitReadable wait,
                                                   std::string& error);
  // The same port opened and set up, as a descriptor (the service's --tty); -1 with the error.
  static int open_serial_fd(const std::string& device, int baud, std::string& error);

  void write(std::string_view text) override;
  void bell() override;
  void clear() override;
  void flush() override;
  void live(const std::vector<std::string>& lines) override;
  void end_live() override;
  void status(std::string_view) override {}
  void graphics(const Graphics&) override {}
  bool full_screen() const override { return false; }
  int columns() const override { return 80; }
  int rows() const override { return 24; }
  bool closed() const override { return closed_; }

 protected:
  int next_key(std::optional<Duration> timeout) override;

 private:
  int in_;
  int out_;
  WaitReadable wait_;
  bool crlf_;
  bool owns_;
  bool closed_ = false;
  bool write_failed_ = false;
  std::string out_buf_;
  unsigned char in_buf_[256];
  std::size_t in_pos_ = 0, in_len_ = 0;
};

// Speeds the serial front end accepts (8N1).
bool valid_terminal_baud(int baud);

}  // namespace tb::term
