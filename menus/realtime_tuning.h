#pragma once
// The realtime display's typed tuning keys (trakbox's own, issue 47; the manual's keys are E, Y, Q,
// + - 0; trakbox adds U, D, L and these):
//   S  the spot: a linear transponder's downlink in the satellite's frame, typed in MHz (435.645)
//      or Hz (435645000); the uplink follows by the transponder's rule
//   R  the RX offset in Hz (+120, -300, 0 resets), the correction + / - step by 100 Hz
//   T  the TX offset in Hz, added to the uplink
//   M  the satellite's mode (issue 59): its modes listed, one typed (case aside); the radio goes to
//      its spot (tracker::StationOps::choose_mode, as host mode's MODE and the page's picker)
// Each goes through tracker::StationOps (tune_spot, tune_offsets), as the page's POST /api/v1/radio
// and host mode's PB / OR / OT do: the same checks, the same corrections kept per satellite and mode,
// the radio asked for from the controller of record (a Y/N when an outside client holds it). A
// value that is not a frequency, or one out of range, is refused in a sentence naming it and the
// range; nothing changes then. An empty answer changes nothing.
//
// Each returns what it has to say (the change made, or the refusal): a serial terminal gets it as a
// line at once; the full screen shows it in the live block under the radio line until the next
// key (a line of text there would be drawn over by the sky plot within the second, and the status
// line is the station's, rewritten every tick).
#include <optional>
#include <string>
#include <string_view>

#include "menus/menus.h"
#include "menus/term/terminal.h"

namespace tb::menus {

// "435.645" (MHz, at most 6 decimals: whole Hz), "435645000" (Hz) or "437" (a whole number under
// 1 000 000: MHz) -> Hz; nothing for anything else (signs, blanks inside, exponents, more than 6
// decimals, 0).
std::optional<long long> parse_spot_hz(std::string_view text);
// "+120", "-300", "0", "120" -> Hz (whole Hz only); nothing otherwise.
std::optional<long long> parse_offset_hz(std::string_view text);

// A key's prompt, on the full screen's row under the live block cleared first (an earlier, longer
// prompt and answer stay there until then).
void live_prompt(term::Terminal& t, const std::string& text);
// What a key has to say: a serial terminal gets it as a line at once; the full screen shows the
// returned text in the live block.
std::string live_said(term::Terminal& t, std::string text);

// The S, R and T keys at the live display: one prompt, then the change or the refusal.
std::string realtime_type_spot(term::Terminal& t, Services& s);
std::string realtime_type_offset(term::Terminal& t, Services& s, bool tx);
std::string realtime_type_mode(term::Terminal& t, Services& s);
// The + / - / 0 keys: the RX offset 100 Hz up, down, or back to 0, through the same operation
// ("Frequency offset +100 Hz", or the refusal).
std::string realtime_step_offset(term::Terminal& t, Services& s, int direction);

}  // namespace tb::menus
