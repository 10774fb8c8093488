#include "netctl/server.h"

#include "netctl/guesses.h"
#include "util/secret.h"

#include <spdlog/spdlog.h>

#include <array>
#include <boost/asio/write.hpp>
#include <chrono>
#include <cstring>
#include <ctime>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "util/keepalive.h"

namespace tb::netctl {

namespace asio = boost::asio;
using asio::ip::tcp;
using boost::system::error_code;

namespace {
class Session;
}

struct LineServer::Core {
  LineHandler* protocol = nullptr;
  ServerOptions options;
  bool open = true;
  std::unordered_map<Session*, std::weak_ptr<Session>> sessions;
  std::shared_ptr<GuessGuard> guesses;  // the process's one (ServerOptions::guard), or this server's
  ServerStats stats;
};

namespace {

std::string describe(const tcp::socket& s) {
  error_code ec;
  const tcp::endpoint ep = s.remote_endpoint(ec);
  if (ec) return "?";
  return ep.address().to_string() + ":" + std::to_string(ep.port());
}

std::string address_of(const tcp::socket& s) {
  error_code ec;
  const tcp::endpoint ep = s.remote_endpoint(ec);
  return ec ? std::string() : ep.address().to_string();
}

// "12:34:56 UTC", some duration from now: when a lockout ends, for the log.
std::string utc_after(std::chrono::steady_clock::duration d) {
  const std::time_t t =
      std::chrono::system_clock::to_time_t(std::chrono::system_clock::now() +
                                           std::chrono::duration_cast<std::chrono::system_clock::duration>(d));
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%H:%M:%S", &tm);
  return std::string(buf) + " UTC";
}

// One client: reads lines, hands them to the protocol in order, queues the replies.
class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, std::shared_ptr<LineServer::Core> core)
      : socket_(std::move(socket)),
        core_(std::move(core)),
        peer_(describe(socket_)),
        address_(address_of(socket_)),
        authenticated_(core_->options.secret.empty()),
        auth_timer_(socket_.get_executor()),
        guess_timer_(socket_.get_executor()) {}

  // How long the client has sent nothing.
  std::chrono::steady_clock::duration silent() const { return std::chrono::steady_clock::now() - last_heard_; }
  const std::string& peer() const { return peer_; }
  const std::string& address() const { return address_; }

  void start() {
    spdlog::info("{}: client {} connected", core_->options.name, peer_);
    if (core_->protocol) queue(core_->protocol->greeting());
    if (closed_) return;
    if (!authenticated_) arm_auth_deadline();
    read();
  }

  void close(const char* why) {
    if (closed_) return;
    closed_ = true;
    auth_timer_.cancel();
    guess_timer_.cancel();
    error_code ec;
    socket_.shutdown(tcp::socket::shutdown_both, ec);
    socket_.close(ec);
    core_->sessions.erase(this);
    spdlog::info("{}: client {} closed ({})", core_->options.name, peer_, why);
    if (core_->protocol && authenticated_) core_->protocol->client_left(peer_);
  }

