#include "radio/hamlib_radio.h"

#include <hamlib/rig.h>
#include <poll.h>
#include <signal.h>

#include <mutex>

#include "util/sigpipe.h"

namespace tb::radio {

using Action = LinkError::Action;

namespace {

// Hamlib's backend registry and debug level are process-wide: one lock around init/open/close.
std::mutex& hamlib_mutex() {
  static std::mutex m;
  return m;
}

void quiet_hamlib_once() {
  static std::once_flag once;
  std::call_once(once, [] { rig_set_debug(RIG_DEBUG_NONE); });
}

std::string error_text(int rc) {
  std::string s = rigerror2(rc);
  if (auto nl = s.find('\n'); nl != std::string::npos) s.resize(nl);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

rmode_t to_hamlib(Mode m) {
  switch (m) {
    case Mode::fm: return RIG_MODE_FM;
    case Mode::lsb: return RIG_MODE_LSB;
    case Mode::usb: return RIG_MODE_USB;
    case Mode::cw: return RIG_MODE_CW;
    case Mode::none: break;
  }
  return RIG_MODE_NONE;
}


}  // namespace

struct HamlibLink::Impl {
  RIG* rig = nullptr;
};

std::string hamlib_model_name(int model) {
  quiet_hamlib_once();
  std::lock_guard lock(hamlib_mutex());
  if (rig_check_backend(model) != RIG_OK) return {};
  const rig_caps* caps = rig_get_caps(model);
  if (!caps) return {};
  return std::string(caps->mfg_name) + " " + caps->model_name;
}

HamlibLink::HamlibLink(HamlibOptions options) : opt_(std::move(options)), impl_(std::make_unique<Impl>()) {
  quiet_hamlib_once();
}

HamlibLink::~HamlibLink() { close(); }

std::string HamlibLink::describe() const {
  if (opt_.model == RIG_MODEL_NETRIGCTL) return "Hamlib rigctld at " + opt_.path;
  std::string s = "Hamlib model " + std::to_string(opt_.model) + " on " + opt_.path;
  if (opt_.baud > 0) s += " at " + std::to_string(opt_.baud) + " bps";
  return s;
}

void HamlibLink::open() {
  sigpipe::block_on_this_thread();  // a dead rigctld gives EPIPE, not the end of the program
  close();
  std::lock_guard lock(hamlib_mutex());
  RIG* rig = rig_init(opt_.model);
  if (!rig) throw LinkError(Action::reconnect, "Hamlib has no rig model " + std::to_string(opt_.model));
  auto conf = [&](const char* name, const std::string& value) {
    const token_t tok = rig_token_lookup(rig, name);
    if (tok != RIG_CONF_END) rig_set_conf(rig, tok, value.c_str());
  };
  if (!opt_.path.empty()) conf("rig_pathname", opt_.path);
  if (opt_.baud > 0) conf("serial_speed", std::to_string(opt_.baud));
  conf("timeout", "1500");   // ms: a dead peer must not hold the worker for long
  conf("retry", "1");
  const int rc = rig_open(rig);
  if (rc != RIG_OK) {
    rig_cleanup(rig);
    throw LinkError(Action::reconnect, describe() + ": cannot open: " + error_text(rc));
  }
  impl_->rig = rig;
  // Dial follow reads the radio: a cached frequency would be trakbox's own last command.
  rig_set_cache_timeout_ms(rig, HAMLIB_CACHE_ALL, 0);
  split_on_ = false;
  scheme_ = opt_.scheme;
  if (scheme_ == HamlibVfoScheme::automatic) {
    const int both = RIG_VFO_MAIN | RIG_VFO_SUB;
    scheme_ = opt_.model != RIG_MODEL_NETRIGCTL && (rig->state.vfo_list & both) == both
                  ? HamlibVfoScheme::main_sub
                  : HamlibVfoScheme::split;
  }
}

void HamlibLink::close() noexcept {
  if (!impl_->rig) return;
  std::lock_guard lock(hamlib_mutex());
  rig_close(impl_->rig);
  rig_cleanup(impl_->rig);
  impl_->rig = nullptr;
}

void HamlibLink::check() {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  const hamlib_port_t& port = impl_->rig->state.rigport;
  // Only a port of its own has a descriptor to watch (not the dummy's RIG_PORT_NONE).
  if ((port.type.rig != RIG_PORT_SERIAL && port.type.rig != RIG_PORT_NETWORK) || port.fd < 0) return;
  const int fd = port.fd;
  pollfd p{fd, POLLRDHUP, 0};
  if (::poll(&p, 1, 0) > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL | POLLRDHUP)) != 0)
    throw LinkError(Action::reconnect, describe() + ": the connection was closed (the port went away)");
}

