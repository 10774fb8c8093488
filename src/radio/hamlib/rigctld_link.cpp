#include "radio/hamlib/rigctld_link.h"

#include <fcntl.h>
#include <hamlib/rig.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "util/sigpipe.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace tb::radio {

using Action = LinkError::Action;
using Clock = std::chrono::steady_clock;

namespace {

// A receiver's refusal is a positive code (GQRX, SDR++: `RPRT 1`), not Hamlib's negative ones.
std::string rprt_text(int rprt) {
  if (rprt > 0) return "RPRT " + std::to_string(rprt);
  return "RPRT " + std::to_string(rprt) + " (" + hamlib_error_text(rprt) + ")";
}

// After being knocked off by another program, the first try again comes after 5 s, then 10, 20 ...
// up to 5 minutes while it keeps happening; a connection that lasted 5 minutes starts it over.
constexpr std::chrono::seconds kTakenFirst{5}, kTakenMax{300};

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::optional<Hz> parse_hz(const std::string& line) {
  char* end = nullptr;
  const double v = std::strtod(line.c_str(), &end);
  if (end == line.c_str() || !std::isfinite(v) || v < 0) return std::nullopt;
  return static_cast<Hz>(std::llround(v));
}

}  // namespace

RigctldLink::RigctldLink(std::string address, HamlibVfoScheme scheme, RigctldPeer peer, std::chrono::milliseconds timeout)
    : peer_(std::move(peer)), address_(std::move(address)), scheme_(scheme), timeout_(timeout) {
  const auto colon = address_.rfind(':');
  host_ = colon == std::string::npos ? address_ : address_.substr(0, colon);
  port_ = colon == std::string::npos ? 4532 : std::atoi(address_.c_str() + colon + 1);
  if (!host_.empty() && host_.front() == '[' && host_.back() == ']') host_ = host_.substr(1, host_.size() - 2);
}

RigctldLink::~RigctldLink() { close(); }

std::string RigctldLink::describe() const {
  return (peer_.receiver ? peer_.name : std::string("Hamlib rigctld")) + " at " + address_;
}

void RigctldLink::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  inbuf_.clear();
}

void RigctldLink::transport(const std::string& what) {
  close();
  throw LinkError(Action::reconnect, describe() + ": " + what);
}

void RigctldLink::open() {
  sigpipe::block_on_this_thread();
  close();
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(port_);
  if (const int rc = ::getaddrinfo(host_.c_str(), port.c_str(), &hints, &found); rc != 0)
    throw LinkError(Action::reconnect, describe() + ": cannot open: " + gai_strerror(rc));
  std::string why = "no address";
  for (addrinfo* a = found; a && fd_ < 0; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int rc = ::connect(fd, a->ai_addr, a->ai_addrlen);
    if (rc != 0 && errno == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      rc = ::poll(&p, 1, static_cast<int>(timeout_.count())) == 1 ? 0 : -1;
      int err = rc == 0 ? 0 : ETIMEDOUT;
      socklen_t len = sizeof err;
      if (rc == 0) ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len);
      if (err != 0) {
        errno = err;
        rc = -1;
      }
    }
    if (rc == 0) {
      fd_ = fd;
    } else {
      why = std::strerror(errno);
      ::close(fd);
    }
  }
  ::freeaddrinfo(found);
  if (fd_ < 0) throw LinkError(Action::reconnect, describe() + ": cannot open: " + why);
  answered_ = false;
  opened_at_ = Clock::now();
  if (peer_.receiver) return open_receiver();

  split_on_ = false;
  split_verified_ = false;
  uplink_refused_.reset();
  satmode_on_ = false;
  // What the daemon can address: with --vfo every command names its VFO.
  const Reply chk = ask("\\chk_vfo", 1);
  vfo_mode_ = chk.rprt == 0 && !chk.lines.empty() && !chk.lines[0].empty() && chk.lines[0].back() == '1';
  bool main_sub = false;
  if (const Reply list = ask("\\get_vfo_list", 1); list.rprt == 0 && !list.lines.empty()) {
    std::istringstream words(list.lines[0]);
    bool main = false, sub = false;
    for (std::string w; words >> w;) {
      main = main || w == "Main";
      sub = sub || w == "Sub";
    }
    main_sub = main && sub;
  }
  std::string note;
  carry_ = Carry::split;
  if (vfo_mode_ && main_sub && scheme_ != HamlibVfoScheme::split) carry_ = Carry::main_sub;
  else if (vfo_mode_ && scheme_ == HamlibVfoScheme::automatic) carry_ = Carry::vfo_ab;
  if (scheme_ == HamlibVfoScheme::main_sub && carry_ != Carry::main_sub)
    note = vfo_mode_ ? "the radio has no Main and Sub VFOs: the links go as split"
                     : "Main/Sub needs rigctld started with --vfo: the links go as split";
  else if (!vfo_mode_ && main_sub && scheme_ == HamlibVfoScheme::automatic)
    note = "rigctld runs without --vfo, so Main and Sub cannot be addressed: the links go as split on the "
           "current VFO (F / I), without satellite mode; start rigctld with --vfo for Main/Sub and satellite mode";
  if (carry_ == Carry::main_sub) {
    // Satellite mode first, before any frequency (the radio may move the bands when it switches).
    const Reply has = ask("u Main SATMODE", 1);
    if (has.rprt == 0) {
      const Reply on = ask("U Main SATMODE 1", 0);
      satmode_on_ = on.rprt == 0;
      if (!satmode_on_) note = "satellite mode refused: " + rprt_text(on.rprt) + "; Main/Sub without it";
    }
  }
  if (!announced_ || !note.empty()) {
    const char* how = carry_ == Carry::main_sub ? (satmode_on_ ? "satellite mode, downlink on Sub, uplink on Main"
                                                               : "downlink on Sub, uplink on Main")
                      : carry_ == Carry::vfo_ab ? "downlink on VFOA, uplink on VFOB (split)"
                                                : "split: downlink F, uplink I";
    if (!note.empty()) spdlog::warn("radio {}: {}", describe(), note);
    if (!announced_) spdlog::info("radio {}: {}", describe(), how);
    announced_ = true;
  }
}

