#include "radio/cat_links.h"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <thread>
#include <utility>

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

std::string tone_text(int tenths_hz) { return std::to_string(tenths_hz / 10) + "." + std::to_string(tenths_hz % 10) + " Hz"; }

// A radio without a CTCSS encoder trakbox can set: a tone is refused with a message, never dropped
// silently; turning the tone off is nothing to refuse.
void refuse_tone(const std::string& radio, int tenths_hz) {
  if (tenths_hz <= 0) return;
  throw LinkError(LinkError::Action::drop, radio + " has no CTCSS encoder trakbox can set: tone " + tone_text(tenths_hz) + " not sent");
}

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
  satellite_asked_ = satellite_on_ = band_refused_ = tx_read_refused_ = silent_ = woke_ = false;
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
    const icom::Band band = opt_.satellite_cmd != 0 ? (l == opt_.main_link ? icom::Band::main : icom::Band::sub)
                                                    : (l == Link::uplink ? icom::Band::main : icom::Band::sub);
    if (opt_.satellite_cmd != 0 && selected_ == band) return;   // no select thrash: only when the band changes
    if (band_refused_) return;
    selected_.reset();
    try {
      exchange(icom::select_band(to, band), expects_reply(to) ? Expect::ack : Expect::nothing);
    } catch (const LinkError& e) {
      if (e.action != Action::drop) throw;
      // Refused or not acknowledged: said once; the commands go to the band the radio has selected
      // until the next connect (a radio without 07 D0/D1 keeps tuning).
      band_refused_ = true;
      spdlog::warn("radio {}: band select not confirmed ({}); tuning goes on without it until the next connect",
                   describe(), e.what());
      return;
    }
    selected_ = band;
  }
}

