#include "live/event_hooks.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <list>

#include <spdlog/spdlog.h>

#include "tracker/events.h"
#include "util/text.h"

extern char** environ;

namespace tb::app {

namespace asio = boost::asio;

std::optional<EventHook> parse_event_hook(const std::string& text, std::string& error) {
  EventHook h;
  h.command = text;
  // KIND[,KIND]=CMD when what is before the first '=' is a list of kinds; else the whole text is
  // the command (a command may hold '=' itself: VAR=1 cmd).
  if (const auto eq = text.find('='); eq != std::string::npos) {
    const std::string head = text.substr(0, eq);
    const auto& known = tracker::event_kinds();
    std::vector<std::string> kinds;
    bool all_kinds = !head.empty();
    for (const auto part : text::split(head, ',')) {
      const std::string k(part);
      if (std::find(known.begin(), known.end(), k) == known.end()) all_kinds = false;
      kinds.push_back(k);
    }
    const bool looks_like_kinds = !head.empty() && head.find_first_of(" \t/$") == std::string::npos &&
                                  std::all_of(head.begin(), head.end(), [](char c) { return c == ',' || c == '-' || (c >= 'a' && c <= 'z'); });
    if (looks_like_kinds && !all_kinds) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      error = "unknown event kind in '" + head + "'; expected " + list;
      return std::nullopt;
    }
    if (all_kinds) {
      h.kinds = std::move(kinds);
      h.command = text.substr(eq + 1);
    }
  }
  if (text::trim(h.command).empty()) {
    error = "no command";
    return std::nullopt;
  }
  return h;
}

namespace {

constexpr std::size_t kOutputKept = 4096;

struct Running {
  std::size_t hook = 0;
  std::string kind;
  std::string satellite;
  std::string label;  // "hook 1 (aos ISS)"
  pid_t pid = -1;
  int out_fd = -1;
  std::string output;
  std::size_t dropped = 0;
  std::chrono::steady_clock::time_point deadline;
  bool killed = false;

  void read_output() {
    char buf[4096];
    for (;;) {
      const ssize_t n = ::read(out_fd, buf, sizeof buf);
      if (n <= 0) return;
      const std::size_t room = kOutputKept > output.size() ? kOutputKept - output.size() : 0;
      const std::size_t take = std::min(room, static_cast<std::size_t>(n));
      output.append(buf, take);
      dropped += static_cast<std::size_t>(n) - take;
    }
  }
};

}  // namespace

struct EventHooks::Impl {
  Impl(asio::io_context& io, std::vector<EventHook> hooks, std::chrono::seconds limit, spdlog::logger& log)
      : hooks(std::move(hooks)), limit(limit), log(log), timer(io) {}
  std::vector<EventHook> hooks;
  std::chrono::seconds limit;
  spdlog::logger& log;
  asio::steady_timer timer;
  std::list<Running> running;
  // Process groups whose `sh` has ended while something it started in the background still runs
  // ("(sleep 300) &"): killed at the hook's limit, or when trakbox stops (issue 38).
  struct Lingering {
    pid_t pgid;
    std::string label;
    std::chrono::steady_clock::time_point deadline;
  };
  std::list<Lingering> lingering;
  bool polling = false;