// A receiver answers its first `f` with the frequency it is on: that answer is the connection.
void RigctldLink::open_receiver() {
  const Reply f = ask("f", 1);
  if (f.rprt != 0 || !parse_hz(f.lines[0]))
    transport("\"f\" answered \"" + (f.rprt != 0 ? rprt_text(f.rprt) : f.lines[0]) + "\", expected a frequency");
  probe_recorder();
  if (!announced_)
    spdlog::info("radio {}: a receiver: the downlink only (F / f, no VFO named), no uplink, no tone{}{}", describe(),
                 peer_.one_client ? "; it keeps one client" : "",
                 records().empty() ? "" : "; it records " + records() + " (--record)");
  announced_ = true;
}

// GQRX says at `u ?` what `u` reads ("RECORD IQRECORD DSP RDS MUTE"); an older one refuses it: its
// recorder is then started and stopped with AOS / LOS, nothing read back.
void RigctldLink::probe_recorder() {
  functions_.clear();
  if (!peer_.reads_recorder) return;
  const Reply r = ask("u ?", 1);
  if (r.rprt != 0) return;
  std::istringstream words(r.lines[0]);
  for (std::string w; words >> w;) functions_.push_back(w);
}

std::string RigctldLink::records() const {
  if (!peer_.receiver || !peer_.audio_recorder) return {};
  const bool iq = peer_.iq_recorder && std::find(functions_.begin(), functions_.end(), "IQRECORD") != functions_.end();
  return iq ? "audio, iq" : "audio";
}

std::optional<bool> RigctldLink::read_function(const char* name) {
  if (std::find(functions_.begin(), functions_.end(), name) == functions_.end()) return std::nullopt;
  const Reply r = ask(std::string("u ") + name, 1);
  if (r.rprt != 0) return std::nullopt;
  return r.lines[0] == "1";
}

RadioLink::Recording RigctldLink::record(Record what) {
  if (records().empty()) return RadioLink::record(what);
  return what == Record::off ? stop_recording() : start_recording(what);
}

