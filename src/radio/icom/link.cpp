#include "radio/icom/link.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <thread>
#include <utility>

#include "radio/link_common.h"
#include "util/format.h"

namespace tb::radio {

using namespace link;  // Action, Clock and the helpers every family shares

namespace {

std::string hexaddr(std::uint8_t a) { return text::printf_string("%02Xh", a); }

}  // namespace

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
  if (!opt_.model.empty())   // a model of the registry: one address
    return "Icom " + opt_.model + " CI-V on " + port_.device() + " (" + hexaddr(opt_.rx_address) +
           (opt_.satellite_cmd ? ", satellite mode)" : ")");
  return "Icom CI-V on " + port_.device() + " (RX " + hexaddr(opt_.rx_address) + ", TX " +
         hexaddr(opt_.tx_address) + ")";
}

void IcomLink::open() {
  port_.open();
  reader_.clear();
  echo_.reset();       // an interface may have been swapped: found again on the first exchange
  selected_.reset();
  satellite_asked_ = satellite_on_ = band_refused_ = tx_read_refused_ = silent_ = woke_ = vfo_ab_ = false;
  set_hz_[0].reset();
  set_hz_[1].reset();
  off_band_[0] = off_band_[1] = xvtr_refused_ = false;
}

void IcomLink::close() noexcept {
  if (port_.is_open() && satellite_on_) {
    try {   // leave the radio as it was found: satellite mode off
      const std::uint8_t to = address(Link::downlink);
      exchange(icom::satellite_mode(to, opt_.satellite_cmd, opt_.satellite_sub, false),
               expects_reply(to) ? Expect::ack : Expect::nothing);
    } catch (const std::exception&) {
    }
  }
  satellite_on_ = false;
  port_.close();
}

std::string IcomLink::who(std::uint8_t to) const {
  return (opt_.model.empty() ? std::string("the Icom radio") : "the " + opt_.model) + " at address " + hexaddr(to);
}

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
  exchange(frame, wait_reply ? Expect::ack : Expect::nothing);
}

