// The web endpoint: HTTP/1.1 and WebSocket with Boost.Beast on the station's io_context (Beast
// stays in server.cpp, the one file that pays for its templates). Each request is handed to
// web::Api; the WebSocket /api/v1/live gets the live state at every push (once a second, and at
// once after a change) and every event as it happens.
//
// Bounds (docs/security.md): every part of a request before it is held (http_reader.h: request
// line 2 kB, headers 8 kB, body 16 kB, 1 kB of a chunked body's framing held at once, the read
// buffer 16 kB), a request must arrive within 10 s, at most 8 connections per address (an IPv6 /64
// as one, as the guessing budget counts) and 64 in all (503 with Retry-After), --allow ranges
// checked at accept (403), a viewer more than 16 messages behind is dropped (a slow client never
// holds the station). Every refusal is logged once a minute per address and kind (refusals.h).
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "util/cidr.h"
#include "util/loop_fwd.h"

namespace tb::web {

class Api;

struct ServerOptions {
  std::string address = "127.0.0.1";
  std::uint16_t port = 8073;
  std::vector<inet::Cidr> allow;
  std::size_t max_connections = 64;
  std::size_t per_address = 8;
  std::chrono::seconds request_timeout{10};
  std::size_t header_limit = 8 * 1024;
  std::size_t viewer_queue = 16;
  std::chrono::milliseconds push_every{1000};
};

class Server {
 public:
  // Listens at once; throws std::runtime_error naming the address when it cannot.
  Server(boost::asio::io_context& io, Api& api, ServerOptions o);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  std::uint16_t port() const;
  // Something changed: the viewers get the state now rather than at the next push.
  void push_soon();
  // Every live viewer closed (the secret changed: a feed opened with the old one ends; the page
  // reconnects and logs in again). The number closed.
  std::size_t close_viewers();
  // A station event (tracker/events.h's JSON) to every viewer; the last 50 go to new viewers.
  void publish_event(const nlohmann::json& event);

  struct Stats {
    std::size_t connections = 0;
    std::size_t viewers = 0;
    std::uint64_t refused = 0;   // by --allow or the connection bounds
    std::uint64_t dropped = 0;   // slow viewers
    std::uint64_t requests = 0;
  };
  Stats stats() const;

  struct Impl;  // server.cpp's (its connections hold it)

 private:
  std::shared_ptr<Impl> impl_;
};

}  // namespace tb::web