// Audio: AOS (GQRX starts its recorder when its DSP runs and a demodulator is chosen), read back,
// and U RECORD 1 when it did not start. IQ: U IQRECORD 1. A recorder already on is left as it is.
RadioLink::Recording RigctldLink::start_recording(Record what) {
  const bool iq = what == Record::iq;
  const char* fn = iq ? "IQRECORD" : "RECORD";
  if (iq && records().find("iq") == std::string::npos)
    return {Record::off, false, "not recording: no IQ recorder",
            fmt::format("not recording IQ: {} has no IQ recorder (u ? lists no IQRECORD)", peer_.name)};
  if (read_function(fn).value_or(false)) {
    started_ = what;
    return {what, true, {}, fmt::format("recording {}: it was already (u {} reads 1): left as it is", to_string(what), fn)};
  }
  std::string sent;
  const auto send = [&](const std::string& cmd) {
    const int rprt = ask(cmd, 0).rprt;
    sent += fmt::format("{}{} -> RPRT {}", sent.empty() ? "" : ", ", cmd, rprt);
    return rprt;
  };
  std::optional<bool> on;
  if (!iq) {
    const int rprt = send("AOS");
    on = read_function(fn);
    if (!on) {   // nothing to read back (SDR++, an older GQRX): its RPRT is all there is
      if (rprt != 0) return {Record::off, false, "not recording: AOS refused", "not recording: " + sent};
      started_ = what;
      return {what, false, {}, fmt::format("recording audio: {} (not read back: {} records when its recorder is "
                                           "set up for it)", sent, peer_.name)};
    }
  }
  if (!on.value_or(false)) {
    send(fmt::format("U {} 1", fn));
    on = read_function(fn);
  }
  if (on.value_or(false)) {
    started_ = what;
    return {what, true, {}, fmt::format("recording {}: {}; u {} reads 1", to_string(what), sent, fn)};
  }
  // Refused: GQRX records only while its DSP runs (and, for audio, with a demodulator chosen).
  const std::optional<bool> dsp = read_function("DSP");
  const std::string why = dsp && !*dsp ? "not recording: DSP off"
                          : dsp        ? (iq ? "not recording: IQ recorder refused" : "not recording: demodulator off?")
                                       : "not recording: DSP off?";
  return {Record::off, on.has_value(), why,
          fmt::format("{} ({}; u {} reads {}{}): a limit; Doppler tuning goes on", why, sent, fn, on ? "0" : "nothing",
                      dsp ? fmt::format(", u DSP reads {}", *dsp ? 1 : 0) : std::string())};
}

// What trakbox started: IQ with U IQRECORD 0; audio with LOS, and U RECORD 0 when it still records.
RadioLink::Recording RigctldLink::stop_recording() {
  const bool iq = started_ == Record::iq;
  const char* fn = iq ? "IQRECORD" : "RECORD";
  const std::string first = iq ? "U IQRECORD 0" : "LOS";
  std::string sent = fmt::format("{} -> RPRT {}", first, ask(first, 0).rprt);
  std::optional<bool> on = read_function(fn);
  if (on.value_or(false) && !iq) {
    sent += fmt::format(", U RECORD 0 -> RPRT {}", ask("U RECORD 0", 0).rprt);
    on = read_function(fn);
  }
  started_ = on.value_or(false) ? started_ : Record::off;
  const Record now = on.value_or(false) ? (iq ? Record::iq : Record::audio) : Record::off;
  return {now, on.has_value(), now == Record::off ? std::string() : "recorder still on after the stop",
          fmt::format("recording stopped: {}{}", sent, on ? fmt::format("; u {} reads {}", fn, *on ? 1 : 0) : "")};
}

void RigctldLink::taken() {
  const bool lasted = Clock::now() - opened_at_ > kTakenMax;
  close();
  if (lasted) takeovers_ = 0;
  const auto wait = std::min<std::chrono::milliseconds>(kTakenFirst * (1 << std::min(takeovers_, 6)), kTakenMax);
  ++takeovers_;
  LinkError e(Action::reconnect, "another program holds " + peer_.name + "'s remote control (it closed trakbox's "
                                 "connection: it keeps one client); trakbox tries again, less often each time");
  e.hold_off = wait;
  throw e;
}

void RigctldLink::check() {
  if (fd_ < 0) throw LinkError(Action::reconnect, describe() + " is not open");
  pollfd p{fd_, POLLRDHUP, 0};
  if (::poll(&p, 1, 0) > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL | POLLRDHUP)) != 0) {
    if (peer_.one_client && answered_) taken();
    transport("the connection was closed (" + peer_.name + " went away)");
  }
}

void RigctldLink::write_all(const std::string& text) {
  std::size_t done = 0;
  const auto until = Clock::now() + timeout_;
  while (done < text.size()) {
    const ssize_t n = ::send(fd_, text.data() + done, text.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
      transport(std::string("cannot send: ") + std::strerror(errno));
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
    pollfd p{fd_, POLLOUT, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) transport("cannot send: timed out");
  }
}

std::string RigctldLink::read_line() {
  const auto until = Clock::now() + timeout_;
  while (true) {
    if (const auto nl = inbuf_.find('\n'); nl != std::string::npos) {
      std::string line = inbuf_.substr(0, nl);
      inbuf_.erase(0, nl + 1);
      // rigctld ends some lists with a NUL and spaces.
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\0')) line.pop_back();
      return line;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) {
      if (peer_.one_client && !answered_)
        transport("no answer within " + std::to_string(timeout_.count()) + " ms: another program may hold " + peer_.name +
                  "'s remote control (it serves one client at a time), or its server is not started");
      transport("no reply within " + std::to_string(timeout_.count()) + " ms");
    }
    char buf[512];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n == 0) {
      if (peer_.one_client && answered_) taken();
      transport("the connection was closed (" + peer_.name + " went away)");
    }
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
      transport(std::string("cannot read: ") + std::strerror(errno));
    }
    inbuf_.append(buf, static_cast<std::size_t>(n));
  }
}

