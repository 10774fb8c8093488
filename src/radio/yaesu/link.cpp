#include "radio/yaesu/link.h"

#include <spdlog/spdlog.h>

#include <thread>
#include <utility>

#include "radio/link_common.h"

namespace tb::radio {

using namespace link;  // Action, Clock and the helpers every family shares

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
    throw LinkError("no uplink", "the " + opt_.label + " carries one link (the downlink): the " + to_string(l) +
                                      " needs a second radio (--uplink-radio)");
}

yaesu::Target Ft8xxLink::target(Link l) const {
  if (opt_.model != Ft8xxOptions::Model::ft847 || !opt_.satellite_mode) return yaesu::Target::main;
  return l == Link::downlink ? yaesu::Target::sat_rx : yaesu::Target::sat_tx;
}

void Ft8xxLink::send(std::span<const std::uint8_t> c, bool gap_after_last) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    port_.write(c.subspan(i, 1), port_.wire_time(1) + kWriteSlack);
    if (opt_.byte_gap.count() > 0 && (gap_after_last || i + 1 < c.size())) std::this_thread::sleep_for(opt_.byte_gap);
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
  require_band("the " + opt_.label, opt_.bands, l, hz);
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
  // The reply paces the next command; the dial it tells is the dial when the command was complete,
  // 50 ms sooner than after a gap (on the FT-847's line a read is 0.21 s instead of 0.26).
  send(opt_.model == Ft8xxOptions::Model::ft847 ? ft847::read(target(l)) : ft817::read(), false);
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

std::unique_ptr<RadioDriver> make_yaesu_radio(const std::string& device, const YaesuOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<YaesuLink>(device, o, at_baud(yaesu_serial(), o.baud)), t);
}

std::unique_ptr<RadioDriver> make_ft8xx_radio(const std::string& device, const Ft8xxOptions& o, WorkerTiming t) {
  return std::make_unique<WorkerRadio>(std::make_unique<Ft8xxLink>(device, o, at_baud(yaesu_serial(), o.baud)), t);
}

}  // namespace tb::radio