void IcomLink::set_frequency(Link l, Hz hz) {
  const std::uint8_t to = address(l);
  const Bytes frame = icom::set_frequency(to, hz, opt_.width);
  ensure_satellite_mode();
  select_band(l);
  transact(frame, expects_reply(to));
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
  ensure_satellite_mode();
  const icom::Band band = l == opt_.main_link ? icom::Band::main : icom::Band::sub;
  const bool tx = opt_.satellite_cmd != 0 && l == Link::uplink && opt_.reads_tx_1c03 && selected_ != band &&
                  satellite_on_ && !tx_read_refused_;
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

// ---------------------------------------------------------------------------------------------
KenwoodLink::KenwoodLink(std::string device, KenwoodOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(options) {}

std::string KenwoodLink::describe() const {
  return (opt_.model == "Kenwood radio" ? std::string("Kenwood") : opt_.model) + " CAT on " + port_.device() +
         (opt_.satellite_mode ? " (satellite mode)" : "");
}

void KenwoodLink::open() {
  port_.open();
  satellite_asked_ = satellite_on_ = tone_on_ = silent_ = woke_ = false;
  found_.reset();
}

void KenwoodLink::close() noexcept {
  if (port_.is_open()) {
    try {   // leave the radio as it was found: the tone off, SA as it was (SatPC32 at exit: SA0010000;)
      if (tone_on_) on_uplink_band([&] { send(kenwood::tone(false)); });
      if (found_) send(kenwood::set_satellite(*found_));
    } catch (const std::exception&) {
    }
  }
  found_.reset();
  satellite_on_ = tone_on_ = false;
  port_.close();
}

void KenwoodLink::send(const std::string& command) {
  port_.write(command, port_.wire_time(command.size()) + kWriteSlack);
  if (opt_.command_gap.count() > 0) std::this_thread::sleep_for(opt_.command_gap);
}

std::optional<std::string> KenwoodLink::query(const std::string& command, std::string_view prefix, bool discard) {
  if (discard) port_.discard_input();
  send(command);
  std::string text;
  const auto deadline = Clock::now() + opt_.reply_timeout;
  std::uint8_t buf[64];
  while (Clock::now() < deadline) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    const std::size_t n = port_.read_some(buf, left);
    if (n == 0) break;
    text.append(reinterpret_cast<const char*>(buf), n);
    for (const std::string& c : kenwood::split_commands(text))   // Auto Information may come first
      if (c.starts_with(prefix) || kenwood::is_refusal(c)) return c;
  }
  return std::nullopt;
}

void KenwoodLink::ensure_satellite_mode() {
  if (!opt_.satellite_mode || satellite_asked_) return;
  satellite_asked_ = true;   // asked once per open: a radio that refuses is not asked every second
  const auto answer = query(kenwood::read_satellite(), "SA");
  if (!answer && silent_) {   // switched off: no verdict on satellite mode, asked once it answers
    satellite_asked_ = false;
    throw LinkError(Action::retry, "no answer from the " + opt_.model + " to " + kenwood::read_satellite());
  }
  if (answer) woke_ = std::exchange(silent_, false) || woke_;
  const auto found = answer ? kenwood::decode_satellite(*answer) : std::nullopt;
  if (!found) {
    if (!std::exchange(satellite_warned_, true))
      spdlog::warn("radio {}: satellite mode not switched on ({} to SA;); tuning goes on with VFO A down, VFO B up",
                   describe(), answer ? "it answered " + *answer : std::string("no answer"));
    return;
  }
  if (!found_) found_ = found;   // as found at the first ask since open: put back at close
  const kenwood::Satellite working = kenwood::satellite_working(*found, false);
  if (*found == working) {
    satellite_on_ = true;
    satellite_warned_ = false;
    return;
  }
  // A VFO in memory mode keeps the radio out of satellite mode (an operator's report to
  // OscarWatch-Tracker, issue #71): VFO A first. FR; is refused in satellite mode: asked only when off.
  if (!found->on()) {
    const auto vfo = query(kenwood::read_vfo(), "FR");
    if (vfo && vfo->size() == 4 && (*vfo)[2] != '0' && (*vfo)[2] != '1') send("FR0;");
  }
  send(kenwood::set_satellite(working));
  std::this_thread::sleep_for(opt_.satellite_settle);
  std::string last = "no answer";
  for (int i = 0; i < opt_.satellite_confirm_tries; ++i) {
    if (i > 0) std::this_thread::sleep_for(opt_.satellite_confirm_gap);
    const auto now = query(kenwood::read_satellite(), "SA");
    if (now) last = *now;
    const auto state = now ? kenwood::decode_satellite(*now) : std::nullopt;
    if (state && state->on()) {
      satellite_on_ = true;
      satellite_warned_ = false;
      spdlog::info("radio {}: satellite mode on ({} found {}): downlink on Main (FA), uplink on Sub (FB)", describe(),
                   kenwood::set_satellite(working), kenwood::set_satellite(*found));
      return;
    }
  }
  // Refused or not taken: reported once, and the Doppler goes on (FA and FB still tune VFO A and B).
  if (std::exchange(satellite_warned_, true)) return;
  spdlog::warn("radio {}: satellite mode not switched on (sent {}, SA; answers {}); tuning goes on with VFO A "
               "down, VFO B up",
               describe(), kenwood::set_satellite(working), last);
}

template <class F>
void KenwoodLink::on_uplink_band(F&& what) {
  if (opt_.one_link) return what();
  const std::string there = satellite_on_ ? kenwood::set_satellite(kenwood::satellite_working(*found_, true))
                                          : kenwood::select_vfo(kenwood::Vfo::b, opt_.vfo_select);
  const std::string back = satellite_on_ ? kenwood::set_satellite(kenwood::satellite_working(*found_, false))
                                         : kenwood::select_vfo(kenwood::Vfo::a, opt_.vfo_select);
  send(there);
  try {
    what();
  } catch (...) {
    send(back);
    throw;
  }
  send(back);
}

void KenwoodLink::set_frequency(Link l, Hz hz) {
  ensure_satellite_mode();
  send(kenwood::set_frequency(vfo_of(l), hz));
}

void KenwoodLink::set_mode(Link l, Mode mode) {
  auto md = kenwood::set_mode(mode);
  if (!md) return;
  ensure_satellite_mode();
  if (opt_.one_link || (satellite_on_ && l == Link::downlink)) return send(*md);
  if (satellite_on_ || l == Link::uplink) return on_uplink_band([&] { send(*md); });
  send(kenwood::select_vfo(kenwood::Vfo::a, opt_.vfo_select));   // the TS-790 family: the VFO the mode goes to, first
  send(*md);
}

void KenwoodLink::send_raw(const std::string& bytes) { send(bytes); }

void KenwoodLink::set_ctcss_tone(int tenths_hz) {
  if (!opt_.ctcss) return refuse_tone("the " + opt_.model, tenths_hz);
  const auto tn = tenths_hz > 0 ? kenwood::set_tone_number(tenths_hz) : std::nullopt;
  if (tenths_hz > 0 && !tn)
    throw LinkError(Action::drop, "the " + opt_.model + " has no CTCSS tone " + tone_text(tenths_hz) + ": not sent");
  ensure_satellite_mode();
  std::optional<std::string> answer;
  auto encoder = [&] {   // the radio answers in order: a ?; for TN or TO comes before TO;'s answer
    port_.discard_input();
    if (tn) send(*tn);
    send(kenwood::tone(tenths_hz > 0));
    answer = query(kenwood::read_tone(), "TO", false);
  };
  on_uplink_band(encoder);
  tone_on_ = tenths_hz > 0;   // on: turned off again at close
  // TO; confirms; a radio that does not answer it is taken at its word (Hamlib's simulator).
  if (answer && *answer != kenwood::tone(tenths_hz > 0))
    throw LinkError(Action::drop, "the " + opt_.model + " refused the tone " +
                                      (tenths_hz > 0 ? tone_text(tenths_hz) + " (" + *tn + "TO1;" : std::string("off (TO0;")) +
                                      " answered " + *answer + ")");
}

Hz KenwoodLink::read_frequency(Link l) {
  if (!opt_.reads) return RadioLink::read_frequency(l);
  ensure_satellite_mode();
  const kenwood::Vfo vfo = vfo_of(l);
  const auto answer = query(kenwood::read_frequency(vfo), vfo == kenwood::Vfo::a ? "FA" : "FB");
  const auto f = answer ? kenwood::decode_frequency(*answer) : std::nullopt;
  if (answer) woke_ = std::exchange(silent_, false) || woke_;
  else silent_ = true, satellite_asked_ = satellite_on_ = false;   // switched off: asked again when it answers
  if (!f) throw LinkError(Action::retry, "no answer from the " + opt_.model + " to " + kenwood::read_frequency(vfo) +
                                             (answer ? " (it answered " + *answer + ")" : ""));
  return f->hz;
}

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

void YaesuLink::set_ctcss_tone(int tenths_hz) { refuse_tone("the FT-736", tenths_hz); }

void YaesuLink::send_raw(const std::string& raw) {
  send(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size()));
}

