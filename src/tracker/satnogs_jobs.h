// The SatNOGS Network's calendar of a ground station (issue 44): the answer of
// GET {url}/api/jobs/?ground_station=ID, read anonymously (with the owner's token that request is
// the station's heartbeat and would mark it online), turned into reservation windows
// (tracker/control.h) in which trakbox's own tracking yields and rotctld/rigctld clients hold under
// the observation's name. Pure: text in, windows or a sentence out.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "orbit/time.h"
#include "tracker/control.h"

namespace tb::tracker {

// The public Network (--satnogs-url's default).
inline constexpr const char* kSatnogsNetworkUrl = "https://network.satnogs.org";
inline constexpr int kSatnogsPollSeconds = 600;  // every 10 minutes
inline constexpr std::size_t kMaxSatnogsJobs = 200;

// The jobs request for a station: "{url}/api/jobs/?ground_station=ID" (a trailing '/' of url dropped).
std::string satnogs_jobs_url(const std::string& base, int station_id);

struct SatnogsJobs {
  std::vector<Window> windows;  // the jobs not yet over at `now`, in start order
  std::optional<std::string> error;  // the answer was not a list of jobs: why (the windows are empty)
};
// Each job needs id (a whole number), start and end (ISO 8601 UTC, end after start), tle0 (the
// satellite's name), frequency (Hz) and mode; the window's note is "MODE FREQUENCY Hz". tle1 and
// tle2, when both are strings, are kept with the window (the job's own elements).
SatnogsJobs parse_satnogs_jobs(const std::string& body, orbit::UtcTime now);

}  // namespace tb::tracker
