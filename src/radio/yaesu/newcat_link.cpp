#include "radio/yaesu/newcat_link.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "radio/kenwood/codec.h"
#include "radio/link_common.h"

namespace tb::radio {

using namespace link;  // Action, Clock and the helpers every family shares

NewcatLink::NewcatLink(std::string device, NewcatOptions options, SerialSettings serial)
    : port_(std::move(device), serial), opt_(std::move(options)) {}

std::string NewcatLink::describe() const {
  return fmt::format("Yaesu {} CAT on {} ({})", opt_.label, port_.device(), opt_.vfo_b ? "VFO-B" : "VFO-A");
}

void NewcatLink::open() {
  port_.open();
  identified_ = locked_ = silent_ = woke_ = false;
  hz_.reset();
}

void NewcatLink::close() noexcept {
  if (port_.is_open() && locked_) {
    try {
      send(newcat::lock(false));
    } catch (const std::exception&) {
    }
  }
  locked_ = false;
  port_.close();
}

void NewcatLink::send(const std::string& command) { port_.write(command, port_.wire_time(command.size()) + kWriteSlack); }

std::optional<std::string> NewcatLink::query(const std::string& command, std::string_view prefix) {
  port_.discard_input();
  send(command);
  std::string text;
  const auto deadline = Clock::now() + opt_.reply_timeout;
  std::uint8_t buf[64];
  while (Clock::now() < deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    const std::size_t n = port_.read_some(buf, left);
    if (n == 0) break;
    text.append(reinterpret_cast<const char*>(buf), n);
    for (const std::string& c : kenwood::split_commands(text))   // Auto Information may come first
      if (c.starts_with(prefix) || newcat::is_refusal(c)) {
        woke_ = std::exchange(silent_, false) || woke_;
        return c;
      }
  }
  if (text.empty()) silent_ = true, identified_ = false;   // switched off: asked again when it answers
  return std::nullopt;
}

void NewcatLink::identify() {
  if (identified_ || opt_.ids.empty()) return;
  const auto answer = query(newcat::identify(), "ID");
  if (!answer) throw LinkError(Action::retry, "no answer from the " + opt_.label + " to ID;");
  identified_ = true;
  const auto id = newcat::decode_id(*answer);
  if (id && std::find(opt_.ids.begin(), opt_.ids.end(), *id) != opt_.ids.end()) return;
  if (std::exchange(id_warned_, true)) return;
  spdlog::warn("radio {}: it answers {} to ID;, not the {}'s ID{};: tuning goes on with the {}'s commands", describe(),
               *answer, opt_.label, opt_.ids.front(), opt_.label);
}

void NewcatLink::require(Link l) const {
  if (l == Link::downlink) return;
  throw LinkError("no uplink", "the " + opt_.label + " carries one link: the " + std::string(to_string(l)) +
                                   " needs a second radio (--uplink-radio)");
}

void NewcatLink::set_frequency(Link l, Hz hz) {
  require(l);
  require_band("the " + opt_.label, opt_.bands, l, hz);
  const std::string command = newcat::set_frequency(vfo(), hz);
  identify();
  send(command);
  hz_ = hz;
}

void NewcatLink::copy_to_b() {
  send(newcat::copy_a_to_b());
  if (hz_) send(newcat::set_frequency(newcat::Vfo::b, *hz_));
}

void NewcatLink::set_mode(Link l, Mode mode) {
  require(l);
  const char band = opt_.vfo_b && opt_.mode_md1 ? '1' : '0';
  const auto md = newcat::set_mode(band, mode);
  if (!md) return;
  identify();
  send(*md);
  if (opt_.vfo_b && !opt_.mode_md1) copy_to_b();
  if (!opt_.fm_dial_lock) return;
  // The FT-991A in FM: the dial locked, as OscarWatch does (a knob brushed in FM detunes the pass).
  const bool lock = mode == Mode::fm;
  if (lock == locked_) return;
  send(newcat::lock(lock));
  locked_ = lock;
}

Hz NewcatLink::read_frequency(Link l) {
  require(l);
  identify();
  const std::string ask = newcat::read_frequency(vfo());
  const auto answer = query(ask, ask.substr(0, 2));
  const auto f = answer ? newcat::decode_frequency(*answer) : std::nullopt;
  if (!f) throw LinkError(Action::retry, "no answer from the " + opt_.label + " to " + ask +
                                             (answer ? " (it answered " + *answer + ")" : ""));
  return f->hz;
}

void NewcatLink::set_ctcss_tone(int tenths_hz) {
  if (!opt_.ctcss) return refuse_tone("the " + opt_.label, tenths_hz);
  const auto tone = tenths_hz > 0 ? newcat::set_tone(tenths_hz) : std::optional(newcat::tone_off());
  if (!tone) throw LinkError(Action::drop, "the " + opt_.label + " has no CTCSS tone " + tone_text(tenths_hz) + ": not sent");
  identify();
  send(*tone);
  if (opt_.vfo_b) copy_to_b();
}

void NewcatLink::send_raw(const std::string& raw) { send(raw); }

std::unique_ptr<RadioDriver> make_newcat_radio(const std::string& device, const NewcatOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<NewcatLink>(device, o, at_baud(yaesu_serial(), o.baud)), t);
}

}  // namespace tb::radio
