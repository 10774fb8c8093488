#include "rotator/hamlib.h"

#include <hamlib/rotator.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <csignal>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <pthread.h>

namespace tb::rotator {

namespace {

using SteadyClock = std::chrono::steady_clock;

// Hamlib writes its debug messages to stderr, which the UI owns: route them to spdlog instead.
int hamlib_debug_to_spdlog(enum rig_debug_level_e level, rig_ptr_t, const char* fmt, va_list ap) {
  char buf[512];
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  std::string line(buf);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  if (line.empty()) return 0;
  if (level <= RIG_DEBUG_ERR)
    spdlog::debug("hamlib: {}", line);
  else
    spdlog::trace("hamlib: {}", line);
  return 0;
}

void quiet_hamlib() {
  static std::once_flag once;
  std::call_once(once, [] {
    rig_set_debug_callback(hamlib_debug_to_spdlog, nullptr);
    rig_set_debug(RIG_DEBUG_WARN);
  });
}

std::string hamlib_error(int rc) {
  const char* e = rigerror2(rc);
  std::string s = e ? e : "error";
  // Keep the first line (the error name); Hamlib may append its debug trail.
  auto nl = s.find('\n');
  if (nl != std::string::npos) s.resize(nl);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  if (s.empty()) s = "error " + std::to_string(rc);
  return s;
}

// A broken TCP link must not kill the process with SIGPIPE: block it on the worker thread (the
// write then fails with EPIPE) and drain any that is pending.
void block_sigpipe() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}
void drain_sigpipe() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGPIPE);
  timespec zero{0, 0};
  while (sigtimedwait(&set, nullptr, &zero) > 0) {
  }
}

std::string default_label(const HamlibOptions& o) {
  if (o.model == ROT_MODEL_NETROTCTL) return "rotctld " + o.pathname;
  std::string s = "hamlib " + std::to_string(o.model) + " " + o.pathname;
  if (o.baud > 0) s += " " + std::to_string(o.baud);
  return s;
}

Drive motion_of(double delta, double eps) {
  if (delta > eps) return Drive::increase;
  if (delta < -eps) return Drive::decrease;
  return Drive::stop;
}

}  // namespace

struct HamlibRotator::Shared {
  HamlibOptions opt;
  std::string label;
  std::mutex m;
  std::condition_variable cv;
  bool quit = false;
  bool done = false;
  // Commands for the worker.
  std::optional<AzEl> pending_pos;
  bool pending_stop = false;
  // The worker's report.
  bool connected = false;
  Health health{LinkState::connecting, "connecting", 0};
  std::optional<AzEl> pos;
  AxisMotion motion;
  Range az_range{0.0, 360.0};

  void run();
  ROT* connect(std::string& error);
  void set_fault(const std::string& message);
  bool wait(std::chrono::milliseconds d);  // false when told to quit
};

bool HamlibRotator::Shared::wait(std::chrono::milliseconds d) {
  std::unique_lock lk(m);
  cv.wait_for(lk, d, [&] { return quit; });
  return !quit;
}

void HamlibRotator::Shared::set_fault(const std::string& message) {
  std::lock_guard lk(m);
  connected = false;
  health.state = LinkState::fault;
  health.message = message;
  pos.reset();
  motion = {};
  pending_pos.reset();  // motion commands stop: nothing queued is replayed after a reconnect
  pending_stop = false;
}

ROT* HamlibRotator::Shared::connect(std::string& error) {
  ROT* rot = rot_init(opt.model);
  if (!rot) {
    error = "Hamlib has no rotator model " + std::to_string(opt.model);
    return nullptr;
  }
  auto conf = [&](const char* name, const std::string& value) {
    token_t tok = rot_token_lookup(rot, name);
    if (tok != 0) rot_set_conf(rot, tok, value.c_str());
  };
  conf("rot_pathname", opt.pathname);
  conf("timeout", std::to_string(opt.io_timeout.count()));
  conf("retry", "0");
  if (opt.baud > 0) conf("serial_speed", std::to_string(opt.baud));
  int rc = rot_open(rot);
  drain_sigpipe();
  if (rc != RIG_OK) {
    error = hamlib_error(rc);
    rot_cleanup(rot);
    return nullptr;
  }
  return rot;
}