// Echo or not: on a one-wire CI-V bus every frame comes back as its echo before the radio answers;
// the IC-9700's USB port (CI-V USB Echo Back OFF, Gpredict's setting) sends only the answer. The
// first exchange after an open tells which: our own frame back (echo), or the radio's answer first
// (no echo). With the echo, a mangled or foreign echo or a jam code is a collision (wait, retry);
// without it there is no shared bus to collide on, and other traffic (transceive frames) is skipped.
std::optional<icom::Frame> IcomLink::exchange(const Bytes& frame, Expect expect) {
  const std::uint8_t to = frame.size() > 2 ? frame[2] : 0;
  const std::uint8_t cmd = frame.size() > 4 ? frame[4] : 0;
  const bool answered = expect != Expect::nothing;
  for (int attempt = 1; attempt <= opt_.max_attempts; ++attempt) {
    if (attempt > 1) std::this_thread::sleep_for(opt_.collision_wait * (attempt - 1));
    port_.discard_input();
    reader_.clear();
    port_.write(frame, port_.wire_time(frame.size()) + kWriteSlack);

    std::optional<Bytes> first;   // a frame already read that is the radio's answer (no echo)
    if (echo_ != false) {
      bool got_any = false;
      // Not knowing yet whether an echo comes, wait as long as the answer could take.
      const milliseconds wait = port_.wire_time(frame.size()) + opt_.echo_margin +
                                (!echo_ && answered ? opt_.reply_timeout : milliseconds(0));
      auto echo = read_frame(wait, got_any);
      if (!echo && !got_any) {
        if (echo_ || !answered)
          throw LinkError(Action::retry, "interface not echoing (nothing came back from the CI-V bus on " +
                                             port_.device() + ")");
        radio_silent();
        throw LinkError(Action::retry, "no reply from " + who(to) + " (neither an echo nor an answer)");
      }
      if (echo && *echo == frame) {
        echo_ = true;
      } else {
        const auto f = echo ? icom::decode_frame(*echo) : std::nullopt;
        const bool from_radio = f && f->to == icom::kController && f->from == to;
        if (!echo_ && answered && from_radio) {
          echo_ = false;    // the radio answered first: no echo on this interface
          first = echo;
        } else {
          selected_.reset();
          continue;         // collision: mangled or foreign echo, or FC
        }
      }
    }
    if (!answered) return std::nullopt;

    const auto deadline = Clock::now() + opt_.reply_timeout;
    bool collided = false;
    while (!collided) {
      std::optional<Bytes> reply = std::exchange(first, std::nullopt);
      if (!reply) {
        const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
        bool any = false;
        reply = left > milliseconds(0) ? read_frame(left, any) : std::nullopt;
      }
      if (!reply) {
        radio_silent();
        throw LinkError(Action::retry, "no reply from " + who(to));
      }
      const auto kind = icom::parse_reply(*reply);
      const auto f = icom::decode_frame(*reply);
      if (kind == icom::Reply::collision) {
        collided = echo_ == true;   // a jam only means something on a shared bus
      } else if (f && f->to == icom::kController && f->from == to) {
        if (kind == icom::Reply::ng || (expect == Expect::ack && kind == icom::Reply::ok) ||
            (f->cmd == cmd && kind != icom::Reply::ok))
          woke_ = std::exchange(silent_, false) || woke_;   // it answers
        if (kind == icom::Reply::ng)
          throw LinkError(Action::drop, who(to) + " refused " + to_hex(frame) + " (NG)");
        if (expect == Expect::ack && kind == icom::Reply::ok) return std::nullopt;
        if (expect == Expect::data && f->cmd == cmd) return f;
        // The same command answered with data instead of FB (Hamlib's simic9700 echoes 16 5A's
        // value): not an acknowledgement, and nothing waiting longer would change.
        if (expect == Expect::ack && f->cmd == cmd)
          throw LinkError(Action::drop, who(to) + " answered " + to_hex(frame) + " with " + to_hex(*reply) + " instead of FB");
      }
      // Anything else is other traffic: another controller on the bus, a late echo of our own
      // frame, or the radio's transceive frames (FE FE 00 <radio> 00 ... FD when the dial turns,
      // which do not say Main or Sub: never trusted, the dial is read with 03 instead).
    }
    selected_.reset();
  }
  throw LinkError(Action::retry, "CI-V bus collision: no clean echo after " +
                                     std::to_string(opt_.max_attempts) + " attempts");
}

// A radio that stopped answering (switched off behind its interface, or its USB cable's radio
// asleep): what it was told since the last answer may be gone when it answers again, so the band is
// selected and satellite mode asked again then, as at a connect.
void IcomLink::radio_silent() {
  selected_.reset();
  satellite_asked_ = false;
  silent_ = true;
}

// Asked once per connect (and after the radio fell silent): confirmed with FB, or reported once
// (refused, unanswered, answered with anything else) and the tuning goes on without it, each link
// still on its own band. Hamlib's path says the same ("Main/Sub without it").
void IcomLink::ensure_satellite_mode() {
  if (opt_.satellite_cmd == 0 || satellite_asked_) return;
  const std::uint8_t to = address(Link::downlink);
  const Bytes on = icom::satellite_mode(to, opt_.satellite_cmd, opt_.satellite_sub, true);
  const bool was_silent = silent_;
  std::string why;
  try {
    exchange(on, expects_reply(to) ? Expect::ack : Expect::nothing);
  } catch (const LinkError& e) {
    // The port gone, or a radio that stopped answering everything (switched off): not a verdict
    // on satellite mode; asked again once it answers.
    if (e.action == Action::reconnect || (e.action == Action::retry && was_silent)) throw;
    why = e.what();
  }
  satellite_asked_ = true;
  satellite_on_ = why.empty();
  if (satellite_on_) {
    if (std::exchange(satellite_warned_, false))
      spdlog::info("radio {}: satellite mode confirmed ({})", describe(), to_hex(on));
    return;
  }
  if (std::exchange(satellite_warned_, true)) return;   // said once; asked again after a silence or connect
  spdlog::warn("radio {}: satellite mode not confirmed ({}); tuning goes on without it, Main/Sub", describe(), why);
}