RigctldLink::Reply RigctldLink::ask(const std::string& command, int lines) {
  if (fd_ < 0) throw LinkError(Action::reconnect, describe() + " is not open");
  write_all(command + "\n");
  Reply r;
  std::string line = read_line();
  answered_ = true;
  if (starts_with(line, "RPRT ")) {
    r.rprt = std::atoi(line.c_str() + 5);
    if (r.rprt == 0 && lines > 0) transport("\"" + command + "\" answered RPRT 0 without its value");
    return r;
  }
  if (lines == 0) transport("\"" + command + "\" answered \"" + line + "\", expected RPRT");
  r.lines.push_back(std::move(line));
  while (static_cast<int>(r.lines.size()) < lines) r.lines.push_back(read_line());
  return r;
}

void RigctldLink::refused(const std::string& what, int rprt, bool frequency, const std::string& lacking) {
  const int code = rprt < 0 ? -rprt : rprt;
  const bool soft = RIG_IS_SOFT_ERRCODE(code);
  std::string msg = describe() + ": " + what + " refused: " + rprt_text(rprt);
  if (!frequency) msg += "; Doppler tuning goes on";
  if (!lacking.empty()) throw LinkError(lacking, msg + " (said once)");
  throw LinkError(frequency && !soft ? Action::retry : Action::drop, msg);
}

std::string RigctldLink::vfo_arg(Link l) const {
  switch (carry_) {
    case Carry::main_sub: return l == Link::downlink ? "Sub " : "Main ";
    case Carry::vfo_ab: return l == Link::downlink ? "VFOA " : "VFOB ";
    case Carry::split: break;
  }
  return vfo_mode_ ? "currVFO " : "";
}

void RigctldLink::ensure_split() {
  if (uplink_refused_) throw LinkError("no uplink", *uplink_refused_);
  if (split_on_ || carry_ == Carry::main_sub) return;
  const std::string cmd = std::string("S ") + (vfo_mode_ ? (carry_ == Carry::vfo_ab ? "VFOA " : "currVFO ") : "") + "1 VFOB";
  const Reply r = ask(cmd, 0);
  if (r.rprt != 0) {
    uplink_refused_ = describe() + ": split (" + cmd + ") refused: " + rprt_text(r.rprt) +
                      "; the uplink is not sent (give it its own radio with --uplink-radio); Doppler tuning "
                      "of the downlink goes on";
    throw LinkError("no uplink", *uplink_refused_);
  }
  split_on_ = true;
}

// After the first uplink in split: is the radio in split with the uplink on a VFO of its own?
void RigctldLink::verify_split(Hz uplink_hz) {
  split_verified_ = true;
  const std::string v = vfo_mode_ ? "currVFO" : "";
  const Reply s = ask(v.empty() ? "s" : "s " + v, 2);
  std::string why;
  if (s.rprt == 0 && s.lines[0] != "1") {
    why = "split is off after S 1 VFOB";
  } else if (last_down_ && std::llabs(*last_down_ - uplink_hz) > kTuningStepHz) {
    const Reply f = ask(v.empty() ? "f" : "f " + v, 1);
    const auto down = f.rprt == 0 ? parse_hz(f.lines[0]) : std::nullopt;
    if (down && std::llabs(*down - uplink_hz) <= kTuningStepHz)
      why = "the downlink's VFO now reads the uplink's " + std::to_string(uplink_hz) + " Hz";
  }
  if (why.empty()) return;
  uplink_refused_ = describe() + ": the radio does not carry the uplink on its own VFO in split (" + why +
                    "); the uplink is not sent, so that both links do not land on one VFO. Start rigctld with "
                    "--vfo so trakbox can address the VFOs, or give the uplink its own radio with "
                    "--uplink-radio; Doppler tuning of the downlink goes on";
  if (last_down_) ask("F " + vfo_arg(Link::downlink) + std::to_string(*last_down_), 0);  // put it back
  throw LinkError("no uplink", *uplink_refused_);
}

void RigctldLink::no_uplink_of_receiver() const {
  throw LinkError("no uplink", describe() + ": a receiver carries no uplink: the uplink is not sent (give it its own "
                               "radio with --uplink-radio); Doppler tuning of the downlink goes on");
}

