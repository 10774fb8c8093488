// The one file that includes Boost.Beast (its templates cost compile time: keep them here).
#include "web/server.h"

#include <deque>
#include <map>
#include <optional>
#include <stdexcept>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "util/backoff.h"
#include "util/keepalive.h"
#include "web/api.h"
#include "web/live_feed.h"

namespace tb::web {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

constexpr std::size_t kRecentEvents = 50;

std::string peer_of(const tcp::socket& s) {
  boost::system::error_code ec;
  const tcp::endpoint e = s.remote_endpoint(ec);
  if (ec) return {};
  asio::ip::address a = e.address();
  if (a.is_v6() && a.to_v6().is_v4_mapped()) a = asio::ip::make_address_v4(asio::ip::v4_mapped, a.to_v6());
  return a.to_string();
}

std::string header(const http::request<http::string_body>& req, http::field f) {
  const auto it = req.find(f);
  return it == req.end() ? std::string() : std::string(it->value());
}

Request to_request(const http::request<http::string_body>& req, const std::string& peer) {
  Request r;
  r.method = std::string(req.method_string());
  r.target = std::string(req.target());
  r.host = header(req, http::field::host);
  r.origin = header(req, http::field::origin);
  r.cookie = header(req, http::field::cookie);
  r.authorization = header(req, http::field::authorization);
  r.content_type = header(req, http::field::content_type);
  r.body = req.body();
  r.peer = peer;
  if (const auto it = req.find("X-Forwarded-Proto"); it != req.end()) r.forwarded_proto = std::string(it->value());
  return r;
}

}  // namespace

// A connection the server can close when it goes (HTTP or WebSocket).
struct Conn {
  virtual ~Conn() = default;
  virtual void close() = 0;
};

struct Viewer;

struct Server::Impl : std::enable_shared_from_this<Impl> {
  Impl(asio::io_context& io, Api& api, ServerOptions o) : io(io), api(api), o(std::move(o)), acceptor(io), timer(io), retry(io) {}
  asio::io_context& io;
  Api& api;
  ServerOptions o;
  tcp::acceptor acceptor;
  asio::steady_timer timer;
  asio::steady_timer retry;       // the next accept after a failed one (util/backoff.h)
  util::AcceptBackoff backoff;
  bool closed = false;
  bool push_posted = false;
  std::map<std::string, std::size_t> per_address;
  std::size_t connections = 0;
  std::vector<std::weak_ptr<Conn>> conns;
  std::vector<std::weak_ptr<Viewer>> viewers;
  std::deque<std::string> recent;  // the last events, as sent
  LiveFeed feed;                   // the live state: whole once, then what changed (live_feed.h)
  Stats stats;

  void accept();
  void tick();
  void push();
  void push_state();  // builds the document once, sends the viewers what changed
  std::shared_ptr<const std::string> full_state();
  void broadcast(const std::shared_ptr<const std::string>& m);
  void track(const std::shared_ptr<Conn>& c) {
    std::erase_if(conns, [](const std::weak_ptr<Conn>& w) { return w.expired(); });
    conns.push_back(c);
  }
};

// One connection's place in the bounds: counted while it lives.
struct Slot {
  std::weak_ptr<Server::Impl> server;
  std::string peer;
  Slot(const std::shared_ptr<Server::Impl>& s, std::string p) : server(s), peer(std::move(p)) {
    ++s->connections;
    ++s->per_address[peer];
  }
  Slot(const Slot&) = delete;
  Slot& operator=(const Slot&) = delete;
  ~Slot() {
    if (auto s = server.lock()) {
      --s->connections;
      if (--s->per_address[peer] == 0) s->per_address.erase(peer);
    }
  }
};

struct Viewer : Conn, std::enable_shared_from_this<Viewer> {
  Viewer(tcp::socket socket, std::shared_ptr<Server::Impl> s, std::unique_ptr<Slot> slot)
      : ws(std::move(socket)), server(std::move(s)), slot(std::move(slot)) {}
  websocket::stream<beast::tcp_stream> ws;
  std::shared_ptr<Server::Impl> server;
  std::unique_ptr<Slot> slot;
  http::request<http::string_body> upgrade;
  beast::flat_buffer buffer;
  std::deque<std::shared_ptr<const std::string>> queue;
  bool writing = false;
  bool open = false;

  void close() override {
    open = false;
    boost::system::error_code ec;
    beast::get_lowest_layer(ws).socket().close(ec);
  }

