#include "tracker/satnogs_jobs.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "util/json_limits.h"
#include "util/safe_text.h"

namespace tb::tracker {

// The request is anonymous (a read with the owner's token is the station's heartbeat): a user or
// password written in --satnogs-url ("http://bob:PW@host") is dropped here, so that it is neither
// sent (libcurl would make it Basic auth) nor shown (status' and the live feed's satnogs.url are
// this URL). Issue 56 item 10; docs/security.md.
std::string satnogs_jobs_url(const std::string& base, int station_id) {
  std::string b = base;
  if (const auto scheme = b.find("://"); scheme != std::string::npos) {
    const std::size_t authority = scheme + 3;
    const std::size_t end = b.find_first_of("/?#", authority);
    const std::size_t at = b.rfind('@', end == std::string::npos ? std::string::npos : end - 1);
    if (at != std::string::npos && at >= authority) b.erase(authority, at + 1 - authority);
  }
  while (!b.empty() && b.back() == '/') b.pop_back();
  return b + "/api/jobs/?ground_station=" + std::to_string(station_id);
}

namespace {

std::optional<std::string> string_of(const nlohmann::json& job, const char* key) {
  const auto it = job.find(key);
  if (it == job.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

}  // namespace

SatnogsJobs parse_satnogs_jobs(const std::string& body, orbit::UtcTime now) {
  SatnogsJobs out;
  std::string why;
  const nlohmann::json j = json_limits::parse_bounded<nlohmann::json>(body, why);
  if (why.starts_with("nested")) {
    out.error = "the jobs answer is nested too deep";
    return out;
  }
  if (j.is_discarded() || !j.is_array()) {
    out.error = "the jobs answer is not a JSON list";
    return out;
  }
  if (j.size() > kMaxSatnogsJobs) {
    out.error = "the jobs answer holds " + std::to_string(j.size()) + " jobs, more than " +
                std::to_string(kMaxSatnogsJobs);
    return out;
  }
  for (std::size_t i = 0; i < j.size(); ++i) {
    const nlohmann::json& job = j[i];
    const std::string where = "job " + std::to_string(i + 1);
    if (!job.is_object()) {
      out.error = where + " is not an object";
      break;
    }
    const auto id = job.find("id");
    const auto start = string_of(job, "start"), end = string_of(job, "end");
    const auto tle0 = string_of(job, "tle0"), mode = string_of(job, "mode");
    const auto freq = job.find("frequency");
    if (id == job.end() || !id->is_number_integer()) {
      out.error = where + ": no whole-number \"id\"";
      break;
    }
    const auto t0 = start ? orbit::parse_iso8601(*start) : std::nullopt;
    const auto t1 = end ? orbit::parse_iso8601(*end) : std::nullopt;
    if (!t0 || !t1 || *t1 <= *t0) {
      out.error = where + " (id " + std::to_string(id->get<long long>()) + "): \"start\" and \"end\" must be ISO 8601 "
                  "times, the end after the start";
      break;
    }
    if (!tle0 || !mode || freq == job.end() || !freq->is_number()) {
      out.error = where + " (id " + std::to_string(id->get<long long>()) + "): needs \"tle0\", \"frequency\" and \"mode\"";
      break;
    }
    if (*t1 <= now) continue;  // over
    Window w;
    w.kind = "satnogs";
    w.id = std::to_string(id->get<long long>());
    w.start = *t0;
    w.end = *t1;
    w.satellite = text::safe_text(tle0->substr(0, 40));
    w.note = text::safe_text(mode->substr(0, 20)) + " " + std::to_string(freq->get<long long>()) + " Hz";
    // The job's elements, kept as sent (69 characters a line); read when its pass is planned.
    const auto tle1 = string_of(job, "tle1"), tle2 = string_of(job, "tle2");
    if (tle1 && tle2) {
      w.tle1 = text::safe_text(tle1->substr(0, 80));
      w.tle2 = text::safe_text(tle2->substr(0, 80));
    }
    out.windows.push_back(std::move(w));
  }
  if (out.error) {
    out.windows.clear();
    return out;
  }
  std::sort(out.windows.begin(), out.windows.end(), [](const Window& a, const Window& b) { return a.start < b.start; });
  return out;
}

}  // namespace tb::tracker
