// The Satrak TCP server: port 4001 by default, on the program's io_context, many clients at once.
//
//   satrak::Server server(io, unit, {.port = 4001});   // binds 127.0.0.1 unless told otherwise
//
// Every client is served with asynchronous reads and writes only, so none can stall the loop or
// the others:
//   * input goes through a bounded frame Decoder (a line longer than max_line is answered with
//     ERR,3 once and discarded up to its end; 1 MB without a newline costs max_line bytes);
//   * each frame is answered in order, at once (Unit::handle);
//   * replies wait in a per-client queue; a client that does not read them and lets the queue pass
//     max_output bytes is disconnected;
//   * at most max_clients connections: when a new client finds them all taken, the one silent
//     longest makes room if it has been silent for evict_idle_after or more; otherwise the newcomer
//     gets an `ERR,8` frame and is closed. TCP keepalive closes connections whose peer vanished.
#pragma once
#include <vector>

#include "util/cidr.h"
#include <boost/asio/io_context.hpp>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>

#include "satrak/unit.h"

namespace tb::satrak {

struct ServerOptions {
  std::string address = "127.0.0.1";  // "0.0.0.0" or "::" to serve other hosts
  unsigned short port = 4001;         // 0: a free port (tests); see Server::port()
  std::size_t max_clients = 16;
  std::chrono::milliseconds evict_idle_after{10000};
  // Connections one address other than loopback may hold at once (half of max_clients: one remote
  // host can never take them all; docs/security.md, "slowloris").
  std::size_t max_per_address = 8;
  std::vector<net::Cidr> allow;  // --allow: clients allowed (empty: everyone); others get ERR,8 and are closed
  std::size_t max_line = Decoder::kDefaultMaxLine;
  std::size_t max_output = 64 * 1024;  // bytes of replies queued for one client before it is dropped
  int send_buffer = 0;                 // SO_SNDBUF of client sockets; 0: the system's (tests set it small)
};

class Server {
 public:
  // Binds and listens at once; throws boost::system::system_error when the address cannot be bound.
  Server(boost::asio::io_context& io, Unit& unit, ServerOptions options = {});
  ~Server();  // closes the listener and every client
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  unsigned short port() const;
  std::size_t clients() const;
  // Counters for logs and tests.
  struct Stats {
    std::size_t accepted = 0;
    std::size_t refused = 0;       // refused at accept, for any reason
    std::size_t refused_per_address = 0;  // that address holds max_per_address already
    std::size_t evicted = 0;       // closed, silent longest, to make room for a new client
    std::size_t dropped_slow = 0;  // output queue over max_output
    std::size_t frames = 0;        // lines answered
  };
  Stats stats() const;
  void close();

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace tb::satrak