  void start(http::request<http::string_body> req) {
    upgrade = std::move(req);
    beast::get_lowest_layer(ws).expires_never();
    ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws.read_message_max(4096);
    ws.set_option(websocket::stream_base::decorator([](websocket::response_type& res) {
      for (const auto& [k, v] : security_headers()) res.set(k, v);
    }));
    ws.async_accept(upgrade, [self = shared_from_this()](boost::system::error_code ec) {
      if (ec || self->server->closed) return;
      self->open = true;
      self->server->push_state();  // the others' patch up to now: this one starts from the same document
      self->server->viewers.push_back(self);
      nlohmann::json events = nlohmann::json::array();
      for (const std::string& e : self->server->recent) events.push_back(nlohmann::json::parse(e, nullptr, false));
      self->send(std::make_shared<const std::string>(nlohmann::json{{"type", "events"}, {"events", events}}.dump()));
      self->send(self->server->full_state());
      self->read();
    });
  }

  void read() {
    ws.async_read(buffer, [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
      if (ec) {
        self->open = false;
        return;
      }
      // Viewers listen; one that missed a message asks for the whole document, the rest is dropped.
      if (LiveFeed::asks_full(beast::buffers_to_string(self->buffer.data()))) self->send(self->server->full_state());
      self->buffer.consume(n);
      self->read();
    });
  }

  void send(const std::shared_ptr<const std::string>& m) {
    if (!open) return;
    if (queue.size() >= server->o.viewer_queue) {
      ++server->stats.dropped;
      spdlog::info("web: a viewer at {} fell {} messages behind: dropped", slot->peer, queue.size());
      close();
      return;
    }
    queue.push_back(m);
    if (!writing) write();
  }

  void write() {
    writing = true;
    ws.text(true);
    ws.async_write(asio::buffer(*queue.front()), [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
      self->writing = false;
      if (!self->queue.empty()) self->queue.pop_front();
      if (ec) {
        self->open = false;
        return;
      }
      if (!self->queue.empty() && self->open) self->write();
    });
  }
};

struct HttpSession : Conn, std::enable_shared_from_this<HttpSession> {
  HttpSession(tcp::socket socket, std::shared_ptr<Server::Impl> s, std::unique_ptr<Slot> slot)
      : stream(std::move(socket)), server(std::move(s)), slot(std::move(slot)) {}
  beast::tcp_stream stream;
  std::shared_ptr<Server::Impl> server;
  std::unique_ptr<Slot> slot;
  beast::flat_buffer buffer;
  std::optional<http::request_parser<http::string_body>> parser;
  http::response<http::string_body> res;

  void close() override {
    boost::system::error_code ec;
    stream.socket().close(ec);
  }

  void read() {
    parser.emplace();
    parser->header_limit(static_cast<std::uint32_t>(server->o.header_limit));
    parser->body_limit(kMaxBody);
    stream.expires_after(server->o.request_timeout);  // a slow client is dropped
    http::async_read(stream, buffer, *parser, [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
      self->on_read(ec);
    });
  }

  void on_read(boost::system::error_code ec) {
    if (server->closed) return;
    if (ec == http::error::body_limit) return reply_and_close(413, "the request body is over 16 kB");
    if (ec == http::error::header_limit) return reply_and_close(431, "the request headers are over 8 kB");
    if (ec) {
      if (ec != http::error::end_of_stream && ec != beast::error::timeout && ec != asio::error::operation_aborted &&
          ec != asio::error::connection_reset && ec != asio::error::eof && buffer.size() > 0)
        return reply_and_close(400, "a malformed HTTP request");
      return close();
    }
    ++server->stats.requests;
    http::request<http::string_body> req = parser->release();
    const std::string peer = slot->peer;
    if (websocket::is_upgrade(req)) {
      if (req.target() != "/api/v1/live") return reply_and_close(404, "the WebSocket is at /api/v1/live");
      if (auto refused = server->api.refuse_live(to_request(req, peer), std::chrono::steady_clock::now()))
        return write(*refused, false);
      stream.expires_never();
      auto viewer = std::make_shared<Viewer>(stream.release_socket(), server, std::move(slot));
      server->track(viewer);
      viewer->start(std::move(req));
      return;
    }
    const Response out = server->api.handle(to_request(req, peer), std::chrono::steady_clock::now());
    write(out, req.keep_alive(), req.method() == http::verb::head);
  }

  void reply_and_close(int status, const std::string& sentence) {
    Response r;
    r.status = status;
    r.body = nlohmann::json{{"error", sentence}}.dump();
    write(r, false);
  }

