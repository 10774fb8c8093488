// The scheduled refresh of the menu-3 database from element sources the operator names (URLs of
// CelesTrak GP queries, other web sources, local files): what is configured and remembered, and
// what one downloaded file does to the database. The downloads and the schedule are in
// tracker/elements_refresh.h; this part is pure.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "orbit/elements.h"
#include "store/database.h"

namespace tb::store {

inline constexpr double kRefreshMinHours = 2.0;       // CelesTrak's data changes at most every 2 h
inline constexpr double kRefreshDefaultHours = 12.0;  // "a few times a day"
inline constexpr double kRefreshMaxHours = 24.0 * 30;
inline constexpr double kRefreshRetryHours = 0.5;     // after a failed attempt (offline at start)
inline constexpr std::size_t kRefreshMaxSources = 8;
inline constexpr std::size_t kRefreshMaxUrl = 400;
// A fresh state's refresh source (issue 30): CelesTrak's amateur group as OMM JSON, which also
// carries the satellites with catalog numbers past 99999 that have no TLE. The shipped data stays
// the offline fallback until the first refresh succeeds.
inline constexpr const char* kDefaultElementsUrl = "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json";

struct RefreshSource {
  std::string url;            // http(s)://, ftp(s)://, file:// or an absolute path
  // The validators of the last good answer, for the next conditional request.
  std::string etag;
  std::string last_modified;
};

struct RefreshSettings {
  std::vector<RefreshSource> sources;  // empty: no refresh
  double interval_hours = kRefreshDefaultHours;
  // Wall time (system clock, seconds since 1970) of the last attempt, kept across restarts so
  // that a restarting service does not ask the servers more often than the interval; 0 = never.
  std::int64_t last_attempt_unix = 0;
  // A source of the last attempt failed: the next comes after kRefreshRetryHours (when that is
  // sooner than the interval), so a station started offline does not wait the whole interval.
  bool last_attempt_failed = false;
};

// Adds a source (when new); the reason when it cannot be taken: not a URL or absolute path, too
// long, a character that does not belong in a URL, too many sources.
std::optional<std::string> add_refresh_source(RefreshSettings& s, const std::string& url);
// The interval, or the reason it is refused (outside kRefreshMinHours .. kRefreshMaxHours).
std::optional<std::string> check_refresh_interval(double hours);

// When the next scheduled refresh is due, from the last attempt (wall time, unix seconds).
bool refresh_due(const RefreshSettings& s, std::int64_t now_unix);
// Seconds until it is due (0 when due now or never attempted); nothing without a source.
std::optional<std::int64_t> seconds_until_refresh(const RefreshSettings& s, std::int64_t now_unix);

struct RefreshChange {
  std::string name;           // the database's name (the source may call it otherwise)
  int catalog_number = 0;
  orbit::UtcTime old_epoch, new_epoch;
};

struct RefreshReport {
  std::vector<RefreshChange> updated;  // newer sets taken
  int unchanged = 0;                   // same epoch as the database's
  int older = 0;                       // older than the database's: kept the database's
  int not_in_database = 0;             // sets of satellites the database does not hold
  // One line for the log and the status line: "3 updated (ISS 2026-05-21 12:00), 2 unchanged, ...".
  std::string summary() const;
};

// Replaces the orbital elements of the database's satellites that `sets` holds newer sets of,
// matched by catalog number. The database's name and radio entry stay; nothing is added or
// removed. Of two sets for one number the newer counts.
RefreshReport apply_refresh(Database& db, const std::vector<orbit::Elements>& sets);

nlohmann::json to_json(const RefreshSettings& s);
// Throws std::runtime_error naming the field; `where` prefixes the field names.
RefreshSettings refresh_settings_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace tb::store
