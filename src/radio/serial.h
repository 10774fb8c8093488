// A serial port for the CAT links: Boost.Asio serial_port on a private io_context, driven from the
// link's worker thread with a timeout on every read and write. Failures throw LinkError.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "radio/worker.h"

namespace tb::radio {

struct SerialSettings {
  unsigned baud = 4800;
  unsigned data_bits = 8;
  enum class Parity { none, even, odd } parity = Parity::none;
  unsigned stop_bits = 2;          // 1 or 2
  bool rts_cts = false;            // hardware flow control
};

// The manual's fixed CAT port settings.
inline SerialSettings icom_serial() { return {1200, 8, SerialSettings::Parity::none, 2, false}; }
inline SerialSettings kenwood_serial() { return {4800, 8, SerialSettings::Parity::none, 2, false}; }
inline SerialSettings yaesu_serial() { return {4800, 8, SerialSettings::Parity::none, 2, false}; }

class SerialPort {
 public:
  SerialPort(std::string device, SerialSettings settings);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  const std::string& device() const { return device_; }
  const SerialSettings& settings() const { return settings_; }

  void open();                  // LinkError(reconnect) "cannot open /dev/x: ..."
  void close() noexcept;
  bool is_open() const;

  // All bytes or LinkError(reconnect) on an error or when the timeout passes.
  void write(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout);
  void write(std::string_view text, std::chrono::milliseconds timeout);
  // Whatever arrives within the timeout (at least one byte), or 0 bytes when nothing came.
  std::size_t read_some(std::span<std::uint8_t> out, std::chrono::milliseconds timeout);
  // Drops whatever is waiting in the input buffer.
  void discard_input() noexcept;
  // LinkError(reconnect) when the port is gone: hung up (a USB adapter unplugged, a pty whose other
  // end closed), or its device node removed or replaced by another device. Never blocks.
  void check() const;

  // How long n bytes take on the wire at these settings.
  std::chrono::milliseconds wire_time(std::size_t n) const;

 private:
  struct Impl;
  std::string device_;
  SerialSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::radio
