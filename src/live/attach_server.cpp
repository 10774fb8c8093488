#include "live/attach_server.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/local/stream_protocol.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/streambuf.hpp>
#include <boost/asio/write.hpp>
#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "live/attach_internal.h"
#include "live/attach_member.h"
#include "live/station_socket.h"
#include "menus/term/curses_terminal.h"
#include "util/backoff.h"
#include "util/safe_text.h"

namespace tb::app {

namespace asio = boost::asio;
using stream = asio::local::stream_protocol;

namespace {

constexpr std::size_t kTranscriptLimit = 16 * 1024;
constexpr int kReplayLines = 30;
constexpr int kMaxRows = 100, kMaxCols = 250;  // a screen's refresh stays far below the pipe's size

}  // namespace

struct AttachServer::Impl {
  // The menus' terminal (see the header): what they write to every attached client's screen (and
  // kept for a client that comes later), their keys from the client that has the keyboard.
  class Mux final : public term::Terminal {
   public:
    explicit Mux(Impl& s) : s_(s) {}
    void write(std::string_view text) override {
      s_.transcript.append(text);
      if (s_.transcript.size() > kTranscriptLimit) s_.transcript.erase(0, s_.transcript.size() - kTranscriptLimit / 2);
      s_.each([&](term::Terminal& t, Member&) { t.write(text); });
    }
    void bell() override {
      s_.each([](term::Terminal& t, Member&) { t.bell(); });
    }
    void clear() override {
      s_.transcript.clear();
      s_.live_block.clear();
      s_.each([](term::Terminal& t, Member&) { t.clear(); });
    }
    void flush() override {
      s_.each([](term::Terminal& t, Member&) { t.flush(); });
    }
    void live(const std::vector<std::string>& lines) override {
      s_.live_block = lines;
      s_.each([&](term::Terminal& t, Member&) { t.live(lines); });
    }
    void end_live() override {
      // The block stays on the screen as text above what follows.
      for (const auto& l : s_.live_block) s_.transcript.append(l).append("\n");
      s_.live_block.clear();
      s_.each([](term::Terminal& t, Member&) { t.end_live(); });
    }
    // The curses screens' status line, behind each client's note of who has the keyboard.
    void status(std::string_view text) override {
      s_.status_text.assign(text);
      s_.each([&](term::Terminal& t, Member& m) {
        if (m.curses) t.status(s_.keyboard_note(m) + s_.status_text);
      });
    }
    void graphics(const term::Graphics& g) override {
      s_.each([&](term::Terminal& t, Member&) { t.graphics(g); });
    }
    // The shape of the screen of the client with the keyboard (a line client's, 80 x 24 for none).
    bool full_screen() const override {
      Member* h = s_.holder();
      return h && h->curses;
    }
    int columns() const override {
      Member* h = s_.holder();
      return h ? h->screen->columns() : 80;
    }
    int rows() const override {
      Member* h = s_.holder();
      return h ? h->screen->rows() : 24;
    }
    bool closed() const override { return false; }

   protected:
    int next_key(std::optional<term::Duration> timeout) override {
      flush();
      const auto deadline = timeout ? std::optional(std::chrono::steady_clock::now() + *timeout) : std::nullopt;
      for (;;) {
        if (Member* h = s_.holder(); h && !h->keys.empty()) {
          const int k = h->keys.front();
          h->keys.pop_front();
          return k;
        } else if (h && h->input_ended) {
          s_.gone(*h, "");  // every key it sent was taken, and the menus answered
        }
        std::optional<term::Duration> left;  // the wait returns after any work: a client's keys come so
        if (deadline) {
          const auto now = std::chrono::steady_clock::now();
          if (now >= *deadline) return term::kTimeout;
          left = *deadline - now;
        }
        s_.wait(-1, left);
      }
    }

   private:
    Impl& s_;
  };

  Impl(asio::io_context& io, term::WaitReadable wait, AttachServerOptions o, spdlog::logger& log)
      : io(io), wait(std::move(wait)), opt(std::move(o)), log(log), acceptor(io), retry(io), mux(*this) {}