void IcomLink::select_band(Link l) {
  const std::uint8_t to = address(l);
  if (opt_.satellite_cmd != 0 || opt_.band_select == IcomBandSelect::main_tx_sub_rx) {
    // With VFO A/B (below) the key cached is VFO A as Main, VFO B as Sub.
    const icom::Band band = vfo_ab_ ? (l == Link::downlink ? icom::Band::main : icom::Band::sub)
                            : opt_.satellite_cmd != 0 ? (l == opt_.main_link ? icom::Band::main : icom::Band::sub)
                                                      : (l == Link::uplink ? icom::Band::main : icom::Band::sub);
    if (opt_.satellite_cmd != 0 && selected_ == band) return;   // no select thrash: only when the band changes
    if (band_refused_) return;
    selected_.reset();
    // VFO A down, VFO B up (07 00 / 07 01) on a radio that has no Main/Sub for trakbox; cached as
    // Main and Sub.
    const Bytes select = vfo_ab_ ? icom::select_vfo(to, l == Link::downlink ? icom::Vfo::a : icom::Vfo::b)
                                 : icom::select_band(to, band);
    try {
      exchange(select, expects_reply(to) ? Expect::ack : Expect::nothing);
    } catch (const LinkError& e) {
      if (e.action != Action::drop) throw;
      // Refused or not acknowledged: said once; 07 D0/D1 gives way to VFO A/B, and a radio that
      // takes neither gets the commands on the band it has selected, until the next connect.
      if (!vfo_ab_) {
        vfo_ab_ = true;
        spdlog::warn("radio {}: band select not confirmed ({}); VFO A down, VFO B up (07 00 / 07 01) until the next connect",
                     describe(), e.what());
        return select_band(l);
      }
      band_refused_ = true;
      spdlog::warn("radio {}: VFO select not confirmed either ({}); tuning goes on without it until the next connect",
                   describe(), e.what());
      return;
    }
    selected_ = band;
  }
}

// A band the radio lacks is a limit learnt once, not a fault: the IC-7300 has no 70 cm, the IC-905
// no 10 GHz without its transverter. Its link is not read while it is there (the dial is elsewhere).
void IcomLink::require_band(Link l, Hz hz) {
  bool& off = off_band_[l == Link::downlink ? 0 : 1];
  off = true;
  const std::string radio = opt_.model.empty() ? std::string("this Icom radio") : "the " + opt_.model;
  if (opt_.xvtr_from > 0 && hz >= opt_.xvtr_from && (!opt_.transverter || xvtr_refused_))
    throw LinkError("no " + band_name(hz),
                    fmt::format("{} tunes {} only with its transverter ({}): the {} at {} Hz is not sent", radio,
                                band_name(hz), xvtr_refused_ ? "refused until the next connect" : "--radio ...:xvtr",
                                to_string(l), hz));
  link::require_band(radio, opt_.bands, l, hz);
  off = false;
}

void IcomLink::set_frequency(Link l, Hz hz) {
  const std::uint8_t to = address(l);
  require_band(l, hz);
  const Bytes frame = icom::set_frequency(to, hz, opt_.width);
  ensure_satellite_mode();
  select_band(l);
  try {
    transact(frame, expects_reply(to));
  } catch (const LinkError& e) {
    // The IC-905 refuses its 10 GHz band when the transverter is absent or off (FA): a limit.
    if (e.action != Action::drop || opt_.xvtr_from == 0 || hz < opt_.xvtr_from) throw;
    off_band_[l == Link::downlink ? 0 : 1] = true;
    xvtr_refused_ = true;   // not sent again until the next connect
    throw LinkError("no " + band_name(hz), fmt::format("{}; its transverter is absent or off: the {} band is left alone",
                                                       e.what(), band_name(hz)));
  }
  set_hz_[l == Link::downlink ? 0 : 1] = hz;
}

void IcomLink::set_mode(Link l, Mode mode) {
  const std::uint8_t to = address(l);
  auto frame = icom::set_mode(to, mode);
  if (!frame) return;
  ensure_satellite_mode();
  select_band(l);
  transact(*frame, expects_reply(to));
}

