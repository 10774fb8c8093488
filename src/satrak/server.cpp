#include "satrak/server.h"

#include <algorithm>
#include "satrak/redact.h"
#include "util/backoff.h"
#include "util/keepalive.h"

#include <array>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <set>

#include <spdlog/spdlog.h>

namespace tb::satrak {
namespace asio = boost::asio;
using asio::ip::tcp;

namespace {
class Session;
}

struct Server::State {
  State(asio::io_context& io, Unit& u, ServerOptions o) : unit(u), opt(std::move(o)), acceptor(io), retry(io) {}
  Unit& unit;
  ServerOptions opt;
  tcp::acceptor acceptor;
  asio::steady_timer retry;  // after a failed accept (out of descriptors): try again a little later
  util::AcceptBackoff backoff;
  std::set<std::shared_ptr<Session>> sessions;
  Stats stats;
  bool closed = false;
};

namespace {

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, std::weak_ptr<Server::State> state, std::size_t max_line, std::size_t max_output)
      : socket_(std::move(socket)), state_(std::move(state)), decoder_(max_line), max_output_(max_output) {
    boost::system::error_code ec;
    const auto ep = socket_.remote_endpoint(ec);
    peer_ = ec ? std::string("?") : ep.address().to_string() + ":" + std::to_string(ep.port());
    address_ = ec ? std::string() : ep.address().to_string();
  }

  // How long the client has sent nothing.
  std::chrono::steady_clock::duration silent() const { return std::chrono::steady_clock::now() - last_heard_; }
  const std::string& peer() const { return peer_; }
  // Who holds the antenna while this connection's commands drive it: "satrak 127.0.0.1:50123".
  std::string label() const { return "satrak " + peer_; }
  const std::string& address() const { return address_; }

  void start() {
    spdlog::info("satrak: client {} connected", peer_);
    read();
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    spdlog::info("satrak: client {} disconnected", peer_);
    // Its hold of the antenna ends with it (tracker/control.h), as a rotctld client's does.
    if (auto s = state_.lock()) s->unit.client_left(label());
    boost::system::error_code ec;
    socket_.shutdown(tcp::socket::shutdown_both, ec);
    socket_.close(ec);
    pending_.clear();
    if (auto s = state_.lock()) s->sessions.erase(shared_from_this());
  }

 private:
  void read() {
    auto self = shared_from_this();
    socket_.async_read_some(asio::buffer(buf_), [self](const boost::system::error_code& ec, std::size_t n) {
      if (self->closed_) return;
      if (ec) {
        if (ec != asio::error::eof && ec != asio::error::operation_aborted)
          spdlog::debug("satrak: client {}: {}", self->peer_, ec.message());
        self->close();
        return;
      }
      try {  // nothing a client sends may end the station: a handler that throws drops that client
        self->received(n);
      } catch (const std::exception& e) {
        spdlog::error("satrak: client {}: handling its request failed: {}; disconnected", self->peer_, e.what());
        self->close();
      }
    });
  }

  void received(std::size_t n) {
    auto state = state_.lock();
    if (!state) {
      close();
      return;
    }
    events_.clear();
    decoder_.feed(std::string_view(buf_.data(), n), events_);
    // Silence is counted from the last whole frame, not the last byte: a client trickling bytes that
    // never make a frame ("slowloris") is as silent as one that sends nothing, and makes room.
    if (!events_.empty()) last_heard_ = std::chrono::steady_clock::now();
    for (const Decoded& d : events_) {
      if (d.kind == Decoded::Kind::overlong) spdlog::warn("satrak: client {}: line longer than {} bytes discarded", peer_, decoder_.max_line());
      ++state->stats.frames;
      std::string reply = state->unit.handle(d, label());
      if (spdlog::should_log(spdlog::level::debug)) {  // --log-level debug: what a client asked, what it got
        std::string asked = redact_payload(d.payload.substr(0, 200));
        for (char& c : asked)
          if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
        spdlog::debug("satrak: client {}: '{}' -> '{}'", peer_, asked, redact_payload(reply));
      }
      queue(encode(reply));
      if (closed_) return;
    }
    read();
  }

  // Replies wait in pending_ while a write is under way; each write takes everything waiting, so
  // output drains as fast as the socket takes it however many frames one read brought in.
  void queue(const std::string& frame) {
    pending_ += frame;
    if (const std::size_t waiting = pending_.size() + sending_.size(); waiting > max_output_) {
      spdlog::warn("satrak: client {} does not read its replies ({} bytes waiting): disconnected", peer_, waiting);
      if (auto s = state_.lock()) ++s->stats.dropped_slow;
      close();
      return;
    }
    if (!writing_) write();
  }

  void write() {
    if (pending_.empty() || closed_) {
      writing_ = false;
      return;
    }
    writing_ = true;
    sending_.swap(pending_);
    auto self = shared_from_this();
    asio::async_write(socket_, asio::buffer(sending_), [self](const boost::system::error_code& ec, std::size_t) {
      if (self->closed_) return;
      if (ec) {
        self->close();
        return;
      }
      self->sending_.clear();
      self->write();
    });
  }