  asio::io_context& io;
  term::WaitReadable wait;
  AttachServerOptions opt;
  spdlog::logger& log;
  stream::acceptor acceptor;
  asio::steady_timer retry;      // the next accept after a failed one
  util::AcceptBackoff backoff;
  std::size_t greeting = 0;      // connections that have not said what they want yet
  bool refusing = false;         // a cap refuses newcomers (logged once a run)
  Mux mux;
  ScreenPool pool;               // before the members: they give their screens back to it
  SocketId made{};               // the socket file this server made
  std::vector<std::unique_ptr<Member>> members;
  std::vector<std::shared_ptr<Outbox>> subscribers;
  int next_id = 1;
  int keyboard = 0;  // the member id with the keyboard (0: nobody)
  std::string transcript;
  std::vector<std::string> live_block;
  std::string status_text;
  bool sweeping = false;

  Member* holder() {
    for (auto& m : members)
      if (m->id == keyboard && !m->gone) return m.get();
    return nullptr;
  }
  template <typename F>
  void each(F&& f) {
    for (auto& m : members) {
      if (m->gone) continue;
      f(*m->screen, *m);
      sent(*m);
    }
  }
  // What a member's screen wrote goes to its client; a client whose output backed up is gone.
  void sent(Member& m) {
    m.drain();
    if (m.out->closed) gone(m, m.out->overflowed ? "stopped reading (output backed up): disconnected" : "");
  }
  void gone(Member& m, const std::string& why) {
    if (m.gone) return;
    m.gone = true;
    if (!why.empty()) log.warn("attach: {} {}", m.who, why);
    else log.info("attach: {} detached", m.who);
    if (keyboard == m.id) keyboard = 0;
    asio::post(io, [this] { sweep(); });
  }
  // Members gone are destroyed outside any loop over them.
  void sweep() {
    if (sweeping) return;
    sweeping = true;
    const auto before = members.size();
    std::erase_if(members, [](const std::unique_ptr<Member>& m) { return m->gone; });
    sweeping = false;
    if (members.size() != before) announce_keyboard();
  }
  std::string keyboard_note(const Member& m) {
    const Member* h = holder();
    if (h == &m) return "[KEYBOARD: you  ^]=detach] ";
    if (h) return "[keyboard: " + h->who + "  ^T=take it  ^]=detach] ";
    return "[keyboard free: type to take it  ^]=detach] ";
  }
  void announce_keyboard() {
    for (auto& m : members) {
      if (m->gone) continue;
      if (m->curses) {
        m->screen->status(keyboard_note(*m) + status_text);
      } else {
        const std::string note = keyboard_note(*m);
        if (note != m->told) {
          m->told = note;
          m->told_at = std::chrono::steady_clock::now();
          m->screen->write("\n*** " + note + "***\n");
        }
      }
      sent(*m);
    }
  }
  // The screen as it was, for a client that just came (or whose screen was laid out again).
  void replay(Member& m) {
    term::Terminal& t = *m.screen;
    t.clear();
    std::size_t from = transcript.size();
    for (int n = 0; n <= kReplayLines && from > 0;) {
      from = transcript.rfind('\n', from - 1);
      if (from == std::string::npos) {
        from = 0;
        break;
      }
      ++n;
      if (n > kReplayLines) ++from;
    }
    t.write(std::string_view(transcript).substr(from));
    if (!live_block.empty()) t.live(live_block);
    if (m.curses) t.status(keyboard_note(m) + status_text);
    t.flush();
    sent(m);
  }

