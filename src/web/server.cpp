// One of the two files that include Boost.Beast, with http_reader.cpp (its templates cost compile
// time: keep them here).
#include "web/server.h"

#include <array>
#include <deque>
#include <map>
#include <optional>
#include <stdexcept>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <spdlog/fmt/fmt.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "netctl/guesses.h"
#include "util/backoff.h"
#include "util/keepalive.h"
#include "web/api.h"
#include "web/http_reader.h"
#include "web/refusals.h"
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
  RefusalLog refusals;
  std::size_t lingering = 0;       // refused at accept, their last bytes being read (Refused)

  void note_refusal(const std::string& peer, int status, const std::string& why);
  void refuse_at_accept(tcp::socket socket, const std::string& peer, int status, const std::string& why);

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
  std::string key;  // as the guessing budget counts addresses (an IPv6 /64 as one)
  Slot(const std::shared_ptr<Server::Impl>& s, std::string p) : server(s), peer(std::move(p)), key(netctl::key_of(peer)) {
    ++s->connections;
    ++s->per_address[key];
  }
  Slot(const Slot&) = delete;
  Slot& operator=(const Slot&) = delete;
  ~Slot() {
    if (auto s = server.lock()) {
      --s->connections;
      if (--s->per_address[key] == 0) s->per_address.erase(key);
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
      res.set(http::field::server, "trakbox");  // ours, not Beast's
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
  RequestReader reader;              // every part of a request bounded (http_reader.h)
  std::array<char, 4096> scratch{};  // what one read brings, before the reader takes it
  http::response<http::string_body> res;
  std::size_t drained = 0;
  // A streamed reply (Response::stream): what makes the next piece, and the piece being written.
  std::function<std::string()> producer;
  std::function<std::vector<std::pair<std::string, std::string>>()> trailers;
  std::string piece;
  bool chunked = false;

  void close() override {
    boost::system::error_code ec;
    stream.socket().close(ec);
  }

  // A new request: it must be whole within the request timeout (a slow client is dropped).
  void read() {
    stream.expires_after(server->o.request_timeout);
    next(reader.feed());  // a pipelined request may be held already
  }

  void next(RequestReader::State st) {
    if (server->closed) return;
    if (st == RequestReader::State::refused) return refuse_and_close(reader.status(), reader.why());
    if (st == RequestReader::State::done) return on_request(reader.take());
    if (reader.take_continue()) return send_continue();
    const std::size_t n = std::min(reader.room(), scratch.size());
    stream.async_read_some(asio::buffer(scratch.data(), n), [self = shared_from_this()](boost::system::error_code ec,
                                                                                       std::size_t got) {
      if (self->server->closed) return;
      if (ec) return self->close();  // gone, or too slow: nothing to answer
      self->next(self->reader.feed(std::string_view(self->scratch.data(), got)));
    });
  }

  // Expect: 100-continue (RFC 9110 10.1.1): the client waits for this before it sends the body.
  void send_continue() {
    static const std::string kContinue = "HTTP/1.1 100 Continue\r\n\r\n";
    asio::async_write(stream, asio::buffer(kContinue), [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
      if (ec || self->server->closed) return self->close();
      self->next(RequestReader::State::more);
    });
  }

  void on_request(ReadRequest in) {
    ++server->stats.requests;
    in.request.peer = slot->peer;
    if (in.upgrade) {
      if (target_path(in.request.target) != "/api/v1/live")
        return refuse_and_close(404, "the WebSocket is at /api/v1/live");
      if (auto refused = server->api.refuse_live(in.request, std::chrono::steady_clock::now())) {
        server->note_refusal(slot->peer, refused->status, refused->why);
        return write(*refused, false);
      }
      http::request<http::string_body> req{http::verb::get, in.request.target, in.version};
      for (const auto& [k, v] : in.fields) req.insert(k, v);
      stream.expires_never();
      auto viewer = std::make_shared<Viewer>(stream.release_socket(), server, std::move(slot));
      server->track(viewer);
      viewer->start(std::move(req));
      return;
    }
    const Response out = server->api.handle(in.request, std::chrono::steady_clock::now());
    if (out.status >= 400) server->note_refusal(slot->peer, out.status, out.why);
    if (out.stream) return write_streamed(out, in.keep_alive, in.head, in.version);
    write(out, in.keep_alive, in.head);
  }

  // A reply made in pieces (Response::stream): the header, then each piece as the client takes the
  // one before (chunked on HTTP/1.1, to the close on HTTP/1.0), each dropped once written; a client
  // that takes none for the request timeout is dropped. HEAD: the header alone.
  void write_streamed(const Response& out, bool keep_alive, bool head, unsigned version) {
    chunked = version >= 11;
    if (!chunked) keep_alive = false;
    std::string h = fmt::format("HTTP/1.1 {} {}\r\nServer: trakbox\r\nContent-Type: {}\r\n", out.status,
                                std::string(http::obsolete_reason(http::int_to_status(static_cast<unsigned>(out.status)))),
                                out.content_type);
    for (const auto& [k, v] : security_headers()) h += k + ": " + v + "\r\n";
    for (const auto& [k, v] : out.headers) h += k + ": " + v + "\r\n";
    h += keep_alive ? "Connection: keep-alive\r\n" : "Connection: close\r\n";
    if (!head && chunked) {
      h += "Transfer-Encoding: chunked\r\n";
      if (out.trailers)
        for (const auto& [k, v] : out.trailers()) h += "Trailer: " + k + "\r\n";
    }
    h += "\r\n";
    producer = head ? nullptr : out.stream;
    trailers = out.trailers;
    piece = std::move(h);
    send_piece(keep_alive, producer == nullptr);
  }

  void send_piece(bool keep_alive, bool last) {
    stream.expires_after(server->o.request_timeout);
    asio::async_write(stream, asio::buffer(piece), [self = shared_from_this(), keep_alive, last](boost::system::error_code ec,
                                                                                                std::size_t) {
      self->piece.clear();
      self->piece.shrink_to_fit();  // dropped once written
      if (ec || self->server->closed) return self->close();
      if (last) {
        self->producer = nullptr;
        self->trailers = nullptr;
        if (!keep_alive) return self->linger();
        return self->read();
      }
      self->next_piece(keep_alive);
    });
  }

  void next_piece(bool keep_alive) {
    std::string body;
    try {
      body = producer();
    } catch (const std::exception& e) {
      spdlog::error("web: a streamed reply to {} stopped: {}", slot->peer, e.what());
      return close();  // the client sees the reply cut (no last chunk): never a whole-looking part
    }
    if (body.empty()) {
      if (!chunked) return close();  // HTTP/1.0: the end of the body is the close
      piece = "0\r\n";
      if (trailers)
        for (const auto& [k, v] : trailers()) piece += k + ": " + v + "\r\n";
      piece += "\r\n";
      return send_piece(keep_alive, true);
    }
    piece = chunked ? fmt::format("{:x}\r\n{}\r\n", body.size(), body) : std::move(body);
    send_piece(keep_alive, false);
  }

  void refuse_and_close(int status, const std::string& sentence) {
    server->note_refusal(slot->peer, status, sentence);
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
    res.keep_alive(keep_alive);
    if (head) {
      res.content_length(out.body.size());  // RFC 9110 9.3.2: the length GET would send
    } else {
      res.body() = out.body;
      res.prepare_payload();
    }
    stream.expires_after(server->o.request_timeout);
    http::async_write(stream, res, [self = shared_from_this(), keep_alive](boost::system::error_code ec, std::size_t) {
      if (ec || self->server->closed) return self->close();
      if (!keep_alive) return self->linger();
      self->read();
    });
  }

  // Closing with the client's bytes unread would reset the connection and could lose the answer
  // (RFC 9112 9.6): what it still sends is read and dropped, up to 1 MB or 2 s, then it is closed.
  void linger() {
    boost::system::error_code ignored;
    stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
    stream.expires_after(std::chrono::seconds(2));
    drain();
  }

  void drain() {
    stream.async_read_some(asio::buffer(scratch), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
      self->drained += n;
      if (ec || self->server->closed || self->drained > (1u << 20)) return self->close();
      self->drain();
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
    const auto it = self->per_address.find(netctl::key_of(peer));
    const std::size_t mine = it == self->per_address.end() ? 0 : it->second;
    if (peer.empty()) {
      ++self->stats.refused;
      boost::system::error_code ignored;
      socket.close(ignored);
    } else if (!inet::allowed(self->o.allow, peer)) {
      self->refuse_at_accept(std::move(socket), peer, 403, "this address is not in --allow");
    } else if (self->connections >= self->o.max_connections) {
      self->refuse_at_accept(std::move(socket), peer, 503,
                             "the station has " + std::to_string(self->o.max_connections) + " web connections already");
    } else if (mine >= self->o.per_address) {
      self->refuse_at_accept(std::move(socket), peer, 503,
                             "this address has " + std::to_string(self->o.per_address) + " web connections already");
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

// A connection refused at accept: a short answer written at once (it fits the socket's buffer),
// then what the client still sends is read and dropped for up to a second so that the close does
// not reset the answer away. At most max_connections of them at once; beyond that, closed at once.
struct Refused : std::enable_shared_from_this<Refused> {
  Refused(tcp::socket s, std::shared_ptr<Server::Impl> owner)
      : socket(std::move(s)), timer(socket.get_executor()), server(std::move(owner)) {
    ++server->lingering;
  }
  ~Refused() { --server->lingering; }
  tcp::socket socket;
  asio::steady_timer timer;
  std::shared_ptr<Server::Impl> server;
  std::array<char, 512> scratch{};

  void start() {
    timer.expires_after(std::chrono::seconds(1));
    timer.async_wait([self = shared_from_this()](boost::system::error_code ec) {
      if (!ec) self->close();
    });
    read();
  }
  void read() {
    socket.async_read_some(asio::buffer(scratch), [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
      if (ec || self->server->closed) {
        self->timer.cancel();
        return self->close();
      }
      self->read();
    });
  }
  void close() {
    boost::system::error_code ignored;
    socket.close(ignored);
  }
};

void Server::Impl::note_refusal(const std::string& peer, int status, const std::string& why) {
  if (const auto unsaid = refusals.note(peer, status, std::chrono::steady_clock::now())) {
    if (*unsaid > 0)
      spdlog::warn("web: refused {} ({}): {} (and {} refusals of it in the minute before)", peer, status, why, *unsaid);
    else
      spdlog::warn("web: refused {} ({}): {}", peer, status, why);
  }
}

void Server::Impl::refuse_at_accept(tcp::socket socket, const std::string& peer, int status, const std::string& why) {
  ++stats.refused;
  note_refusal(peer, status, why);
  const std::string body = nlohmann::json{{"error", why}}.dump();
  std::string reply = status == 403 ? "HTTP/1.1 403 Forbidden\r\n" : "HTTP/1.1 503 Service Unavailable\r\nRetry-After: 10\r\n";
  reply += "Server: trakbox\r\nContent-Type: application/json\r\nX-Content-Type-Options: nosniff\r\n"
           "Cache-Control: no-store\r\nConnection: close\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  boost::system::error_code ec;
  socket.non_blocking(true, ec);
  if (!ec) socket.write_some(asio::buffer(reply), ec);
  socket.shutdown(tcp::socket::shutdown_send, ec);
  if (lingering >= o.max_connections) {
    socket.close(ec);
    return;
  }
  std::make_shared<Refused>(std::move(socket), shared_from_this())->start();
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

std::size_t Server::close_viewers() {
  std::size_t n = 0;
  for (const auto& w : impl_->viewers)
    if (const auto v = w.lock(); v && v->open) {
      v->close();
      ++n;
    }
  return n;
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