  void write(const Response& out, bool keep_alive, bool head = false) {
    res = {};
    res.version(11);
    res.result(static_cast<unsigned>(out.status));
    res.set(http::field::server, "trakbox");
    res.set(http::field::content_type, out.content_type);
    for (const auto& [k, v] : security_headers()) res.set(k, v);
    for (const auto& [k, v] : out.headers) res.insert(k, v);
    res.body() = head ? std::string() : out.body;
    res.keep_alive(keep_alive);
    res.prepare_payload();
    stream.expires_after(server->o.request_timeout);
    http::async_write(stream, res, [self = shared_from_this(), keep_alive](boost::system::error_code ec, std::size_t) {
      if (ec || !keep_alive || self->server->closed) {
        boost::system::error_code ignored;
        self->stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read();
    });
  }
};

void Server::Impl::accept() {
  acceptor.async_accept([self = shared_from_this()](boost::system::error_code ec, tcp::socket socket) {
    if (self->closed || ec == asio::error::operation_aborted) return;
    if (ec) {
      // Out of descriptors and the like: the next accept after a back-off, never at once (issue 38:
      // re-arming at once spun a core), said once a run.
      if (self->backoff.failed())
        spdlog::error("web: accept failed: {}; retrying every 100 ms to 1 s (said once until it works again)",
                      ec.message());
      self->retry.expires_after(self->backoff.delay());
      self->retry.async_wait([w = self->weak_from_this()](boost::system::error_code e) {
        if (auto me = w.lock(); me && !e && !me->closed) me->accept();
      });
      return;
    }
    if (const auto failed = self->backoff.succeeded())
      spdlog::warn("web: accepting again after {} failed accepts", failed);
    const std::string peer = peer_of(socket);
    const auto it = self->per_address.find(peer);
    const std::size_t mine = it == self->per_address.end() ? 0 : it->second;
    if (peer.empty() || !inet::allowed(self->o.allow, peer) || self->connections >= self->o.max_connections ||
        mine >= self->o.per_address) {
      ++self->stats.refused;
      boost::system::error_code ignored;
      socket.close(ignored);
    } else {
      inet::enable_keepalive(socket.native_handle());
      auto slot = std::make_unique<Slot>(self, peer);
      auto session = std::make_shared<HttpSession>(std::move(socket), self, std::move(slot));
      self->track(session);
      session->read();
    }
    self->accept();
  });
}

void Server::Impl::tick() {
  timer.expires_after(o.push_every);
  timer.async_wait([w = weak_from_this()](boost::system::error_code ec) {
    auto self = w.lock();
    if (ec || !self || self->closed) return;
    self->push();
    self->tick();
  });
}

void Server::Impl::push() {
  std::erase_if(viewers, [](const std::weak_ptr<Viewer>& v) {
    const auto p = v.lock();
    return !p || !p->open;
  });
  if (viewers.empty()) {
    feed.forget();  // nobody to patch: the next viewer starts from a fresh document
    return;
  }
  push_state();
}

void Server::Impl::push_state() {
  try {
    if (auto m = feed.next(api.live_document())) broadcast(std::make_shared<const std::string>(std::move(*m)));
  } catch (const std::exception&) {
    feed.forget();
    broadcast(std::make_shared<const std::string>(api.live_state()));  // the error, as before
  }
}

std::shared_ptr<const std::string> Server::Impl::full_state() {
  if (auto m = feed.full()) return std::make_shared<const std::string>(std::move(*m));
  return std::make_shared<const std::string>(api.live_state());
}

void Server::Impl::broadcast(const std::shared_ptr<const std::string>& m) {
  for (const auto& w : viewers)
    if (const auto v = w.lock()) v->send(m);
}

Server::Server(asio::io_context& io, Api& api, ServerOptions o) : impl_(std::make_shared<Impl>(io, api, std::move(o))) {
  const std::string where = impl_->o.address + ":" + std::to_string(impl_->o.port);
  try {
    const tcp::endpoint ep(asio::ip::make_address(impl_->o.address), impl_->o.port);
    impl_->acceptor.open(ep.protocol());
    impl_->acceptor.set_option(tcp::acceptor::reuse_address(true));
    impl_->acceptor.bind(ep);
    impl_->acceptor.listen();
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot listen on " + where + ": " + e.what());
  }
  impl_->accept();
  impl_->tick();
}

Server::~Server() {
  impl_->closed = true;
  boost::system::error_code ec;
  impl_->acceptor.close(ec);
  impl_->timer.cancel();
  impl_->retry.cancel();
  for (const auto& w : impl_->conns)
    if (const auto c = w.lock()) c->close();
}

std::uint16_t Server::port() const {
  boost::system::error_code ec;
  return impl_->acceptor.local_endpoint(ec).port();
}

void Server::push_soon() {
  if (impl_->push_posted) return;
  impl_->push_posted = true;
  asio::post(impl_->io, [w = std::weak_ptr<Impl>(impl_)] {
    if (auto self = w.lock(); self && !self->closed) {
      self->push_posted = false;
      self->push();
    }
  });
}

void Server::publish_event(const nlohmann::json& event) {
  const std::string e = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  impl_->recent.push_back(e);
  if (impl_->recent.size() > kRecentEvents) impl_->recent.pop_front();
  impl_->broadcast(std::make_shared<const std::string>("{\"type\":\"event\",\"event\":" + e + "}"));
}

Server::Stats Server::stats() const {
  Stats s = impl_->stats;
  s.connections = impl_->connections;
  std::size_t v = 0;
  for (const auto& w : impl_->viewers)
    if (const auto p = w.lock(); p && p->open) ++v;
  s.viewers = v;
  return s;
}

}  // namespace tb::web