void HamlibLink::require(int rc, const std::string& what) {
  if (rc == RIG_OK) return;
  const int code = rc < 0 ? -rc : rc;
  const std::string msg = describe() + ": " + what + " failed: " + error_text(rc);
  throw LinkError(RIG_IS_SOFT_ERRCODE(code) ? Action::drop : Action::reconnect, msg);
}

void HamlibLink::ensure_split() {
  if (split_on_) return;
  require(rig_set_split_vfo(impl_->rig, RIG_VFO_CURR, RIG_SPLIT_ON, RIG_VFO_B), "split on (VFO B)");
  split_on_ = true;
}

void HamlibLink::set_frequency(Link l, Hz hz) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  const freq_t f = static_cast<freq_t>(hz);
  if (scheme_ == HamlibVfoScheme::main_sub) {
    require(rig_set_freq(impl_->rig, l == Link::downlink ? RIG_VFO_SUB : RIG_VFO_MAIN, f),
          l == Link::downlink ? "set Sub frequency" : "set Main frequency");
    return;
  }
  if (l == Link::downlink) {
    require(rig_set_freq(impl_->rig, RIG_VFO_CURR, f), "set frequency");
  } else {
    ensure_split();
    require(rig_set_split_freq(impl_->rig, RIG_VFO_CURR, f), "set split frequency");
  }
}

void HamlibLink::set_mode(Link l, Mode mode) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  const rmode_t m = to_hamlib(mode);
  if (m == RIG_MODE_NONE) return;
  if (scheme_ == HamlibVfoScheme::main_sub) {
    require(rig_set_mode(impl_->rig, l == Link::downlink ? RIG_VFO_SUB : RIG_VFO_MAIN, m,
                       RIG_PASSBAND_NOCHANGE),
          "set mode");
    return;
  }
  if (l == Link::downlink) {
    require(rig_set_mode(impl_->rig, RIG_VFO_CURR, m, RIG_PASSBAND_NOCHANGE), "set mode");
  } else {
    ensure_split();
    require(rig_set_split_mode(impl_->rig, RIG_VFO_CURR, m, RIG_PASSBAND_NOCHANGE), "set split mode");
  }
}

Hz HamlibLink::read_frequency(Link l) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  freq_t f = 0;
  if (scheme_ == HamlibVfoScheme::main_sub) {
    require(rig_get_freq(impl_->rig, l == Link::downlink ? RIG_VFO_SUB : RIG_VFO_MAIN, &f),
            l == Link::downlink ? "get Sub frequency" : "get Main frequency");
  } else if (l == Link::downlink) {
    require(rig_get_freq(impl_->rig, RIG_VFO_CURR, &f), "get frequency");
  } else {
    ensure_split();
    require(rig_get_split_freq(impl_->rig, RIG_VFO_CURR, &f), "get split frequency");
  }
  return static_cast<Hz>(f + 0.5);
}

void HamlibLink::set_ctcss_tone(int tenths_hz) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  const vfo_t vfo = scheme_ == HamlibVfoScheme::main_sub ? RIG_VFO_MAIN : RIG_VFO_CURR;
  require(rig_set_ctcss_tone(impl_->rig, vfo, static_cast<tone_t>(tenths_hz)), "set CTCSS tone");
  if (tenths_hz > 0) require(rig_set_func(impl_->rig, vfo, RIG_FUNC_TONE, 1), "CTCSS encoder on");
}

void HamlibLink::send_raw(const std::string& bytes) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  unsigned char reply[256];
  const int rc = rig_send_raw(impl_->rig, reinterpret_cast<const unsigned char*>(bytes.data()),
                              static_cast<int>(bytes.size()), reply, sizeof reply, nullptr);
  if (rc < 0) require(rc, "send raw bytes");
}

std::unique_ptr<RadioDriver> make_hamlib_radio(const HamlibOptions& options, WorkerTiming timing) {
  return std::make_unique<WorkerRadio>(std::make_unique<HamlibLink>(options), timing);
}

}  // namespace tb::radio