  tcp::socket socket_;
  std::weak_ptr<Server::State> state_;
  Decoder decoder_;
  std::size_t max_output_;
  std::array<char, 4096> buf_{};
  std::vector<Decoded> events_;
  std::string pending_;  // replies not yet handed to a write
  std::string sending_;  // the write under way
  bool writing_ = false;
  bool closed_ = false;
  std::string peer_;
  std::string address_;
  std::chrono::steady_clock::time_point last_heard_ = std::chrono::steady_clock::now();
};

// Every connection is taken: closes the one silent longest if it has been silent long enough.
bool make_room(Server::State& s) {
  std::shared_ptr<Session> quietest;
  for (const auto& session : s.sessions)
    if (!quietest || session->silent() > quietest->silent()) quietest = session;
  if (!quietest || quietest->silent() < s.opt.evict_idle_after) return false;
  ++s.stats.evicted;
  spdlog::warn("satrak: all {} connections taken; closing {}, silent for {} s, to serve a new client",
               s.sessions.size(), quietest->peer(),
               std::chrono::duration_cast<std::chrono::seconds>(quietest->silent()).count());
  quietest->close();
  return true;
}

void accept(const std::shared_ptr<Server::State>& state) {
  std::weak_ptr<Server::State> weak = state;
  state->acceptor.async_accept([weak](const boost::system::error_code& ec, tcp::socket socket) {
    auto s = weak.lock();
    if (!s || s->closed) return;
    if (ec) {
      if (ec == asio::error::operation_aborted) return;
      if (s->backoff.failed())  // util/backoff.h: never at once, said once a run
        spdlog::error("satrak: accept failed: {}; retrying every 100 ms to 1 s (said once until it works again)",
                      ec.message());
      s->retry.expires_after(s->backoff.delay());
      s->retry.async_wait([weak](const boost::system::error_code& e) {
        auto st = weak.lock();
        if (!e && st && !st->closed) accept(st);
      });
      return;
    }
    if (const auto failed = s->backoff.succeeded()) spdlog::warn("satrak: accepting again after {} failed accepts", failed);
    boost::system::error_code peer_ec;
    const auto peer = socket.remote_endpoint(peer_ec);
    const std::string who = peer_ec ? std::string() : peer.address().to_string();
    if (!inet::allowed(s->opt.allow, who)) {
      ++s->stats.refused;
      spdlog::warn("satrak: connection from {} refused: not in --allow", who);
      boost::system::error_code ignored;
      asio::write(socket, asio::buffer(encode(reply_error("", Error::not_allowed))), ignored);
      socket.close(ignored);
    } else if (const std::size_t held = static_cast<std::size_t>(std::count_if(
                   s->sessions.begin(), s->sessions.end(), [&](const auto& x) { return x->address() == who; }));
               held >= s->opt.max_per_address && !inet::is_loopback(who)) {
      ++s->stats.refused;
      ++s->stats.refused_per_address;
      spdlog::warn("satrak: connection from {} refused: it has {} connections already (at most {} an address)", who,
                   held, s->opt.max_per_address);
      boost::system::error_code ignored;
      asio::write(socket, asio::buffer(encode(reply_error("", Error::not_allowed))), ignored);
      socket.close(ignored);
    } else if (s->sessions.size() >= s->opt.max_clients && !make_room(*s)) {
      ++s->stats.refused;
      spdlog::warn("satrak: {} clients, none silent for {} s: connection refused", s->opt.max_clients,
                   s->opt.evict_idle_after.count() / 1000.0);
      boost::system::error_code ignored;
      asio::write(socket, asio::buffer(encode(reply_error("", Error::not_allowed))), ignored);  // $ERR,8*..
      socket.close(ignored);
    } else {
      ++s->stats.accepted;
      boost::system::error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);
      inet::enable_keepalive(socket.native_handle());
      if (s->opt.send_buffer > 0) socket.set_option(asio::socket_base::send_buffer_size(s->opt.send_buffer), ignored);
      auto session = std::make_shared<Session>(std::move(socket), weak, s->opt.max_line, s->opt.max_output);
      s->sessions.insert(session);
      session->start();
    }
    accept(s);
  });
}

}  // namespace

Server::Server(asio::io_context& io, Unit& unit, ServerOptions options)
    : state_(std::make_shared<State>(io, unit, std::move(options))) {
  const tcp::endpoint ep(asio::ip::make_address(state_->opt.address), state_->opt.port);
  state_->acceptor.open(ep.protocol());
  state_->acceptor.set_option(tcp::acceptor::reuse_address(true));
  state_->acceptor.bind(ep);
  state_->acceptor.listen();
  spdlog::info("satrak: listening on {}:{}", state_->opt.address, port());
  accept(state_);
}

Server::~Server() { close(); }

void Server::close() {
  if (state_->closed) return;
  state_->closed = true;
  boost::system::error_code ec;
  state_->acceptor.close(ec);
  state_->retry.cancel();
  auto sessions = state_->sessions;  // close() erases from the set
  for (const auto& s : sessions) s->close();
  state_->sessions.clear();
}

unsigned short Server::port() const {
  boost::system::error_code ec;
  const auto ep = state_->acceptor.local_endpoint(ec);
  return ec ? 0 : ep.port();
}

std::size_t Server::clients() const { return state_->sessions.size(); }

Server::Stats Server::stats() const { return state_->stats; }

}  // namespace tb::satrak
