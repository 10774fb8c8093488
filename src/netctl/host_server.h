// TrakBox host mode (menu 7) on TCP: each client gets the banner, the command line and the
// "TrakBox>>" prompt, then a prompt after every reply, exactly as on the terminal; Q closes the
// connection. The commands are src/host/host_mode.h, the same interpreter as menu 7 and
// `trakbox host`, acting on the same station.
//
//   netctl::HostServer host(io, 4535, station);   // trakbox --host-port 4535
//
// Lines end in CR, LF or CR LF (a terminal program sends CR); replies end in CR LF. A line longer
// than kMaxHostLine is refused with one ERROR line and discarded; bounds and slow clients are the
// LineServer's (server.h).
#pragma once
#include <cstdint>
#include <string>

#include "netctl/server.h"

namespace tb::netctl {

inline constexpr std::size_t kMaxHostLine = 256;  // as menu 7 reads on the terminal

class HostProtocol final : public LineHandler {
 public:
  explicit HostProtocol(tracker::StationLoop& station);
  ~HostProtocol() override;
  Reply handle(std::string_view line) override;
  Reply overlong() const override;
  std::string greeting() const override;
  std::string refusal(Refusal why) const override;  // "ERROR busy: ...", "ERROR not allowed: ..."
  // With a secret (--host-secret-file): "PASS SECRET" first; before it only Q works.
  Gate gate(std::string_view line) const override;
  std::string auth_reply(bool ok) const override;
  std::string auth_required() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class HostServer {
 public:
  HostServer(boost::asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
             ServerOptions options = defaults());
  std::uint16_t port() const { return server_.port(); }
  std::size_t client_count() const { return server_.client_count(); }
  const LineServer& server() const { return server_; }
  void close() { server_.close(); }
  void set_secret(std::string secret) { server_.set_secret(std::move(secret)); }

  static ServerOptions defaults();

 private:
  HostProtocol protocol_;
  LineServer server_;
};

}  // namespace tb::netctl
