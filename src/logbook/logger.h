#pragma once
// The logger (Cloudlog or Wavelog) as pure decisions and texts: the --logger specification, the two
// endpoints, the radio-state body and when to post it, the QSO body (one ADIF record), how to read
// the logger's reply, and the retry backoff. No I/O here: live/logger_upload.h sends them.
//
// What the replies mean comes from the loggers' own code (application/controllers/Api.php):
//  - api/qso: Cloudlog answers 201 {"status":"created", ..., "imported_count":N, "messages":[...]}
//    where N counts the records stored and each refused record leaves a message (a duplicate's
//    ends in "Duplicate"); Wavelog answers the same 201 but counts the records it read before
//    storing them and leaves messages [""]. A bad key or station profile is 401 {"status":"failed",
//    "reason":...}; JSON it cannot decode is {"status":"failed","reason":"wrong JSON"} (status 200).
//  - api/radio: {"status":"success"}; 401 {"status":"failed","reason":"missing api key"}; Wavelog
//    404 "missing radio element in payload".
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "logbook/qso.h"

namespace tb::logbook {

enum class LoggerKind { cloudlog, wavelog };
std::string_view logger_kind_name(LoggerKind k);

struct LoggerSpec {
  LoggerKind kind = LoggerKind::cloudlog;
  std::string base_url;   // http(s)://host[:port][/path], no trailing '/'
  bool operator==(const LoggerSpec&) const = default;
};

struct LoggerSpecParse {
  std::optional<LoggerSpec> spec;  // none with "none" (or on a refusal)
  bool none = false;               // "none": the logger removed
  std::string error;               // "--logger: ..." when refused
};

// "cloudlog:URL", "wavelog:URL" or "none". The URL is http:// or https:// with a host, no query,
// fragment or white space; one trailing '/' is dropped.
LoggerSpecParse parse_logger_spec(std::string_view text);
// "cloudlog:https://log.example.org" (what --logger takes back).
std::string logger_spec_text(const LoggerSpec& s);
// The URL without a password (user:<redacted>@host) for status and the log.
std::string logger_display_url(const LoggerSpec& s);

std::string radio_url(const LoggerSpec& s);   // {base}/index.php/api/radio
std::string qso_url(const LoggerSpec& s);     // {base}/index.php/api/qso

// What the radio does now, as Cloudlog shows it. The satellite fields only while one is tracked.
struct RadioState {
  bool tracking = false;
  std::string sat_name;                // TQSL's name ("RS-44", "ARISS"); "" when not known
  std::int64_t uplink_hz = 0;          // as tuned (what the radio transmits on)
  std::int64_t downlink_hz = 0;
  std::string mode, mode_rx;           // the radio's modes: "LSB", "USB", "FM", "CW"
  bool operator==(const RadioState&) const = default;
};

inline constexpr std::int64_t kRadioRepostSeconds = 300;    // at least every 5 minutes while tracking
inline constexpr std::int64_t kRadioThresholdHz = 1000;     // a change of tuning worth a post

// {"key","radio":"trakbox","frequency","mode","frequency_rx","mode_rx","prop_mode","sat_name"}
// with frequencies in Hz as text; prop_mode "SAT" and sat_name only while tracking, "" otherwise.
std::string radio_body(std::string_view key, const RadioState& r);

// The last post (none yet: nothing posted) and when (UTC seconds).
struct RadioPosted {
  RadioState state;
  std::int64_t at = 0;
};
// Post now? On a change of tracking, satellite or mode, a tuning moved more than the threshold,
// and every kRadioRepostSeconds while tracking; once when tracking ends; never while idle.
bool radio_post_due(const std::optional<RadioPosted>& last, const RadioState& now_state, std::int64_t now);

// {"key","station_profile_id":"N","type":"adif","string":"<one ADIF record>"}.
std::string qso_body(std::string_view key, int station_profile_id, const Qso& q);

struct ReplyVerdict {
  bool accepted = false;
  bool duplicate = false;   // the logger already has the record (Cloudlog's "Duplicate")
  std::string message;      // why not accepted: the logger's words, one line
};
// api/qso's reply to one record: accepted only when it says the record was created and imported
// with no message; a duplicate is accepted (the logger has it: an upload whose answer was lost).
ReplyVerdict judge_qso_reply(long http_status, std::string_view body);
// api/radio's reply: accepted on {"status":"success"}.
ReplyVerdict judge_radio_reply(long http_status, std::string_view body);

// Seconds to wait after the n-th failure in a row (n >= 1): 30, 60, 120, ... at most 1800.
std::int64_t upload_backoff_s(int failures);

}  // namespace tb::logbook
