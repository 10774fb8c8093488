#pragma once
// The logger (Cloudlog or Wavelog) as pure decisions and texts: the --logger specification, the two
// endpoints, the radio-state body and when to post it, the QSO body (one ADIF record), how to read
// the logger's reply, and the retry backoff. No I/O here: live/logger_upload.h sends them.
//
// What the replies mean comes from the loggers' own code (application/controllers/Api.php), one
// rule per logger:
//  - Cloudlog's api/qso: 201 {"status":"created", ..., "imported_count":N, "messages":[...]} where N
//    counts the records stored and each refused record leaves a message (a duplicate's ends in
//    "Duplicate").
//  - Wavelog's api/qso (2.0.5): 201 {"status":"created","adif_count":N,"adif_errors":0,
//    "messages":[""]} when stored; any record refused is 400 {"status":"abort","adif_count":N,
//    "adif_errors":E,"messages":["", the refusals]}, a duplicate's "... Duplicate for <call>".
//  - Both: a bad key or station profile is 401 {"status":"failed","reason":...}; JSON it cannot
//    decode is {"status":"failed","reason":"wrong JSON"} (status 200).
//  - api/radio: {"status":"success"} (200, or 201); 401 {"status":"failed","reason":"missing api
//    key"}; Wavelog 404 "missing radio element in payload".
// A reply is read under json_limits' nesting bound and its members by reference; any text taken
// from it has the key redacted before it is cut to a line.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// The record as a logger may read it: Cloudlog's and Wavelog's Adif_parser.php split the text on
// "<eor>" before they read any length, so no text field may hold '<' (nor '>', for symmetry):
// each becomes '(' or ')'. `changed` gets the ADIF names of the fields that were changed.
Qso for_logger(Qso q, std::vector<std::string>* changed = nullptr);

// {"key","station_profile_id":"N","type":"adif","string":"<one ADIF record>"}, of for_logger(q).
std::string qso_body(std::string_view key, int station_profile_id, const Qso& q,
                     std::vector<std::string>* changed = nullptr);

struct ReplyVerdict {
  bool accepted = false;
  bool duplicate = false;   // the logger already has the record (its "Duplicate")
  std::string message;      // why not accepted: the logger's words, one line, `secret` redacted
};
// api/qso's reply to one record, by the rule of `kind`: accepted only when it says the record was
// stored; a duplicate is accepted (the logger has it: an upload whose answer was lost). `secret`
// (the key) is redacted from the message.
ReplyVerdict judge_qso_reply(LoggerKind kind, long http_status, std::string_view body, std::string_view secret = {});
// api/radio's reply: accepted on {"status":"success"} with a 2xx status.
ReplyVerdict judge_radio_reply(long http_status, std::string_view body, std::string_view secret = {});

// Seconds to wait after the n-th failure in a row (n >= 1): 30, 60, 120, ... at most 1800.
std::int64_t upload_backoff_s(int failures);

}  // namespace tb::logbook
