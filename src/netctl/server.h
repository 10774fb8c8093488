// Line-oriented TCP servers on the event loop: trakbox answering the rotctld and rigctld protocols.
//
//   boost::asio::io_context io;
//   netctl::RotctldServer rot(io, 4533, station);   // Gpredict "Rotators": localhost:4533
//   netctl::RigctldServer rig(io, 4532, station);   // Gpredict "Radios": localhost:4532
//   io.run();                                       // the same loop that ticks the station
//
// Everything runs on the io_context's thread, the one that ticks the StationLoop: construct, use and
// destroy the servers there (or while the loop is not running). Nothing blocks: a client that
// stops reading, never sends a newline or floods is dealt with without stalling the loop:
//  * a line longer than max_line is answered "RPRT -8" once and discarded up to its newline;
//  * a client whose unsent replies exceed max_output (it sends but does not read) is disconnected;
//  * at most max_clients connections, max_per_address of them from one remote address. When a new
//    client finds them all taken, the connection that has been silent longest (counted from its last
//    whole line, so a client trickling bytes that never end a line counts as silent) makes room for
//    it if it has been silent for evict_idle_after or more (idle holders, "slowloris" clients and
//    dead peers cannot lock the port; a client that polls, as Gpredict does, is never the longest
//    silent); otherwise the newcomer gets the protocol's refusal
//    (LineHandler::refusal(), e.g. "RPRT -9") and is closed. Every connection has TCP keepalive
//    (60 s idle, then 3 probes 10 s apart), so a peer that vanished is found and closed.
#pragma once
#include <vector>

#include "util/backoff.h"
#include "util/cidr.h"
#include <chrono>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "netctl/guesses.h"
#include "netctl/protocol.h"
#include "netctl/rigctl_protocol.h"
#include "netctl/rotctl_protocol.h"
#include "tracker/station_loop.h"

namespace tb::netctl {

struct ServerOptions {
  std::string address = "127.0.0.1";       // loopback unless told otherwise ("0.0.0.0", "::")
  std::size_t max_line = kMaxLineLength;   // bytes a line may have, newline excluded
  std::size_t max_output = 64 * 1024;      // bytes of replies queued for one client
  std::size_t max_clients = 16;
  std::chrono::milliseconds evict_idle_after{10000};  // see above
  // Clients allowed to connect (--allow); empty: everyone. Others are refused at accept with the
  // protocol's refusal line, and the log names their address.
  std::vector<inet::Cidr> allow;
  std::string name = "netctl";             // for the log: "rotctld", "rigctld", "host"
  // A CR ends a line as well as a LF (a CR LF pair ends one line): terminal programs send CR.
  bool cr_ends_line = false;
  // A shared secret (--rotctld-secret-file, ...): a client must give it with the protocol's
  // password command (LineHandler::gate) before anything else works; it has auth_deadline to do so
  // and max_auth_failures tries, then it is closed. Empty: no authentication (Gpredict's way).
  std::string secret;
  std::chrono::milliseconds auth_deadline{10000};
  int max_auth_failures = 3;
  // Wrong secrets from one address wait longer and longer for their answer, then lock the address out
  // (netctl/guesses.h: about 10 guesses in 12 minutes).
  GuessPolicy guesses;
  // The guessing budget shared by every endpoint of the process (issue 38); null: this server makes
  // its own from `guesses` (tests).
  std::shared_ptr<GuessGuard> guard;
  // Connections one address other than loopback may hold at once: half of max_clients, so that one
  // remote host (a program that leaks connections, a client that keeps many open) can never take
  // every connection. Loopback clients are this machine's own programs. Attackers with many
  // addresses are kept out by --allow (docs/security.md).
  std::size_t max_per_address = 8;
  bool loopback_exempt = true;  // tests turn it off: their clients are all loopback
};

// What a server has refused and why, since it started (for the log's reader and `trakbox status`).
struct ServerStats {
  std::uint64_t refused_not_allowed = 0;   // not in --allow
  std::uint64_t refused_busy = 0;          // every connection taken, none silent long enough
  std::uint64_t refused_per_address = 0;   // that address holds max_per_address already
  std::uint64_t refused_locked_out = 0;    // that address is locked out for wrong secrets
  std::uint64_t wrong_secrets = 0;
  std::uint64_t lockouts = 0;
};

// A TCP server handing each line of each client to one LineHandler, in order of arrival; the
// handler's greeting goes to each client as it connects.
// Port 0 picks a free port (port() says which). Throws std::system_error when it cannot listen.
class LineServer {
 public:
  LineServer(boost::asio::io_context& io, std::uint16_t port, LineHandler& handler, ServerOptions options = {});
  ~LineServer();
  LineServer(const LineServer&) = delete;
  LineServer& operator=(const LineServer&) = delete;

  std::uint16_t port() const { return port_; }
  std::size_t client_count() const;
  const ServerStats& stats() const;
  const ServerOptions& options() const;
  // A new secret (SIGHUP re-read its file): the clients of the old one are closed, each newcomer
  // must give the new one. Nothing happens when it is the same.
  void set_secret(std::string secret);
  // Stops listening and drops every client. Also done by the destructor.
  void close();

  struct Core;  // shared with the sessions, which may outlive the server by a handler or two

 private:
  void accept();
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer retry_;
  util::AcceptBackoff backoff_;
  std::shared_ptr<Core> core_;
  std::uint16_t port_ = 0;
};

// rotctld-compatible: the antenna of `station`.
class RotctldServer {
 public:
  static constexpr std::uint16_t kDefaultPort = 4533;
  RotctldServer(boost::asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
                ServerOptions options = named("rotctld"));
  std::uint16_t port() const { return server_.port(); }
  std::size_t client_count() const { return server_.client_count(); }
  const LineServer& server() const { return server_; }
  RotctlProtocol& protocol() { return protocol_; }
  void close() { server_.close(); }
  void set_secret(std::string secret) { server_.set_secret(std::move(secret)); }

  static ServerOptions named(std::string name) {
    ServerOptions o;
    o.name = std::move(name);
    return o;
  }

 private:
  RotctlProtocol protocol_;
  LineServer server_;
};

// rigctld-compatible: the radio of `station` (VFO A = downlink, VFO B = uplink).
class RigctldServer {
 public:
  static constexpr std::uint16_t kDefaultPort = 4532;
  RigctldServer(boost::asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
                ServerOptions options = RotctldServer::named("rigctld"));
  std::uint16_t port() const { return server_.port(); }
  std::size_t client_count() const { return server_.client_count(); }
  const LineServer& server() const { return server_; }
  RigctlProtocol& protocol() { return protocol_; }
  void close() { server_.close(); }
  void set_secret(std::string secret) { server_.set_secret(std::move(secret)); }

 private:
  RigctlProtocol protocol_;
  LineServer server_;
};

}  // namespace tb::netctl
