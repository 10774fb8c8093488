// Recording a pass on the receiver trakbox drives (--record; docs/radio.md "Recording a pass"):
// which satellites are recorded, and the name the receiver gives the file. Pure.
#pragma once
#include <string>
#include <string_view>

#include "orbit/time.h"
#include "radio/config.h"

namespace tb::tracker {

// Whether --record records this satellite: recording on, and the satellite among
// record_satellites (comma-separated names, case aside, blanks around them aside; "" is every one).
bool records_satellite(const radio::RadioConfig& c, std::string_view name);

// The file the receiver's recorder writes, from the start (UTC) and the receiver's frequency:
// GQRX's audio recorder "gqrx_yyyyMMdd_hhmmss_<Hz>.wav" ("gqrx_20260521_141002_436795000.wav");
// "" where trakbox cannot know it (SDR++ names its files by its recorder module's template; GQRX's
// IQ file carries its sample rate).
std::string recording_file_name(std::string_view receiver, radio::Record kind, orbit::UtcTime start, radio::Hz hz);

}  // namespace tb::tracker