  // A handler of the client's input: an exception ends that client, never the station (issue 38).
  template <typename F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      spdlog::error("{}: client {}: handling its input failed: {}; disconnected", core_->options.name, peer_, e.what());
      close("a handler failed");
    }
  }

 private:
  void read() {
    socket_.async_read_some(asio::buffer(buf_), [self = shared_from_this()](const error_code& ec, std::size_t n) {
      self->guarded([&] { self->on_read(ec, n); });
    });
  }

  void on_read(const error_code& ec, std::size_t n) {
    if (closed_) return;
    if (ec) {
      if (ec != asio::error::eof) {
        close(ec.message().c_str());
        return;
      }
      // The client has sent all it will: answer an unterminated last line, send what is queued,
      // then close.
      if (!discarding_ && !line_.empty()) handle_line();
      closing_ = true;
      write();
      return;
    }
    feed(buf_.data(), n);
    go_on();
  }

  // After a batch of input: read more, unless the session closes or waits to answer a secret.
  void go_on() {
    if (closed_ || paused_) return;
    if (closing_) {
      write();  // q: no more reading; close once the reply is out
      return;
    }
    read();
  }

  void feed(const char* p, std::size_t n) {
    const char* const end = p + n;
    const std::size_t max_line = core_->options.max_line;
    const bool cr = core_->options.cr_ends_line;
    while (p < end && !closed_ && !closing_ && !paused_) {
      if (after_cr_) {  // the LF of a CR LF pair: that line has been handled
        after_cr_ = false;
        if (*p == '\n') {
          ++p;
          continue;
        }
      }
      const char* nl = cr ? line_end(p, end) : static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      const char* stop = nl ? nl : end;
      if (!discarding_) {
        const std::size_t take = static_cast<std::size_t>(stop - p);
        if (line_.size() + take > max_line) {
          // Too long: answered once, the rest discarded up to the newline.
          discarding_ = true;
          std::string().swap(line_);
          if (core_->protocol) queue(core_->protocol->overlong().text);
        } else {
          line_.append(p, take);
        }
      }
      if (!nl) break;
      // Silence is counted from the last line, not the last byte: a client trickling bytes that never
      // make a line ("slowloris") is as silent as one that sends nothing, and makes room.
      last_heard_ = std::chrono::steady_clock::now();
      if (discarding_) {
        discarding_ = false;
      } else {
        handle_line();
      }
      line_.clear();
      after_cr_ = *nl == '\r';
      p = nl + 1;
    }
    // Waiting to answer a secret: what came after it is read when the answer has been given.
    if (paused_ && p < end) backlog_.append(p, end);
  }

  static const char* line_end(const char* p, const char* end) {
    for (; p < end; ++p)
      if (*p == '\n' || *p == '\r') return p;
    return nullptr;
  }

  // A client that has not given the secret in time is closed.
  void arm_auth_deadline() {
    auth_timer_.expires_after(core_->options.auth_deadline);
    auth_timer_.async_wait([self = shared_from_this()](const error_code& ec) {
      if (ec || self->closed_ || self->authenticated_) return;
      if (self->paused_) {  // it gave a secret in time, which waits for its answer (GuessGuard)
        self->arm_auth_deadline();
        return;
      }
      spdlog::warn("{}: client {} did not give the secret within {} s; closed", self->core_->options.name, self->peer_,
                   std::chrono::duration_cast<std::chrono::seconds>(self->core_->options.auth_deadline).count());
      self->queue(self->core_->protocol ? self->core_->protocol->auth_required() : std::string());
      self->closing_ = true;
      self->write();
    });
  }

  // The password command is checked here, whenever it comes (never logged, never handed to the
  // protocol, never echoed); before the secret only the handshake lines pass and the rest is refused.
  // True when the line has been dealt with here.
  bool gate_line() {
    const LineHandler::Gate g = core_->protocol->gate(line_);
    if (g.kind == LineHandler::Gate::Kind::password && !core_->options.secret.empty()) {
      attempt(g.password);
      return true;
    }
    if (authenticated_ || g.kind == LineHandler::Gate::Kind::allowed) return false;
    spdlog::debug("{}: client {}: a command before the secret: refused", core_->options.name, peer_);
    queue(core_->protocol->auth_required());
    return true;
  }

  // A secret given: answered when this address is free of its earlier wrong guesses (GuessGuard),
  // with reading paused until then so nothing sent after it runs first.
  void attempt(const std::string& secret_given) {
    const auto now = std::chrono::steady_clock::now();
    const auto at = core_->guesses->free_at(address_, now);
    if (at <= now) {
      answer(secret_given);
      return;
    }
    paused_ = true;
    pending_secret_ = secret_given;
    guess_timer_.expires_at(at);
    guess_timer_.async_wait([self = shared_from_this()](const error_code& ec) {
      if (ec || self->closed_) return;
      self->guarded([&] { self->resume(); });
    });
  }
  void resume() {
    {
      Session* self = this;
      self->paused_ = false;
      std::string s = std::move(self->pending_secret_);
      self->attempt(s);  // another connection of the address may have been answered first: wait again
      if (self->paused_ || self->closed_) return;
      std::string rest;
      rest.swap(self->backlog_);
      if (!rest.empty() && !self->closing_) self->feed(rest.data(), rest.size());
      self->go_on();
    }
  }

  void answer(const std::string& secret_given) {
    const bool ok = secret::equal(secret_given, core_->options.secret);
    queue(core_->protocol->auth_reply(ok));
    if (ok) {
      core_->guesses->right(address_);
      if (authenticated_) return;
      authenticated_ = true;
      auth_timer_.cancel();
      spdlog::info("{}: client {} authenticated", core_->options.name, peer_);
      return;
    }
    ++core_->stats.wrong_secrets;
    const auto now = std::chrono::steady_clock::now();
    if (core_->guesses->wrong(address_, now, core_->options.name)) {
      ++core_->stats.lockouts;
      const auto left = core_->guesses->locked_until(address_, now) - now;
      spdlog::warn("{}: {} locked out until {} ({} s) after {} wrong secrets; its connections are refused until then",
                   core_->options.name, address_, utc_after(left),
                   std::chrono::duration_cast<std::chrono::seconds>(left).count(),
                   core_->guesses->policy().lockout_after);
      closing_ = true;
      // Its other connections (waiting for answers, or logged out) go too: none holds a slot for
      // the lockout's ten minutes.
      std::vector<std::shared_ptr<Session>> same;
      for (auto& [p, w] : core_->sessions)
        if (auto s = w.lock(); s && s.get() != this && s->address() == address_) same.push_back(std::move(s));
      for (auto& s : same)
        if (!s->authenticated_) s->close("its address is locked out");
    } else if (++auth_failures_ >= core_->options.max_auth_failures) {
      spdlog::warn("{}: client {} gave a wrong secret {} times; closed", core_->options.name, peer_, auth_failures_);
      closing_ = true;
    } else {
      spdlog::warn("{}: client {} gave a wrong secret", core_->options.name, peer_);
    }
  }

  void handle_line() {
    if (!core_->protocol) return;
    if (gate_line()) return;
    core_->protocol->client_line(peer_);
    const Reply r = core_->protocol->handle(line_);
    if (spdlog::should_log(spdlog::level::debug))  // --log-level debug: what a client asked, what it got
      spdlog::debug("{}: client {}: '{}' -> '{}'", core_->options.name, peer_, one_line(line_.substr(0, 200)),
                    one_line(r.text.substr(0, 200)));
    queue(r.text);
    if (r.close) closing_ = true;
  }

  void queue(const std::string& text) {
    if (text.empty() || closed_) return;
    if (out_.size() + writing_.size() + text.size() > core_->options.max_output) {
      spdlog::warn("{}: client {} does not read its replies; disconnected", core_->options.name, peer_);
      close("output queue full");
      return;
    }
    out_ += text;
    write();
  }

  void write() {
    if (closed_ || !writing_.empty()) return;
    if (out_.empty()) {
      if (closing_) close("done");
      return;
    }
    writing_.swap(out_);
    asio::async_write(socket_, asio::buffer(writing_), [self = shared_from_this()](const error_code& ec, std::size_t) {
      if (self->closed_) return;
      if (ec) {
        self->close(ec.message().c_str());
        return;
      }
      self->writing_.clear();
      self->write();
    });
  }

  tcp::socket socket_;
  std::shared_ptr<LineServer::Core> core_;
  std::string peer_;
  std::string address_;  // the peer's address alone: what --allow, the guess delay and the per-address cap see
  std::array<char, 4096> buf_{};
  std::string line_;
  std::chrono::steady_clock::time_point last_heard_ = std::chrono::steady_clock::now();
  bool discarding_ = false;
  bool after_cr_ = false;  // the last line ended with a CR (cr_ends_line)
  std::string out_;      // queued
  std::string writing_;  // handed to async_write
  bool closing_ = false; // close once out_ and writing_ are sent
  bool closed_ = false;
  bool authenticated_;   // no secret, or the client gave it
  int auth_failures_ = 0;
  asio::steady_timer auth_timer_;
  bool paused_ = false;          // a secret waits until its address may be answered
  std::string pending_secret_;   // that secret
  std::string backlog_;          // what the client sent after it
  asio::steady_timer guess_timer_;
};

}  // namespace