Hz IcomLink::read_frequency(Link l) {
  const std::uint8_t to = address(l);
  if (!can_read(l)) return RadioLink::read_frequency(l);
  if (off_band_[l == Link::downlink ? 0 : 1])   // its frequency was not sent: nothing to follow
    throw LinkError(Action::drop, std::string(to_string(l)) + " not read: its band is one the radio lacks");
  ensure_satellite_mode();
  const icom::Band band = l == opt_.main_link ? icom::Band::main : icom::Band::sub;   // (not with VFO A/B)
  const bool tx = opt_.satellite_cmd != 0 && l == Link::uplink && opt_.reads_tx_1c03 && selected_ != band &&
                  satellite_on_ && !tx_read_refused_ && !vfo_ab_;
  if (tx) {
    try {
      if (const auto answer = exchange(icom::read_transmit_frequency(to), Expect::data))
        if (const auto hz = icom::decode_frequency(*answer)) return *hz;
      throw LinkError(Action::drop, who(to) + " answered 1C 03 without a frequency");
    } catch (const LinkError& e) {
      if (e.action != Action::drop) throw;
      // Refused (Hamlib's simic9700 answers FA): the uplink is read on its band from now on.
      tx_read_refused_ = true;
      spdlog::warn("radio {}: {}; the uplink is read with a band select and 03 until the next connect", describe(),
                   e.what());
    }
  }
  select_band(l);
  const auto answer = exchange(icom::read_frequency(to), Expect::data);
  const auto hz = answer ? icom::decode_frequency(*answer) : std::nullopt;
  if (!hz) throw LinkError(Action::retry, who(to) + " answered 03 without a frequency");
  // A band select acknowledged but not acted on (Hamlib's simic910 answers 07 D0/D1 with FB and
  // stays on VFO A): this link's band reads what the other link was set to. VFO A/B from now on,
  // said once, and everything is sent again (answered_again); the read is taken as no turn.
  const std::optional<Hz>& mine = set_hz_[l == Link::downlink ? 0 : 1];
  const std::optional<Hz>& other = set_hz_[l == Link::downlink ? 1 : 0];
  if (!vfo_ab_ && opt_.satellite_cmd != 0 && mine && other && *hz == *other && *hz != *mine) {
    vfo_ab_ = true;
    selected_.reset();
    woke_ = true;
    spdlog::warn("radio {}: the {} band reads {} Hz, the {}'s frequency: its band select (07 D0/D1) is acknowledged "
                 "but not followed; VFO A down, VFO B up (07 00 / 07 01) until the next connect",
                 describe(), to_string(l), *hz, to_string(l == Link::downlink ? Link::uplink : Link::downlink));
    return *mine;
  }
  return *hz;
}

void IcomLink::set_ctcss_tone(int tenths_hz) {
  const std::uint8_t to = address(Link::uplink);
  if (!opt_.ctcss) return refuse_tone(opt_.model.empty() ? std::string("this Icom radio") : "the " + opt_.model, tenths_hz);
  const Bytes tone = tenths_hz > 0 ? icom::set_tone_frequency(to, tenths_hz) : Bytes{};
  ensure_satellite_mode();
  select_band(Link::uplink);
  if (tenths_hz > 0) transact(tone, expects_reply(to));
  transact(icom::tone_function(to, tenths_hz > 0), expects_reply(to));
}

void IcomLink::send_raw(const std::string& raw) {
  const Bytes bytes(raw.begin(), raw.end());
  selected_.reset();   // the caller's frame may select a band
  if (icom::decode_frame(bytes)) {
    transact(bytes, false);   // checked against its echo like any frame; any reply is the caller's
  } else {
    port_.write(bytes, port_.wire_time(bytes.size()) + kWriteSlack);
  }
}

std::unique_ptr<RadioDriver> make_icom_radio(const std::string& device, const IcomOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<IcomLink>(device, o, at_baud(icom_serial(), o.baud)), t);
}

}  // namespace tb::radio
