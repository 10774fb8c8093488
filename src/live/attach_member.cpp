#include "live/attach_member.h"

#include <fcntl.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <string_view>
#include <utility>

#include <spdlog/spdlog.h>

#include "menus/term/curses_terminal.h"
#include "menus/term/line_terminal.h"

namespace tb::app {

namespace {

// Plain lines into an outbox (the attached client's line mode): a LineTerminal's output rules.
class LineSink final : public term::LineOutput {
 public:
  LineSink(std::function<void(std::string_view)> out, bool crlf) : LineOutput(crlf), out_(std::move(out)) {}
  void flush() override {}
  bool closed() const override { return false; }

 protected:
  int next_key(std::optional<term::Duration>) override { return term::kEndOfInput; }
  void emit(std::string_view bytes) override { out_(bytes); }

 private:
  std::function<void(std::string_view)> out_;
};

}  // namespace

void Member::open_lines(bool crlf) {
  screen = std::make_unique<LineSink>([this](std::string_view s) { out->send(s); }, crlf);
  curses = nullptr;
}

bool Member::open_screen(ScreenPool& from, const std::string& term_type, int rows, int cols, spdlog::logger& log) {
  ScreenSlot made;
  auto& kept = from.kept;
  if (const auto k = std::find_if(kept.begin(), kept.end(), [&](const ScreenSlot& s) { return s.type == term_type; });
      k != kept.end()) {
    made = *k;
    kept.erase(k);
  } else {
    if (from.types >= kMaxScreenTypes) {
      log.info("attach: {} terminal types have screens already: '{}' gets plain lines", kMaxScreenTypes, term_type);
      return false;
    }
    int p[2];
    if (::pipe2(p, O_CLOEXEC) != 0) return false;
    ::fcntl(p[1], F_SETPIPE_SZ, 1 << 20);
    ::fcntl(p[0], F_SETFL, O_NONBLOCK);
    made.type = term_type;
    made.out = ::fdopen(p[1], "w");
    made.in = std::fopen("/dev/null", "r");
    made.pipe_rd = p[0];
    made.screen = (made.out && made.in) ? term::new_screen(term_type, made.out, made.in) : nullptr;
    if (!made.screen) {
      if (made.out) std::fclose(made.out);
      else ::close(p[1]);
      if (made.in) std::fclose(made.in);
      ::close(p[0]);
      log.info("attach: terminal type '{}' unknown here: plain lines", term_type);
      return false;
    }
    ++from.types;
  }
  slot = made;
  pool = &from;
  auto c = std::make_unique<term::CursesTerminal>(slot.screen, rows, cols);
  curses = c.get();
  screen = std::move(c);
  return true;
}

void Member::drain() {
  if (slot.pipe_rd < 0) return;
  std::fflush(slot.out);
  std::array<char, 16384> buf{};
  for (;;) {
    const ssize_t n = ::read(slot.pipe_rd, buf.data(), buf.size());
    if (n <= 0) break;
    if (!out->send(std::string_view(buf.data(), static_cast<std::size_t>(n)))) break;
  }
}

Member::~Member() {
  screen.reset();  // endwin: the client's terminal is given back as it was
  drain();
  if (slot.screen && pool) {
    // Whatever the client did not take is not for the next one.
    std::array<char, 16384> buf{};
    while (::read(slot.pipe_rd, buf.data(), buf.size()) > 0) {
    }
    pool->kept.push_back(slot);
  }
  if (!out->closed) {
    out->send(farewell);
    out->finish();
  }
}

std::string peer_name(int fd, const std::string& tty) {
  ucred cred{};
  socklen_t len = sizeof cred;
  std::string user = "?";
  if (::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cred, &len) == 0) {
    std::array<char, 4096> buf{};
    passwd pw{};
    passwd* found = nullptr;
    if (::getpwuid_r(cred.uid, &pw, buf.data(), buf.size(), &found) == 0 && found) user = found->pw_name;
    else user = "uid " + std::to_string(cred.uid);
  }
  std::string t = tty;
  if (t.rfind("/dev/", 0) == 0) t.erase(0, 5);
  return t.empty() ? user : user + " " + t;
}

}  // namespace tb::app