  // Accepts, backing off on errors (util/backoff.h): out of descriptors never spins the loop.
  void accept() {
    acceptor.async_accept([this](const boost::system::error_code& ec, stream::socket sock) {
      if (ec == asio::error::operation_aborted || !acceptor.is_open()) return;
      if (ec) {
        if (backoff.failed())
          log.error("attach: accept failed: {}; retrying every {} ms to 1 s (said once until it works again)",
                    ec.message(), util::AcceptBackoff::kFirst.count());
        retry.expires_after(backoff.delay());
        retry.async_wait([this](const boost::system::error_code& e) {
          if (!e && acceptor.is_open()) accept();
        });
        return;
      }
      if (const auto failed = backoff.succeeded()) log.warn("attach: accepting again after {} failed accepts", failed);
      try {
        greet(std::move(sock));
      } catch (const std::exception& e) {  // nothing a client does may end the station
        log.error("attach: a new connection failed: {}; dropped", e.what());
      }
      accept();
    });
  }
  // A client refused for a cap: told why, the station goes on (logged once until one is admitted).
  void refuse_cap(const std::shared_ptr<Outbox>& out, const std::string& what, std::size_t cap) {
    if (!refusing) log.warn("attach: {} (at most {}): newcomers refused until one leaves", what, cap);
    refusing = true;
    out->send("refused: " + what + " (at most " + std::to_string(cap) + ")\n");
    out->finish();
  }
  // A handler of a client's input: an exception ends that client, never the station.
  template <typename F>
  void guarded(const char* what, const std::shared_ptr<Outbox>& out, F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      log.error("attach: {} failed: {}; that client is dropped", what, e.what());
      out->close();
    }
  }
  // The first line says what the client wants: "status", "events" or "attach {json}".
  void greet(stream::socket sock) {
    auto out = std::make_shared<Outbox>(asio::posix::stream_descriptor(io, sock.release()), opt.output_limit);
    if (greeting >= kMaxGreeting) {
      refuse_cap(out, "too many connections still to say what they want", kMaxGreeting);
      return;
    }
    ++greeting;
    // The longest first line, a `trakbox log import` with its file (a local socket).
    auto buf = std::make_shared<asio::streambuf>(kMaxRequestBytes);
    auto timer = std::make_shared<asio::steady_timer>(io, std::chrono::seconds(10));
    timer->async_wait([out](const boost::system::error_code& ec) {
      if (!ec) out->close();
    });
    asio::async_read_until(out->sock, *buf, '\n', [this, out, buf, timer](const boost::system::error_code& ec, std::size_t n) {
      --greeting;
      timer->cancel();
      if (ec) {
        out->close();
        return;
      }
      guarded("a request", out, [&] { request(out, *buf, n); });
    });
  }
  // The first line of a connection, and what came after it.
  void request(const std::shared_ptr<Outbox>& out, asio::streambuf& buf, std::size_t n) {
    {
      std::string line(asio::buffers_begin(buf.data()), asio::buffers_begin(buf.data()) + static_cast<long>(n));
      buf.consume(n);
      std::string rest(asio::buffers_begin(buf.data()), asio::buffers_end(buf.data()));
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
      if (line == "status") {
        out->send(opt.status().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        out->finish();
      } else if (line == "events") {
        subscribe(out);
      } else if (line.rfind("log ", 0) == 0 && opt.log) {
        opt.log(line.substr(4), [out](std::string reply) { out->send(reply + "\n"); });
      } else if (opt.is_command && opt.is_command(line)) {
        out->send(text::safe_text(opt.command(line)) + "\n");
        out->finish();
      } else if (line.rfind("attach", 0) == 0 && !opt.menus) {
        out->send("refused: this trakbox's menus are on its own terminal (pid " + std::to_string(::getpid()) +
                  "); status and events answer here\n");
        out->finish();
      } else if (line.rfind("attach", 0) == 0) {
        attach(out, line.size() > 6 ? line.substr(6) : "", rest);
      } else {
        out->send("trakbox: unknown request; expected status, events or attach\n");
        out->finish();
      }
    }
  }

  // An events client: its line of each event; reading its socket notices at once when it leaves.
  void subscribe(const std::shared_ptr<Outbox>& out) {
    std::erase_if(subscribers, [](const auto& s) { return s->closed; });
    if (subscribers.size() >= kMaxSubscribers) {
      refuse_cap(out, "too many events clients", kMaxSubscribers);
      return;
    }
    refusing = false;
    subscribers.push_back(out);
    watch(out, std::make_shared<std::array<char, 256>>());
  }
  void watch(const std::shared_ptr<Outbox>& out, const std::shared_ptr<std::array<char, 256>>& scratch) {
    out->sock.async_read_some(asio::buffer(*scratch), [this, out, scratch](const boost::system::error_code& ec, std::size_t) {
      if (ec == asio::error::operation_aborted || out->closed) return;
      if (!ec) {
        watch(out, scratch);  // what an events client sends is not read: it is dropped
        return;
      }
      out->close();  // it left (or its socket failed): noticed now, not at the next event
      std::erase_if(subscribers, [](const auto& s) { return s->closed; });
    });
  }

  void attach(const std::shared_ptr<Outbox>& out, const std::string& hello_text, const std::string& rest) {
    std::string why;
    const auto hello = parse_attach_hello(hello_text, why);
    if (!hello) {
      log.warn("attach: a greeting refused: {}", why);
      out->send("refused: " + why + "\n");
      out->finish();
      return;
    }
    std::erase_if(members, [](const std::unique_ptr<Member>& m) { return m->gone; });
    if (members.size() >= kMaxAttached) {
      refuse_cap(out, "too many attached terminals", kMaxAttached);
      return;
    }
    refusing = false;
    auto m = std::make_unique<Member>();
    m->id = next_id++;
    m->out = out;
    m->who = peer_name(out->sock.native_handle(), hello->tty);
    const std::string& term_type = hello->term;
    const int rows = static_cast<int>(std::clamp<long long>(hello->rows, 5, kMaxRows));
    const int cols = static_cast<int>(std::clamp<long long>(hello->cols, 20, kMaxCols));
    if (!hello->full_screen || term_type.empty() || !m->open_screen(pool, term_type, rows, cols, log))
      m->open_lines(hello->crlf);
    log.info("attach: {} attached ({})", m->who, m->curses ? "full screen " + term_type : std::string("lines"));
    Member& ref = *m;
    members.push_back(std::move(m));
    out->send("ok\n");  // the session follows
    if (!m_is_line(ref)) ref.screen->status(keyboard_note(ref) + status_text);
    else ref.screen->write("trakbox: attached to the running station; Ctrl-] detaches, Ctrl-T takes the keyboard\n");
    replay(ref);
    announce_keyboard();
    if (!rest.empty()) input(ref, rest);
    read(ref);
  }
  static bool m_is_line(const Member& m) { return m.curses == nullptr; }

  // --tty with --service: the serial port is a client for good (it never detaches).
  void add_serial(int fd, const std::string& who) {
    auto out = std::make_shared<Outbox>(asio::posix::stream_descriptor(io, fd), opt.output_limit);
    auto m = std::make_unique<Member>();
    m->id = next_id++;
    m->out = out;
    m->who = who;
    m->permanent = true;
    m->open_lines(true);
    log.info("attach: the menus on {} too", who);
    Member& ref = *m;
    members.push_back(std::move(m));
    replay(ref);
    read(ref);
  }

  void read(Member& m) {
    const int id = m.id;
    m.out->sock.async_read_some(asio::buffer(m.rbuf), [this, id](const boost::system::error_code& ec, std::size_t n) {
      Member* m = find(id);
      if (!m || m->gone) return;
      try {
        on_read(*m, ec, n);
      } catch (const std::exception& e) {
        log.error("attach: {}'s input failed: {}; detached", m->who, e.what());
        gone(*m, "");
      }
    });
  }
  void on_read(Member& member, const boost::system::error_code& ec, std::size_t n) {
    {
      Member* m = &member;
      if (ec) {
        if (ec == asio::error::eof && keyboard == m->id && !m->keys.empty()) {
          m->input_ended = true;  // its answers are still to come (next_key detaches it after)
          return;
        }
        gone(*m, "");
        return;
      }
      input(*m, std::string(m->rbuf.data(), n));
      if (!m->gone) read(*m);
    }
  }
  Member* find(int id) {
    for (auto& m : members)
      if (m->id == id) return m.get();
    return nullptr;
  }

  void input(Member& m, const std::string& data) {
    const ClientFrames f = m.frames.feed(data);
    for (const auto& [r, c] : f.sizes) {
      if (!m.curses) continue;
      m.curses->resize(std::clamp(r, 5, kMaxRows), std::clamp(c, 20, kMaxCols));
      replay(m);
    }
    for (const int key : decode_keys(f.bytes)) {
      // Ctrl-C leaves trakbox at its console; attached, leaving is detaching.
      if ((key == kDetachKey || key == 3) && !m.permanent) {
        gone(m, "");
        return;
      }
      if (key == kTakeOverKey || keyboard == 0) {
        if (keyboard != m.id) {
          keyboard = m.id;
          log.info("attach: {} has the keyboard", m.who);
          announce_keyboard();
        }
        if (key == kTakeOverKey) continue;
      }
      if (keyboard == m.id) {
        m.keys.push_back(key);
      } else if (!m.curses && std::chrono::steady_clock::now() - m.told_at > std::chrono::seconds(2)) {
        m.told.clear();  // say again who has it (at most every 2 s, however many keys come)
        announce_keyboard();
      }
    }
  }
};

AttachServer::AttachServer(asio::io_context& io, term::WaitReadable wait, AttachServerOptions options,
                           spdlog::logger& log)
    : impl_(std::make_unique<Impl>(io, std::move(wait), std::move(options), log)) {
  // Clients are written to as descriptors (write(2), not send with MSG_NOSIGNAL): one that went
  // away must be an EPIPE for that client, never a SIGPIPE that ends the station.
  std::signal(SIGPIPE, SIG_IGN);
  const std::string& path = impl_->opt.path;
  if (path.size() >= sizeof(sockaddr_un{}.sun_path))
    throw std::runtime_error(path + ": too long for a Unix socket (at most 107 bytes)");
  impl_->made = bind_socket(impl_->acceptor, path);
  impl_->accept();
}

AttachServer::~AttachServer() {
  boost::system::error_code ec;
  impl_->acceptor.close(ec);
  for (auto& s : impl_->subscribers) s->finish();
  // The station stops: each client is told so, its screen given back (endwin) and all of it
  // written before the loop ends, so an attached terminal is never left in the menus' full screen.
  std::vector<std::shared_ptr<Outbox>> outs;
  for (auto& m : impl_->members) {
    m->farewell = "\r\n[the station stopped: this session ends]\r\n";
    outs.push_back(m->out);
  }
  impl_->members.clear();
  for (auto& o : outs) o->flush_now(std::chrono::milliseconds(500));
  remove_socket(impl_->opt.path, impl_->made);
}

term::Terminal& AttachServer::terminal() { return impl_->mux; }

void AttachServer::publish(const nlohmann::json& event) {
  const std::string line = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  for (auto& s : impl_->subscribers)
    if (!s->send(line) && s->overflowed) impl_->log.warn("events: a reader stopped reading: disconnected");
  std::erase_if(impl_->subscribers, [](const auto& s) { return s->closed; });
}

void AttachServer::add_serial(int fd, const std::string& who) { impl_->add_serial(fd, who); }

void AttachServer::detach_keyboard() {
  if (Member* h = impl_->holder()) impl_->gone(*h, "");
}

std::vector<std::string> AttachServer::attached() const {
  std::vector<std::string> out;
  for (const auto& m : impl_->members)
    if (!m->gone) out.push_back(m->who);
  return out;
}

std::string AttachServer::keyboard() const {
  const Member* h = impl_->holder();
  return h ? h->who : std::string();
}

const std::string& AttachServer::path() const { return impl_->opt.path; }

}  // namespace tb::app
