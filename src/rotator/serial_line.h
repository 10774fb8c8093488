// A rotator's serial line (8N1, raw, no flow control) for the native text protocols (Easycomm),
// used from a WorkerRotator's thread: every read and write has a timeout; a port that hangs up (a
// USB adapter unplugged, a pty whose other end closed) is an error, not a silence.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

namespace tb::rotator {

class SerialLine {
 public:
  SerialLine() = default;
  ~SerialLine() { close(); }
  SerialLine(const SerialLine&) = delete;
  SerialLine& operator=(const SerialLine&) = delete;

  bool open(const std::string& device, int baud, std::string& error);
  void close() noexcept;
  bool is_open() const { return fd_ >= 0; }
  bool write(std::string_view bytes, std::chrono::milliseconds timeout, std::string& error);
  // The next line ("\n" ends it; "\r" taken off), or nullopt: `error` empty when nothing came in
  // time, set when the port failed.
  std::optional<std::string> read_line(std::chrono::milliseconds timeout, std::string& error);
  // Drops what waits in the input (a late answer to the command before).
  void discard_input() noexcept;

 private:
  int fd_ = -1;
  std::string inbuf_;
};

}  // namespace tb::rotator
