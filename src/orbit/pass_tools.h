// Passes for planning: the times a satellite is in view of two stations at once (a QSO partner's
// grid: `passes --with`, the web's with=), overlaps between passes of several satellites, and the
// passes as an iCalendar (RFC 5545: `passes --ics`, GET /api/v1/passes.ics). Pure.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "orbit/passes.h"

namespace tb::orbit {

// The passes over `here` found in [start, stop) cut to the times `there` has the satellite above
// options.horizon_deg too: AOS is the later of the two AOS, LOS the earlier LOS; TCA and the
// maximum elevation (and the azimuths) are here's, over the shared time (sampled each second, then
// refined). Only shared times whose maximum here reaches options.min_max_elevation_deg are kept.
std::vector<Pass> mutual_passes(const Sgp4& sat, const Observer& here, const Observer& there, UtcTime start,
                                UtcTime stop, const PassOptions& options = {});

struct NamedPass {
  std::string satellite;
  Pass pass;
};
// For each pass (sorted by AOS or not), the indices of the others whose [AOS, LOS] overlaps it.
std::vector<std::vector<int>> overlaps(const std::vector<NamedPass>& passes);

// An iCalendar of the passes: one VEVENT each (SUMMARY "SAT pass, max EL deg", DTSTART AOS, DTEND
// LOS, DESCRIPTION with TCA and the azimuths, a UID stable for the same satellite and AOS minute),
// DTSTAMP `stamp`, CRLF line ends, lines folded at 75 octets (never inside a UTF-8 sequence), text
// escaped (\\ \; \, \n). `where` names the station in each DESCRIPTION.
std::string ical_passes(const std::vector<NamedPass>& passes, UtcTime stamp, std::string_view where);

// RFC 5545 content lines (for tests and the writer): "NAME:VALUE" folded, with CRLF.
std::string ical_line(std::string_view line);
// RFC 5545 TEXT escaping.
std::string ical_text(std::string_view text);

}  // namespace tb::orbit