LineServer::LineServer(asio::io_context& io, std::uint16_t port, LineHandler& protocol, ServerOptions options)
    : acceptor_(io), retry_(io), core_(std::make_shared<Core>()) {
  core_->protocol = &protocol;
  core_->options = std::move(options);
  core_->guesses = core_->options.guard ? core_->options.guard : std::make_shared<GuessGuard>(core_->options.guesses);
  const std::string where = core_->options.address + ":" + std::to_string(port);
  error_code ec;
  const asio::ip::address addr = asio::ip::make_address(core_->options.address, ec);
  if (ec) throw std::system_error(ec, core_->options.name + ": bad listening address " + core_->options.address);
  const tcp::endpoint ep(addr, port);
  acceptor_.open(ep.protocol(), ec);
  if (!ec) acceptor_.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(ep, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw std::system_error(ec, core_->options.name + ": cannot listen on " + where);
  port_ = acceptor_.local_endpoint().port();
  spdlog::info("{}: listening on {}:{}", core_->options.name, core_->options.address, port_);
  accept();
}

LineServer::~LineServer() { close(); }

std::size_t LineServer::client_count() const { return core_->sessions.size(); }

const ServerStats& LineServer::stats() const { return core_->stats; }

const ServerOptions& LineServer::options() const { return core_->options; }

void LineServer::set_secret(std::string secret) {
  if (secret == core_->options.secret) return;
  core_->options.secret = std::move(secret);
  std::vector<std::shared_ptr<Session>> live;
  for (auto& [p, w] : core_->sessions)
    if (auto s = w.lock()) live.push_back(std::move(s));
  for (auto& s : live) s->close("the secret changed");
  spdlog::info("{}: the secret changed (its file re-read on SIGHUP): {} client(s) of the old one closed",
               core_->options.name, live.size());
}

void LineServer::close() {
  if (!core_->open) return;
  core_->open = false;
  core_->protocol = nullptr;
  error_code ec;
  acceptor_.close(ec);
  retry_.cancel();
  std::vector<std::shared_ptr<Session>> live;
  for (auto& [p, w] : core_->sessions)
    if (auto s = w.lock()) live.push_back(std::move(s));
  for (auto& s : live) s->close("server closed");
  core_->sessions.clear();
}

namespace {

std::size_t per_address(const LineServer::Core& core, const std::string& address) {
  std::size_t n = 0;
  for (const auto& [p, w] : core.sessions)
    if (auto s = w.lock(); s && s->address() == address) ++n;
  return n;
}

// Every connection is taken: closes the one silent longest if it has been silent long enough.
bool make_room(LineServer::Core& core) {
  std::shared_ptr<Session> quietest;
  for (auto& [p, w] : core.sessions)
    if (auto s = w.lock(); s && (!quietest || s->silent() > quietest->silent())) quietest = std::move(s);
  if (!quietest || quietest->silent() < core.options.evict_idle_after) return false;
  const auto secs = std::chrono::duration_cast<std::chrono::seconds>(quietest->silent()).count();
  spdlog::warn("{}: all {} connections taken; closing {}, silent for {} s, to serve a new client", core.options.name,
               core.sessions.size(), quietest->peer(), secs);
  quietest->close("silent longest while the server was full");
  return true;
}

}  // namespace

void LineServer::accept() {
  acceptor_.async_accept([this, core = core_](const error_code& ec, tcp::socket socket) {
    if (!core->open) return;
    if (ec) {
      if (ec == asio::error::operation_aborted) return;
      // Out of descriptors and the like: try again after a back-off rather than spin (util/backoff.h),
      // said once a run.
      if (backoff_.failed())
        spdlog::error("{}: accept failed: {}; retrying every 100 ms to 1 s (said once until it works again)",
                      core->options.name, ec.message());
      retry_.expires_after(backoff_.delay());
      retry_.async_wait([this, core](const error_code& e) {
        if (!e && core->open) accept();
      });
      return;
    }
    if (const auto failed = backoff_.succeeded())
      spdlog::warn("{}: accepting again after {} failed accepts", core->options.name, failed);
    const std::string who = address_of(socket);
    const auto now = std::chrono::steady_clock::now();
    auto refuse = [&](Refusal why) {
      error_code ignored;
      if (core->protocol) asio::write(socket, asio::buffer(core->protocol->refusal(why)), ignored);
      socket.close(ignored);
    };
    if (!inet::allowed(core->options.allow, who)) {
      ++core->stats.refused_not_allowed;
      spdlog::warn("{}: connection from {} refused: not in --allow", core->options.name, who);
      refuse(Refusal::not_allowed);
    } else if (core->guesses->locked_until(who, now) > now) {
      ++core->stats.refused_locked_out;
      spdlog::warn("{}: connection from {} refused: locked out until {}: {}", core->options.name, who,
                   utc_after(core->guesses->locked_until(who, now) - now), core->guesses->lockout_cause(who));
      refuse(Refusal::locked_out);
    } else if (per_address(*core, who) >= core->options.max_per_address &&
               !(core->options.loopback_exempt && inet::is_loopback(who))) {
      ++core->stats.refused_per_address;
      spdlog::warn("{}: connection from {} refused: it has {} connections already (at most {} an address)",
                   core->options.name, who, per_address(*core, who), core->options.max_per_address);
      refuse(Refusal::busy);
    } else if (core->sessions.size() >= core->options.max_clients && !make_room(*core)) {
      ++core->stats.refused_busy;
      spdlog::warn("{}: {} clients already, none silent for {} s; connection from {} refused", core->options.name,
                   core->sessions.size(), core->options.evict_idle_after.count() / 1000.0, describe(socket));
      refuse(Refusal::busy);
    } else {
      error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);
      inet::enable_keepalive(socket.native_handle());
      auto s = std::make_shared<Session>(std::move(socket), core);
      core->sessions.emplace(s.get(), s);
      s->start();
    }
    accept();
  });
}

RotctldServer::RotctldServer(asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
                             ServerOptions options)
    : protocol_(station), server_(io, port, protocol_, std::move(options)) {}

RigctldServer::RigctldServer(asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
                             ServerOptions options)
    : protocol_(station), server_(io, port, protocol_, std::move(options)) {}

}  // namespace tb::netctl
