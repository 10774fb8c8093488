#include "radio/flex/link.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>

#include "radio/link_common.h"
#include "util/text.h"
#include "util/sigpipe.h"

namespace tb::radio {

using namespace link;

namespace {

constexpr std::size_t kLongestLine = 64 * 1024;   // a status line is far shorter; more is not the API

// A TCP connection to host:port within `timeout`; -1 with `why` when none.
int connect_tcp(const std::string& host, int port, std::chrono::milliseconds timeout, std::string& why) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found); rc != 0) {
    why = gai_strerror(rc);
    return -1;
  }
  int fd = -1;
  why = "no address";
  for (addrinfo* a = found; a && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int err = ::connect(fd, a->ai_addr, a->ai_addrlen) == 0 ? 0 : errno;
    if (err == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      err = ::poll(&p, 1, static_cast<int>(timeout.count())) == 1 ? 0 : ETIMEDOUT;
      socklen_t len = sizeof err;
      if (err == 0) ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len);
    }
    if (err != 0) {
      why = std::strerror(err);
      ::close(fd);
      fd = -1;
    }
  }
  ::freeaddrinfo(found);
  return fd;
}

std::string slice_text(const std::optional<int>& slice) { return slice ? std::to_string(*slice) : "new"; }

}  // namespace

FlexLink::FlexLink(FlexOptions options) : opt_(std::move(options)) {
  std::string& h = opt_.host;   // "[2001:db8::7]" as the spec keeps an IPv6 address
  if (h.size() > 2 && h.front() == '[' && h.back() == ']') h = h.substr(1, h.size() - 2);
}

FlexLink::~FlexLink() { close(); }

std::string FlexLink::describe() const {
  const bool v6 = opt_.host.find(':') != std::string::npos;
  return fmt::format("FlexRadio at {}{}{}:{}", v6 ? "[" : "", opt_.host, v6 ? "]" : "", opt_.port);
}

void FlexLink::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  inbuf_.clear();
}

void FlexLink::transport(const std::string& what) {
  close();
  throw LinkError(Action::reconnect, what);
}

void FlexLink::refused(const std::string& what, const flex::Reply& r, const std::string& lacking) {
  throw LinkError(lacking, fmt::format("\"{}\" refused ({}{}{}): {}, said once; Doppler tuning goes on", what,
                                       flex::error_text(r.status), r.data.empty() ? "" : ": ", r.data, lacking));
}

void FlexLink::band_refused(Link s, Hz hz, const std::string& cmd, const flex::Reply& r) {
  Leg& g = leg(s);
  g.lacks = band_name(hz);
  throw LinkError("no " + *g.lacks,
                  fmt::format("the {} at {} Hz refused (\"{}\": {}): no {} on this radio (a transverter for it is "
                              "not set up in SmartSDR?); the {} is not sent on that band again, Doppler tuning goes on",
                              to_string(s), hz, cmd, flex::error_text(r.status), *g.lacks, to_string(s)));
}

Link FlexLink::station(Link l) const {
  if (opt_.role == RadioRole::uplink) return Link::uplink;
  if (opt_.role == RadioRole::downlink) return Link::downlink;
  return l;
}

void FlexLink::open() {
  sigpipe::block_on_this_thread();
  close();
  std::string why;
  fd_ = connect_tcp(opt_.host, opt_.port, opt_.timeout, why);
  if (fd_ < 0) throw LinkError(Action::reconnect, "cannot open: " + why);
  slice_hz_.clear();
  slice_tx_.clear();
  for (Leg& g : legs_) {
    g.slice.reset();
    g.tx_set = false;
  }
  greeting();
  if (const flex::Reply r = ask(flex::subscribe_slices()); r.status != 0)
    spdlog::warn("radio {}: \"{}\" refused ({}): dial turns are not followed", describe(), flex::subscribe_slices(),
                 flex::error_text(r.status));
  find_slices();
  if (opt_.full_duplex && opt_.role == RadioRole::both) {
    const flex::Reply r = ask(flex::full_duplex(true));
    if (r.status != 0 && !duplex_warned_)
      spdlog::warn("radio {}: full duplex refused ({}): the downlink is not heard while transmitting", describe(),
                   flex::error_text(r.status));
    duplex_warned_ = duplex_warned_ || r.status != 0;
  }
  if (!announced_)
    spdlog::info("radio {}: SmartSDR API {}, handle {:08X}; downlink on slice {}, uplink on slice {}{}", describe(),
                 version_, handle_, slice_text(leg(Link::downlink).slice), slice_text(leg(Link::uplink).slice),
                 opt_.role != RadioRole::both ? " (one of two radios: its one link only)"
                 : opt_.full_duplex      ? ", full duplex"
                                         : ", full duplex left as SmartSDR has it");
  announced_ = true;
}