void RigctldLink::set_frequency(Link l, Hz hz) {
  if (l == Link::uplink && peer_.receiver) no_uplink_of_receiver();
  const std::string value = std::to_string(hz);
  if (l == Link::uplink && carry_ != Carry::main_sub) {
    ensure_split();
    const bool split_cmd = carry_ == Carry::split;
    const Reply r = ask(split_cmd ? "I " + vfo_arg(l) + value : "F " + vfo_arg(l) + value, 0);
    if (r.rprt != 0) refused(split_cmd ? "split frequency" : "uplink frequency", r.rprt, true);
    if (split_cmd && !split_verified_) verify_split(hz);
    return;
  }
  const Reply r = ask("F " + vfo_arg(l) + value, 0);
  if (r.rprt != 0) refused(std::string(to_string(l)) + " frequency", r.rprt, true);
  if (l == Link::downlink) last_down_ = hz;
}

void RigctldLink::set_mode(Link l, Mode mode) {
  if (mode == Mode::none) return;
  if (l == Link::uplink && peer_.receiver) no_uplink_of_receiver();
  const char* name = to_string(mode);   // rigctld's names: FM, LSB, USB, CW
  const bool split_cmd = l == Link::uplink && carry_ == Carry::split;
  if (l == Link::uplink && carry_ != Carry::main_sub) ensure_split();
  const Reply r = ask(std::string(split_cmd ? "X " : "M ") + vfo_arg(l) + name + " 0", 0);
  if (r.rprt != 0) refused(std::string(to_string(l)) + " mode " + name, r.rprt, false, std::string("no mode ") + name);
}

bool RigctldLink::can_read(Link l) const { return !(l == Link::uplink && (uplink_refused_ || peer_.receiver)); }

Hz RigctldLink::read_frequency(Link l) {
  if (l == Link::uplink && uplink_refused_) throw LinkError("no uplink", *uplink_refused_);
  if (l == Link::uplink && peer_.receiver) no_uplink_of_receiver();
  const bool split_cmd = l == Link::uplink && carry_ == Carry::split;
  const std::string cmd = std::string(split_cmd ? "i" : "f") + (vfo_mode_ ? " " + vfo_arg(l) : "");
  Reply r = ask(cmd.back() == ' ' ? cmd.substr(0, cmd.size() - 1) : cmd, 1);
  if (r.rprt != 0) refused("reading the " + std::string(to_string(l)) + " frequency", r.rprt, false);
  const auto hz = parse_hz(r.lines[0]);
  if (!hz) transport("\"" + cmd + "\" answered \"" + r.lines[0] + "\", expected a frequency");
  return *hz;
}

void RigctldLink::set_ctcss_tone(int tenths_hz) {
  if (peer_.receiver) {
    if (tenths_hz > 0)
      throw LinkError("no CTCSS", describe() + ": a receiver has no CTCSS encoder: tone " + std::to_string(tenths_hz / 10) +
                                      "." + std::to_string(tenths_hz % 10) + " Hz not sent");
    return;
  }
  // The encoder of the transmitting VFO: Main in Main/Sub, VFOB in VFO A/B, the current one in split.
  const std::string v = vfo_arg(Link::uplink);
  const std::string vfo = carry_ == Carry::split ? (vfo_mode_ ? "currVFO " : "") : v;
  const Reply r = ask("C " + vfo + std::to_string(tenths_hz), 0);
  if (r.rprt != 0) refused("CTCSS tone " + std::to_string(tenths_hz / 10) + "." + std::to_string(tenths_hz % 10) + " Hz",
                           r.rprt, false, "no CTCSS");
  if (tenths_hz <= 0) return;
  const Reply on = ask("U " + vfo + "TONE 1", 0);
  if (on.rprt != 0) refused("CTCSS encoder on (U TONE 1)", on.rprt, false, "no CTCSS");
}

void RigctldLink::send_raw(const std::string& bytes) {
  std::string cmd = bytes;
  while (!cmd.empty() && (cmd.back() == '\n' || cmd.back() == '\r')) cmd.pop_back();
  if (fd_ < 0) throw LinkError(Action::reconnect, describe() + " is not open");
  write_all(cmd + "\n");
  // A reply of unknown length: its first line, then whatever follows at once.
  std::string line = read_line();
  while (!starts_with(line, "RPRT ")) {
    pollfd p{fd_, POLLIN, 0};
    if (inbuf_.find('\n') == std::string::npos && ::poll(&p, 1, 100) <= 0) return;
    line = read_line();
  }
  if (const int rprt = std::atoi(line.c_str() + 5); rprt != 0) refused("\"" + cmd + "\"", rprt, false);
}

}  // namespace tb::radio
