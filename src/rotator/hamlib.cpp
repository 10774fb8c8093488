#include "rotator/hamlib.h"

#include <hamlib/rotator.h>
#include <spdlog/spdlog.h>

#include <cerrno>
#include <csignal>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <pthread.h>
#include <string>
#include <vector>

#include "util/sigpipe.h"

namespace tb::rotator {

namespace {

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

// One Hamlib connection, on the worker thread of WorkerRotator.
class HamlibLink final : public RotatorLink {
 public:
  explicit HamlibLink(HamlibOptions opt) : opt_(std::move(opt)) { quiet_hamlib(); }
  ~HamlibLink() override { close(); }

  bool open(std::string& error) override {
    sigpipe::block_on_this_thread();  // a broken rotctld link gives EPIPE, not the end of the program
    last_.reset();
    rot_ = rot_init(opt_.model);
    if (!rot_) {
      error = "Hamlib has no rotator model " + std::to_string(opt_.model);
      return false;
    }
    auto conf = [&](const char* name, const std::string& value) {
      token_t tok = rot_token_lookup(rot_, name);
      if (tok != 0) rot_set_conf(rot_, tok, value.c_str());
    };
    conf("rot_pathname", opt_.pathname);
    conf("timeout", std::to_string(opt_.io_timeout.count()));
    conf("retry", "0");
    if (opt_.baud > 0) conf("serial_speed", std::to_string(opt_.baud));
    const int rc = rot_open(rot_);
    sigpipe::drain_pending();
    if (rc != RIG_OK) {
      error = hamlib_error(rc);
      rot_cleanup(rot_);
      rot_ = nullptr;
      return false;
    }
    return true;
  }

  void close() override {
    if (!rot_) return;
    rot_close(rot_);
    rot_cleanup(rot_);
    rot_ = nullptr;
    sigpipe::drain_pending();
  }

  Range az_range() override { return {rot_->state.min_az, rot_->state.max_az}; }

  std::string peer() const override {
    if (opt_.model == ROT_MODEL_NETROTCTL) return "the rotctld at " + opt_.pathname;
    std::string name = rot_ && rot_->caps && rot_->caps->model_name ? rot_->caps->model_name : "rotator";
    const int baud = opt_.baud > 0 ? opt_.baud : rot_ ? rot_->state.rotport.parm.serial.rate : 0;
    return "the " + name + " on " + opt_.pathname + (baud > 0 ? " at " + std::to_string(baud) + " baud" : "");
  }

  std::string silent_hint() const override {
    if (opt_.model == ROT_MODEL_NETROTCTL) return "check that rotctld runs and reaches its rotator";
    return "check the speed, the cable, the power";
  }

  bool stop(std::string& error) override {
    int rc = rot_stop(rot_);
    if (rc == -RIG_ENAVAIL || rc == -RIG_ENIMPL) rc = RIG_OK;  // nothing moving to stop
    return done(rc, error);
  }

  bool go_to(AzEl p, std::optional<std::string>&, std::string& error) override {
    return done(rot_set_position(rot_, static_cast<azimuth_t>(p.az), static_cast<elevation_t>(p.el)), error);
  }

  bool poll(LinkReport& report, std::string& error) override {
    azimuth_t az = 0;
    elevation_t el = 0;
    const int rc = rot_get_position(rot_, &az, &el);
    if (rc == RIG_OK) {
      const AzEl now{az, el};
      if (last_) report.motion = AxisMotion{motion_of(now.az - last_->az, 0.05), motion_of(now.el - last_->el, 0.05)};
      report.position = now;
      last_ = now;
    }
    return done(rc, error);
  }

 private:
  bool done(int rc, std::string& error) {
    sigpipe::drain_pending();
    if (rc == RIG_OK) return true;
    error = hamlib_error(rc);
    return false;
  }

  const HamlibOptions opt_;
  ROT* rot_ = nullptr;
  std::optional<AzEl> last_;  // the previous position read on this connection
};

}  // namespace

HamlibRotator::HamlibRotator(HamlibOptions options)
    : WorkerRotator(options.label.empty() ? default_label(options) : options.label,
                    std::make_unique<HamlibLink>(options),
                    {options.poll, options.io_timeout, options.backoff_min, options.backoff_max}) {}

bool hamlib_rotator_model_exists(int model) {
  quiet_hamlib();
  ROT* rot = rot_init(model);
  if (!rot) return false;
  rot_cleanup(rot);
  return true;
}

namespace {
std::string name_key(std::string_view s) {
  std::string k;
  for (const char c : s)
    if ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z')) k += c;
    else if (c >= 'A' && c <= 'Z') k += static_cast<char>(c - 'A' + 'a');
  return k;
}
}  // namespace

std::optional<int> hamlib_rotator_model_by_name(std::string_view name) {
  struct Known {
    int model;
    std::string key, full_key;
  };
  static const std::vector<Known> known = [] {
    quiet_hamlib();
    rot_load_all_backends();
    std::vector<Known> out;
    rot_list_foreach(
        [](const rot_caps* caps, void* data) -> int {
          const std::string mfg = caps->mfg_name ? caps->mfg_name : "", model = caps->model_name ? caps->model_name : "";
          static_cast<std::vector<Known>*>(data)->push_back(
              {static_cast<int>(caps->rot_model), name_key(model), name_key(mfg + model)});
          return 1;
        },
        &out);
    return out;
  }();
  const std::string want = name_key(name);
  if (want.empty()) return std::nullopt;
  std::optional<int> found;
  for (const Known& k : known)
    if (k.key == want || k.full_key == want) {
      if (found && *found != k.model) return std::nullopt;   // two of that name: the number decides
      found = k.model;
    }
  return found;
}

}  // namespace tb::rotator