  void spawn(std::size_t k, const tracker::Event& e) {
    Running r;
    r.hook = k;
    r.kind = e.kind;
    r.satellite = e.satellite;
    r.label = "hook " + std::to_string(k + 1) + " (" + e.kind + (e.satellite.empty() ? "" : " " + e.satellite) + ")";
    int p[2];
    if (::pipe2(p, O_CLOEXEC) != 0) {
      log.error("{}: not started: {}", r.label, std::strerror(errno));
      return;
    }
    // The environment: the station's own, without TRAKBOX_ variables of an outer event, and the event.
    std::vector<std::string> env;
    for (char** v = environ; v && *v; ++v)
      if (std::strncmp(*v, "TRAKBOX_", 8) != 0) env.emplace_back(*v);
    for (const auto& [name, value] : tracker::event_environment(e)) env.push_back(name + "=" + value);
    std::vector<char*> envp;
    for (auto& s : env) envp.push_back(s.data());
    envp.push_back(nullptr);
    std::string sh = "/bin/sh", dash_c = "-c", cmd = hooks[k].command;
    char* argv[] = {sh.data(), dash_c.data(), cmd.data(), nullptr};

    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, p[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&fa, p[1], STDERR_FILENO);
    posix_spawnattr_t at;
    posix_spawnattr_init(&at);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int sig : {SIGTERM, SIGINT, SIGHUP, SIGPIPE, SIGCHLD}) sigaddset(&defaults, sig);
    posix_spawnattr_setsigmask(&at, &none);
    posix_spawnattr_setsigdefault(&at, &defaults);
    posix_spawnattr_setpgroup(&at, 0);  // its own group: the limit kills what it started too
    posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const int rc = posix_spawn(&r.pid, argv[0], &fa, &at, argv, envp.data());
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&at);
    ::close(p[1]);
    if (rc != 0) {
      ::close(p[0]);
      log.error("{}: not started: {}", r.label, std::strerror(rc));
      return;
    }
    ::fcntl(p[0], F_SETFL, O_NONBLOCK);
    r.out_fd = p[0];
    r.deadline = std::chrono::steady_clock::now() + limit;
    log.info("{}: started (pid {}): {}", r.label, r.pid, hooks[k].command);
    running.push_back(std::move(r));
    poll();
  }

  // Every 100 ms while hooks run: their output, their end, their limit.
  void poll() {
    if (polling) return;
    polling = true;
    timer.expires_after(std::chrono::milliseconds(100));
    timer.async_wait([this](const boost::system::error_code& ec) {
      polling = false;
      if (ec) return;
      try {  // a hook's output and end are outside input: never an exception out of the loop
        check();
      } catch (const std::exception& e) {
        log.error("hooks: checking the running hooks failed: {}", e.what());
      }
      if (!running.empty() || !lingering.empty()) poll();
    });
  }
  void check() {
    const auto now = std::chrono::steady_clock::now();
    for (auto it = running.begin(); it != running.end();) {
      Running& r = *it;
      r.read_output();
      int status = 0;
      const pid_t done = ::waitpid(r.pid, &status, WNOHANG);
      if (done == r.pid) {
        r.read_output();
        finished(r, status);
        ::close(r.out_fd);
        if (group_alive(r.pid)) {
          if (r.killed) ::kill(-r.pid, SIGKILL);
          else lingering.push_back({r.pid, r.label, r.deadline});
        }
        it = running.erase(it);
        continue;
      }
      if (!r.killed && now >= r.deadline) {
        r.killed = true;
        ::kill(-r.pid, SIGKILL);
        log.warn("{}: still running after its limit of {} s: killed", r.label, limit.count());
      }
      ++it;
    }
    for (auto it = lingering.begin(); it != lingering.end();) {
      if (!group_alive(it->pgid)) {
        it = lingering.erase(it);
      } else if (now >= it->deadline) {
        ::kill(-it->pgid, SIGKILL);
        log.warn("{}: what it left running in the background was still running at its limit of {} s: killed",
                 it->label, limit.count());
        it = lingering.erase(it);
      } else {
        ++it;
      }
    }
  }
  // Whether any process of the group is left (its leader, `sh`, has been reaped: the group id is not
  // reused while a member lives).
  static bool group_alive(pid_t pgid) { return ::kill(-pgid, 0) == 0 || errno == EPERM; }
  void finished(const Running& r, int status) {
    std::string out = r.output;
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    for (auto& c : out)
      if (c == '\n') c = '|';
    if (r.dropped) out += " (" + std::to_string(r.dropped) + " more bytes not kept)";
    if (r.killed) {
      log.warn("{}: killed at its limit; output: {}", r.label, out.empty() ? "none" : out);
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      log.info("{}: exit status 0; output: {}", r.label, out.empty() ? "none" : out);
    } else if (WIFEXITED(status)) {
      log.warn("{}: failed, exit status {} (not retried); output: {}", r.label, WEXITSTATUS(status),
               out.empty() ? "none" : out);
    } else {
      log.warn("{}: ended by signal {} (not retried); output: {}", r.label, WTERMSIG(status), out.empty() ? "none" : out);
    }
  }
};

EventHooks::EventHooks(asio::io_context& io, std::vector<EventHook> hooks, std::chrono::seconds limit,
                       spdlog::logger& log)
    : impl_(std::make_unique<Impl>(io, std::move(hooks), limit, log)) {}

EventHooks::~EventHooks() {
  for (auto& r : impl_->running) {
    ::kill(-r.pid, SIGKILL);
    int status = 0;
    ::waitpid(r.pid, &status, 0);
    ::close(r.out_fd);
    impl_->log.warn("{}: killed: trakbox is stopping", r.label);
  }
  for (auto& g : impl_->lingering) {
    if (!Impl::group_alive(g.pgid)) continue;
    ::kill(-g.pgid, SIGKILL);
    impl_->log.warn("{}: what it left running in the background killed: trakbox is stopping", g.label);
  }
}

void EventHooks::fire(const tracker::Event& e) {
  Impl& m = *impl_;
  for (std::size_t k = 0; k < m.hooks.size(); ++k) {
    const auto& kinds = m.hooks[k].kinds;
    if (!kinds.empty() && std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) continue;
    const bool busy = std::any_of(m.running.begin(), m.running.end(),
                                  [&](const Running& r) { return r.hook == k && r.kind == e.kind && r.satellite == e.satellite; });
    if (busy) {
      m.log.warn("hook {} ({}{}): not started: it still runs for the last one", k + 1, e.kind,
                 e.satellite.empty() ? "" : " " + e.satellite);
      continue;
    }
    try {
      m.spawn(k, e);
    } catch (const std::exception& x) {
      m.log.error("hook {} ({}): not started: {}", k + 1, e.kind, x.what());
    }
  }
}

}  // namespace tb::app