// ---------------------------------------------------------------------------------------------
Ft8xxLink::Ft8xxLink(std::string device, Ft8xxOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(std::move(options)) {}

std::string Ft8xxLink::describe() const { return "Yaesu " + opt_.label + " CAT on " + port_.device(); }

bool Ft8xxLink::carries(Link l) const {
  return l == Link::downlink || (opt_.model == Ft8xxOptions::Model::ft847 && opt_.satellite_mode);
}

void Ft8xxLink::require(Link l) const {
  if (!carries(l))
    throw LinkError(Action::drop, "the " + opt_.label + " carries one link (the downlink): the " + to_string(l) +
                                      " needs a second radio (--uplink-radio)");
}

yaesu::Target Ft8xxLink::target(Link l) const {
  if (opt_.model != Ft8xxOptions::Model::ft847 || !opt_.satellite_mode) return yaesu::Target::main;
  return l == Link::downlink ? yaesu::Target::sat_rx : yaesu::Target::sat_tx;
}

void Ft8xxLink::send(std::span<const std::uint8_t> c) {
  for (std::uint8_t b : c) {
    port_.write(std::span<const std::uint8_t>(&b, 1), port_.wire_time(1) + kWriteSlack);
    if (opt_.byte_gap.count() > 0) std::this_thread::sleep_for(opt_.byte_gap);
  }
}

void Ft8xxLink::open() {
  port_.open();
  satellite_on_ = silent_ = woke_ = false;
  cat_on_ = opt_.model == Ft8xxOptions::Model::ft847;
  if (cat_on_) send(ft847::cat_on());   // (on the FT-817, 00 is LOCK ON)
}

void Ft8xxLink::close() noexcept {
  if (port_.is_open() && opt_.model == Ft8xxOptions::Model::ft847) {
    try {
      if (satellite_on_) send(ft847::sat_mode_off());
      send(ft847::cat_off());
    } catch (const std::exception&) {
    }
  }
  satellite_on_ = false;
  port_.close();
}

void Ft8xxLink::ensure_satellite_mode() {
  if (!cat_on_ && opt_.model == Ft8xxOptions::Model::ft847) send(ft847::cat_on());   // again after a silence
  cat_on_ = true;
  if (satellite_on_ || target(Link::downlink) == yaesu::Target::main) return;
  send(ft847::sat_mode_on());   // never acknowledged: sent once per open, before the first frequency
  satellite_on_ = true;
}

void Ft8xxLink::set_frequency(Link l, Hz hz) {
  require(l);
  const yaesu::Command c = opt_.model == Ft8xxOptions::Model::ft847 ? ft847::set_frequency(target(l), hz)
                                                                    : ft817::set_frequency(hz);
  ensure_satellite_mode();
  send(c);
}

void Ft8xxLink::set_mode(Link l, Mode mode) {
  require(l);
  const auto c = opt_.model == Ft8xxOptions::Model::ft847 ? ft847::set_mode(target(l), mode) : ft817::set_mode(mode);
  if (!c) return;
  ensure_satellite_mode();
  send(*c);
}

Hz Ft8xxLink::read_frequency(Link l) {
  require(l);
  ensure_satellite_mode();
  port_.discard_input();
  send(opt_.model == Ft8xxOptions::Model::ft847 ? ft847::read(target(l)) : ft817::read());
  Bytes answer;
  const auto deadline = Clock::now() + opt_.reply_timeout;
  std::uint8_t buf[16];
  while (answer.size() < 5 && Clock::now() < deadline) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now());
    const std::size_t n = port_.read_some(std::span<std::uint8_t>(buf, std::min<std::size_t>(sizeof buf, 5 - answer.size())), left);
    if (n == 0) break;
    answer.insert(answer.end(), buf, buf + n);
  }
  const auto hz = ft847::decode_read(answer);   // the same 4 BCD bytes + mode on both radios
  // Nothing at all: switched off. Its CAT and satellite mode are sent again when it answers, as
  // after a connect (a radio switched on again starts with CAT off).
  if (answer.empty()) cat_on_ = satellite_on_ = false, silent_ = true;
  else woke_ = std::exchange(silent_, false) || woke_;
  if (!hz) throw LinkError(Action::retry, "no answer from the " + opt_.label + " to its read command (" +
                                             std::to_string(answer.size()) + " of 5 bytes)");
  return *hz;
}

void Ft8xxLink::set_ctcss_tone(int tenths_hz) {
  const bool ft847 = opt_.model == Ft8xxOptions::Model::ft847;
  // The FT-817 as the uplink radio of two carries the uplink on its only VFO.
  const yaesu::Target t = ft847 ? target(Link::uplink) : yaesu::Target::main;
  if (tenths_hz <= 0) {
    send(ft847 ? ft847::tone_encoder(t, false) : ft817::tone_encoder(false));
    return;
  }
  std::optional<yaesu::Command> tone = ft847 ? ft847::set_tone(t, tenths_hz) : std::optional(ft817::set_tone(tenths_hz));
  if (!tone)
    throw LinkError(Action::drop, "the " + opt_.label + " has no CTCSS tone " + tone_text(tenths_hz) + ": not sent");
  ensure_satellite_mode();
  send(*tone);
  send(ft847 ? ft847::tone_encoder(t, true) : ft817::tone_encoder(true));
}

void Ft8xxLink::send_raw(const std::string& raw) {
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

std::unique_ptr<RadioDriver> make_ft8xx_radio(const std::string& device, const Ft8xxOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<Ft8xxLink>(device, o, at_baud(yaesu_serial(), o.baud)), t);
}

}  // namespace tb::radio
