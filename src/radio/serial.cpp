#include "radio/serial.h"

#include <poll.h>
#include <sys/stat.h>
#include <termios.h>

#include <cerrno>
#include <system_error>

#include <boost/asio/io_context.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/serial_port.hpp>
#include <boost/asio/write.hpp>

namespace tb::radio {

namespace asio = boost::asio;
using Action = LinkError::Action;

struct SerialPort::Impl {
  asio::io_context io;
  asio::serial_port port{io};

  // Runs the io_context until the operation finished or the timeout; cancels it then.
  // Returns false on timeout.
  bool run_for(std::chrono::milliseconds timeout, const bool& done) {
    io.restart();
    io.run_for(timeout);
    if (done) return true;
    boost::system::error_code ignored;
    port.cancel(ignored);
    io.restart();
    io.run();   // lets the cancelled handler run
    return done;
  }
};

SerialPort::SerialPort(std::string device, SerialSettings settings)
    : device_(std::move(device)), settings_(settings), impl_(std::make_unique<Impl>()) {}

SerialPort::~SerialPort() { close(); }

bool SerialPort::is_open() const { return impl_->port.is_open(); }

void SerialPort::open() {
  close();
  boost::system::error_code ec;
  impl_->port.open(device_, ec);
  if (ec) throw LinkError(Action::reconnect, "cannot open " + device_ + ": " + ec.message());
  using P = asio::serial_port_base;
  auto& p = impl_->port;
  const auto parity = settings_.parity == SerialSettings::Parity::none ? P::parity::none
                      : settings_.parity == SerialSettings::Parity::even ? P::parity::even
                                                                         : P::parity::odd;
  p.set_option(P::baud_rate(settings_.baud), ec);
  if (!ec) p.set_option(P::character_size(settings_.data_bits), ec);
  if (!ec) p.set_option(P::parity(parity), ec);
  if (!ec) p.set_option(P::stop_bits(settings_.stop_bits == 2 ? P::stop_bits::two : P::stop_bits::one), ec);
  if (!ec) p.set_option(P::flow_control(settings_.rts_cts ? P::flow_control::hardware
                                                            : P::flow_control::none), ec);
  if (ec) {
    close();
    throw LinkError(Action::reconnect, "cannot configure " + device_ + ": " + ec.message());
  }
  discard_input();
}

void SerialPort::close() noexcept {
  boost::system::error_code ignored;
  if (impl_->port.is_open()) impl_->port.close(ignored);
}

void SerialPort::write(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout) {
  if (!is_open()) throw LinkError(Action::reconnect, device_ + " is not open");
  bool done = false;
  boost::system::error_code ec;
  asio::async_write(impl_->port, asio::buffer(bytes.data(), bytes.size()),
                    [&](const boost::system::error_code& e, std::size_t) {
                      ec = e;
                      done = true;
                    });
  if (!impl_->run_for(timeout, done) || ec == asio::error::operation_aborted)
    throw LinkError(Action::reconnect, "write to " + device_ + " timed out");
  if (ec) throw LinkError(Action::reconnect, "write to " + device_ + " failed: " + ec.message());
}

void SerialPort::write(std::string_view text, std::chrono::milliseconds timeout) {
  write(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
        timeout);
}

std::size_t SerialPort::read_some(std::span<std::uint8_t> out, std::chrono::milliseconds timeout) {
  if (!is_open()) throw LinkError(Action::reconnect, device_ + " is not open");
  bool done = false;
  boost::system::error_code ec;
  std::size_t n = 0;
  impl_->port.async_read_some(asio::buffer(out.data(), out.size()),
                              [&](const boost::system::error_code& e, std::size_t got) {
                                ec = e;
                                n = got;
                                done = true;
                              });
  if (!impl_->run_for(timeout, done) || ec == asio::error::operation_aborted) return 0;
  if (ec) throw LinkError(Action::reconnect, "read from " + device_ + " failed: " + ec.message());
  return n;
}

void SerialPort::discard_input() noexcept {
  if (is_open()) ::tcflush(impl_->port.native_handle(), TCIFLUSH);
}

void SerialPort::check() const {
  if (!is_open()) throw LinkError(Action::reconnect, device_ + " is not open");
  const int fd = impl_->port.native_handle();
  pollfd p{fd, 0, 0};  // no events asked: POLLHUP, POLLERR and POLLNVAL are reported anyway
  if (::poll(&p, 1, 0) > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0)
    throw LinkError(Action::reconnect, device_ + " went away (the port hung up)");
  struct stat opened {}, named {};
  if (::fstat(fd, &opened) != 0) return;
  if (::stat(device_.c_str(), &named) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw LinkError(Action::reconnect, device_ + " went away (" + std::generic_category().message(errno) + ")");
    return;
  }
  if (S_ISCHR(opened.st_mode) && named.st_rdev != opened.st_rdev)
    throw LinkError(Action::reconnect, device_ + " went away (now another device)");
}

std::chrono::milliseconds SerialPort::wire_time(std::size_t n) const {
  const unsigned bits = 1 + settings_.data_bits + (settings_.parity == SerialSettings::Parity::none ? 0 : 1) +
                        settings_.stop_bits;
  const auto ms = (n * bits * 1000 + settings_.baud - 1) / settings_.baud;
  return std::chrono::milliseconds(ms);
}

}  // namespace tb::radio
