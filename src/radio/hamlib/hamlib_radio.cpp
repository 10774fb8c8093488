#include "radio/hamlib/hamlib_radio.h"

#include <hamlib/rig.h>
#include <poll.h>
#include <signal.h>

#include <mutex>

#include <spdlog/spdlog.h>

#include "radio/registry.h"
#include "radio/hamlib/rigctld_link.h"
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

std::string hamlib_error_text(int rc) {
  std::string s = rigerror2(rc);
  if (auto nl = s.find('\n'); nl != std::string::npos) s.resize(nl);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

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
  // The model's own Main/Sub from the radio registry, as the native path uses it (Main transmits on
  // the IC-9100 / IC-910H, receives on the IC-9700); Main up for a model the registry does not know.
  if (const RadioModel* m = find_radio_model_by_hamlib(opt_.model)) opt_.main_link = m->main_link;
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
    throw LinkError(Action::reconnect, describe() + ": cannot open: " + hamlib_error_text(rc));
  }
  impl_->rig = rig;
  // Dial follow reads the radio: a cached frequency would be trakbox's own last command.
  rig_set_cache_timeout_ms(rig, HAMLIB_CACHE_ALL, 0);
  split_on_ = false;
  satmode_on_ = false;
  scheme_ = opt_.scheme;
  const int both = RIG_VFO_MAIN | RIG_VFO_SUB;
  const bool main_sub = opt_.model != RIG_MODEL_NETRIGCTL && (rig->state.vfo_list & both) == both;
  if (scheme_ == HamlibVfoScheme::automatic)
    scheme_ = main_sub ? HamlibVfoScheme::main_sub : HamlibVfoScheme::split;
  // Satellite mode, where the backend has it (IC-9700, IC-9100, IC-910H, TS-2000, FT-847 ...), is
  // switched on here, before the first frequency: the links then go on Main and Sub. A refusal is
  // reported and Main/Sub used without it.
  std::string note;
  if (scheme_ == HamlibVfoScheme::main_sub && rig_has_set_func(rig, RIG_FUNC_SATMODE)) {
    const int on = rig_set_func(rig, RIG_VFO_CURR, RIG_FUNC_SATMODE, 1);
    satmode_on_ = on == RIG_OK;
    if (!satmode_on_) note = "satellite mode refused: " + hamlib_error_text(on) + "; Main/Sub without it";
  } else if (scheme_ == HamlibVfoScheme::split && opt_.scheme == HamlibVfoScheme::automatic) {
    note = "Hamlib gives this model no satellite mode and no Main/Sub VFOs: the links go as split "
           "(downlink on the receive VFO, uplink on VFO B)";
  }
  if (!announced_) {
    const std::string bands = opt_.main_link == Link::uplink ? "downlink on Sub, uplink on Main"
                                                             : "downlink on Main, uplink on Sub";
    const std::string how = scheme_ == HamlibVfoScheme::split ? "split: downlink on the receive VFO, uplink on VFO B"
                            : satmode_on_                     ? "satellite mode, " + bands
                                                              : bands;
    if (!note.empty()) spdlog::warn("radio {}: {}", describe(), note);
    spdlog::info("radio {}: {}", describe(), how);
    announced_ = true;
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
  const std::string msg = describe() + ": " + what + " failed: " + hamlib_error_text(rc);
  throw LinkError(RIG_IS_SOFT_ERRCODE(code) ? Action::drop : Action::reconnect, msg);
}

// A tone, mode or satellite-mode command the radio refused, or did not answer (many radios ignore a
// command they lack), is reported and dropped: Doppler goes on. Only an I/O error (the port or the
// connection broke) reconnects.
void HamlibLink::require_aux(int rc, const std::string& what) {
  if (rc == RIG_OK) return;
  const int code = rc < 0 ? -rc : rc;
  if (code == RIG_EIO) require(rc, what);
  throw LinkError(Action::drop, describe() + ": " + what + " refused: " + hamlib_error_text(rc) + "; Doppler tuning goes on");
}

namespace {
// Main/Sub: the band `l` is on.
vfo_t band_of(Link main_link, Link l) { return l == main_link ? RIG_VFO_MAIN : RIG_VFO_SUB; }
}  // namespace

void HamlibLink::ensure_split() {
  if (split_on_) return;
  require(rig_set_split_vfo(impl_->rig, RIG_VFO_CURR, RIG_SPLIT_ON, RIG_VFO_B), "split on (VFO B)");
  split_on_ = true;
}

void HamlibLink::set_frequency(Link l, Hz hz) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  const freq_t f = static_cast<freq_t>(hz);
  if (scheme_ == HamlibVfoScheme::main_sub) {
    const vfo_t band = band_of(opt_.main_link, l);
    require(rig_set_freq(impl_->rig, band, f), band == RIG_VFO_MAIN ? "set Main frequency" : "set Sub frequency");
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
    require_aux(rig_set_mode(impl_->rig, band_of(opt_.main_link, l), m, RIG_PASSBAND_NOCHANGE),
                "set mode");
    return;
  }
  if (l == Link::downlink) {
    require_aux(rig_set_mode(impl_->rig, RIG_VFO_CURR, m, RIG_PASSBAND_NOCHANGE), "set mode");
  } else {
    ensure_split();
    require_aux(rig_set_split_mode(impl_->rig, RIG_VFO_CURR, m, RIG_PASSBAND_NOCHANGE), "set split mode");
  }
}

Hz HamlibLink::read_frequency(Link l) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  freq_t f = 0;
  // Hamlib 4.5 answers get_freq from its cache whatever the cache timeout once it has seen the
  // radio's transceive frames (use_cached_freq), and the IC-9700's carry no VFO: the Sub band then
  // reads a stale value and dial follow would take it for a turn (seen against Hamlib's simic9700).
  impl_->rig->state.use_cached_freq = 0;
  if (scheme_ == HamlibVfoScheme::main_sub) {
    const vfo_t band = band_of(opt_.main_link, l);
    require(rig_get_freq(impl_->rig, band, &f), band == RIG_VFO_MAIN ? "get Main frequency" : "get Sub frequency");
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
  const vfo_t vfo = scheme_ == HamlibVfoScheme::main_sub ? band_of(opt_.main_link, Link::uplink) : RIG_VFO_CURR;
  require_aux(rig_set_ctcss_tone(impl_->rig, vfo, static_cast<tone_t>(tenths_hz)), "set CTCSS tone");
  if (tenths_hz > 0) require_aux(rig_set_func(impl_->rig, vfo, RIG_FUNC_TONE, 1), "CTCSS encoder on");
}

void HamlibLink::send_raw(const std::string& bytes) {
  if (!impl_->rig) throw LinkError(Action::reconnect, describe() + " is not open");
  unsigned char reply[256];
  const int rc = rig_send_raw(impl_->rig, reinterpret_cast<const unsigned char*>(bytes.data()),
                              static_cast<int>(bytes.size()), reply, sizeof reply, nullptr);
  if (rc < 0) require(rc, "send raw bytes");
}

std::unique_ptr<RadioDriver> make_hamlib_radio(const HamlibOptions& options, WorkerTiming timing) {
  // rigctld is spoken to in its own protocol (rigctld_link.h), not through the NET rigctl backend.
  if (options.model == RIG_MODEL_NETRIGCTL)
    return std::make_unique<WorkerRadio>(std::make_unique<RigctldLink>(options.path, options.scheme), timing);
  return std::make_unique<WorkerRadio>(std::make_unique<HamlibLink>(options), timing);
}

}  // namespace tb::radio
