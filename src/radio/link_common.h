// What the serial CAT links of every family share (internal to src/radio): the write slack, the
// tone's text, the refusal of a tone a radio cannot set, a rig's serial settings at a configured
// speed, and the names they use (each link's file says `using namespace link;`).
#pragma once
#include <chrono>
#include <span>
#include <string>

#include "radio/registry.h"
#include "radio/serial.h"
#include "radio/worker.h"

namespace tb::radio::link {

using Action = LinkError::Action;
using Clock = std::chrono::steady_clock;

// A write may take its time on the wire plus this.
inline constexpr std::chrono::milliseconds kWriteSlack{1000};

inline std::string tone_text(int tenths_hz) {
  return std::to_string(tenths_hz / 10) + "." + std::to_string(tenths_hz % 10) + " Hz";
}

// A radio without a CTCSS encoder trakbox can set: a tone is refused with a message, never dropped
// silently (a limit of the radio, said once: not a fault); turning the tone off is nothing to refuse.
inline void refuse_tone(const std::string& radio, int tenths_hz) {
  if (tenths_hz <= 0) return;
  throw LinkError("no CTCSS", radio + " has no CTCSS encoder trakbox can set: tone " + tone_text(tenths_hz) + " not sent");
}

// The amateur band a frequency is in, as operators name it ("10 m", "70 cm", "10 GHz"), for the
// limit a radio without it shows ("no 70 cm"); outside them its frequency in MHz.
std::string band_name(Hz hz);

// A frequency outside a radio's bands (none given: any): throws LinkError(lacks) "no 70 cm",
// a limit learnt once, never a fault. `radio` as in messages ("the IC-7300").
void require_band(const std::string& radio, std::span<const HzRange> bands, Link l, Hz hz);

// A rig's standard serial settings at the configured speed (STATION.DAT line 4), when one is set.
inline SerialSettings at_baud(SerialSettings s, int baud) {
  if (baud > 0) s.baud = static_cast<unsigned>(baud);
  return s;
}

}  // namespace tb::radio::link
