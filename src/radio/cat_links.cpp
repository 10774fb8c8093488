#include "radio/cat_links.h"

#include <cstdio>
#include <thread>

namespace tb::radio {

using Action = LinkError::Action;
using Clock = std::chrono::steady_clock;

namespace {

std::string hexaddr(std::uint8_t a) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02Xh", a);
  return buf;
}

constexpr milliseconds kWriteSlack{1000};

// A rig's standard serial settings at the configured speed (STATION.DAT line 4), when one is set.
SerialSettings at_baud(SerialSettings s, int baud) {
  if (baud > 0) s.baud = static_cast<unsigned>(baud);
  return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
IcomOptions IcomOptions::from(const RadioConfig& c) {
  IcomOptions o;
  o.rx_address = c.icom_rx_address;
  o.tx_address = c.icom_tx_address;
  o.band_select = c.icom_band_select;
  o.width = c.icom_four_byte_frequency ? icom::FrequencyWidth::four_bytes
                                       : icom::FrequencyWidth::five_bytes;
  o.baud = c.cat_baud;
  return o;
}

IcomLink::IcomLink(std::string device, IcomOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(options) {}

std::string IcomLink::describe() const {
  return "Icom CI-V on " + port_.device() + " (RX " + hexaddr(opt_.rx_address) + ", TX " +
         hexaddr(opt_.tx_address) + ")";
}

void IcomLink::open() {
  port_.open();
  reader_.clear();
}

void IcomLink::close() noexcept { port_.close(); }

std::optional<Bytes> IcomLink::read_frame(milliseconds timeout, bool& got_any) {
  const auto deadline = Clock::now() + timeout;
  std::uint8_t buf[64];
  while (true) {
    if (auto f = reader_.next()) return f;
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    if (left <= milliseconds(0)) return std::nullopt;
    const std::size_t n = port_.read_some(buf, left);
    if (n == 0) return std::nullopt;
    got_any = true;
    reader_.feed(std::span<const std::uint8_t>(buf, n));
  }
}

void IcomLink::transact(const Bytes& frame, bool wait_reply) {
  const std::uint8_t to = frame.size() > 2 ? frame[2] : 0;
  for (int attempt = 1; attempt <= opt_.max_attempts; ++attempt) {
    if (attempt > 1) std::this_thread::sleep_for(opt_.collision_wait * (attempt - 1));
    port_.discard_input();
    reader_.clear();
    port_.write(frame, port_.wire_time(frame.size()) + kWriteSlack);

    bool got_any = false;
    auto echo = read_frame(port_.wire_time(frame.size()) + opt_.echo_margin, got_any);
    if (!echo && !got_any)
      throw LinkError(Action::retry, "interface not echoing (nothing came back from the CI-V bus on " +
                                         port_.device() + ")");
    if (!echo || *echo != frame) continue;   // collision: mangled or foreign echo, or FC
    if (!wait_reply) return;

    const auto deadline = Clock::now() + opt_.reply_timeout;
    bool collided = false;
    while (!collided) {
      const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
      bool any = false;
      auto reply = left > milliseconds(0) ? read_frame(left, any) : std::nullopt;
      if (!reply)
        throw LinkError(Action::retry, "no reply from the Icom radio at address " + hexaddr(to));
      const auto kind = icom::parse_reply(*reply);
      const auto f = icom::decode_frame(*reply);
      if (kind == icom::Reply::collision) {
        collided = true;
      } else if (f && f->to == icom::kController && f->from == to) {
        if (kind == icom::Reply::ok) return;
        if (kind == icom::Reply::ng)
          throw LinkError(Action::drop, "the Icom radio at address " + hexaddr(to) +
                                            " refused " + to_hex(frame) + " (NG)");
      }
      // Anything else is other traffic on the bus: keep listening.
    }
  }
  throw LinkError(Action::retry, "CI-V bus collision: no clean echo after " +
                                     std::to_string(opt_.max_attempts) + " attempts");
}

void IcomLink::select_band(Link l) {
  if (opt_.band_select != IcomBandSelect::main_tx_sub_rx) return;
  const std::uint8_t to = address(l);
  transact(icom::select_band(to, l == Link::uplink ? icom::Band::main : icom::Band::sub),
           opt_.expect_reply && to != icom::kBroadcast);
}

void IcomLink::set_frequency(Link l, Hz hz) {
  const std::uint8_t to = address(l);
  const Bytes frame = icom::set_frequency(to, hz, opt_.width);
  select_band(l);
  transact(frame, opt_.expect_reply && to != icom::kBroadcast);
}

void IcomLink::set_mode(Link l, Mode mode) {
  const std::uint8_t to = address(l);
  auto frame = icom::set_mode(to, mode);
  if (!frame) return;
  select_band(l);
  transact(*frame, opt_.expect_reply && to != icom::kBroadcast);
}

void IcomLink::send_raw(const std::string& raw) {
  const Bytes bytes(raw.begin(), raw.end());
  if (icom::decode_frame(bytes)) {
    transact(bytes, false);   // checked against its echo like any frame; any reply is the caller's
  } else {
    port_.write(bytes, port_.wire_time(bytes.size()) + kWriteSlack);
  }
}

// ---------------------------------------------------------------------------------------------
KenwoodLink::KenwoodLink(std::string device, KenwoodOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(options) {}

std::string KenwoodLink::describe() const { return "Kenwood CAT on " + port_.device(); }

void KenwoodLink::open() { port_.open(); }
void KenwoodLink::close() noexcept { port_.close(); }

void KenwoodLink::send(const std::string& command) {
  port_.write(command, port_.wire_time(command.size()) + kWriteSlack);
  if (opt_.command_gap.count() > 0) std::this_thread::sleep_for(opt_.command_gap);
}

void KenwoodLink::set_frequency(Link l, Hz hz) {
  send(kenwood::set_frequency(l == Link::downlink ? kenwood::Vfo::a : kenwood::Vfo::b, hz));
}

void KenwoodLink::set_mode(Link l, Mode mode) {
  auto md = kenwood::set_mode(mode);
  if (!md) return;
  send(kenwood::select_vfo(l == Link::downlink ? kenwood::Vfo::a : kenwood::Vfo::b));
  send(*md);
  if (l == Link::uplink) send(kenwood::select_vfo(kenwood::Vfo::a));
}

void KenwoodLink::send_raw(const std::string& bytes) { send(bytes); }

// ---------------------------------------------------------------------------------------------
YaesuOptions YaesuOptions::from(const RadioConfig& c) {
  YaesuOptions o;
  o.wide_fm = c.ft736_wide_fm;
  o.baud = c.cat_baud;
  return o;
}

YaesuLink::YaesuLink(std::string device, YaesuOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(options) {}

std::string YaesuLink::describe() const { return "Yaesu FT-736 CAT on " + port_.device(); }

void YaesuLink::send(std::span<const std::uint8_t> bytes) {
  for (std::uint8_t b : bytes) {
    port_.write(std::span<const std::uint8_t>(&b, 1), port_.wire_time(1) + kWriteSlack);
    if (opt_.byte_gap.count() > 0) std::this_thread::sleep_for(opt_.byte_gap);
  }
}

void YaesuLink::open() {
  port_.open();
  send(yaesu::cat_on());
  if (opt_.satellite_mode) send(yaesu::sat_mode_on());
}

void YaesuLink::close() noexcept {
  if (port_.is_open()) {
    try {
      send(yaesu::cat_off());
    } catch (const std::exception&) {
    }
  }
  port_.close();
}

yaesu::Target YaesuLink::target(Link l) const {
  if (!opt_.satellite_mode) return yaesu::Target::main;
  return l == Link::downlink ? yaesu::Target::sat_rx : yaesu::Target::sat_tx;
}

void YaesuLink::set_frequency(Link l, Hz hz) {
  if (!opt_.satellite_mode && l == Link::uplink)
    throw LinkError(Action::drop, "FT-736 uplink needs satellite mode");
  send(yaesu::set_frequency(target(l), hz));
}

void YaesuLink::set_mode(Link l, Mode mode) {
  if (!opt_.satellite_mode && l == Link::uplink)
    throw LinkError(Action::drop, "FT-736 uplink needs satellite mode");
  auto cmd = yaesu::set_mode(target(l), mode, l == Link::downlink && opt_.wide_fm);
  if (cmd) send(*cmd);
}

void YaesuLink::send_raw(const std::string& raw) {
  send(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()));
}

// ---------------------------------------------------------------------------------------------
std::unique_ptr<RadioDriver> make_icom_radio(const std::string& device, const IcomOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<IcomLink>(device, o, at_baud(icom_serial(), o.baud)), t);
}

std::unique_ptr<RadioDriver> make_kenwood_radio(const std::string& device, const KenwoodOptions& o,
                                                WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<KenwoodLink>(device, o, at_baud(kenwood_serial(), o.baud)), t);
}

std::unique_ptr<RadioDriver> make_yaesu_radio(const std::string& device, const YaesuOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<YaesuLink>(device, o, at_baud(yaesu_serial(), o.baud)), t);
}

}  // namespace tb::radio
