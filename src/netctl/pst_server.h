// trakbox aimed over PstRotator's UDP protocol (--pst-port N, rotator/pst/codec.h): a program that
// speaks it (PstRotator itself, SatDump, Horus-GUI, a logger) sends <PST><AZIMUTH>..</AZIMUTH></PST>
// and <PST><ELEVATION>..</ELEVATION></PST> to the port, and is an outside client of the antenna as a
// rotctld client is: the same StationOps::go_to (stop, park), the rotor control switched on as
// rotctld's set_pos does. Azimuth and elevation come in datagrams of their own; each moves the
// antenna to it and to the other axis's last one (the antenna's own while none came). AZ? and EL?
// are answered with where the antenna is ("AZ:297.0"), to the sender's address on the port after
// this server's, PstRotator's convention (commands to 12000, replies to the sender's 12001).
// Loopback unless --listen; senders outside --allow are refused; a bad datagram is refused whole,
// counted and logged (at most once a second), never acted on.
#pragma once
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tracker/station_loop.h"
#include "util/cidr.h"

namespace tb::netctl {

struct PstOptions {
  std::string address = "127.0.0.1";
  std::vector<inet::Cidr> allow;   // empty: everyone who can reach the address
};

struct PstStats {
  std::uint64_t taken = 0;          // datagrams acted on
  std::uint64_t refused_bad = 0;    // malformed, unknown or out of range
  std::uint64_t refused_not_allowed = 0;
  std::uint64_t refused_by_station = 0;   // StationOps said no (the rotator link down, limits)
};

// The whole server but the socket (the fuzz target's and the unit tests' way in): one datagram from
// an address, what to send back (nothing: no reply). Never throws for what a datagram holds.
class PstHandler {
 public:
  PstHandler(tracker::StationLoop& station, PstOptions options) : station_(station), options_(std::move(options)) {}
  std::vector<std::string> handle(std::string_view datagram, const std::string& from);
  const PstStats& stats() const { return stats_; }
  const PstOptions& options() const { return options_; }
  void refuse(const std::string& from, const std::string& why);   // logged at most once a second

 private:
  tracker::StationLoop& station_;
  PstOptions options_;
  PstStats stats_;
  std::optional<double> az_, el_;   // the last azimuth and elevation a client asked for
  std::chrono::steady_clock::time_point said_at_{};
};

class PstServer {
 public:
  // Port 0 picks a free port (port() says which). Throws std::system_error when it cannot bind.
  PstServer(boost::asio::io_context& io, std::uint16_t port, tracker::StationLoop& station, PstOptions options = {});
  ~PstServer();
  PstServer(const PstServer&) = delete;
  PstServer& operator=(const PstServer&) = delete;

  std::uint16_t port() const { return port_; }
  const PstStats& stats() const { return handler_.stats(); }

 private:
  void receive();

  PstHandler handler_;
  boost::asio::ip::udp::socket socket_;
  boost::asio::ip::udp::endpoint sender_;
  std::array<char, 2048> buf_{};
  std::uint16_t port_ = 0;
};

}  // namespace tb::netctl
