#include "radio/kenwood/link.h"

#include <spdlog/spdlog.h>

#include <thread>
#include <utility>

#include "radio/link_common.h"

namespace tb::radio {

using namespace link;  // Action, Clock and the helpers every family shares

KenwoodLink::KenwoodLink(std::string device, KenwoodOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(options) {}

std::string KenwoodLink::describe() const {
  return opt_.label + " CAT on " + port_.device() +
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

std::unique_ptr<RadioDriver> make_kenwood_radio(const std::string& device, const KenwoodOptions& o,
                                                WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<KenwoodLink>(device, o, at_baud(kenwood_serial(), o.baud)), t);
}

}  // namespace tb::radio
