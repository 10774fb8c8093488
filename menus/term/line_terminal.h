// Plain lines for a serial line (a dumb terminal or a terminal program) or a pipe: no escape codes,
// typed characters echoed back, live displays printed as one line per update.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "menus/term/terminal.h"

namespace tb::term {

// The line front end's output rules, whatever carries the bytes: '\n' sent as "\r\n" when crlf (what
// a serial terminal expects), the bell as BEL, a new screen as a new line, a live block printed as
// its lines once per update, no status line and no pictures, 80 x 24. LineTerminal sends them to a
// descriptor; an attached client's line mode (live/attach_server.cpp) to its socket.
class LineOutput : public Terminal {
 public:
  explicit LineOutput(bool crlf) : crlf_(crlf) {}

  void write(std::string_view text) final {
    std::string converted;
    converted.reserve(text.size());
    for (char c : text) {
      if (c == '\n' && crlf_) converted.push_back('\r');
      converted.push_back(c);
    }
    emit(converted);
  }
  void bell() final { write("\a"); }
  void clear() final {
    write("\n");
    flush();
  }
  void live(const std::vector<std::string>& lines) final {
    for (const auto& l : lines) {
      write(l);
      write("\n");
    }
    flush();
  }
  void end_live() final { flush(); }
  void status(std::string_view) final {}
  void graphics(const Graphics&) final {}
  bool full_screen() const final { return false; }
  int columns() const final { return 80; }
  int rows() const final { return 24; }

 protected:
  // Where the converted bytes go (flush() sends what is held back).
  virtual void emit(std::string_view bytes) = 0;

 private:
  bool crlf_;
};

class LineTerminal final : public LineOutput {
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

  void flush() override;
  bool closed() const override { return closed_; }

 protected:
  int next_key(std::optional<Duration> timeout) override;
  void emit(std::string_view bytes) override;

 private:
  int in_;
  int out_;
  WaitReadable wait_;
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