// V<a.b.c.d> and H<handle> come first on every connection; anything else before them is taken as it comes.
void FlexLink::greeting() {
  version_.clear();
  handle_ = 0;
  bool have_handle = false;
  while (version_.empty() || !have_handle) {
    std::string line;
    try {
      line = read_line();
    } catch (const LinkError& e) {
      throw LinkError(Action::reconnect, std::string(e.what()) + " before the radio's V and H lines: is this the "
                                                                 "SmartSDR API's port (4992) of a FlexRadio?");
    }
    if (const auto v = flex::decode_version(line)) version_ = *v;
    else if (const auto h = flex::decode_handle(line)) handle_ = *h, have_handle = true;
    else take(line);
  }
}

// The slices the radio has: the one marked tx=1 carries the uplink, the first other one the downlink.
void FlexLink::find_slices() {
  const flex::Reply r = ask(flex::list_slices());
  const auto list = r.status == 0 ? flex::decode_slice_list(r.data) : std::nullopt;
  if (!list) return;
  std::optional<int> tx;
  std::vector<int> rx;   // the others, in the radio's order
  for (int s : *list) {
    if (slice_tx_[s] && !tx) tx = s;
    else rx.push_back(s);
  }
  const auto rx_at = [&](std::size_t i) { return i < rx.size() ? std::optional<int>(rx[i]) : std::nullopt; };
  switch (opt_.role) {
    case RadioRole::uplink: leg(Link::uplink).slice = tx ? tx : rx_at(0); break;
    case RadioRole::downlink: leg(Link::downlink).slice = rx.empty() ? tx : rx_at(0); break;
    case RadioRole::both:   // no slice marked tx: the second one becomes the transmit slice
      leg(Link::downlink).slice = rx_at(0);
      leg(Link::uplink).slice = tx ? tx : rx_at(1);
      break;
  }
}

void FlexLink::write_all(const std::string& text) {
  std::size_t done = 0;
  const auto until = Clock::now() + opt_.timeout;
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

bool FlexLink::line_waiting(int wait_ms) {
  if (inbuf_.find('\n') != std::string::npos) return true;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, wait_ms) > 0;
}

std::string FlexLink::read_line() {
  const auto until = Clock::now() + opt_.timeout;
  while (true) {
    if (const auto nl = inbuf_.find('\n'); nl != std::string::npos) {
      std::string line = inbuf_.substr(0, nl);
      inbuf_.erase(0, nl + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (inbuf_.size() > kLongestLine) transport("a line longer than 64 KiB: not the SmartSDR API");
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
    pollfd p{fd_, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0)
      transport(fmt::format("no reply within {} ms", opt_.timeout.count()));
    char buf[4096];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n == 0) transport("the connection was closed");
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
      transport(std::string("cannot read: ") + std::strerror(errno));
    }
    inbuf_.append(buf, static_cast<std::size_t>(n));
  }
}

// A slice's status: its frequency (the operator's turn of the knob too) and tx; a slice no longer
// in use is forgotten, and a link it carried gets a new one at its next frequency.
void FlexLink::take(const std::string& line) {
  const auto s = flex::decode_slice_status(line);
  if (!s) return;
  if (s->hz) slice_hz_[s->index] = *s->hz;
  if (s->tx) slice_tx_[s->index] = *s->tx;
  if (s->in_use && !*s->in_use) {
    slice_hz_.erase(s->index);
    slice_tx_.erase(s->index);
    for (Leg& g : legs_)
      if (g.slice == s->index) g.slice.reset(), g.tx_set = false;
  }
}

flex::Reply FlexLink::ask(const std::string& body) {
  if (fd_ < 0) throw LinkError(Action::reconnect, "the connection is not open");
  const std::uint32_t seq = ++seq_;
  write_all(flex::command(seq, body));
  while (true) {
    const std::string line = read_line();
    if (line.empty() || line[0] != 'R') {
      take(line);
      continue;
    }
    const auto r = flex::decode_reply(line);
    if (!r) transport("\"" + line.substr(0, 80) + "\" is not a SmartSDR reply");
    if (r->seq == seq) return *r;   // a reply to an earlier command (after a timeout) is passed over
  }
}