void HamlibRotator::Shared::run() {
  block_sigpipe();
  auto backoff = opt.backoff_min;
  bool reported = false;  // a failed attempt has been logged since the last success
  for (;;) {
    {
      std::lock_guard lk(m);
      if (quit) break;
    }
    std::string error;
    ROT* rot = connect(error);
    if (!rot) {
      std::string msg = "cannot connect to " + label + ": " + error + "; retrying in " +
                        std::to_string(backoff.count()) + " ms";
      set_fault(msg);
      if (!reported) spdlog::warn("rotator: {}", msg);
      reported = true;
      if (!wait(backoff)) break;
      backoff = std::min(backoff * 2, opt.backoff_max);
      continue;
    }
    {
      std::lock_guard lk(m);
      connected = true;
      health.state = LinkState::ok;
      health.message.clear();
      ++health.connects;
      pending_pos.reset();
      pending_stop = false;
      az_range = {rot->state.min_az, rot->state.max_az};
      if (az_range.empty()) az_range = {0.0, 360.0};
    }
    spdlog::info("rotator: connected to {}", label);
    reported = false;
    backoff = opt.backoff_min;

    std::string lost;
    auto next_poll = SteadyClock::now();
    std::optional<AzEl> last;
    for (;;) {
      std::optional<AzEl> cmd;
      bool stop_now = false;
      {
        std::unique_lock lk(m);
        cv.wait_until(lk, next_poll, [&] { return quit || pending_stop || pending_pos.has_value(); });
        if (quit) break;
        stop_now = pending_stop;
        pending_stop = false;
        cmd = pending_pos;
        pending_pos.reset();
      }
      int rc = RIG_OK;
      if (stop_now) {
        rc = rot_stop(rot);
        if (rc == -RIG_ENAVAIL || rc == -RIG_ENIMPL) rc = RIG_OK;  // nothing moving to stop
      }
      if (rc == RIG_OK && cmd) rc = rot_set_position(rot, static_cast<azimuth_t>(cmd->az), static_cast<elevation_t>(cmd->el));
      if (rc == RIG_OK && SteadyClock::now() >= next_poll) {
        azimuth_t az = 0;
        elevation_t el = 0;
        rc = rot_get_position(rot, &az, &el);
        if (rc == RIG_OK) {
          AzEl now{az, el};
          std::lock_guard lk(m);
          if (last) motion = {motion_of(now.az - last->az, 0.05), motion_of(now.el - last->el, 0.05)};
          pos = now;
          last = now;
        }
        next_poll = SteadyClock::now() + opt.poll;
      }
      drain_sigpipe();
      if (rc != RIG_OK) {
        lost = hamlib_error(rc);
        break;
      }
    }
    rot_close(rot);
    rot_cleanup(rot);
    drain_sigpipe();
    {
      std::lock_guard lk(m);
      if (quit) break;
    }
    std::string msg = "lost " + label + ": " + lost + "; motion stopped, reconnecting";
    set_fault(msg);
    spdlog::warn("rotator: {}", msg);
    reported = false;
    if (!wait(backoff)) break;
  }
  std::lock_guard lk(m);
  connected = false;
  done = true;
  cv.notify_all();
}

HamlibRotator::HamlibRotator(HamlibOptions options) : s_(std::make_shared<Shared>()) {
  quiet_hamlib();
  s_->opt = std::move(options);
  s_->label = s_->opt.label.empty() ? default_label(s_->opt) : s_->opt.label;
  s_->health = {LinkState::connecting, "connecting to " + s_->label, 0};
  worker_ = std::thread([s = s_] { s->run(); });
}

HamlibRotator::~HamlibRotator() {
  std::unique_lock lk(s_->m);
  s_->quit = true;
  s_->cv.notify_all();
  const auto patience = 2 * s_->opt.io_timeout + std::chrono::seconds(1);
  bool finished = s_->cv.wait_for(lk, patience, [&] { return s_->done; });
  lk.unlock();
  if (finished)
    worker_.join();
  else
    worker_.detach();  // stuck in a Hamlib call; it holds its own reference to the shared state
}

std::string HamlibRotator::description() const { return s_->label; }

Health HamlibRotator::health() {
  std::lock_guard lk(s_->m);
  return s_->health;
}

AxisMotion HamlibRotator::motion() {
  std::lock_guard lk(s_->m);
  return s_->motion;
}

void HamlibRotator::stop() {
  std::lock_guard lk(s_->m);
  s_->pending_pos.reset();
  if (s_->connected) s_->pending_stop = true;
  s_->cv.notify_all();
}

std::optional<AzEl> HamlibRotator::read() {
  std::lock_guard lk(s_->m);
  return s_->pos;
}

void HamlibRotator::set_position(AzEl p) {
  std::lock_guard lk(s_->m);
  if (!s_->connected) return;  // dropped while the link is down
  s_->pending_pos = p;
  s_->cv.notify_all();
}

Range HamlibRotator::az_range() {
  std::lock_guard lk(s_->m);
  return s_->az_range;
}

bool hamlib_rotator_model_exists(int model) {
  quiet_hamlib();
  ROT* rot = rot_init(model);
  if (!rot) return false;
  rot_cleanup(rot);
  return true;
}

}  // namespace tb::rotator