void FlexLink::ensure_tx(Link s) {
  Leg& g = leg(s);
  if (s != Link::uplink || g.tx_set || !g.slice) return;
  g.tx_set = true;
  if (slice_tx_[*g.slice]) return;
  if (const flex::Reply r = ask(flex::set_tx(*g.slice)); r.status != 0)
    refused(flex::set_tx(*g.slice), r, "no uplink");
  slice_tx_[*g.slice] = true;
}

void FlexLink::ensure_slice(Link s, Hz hz) {
  Leg& g = leg(s);
  const std::string cmd = flex::create(hz, g.mode);
  const flex::Reply r = ask(cmd);
  if (r.status == 0x50000001) refused(cmd, r, "no free slice");
  if (r.status != 0) band_refused(s, hz, cmd, r);
  const auto index = text::parse_integer<int>(text::trimmed(r.data));
  if (!index) transport("\"" + cmd + "\" answered \"" + r.data + "\", expected the new slice's number");
  g.slice = *index;
  slice_hz_[*index] = hz;
}

void FlexLink::set_frequency(Link l, Hz hz) {
  const Link s = station(l);
  Leg& g = leg(s);
  const std::string band = band_name(hz);
  if (g.lacks == band)
    throw LinkError("no " + band, fmt::format("the radio refused {} for the {}: the {} at {} Hz is not sent", band,
                                              to_string(s), to_string(s), hz));
  if (!g.slice) {
    ensure_slice(s, hz);
  } else {
    const std::string cmd = flex::tune(*g.slice, hz);
    const flex::Reply r = ask(cmd);
    if (r.status != 0) band_refused(s, hz, cmd, r);
    slice_hz_[*g.slice] = hz;
  }
  if (g.lacks && *g.lacks != band) g.lacks.reset();   // the band it lacked is not this one
  ensure_tx(s);
  if (s == Link::uplink && tone_pending_) set_ctcss_tone(tone_);
}

void FlexLink::set_mode(Link l, Mode mode) {
  if (mode == Mode::none) return;
  Leg& g = leg(station(l));
  g.mode = mode;
  if (!g.slice) return;   // sent with the slice's creation
  const auto cmd = flex::set_mode(*g.slice, mode);
  if (const flex::Reply r = ask(*cmd); r.status != 0) refused(*cmd, r, std::string("no mode ") + to_string(mode));
}

bool FlexLink::can_read(Link l) const {
  const Leg& g = leg(station(l));
  return g.slice.has_value() && !g.lacks;
}

Hz FlexLink::read_frequency(Link l) {
  const Link s = station(l);
  const Leg& g = leg(s);
  if (!g.slice) throw LinkError(Action::drop, std::string("the ") + to_string(s) + " has no slice yet");
  (void)ask(flex::ping());   // what the radio said before its reply is in
  const auto it = slice_hz_.find(*g.slice);
  if (it == slice_hz_.end())
    throw LinkError(Action::drop, fmt::format("slice {} has said no frequency", *g.slice));
  return it->second;
}

void FlexLink::set_ctcss_tone(int tenths_hz) {
  if (opt_.role == RadioRole::downlink) return refuse_tone("the FlexRadio carrying the downlink", tenths_hz);
  tone_ = tenths_hz;
  const Leg& g = leg(Link::uplink);
  tone_pending_ = !g.slice;
  if (!g.slice) return;   // sent when the uplink has its slice
  const std::string cmd = flex::set_tone(*g.slice, tenths_hz);
  if (const flex::Reply r = ask(cmd); r.status != 0) refused(cmd, r, "no CTCSS");
}

void FlexLink::send_raw(const std::string& text) {
  std::string cmd = text;
  while (!cmd.empty() && (cmd.back() == '\n' || cmd.back() == '\r')) cmd.pop_back();
  if (const flex::Reply r = ask(cmd); r.status != 0)
    throw LinkError(Action::drop, fmt::format("\"{}\" refused ({})", cmd, flex::error_text(r.status)));
}

// Idle: the status lines that came (a turn of the knob) are taken; a closed connection is seen.
void FlexLink::check() {
  if (fd_ < 0) throw LinkError(Action::reconnect, "the connection is not open");
  while (line_waiting(0)) take(read_line());
}

std::unique_ptr<RadioDriver> make_flex_radio(const FlexOptions& options, WorkerTiming timing) {
  return std::make_unique<WorkerRadio>(std::make_unique<FlexLink>(options), timing);
}

}  // namespace tb::radio
