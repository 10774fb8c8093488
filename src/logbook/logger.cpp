#include "logbook/logger.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>

#include "logbook/adif.h"
#include "util/json_limits.h"
#include "util/redact.h"
#include "util/text.h"

namespace tb::logbook {

using ojson = nlohmann::ordered_json;

std::string_view logger_kind_name(LoggerKind k) { return k == LoggerKind::wavelog ? "wavelog" : "cloudlog"; }

LoggerSpecParse parse_logger_spec(std::string_view text) {
  LoggerSpecParse r;
  const auto fail = [&](const std::string& why) {
    r.error = "--logger: " + why;
    return r;
  };
  if (text == "none") {
    r.none = true;
    return r;
  }
  const auto colon = text.find(':');
  const std::string kind = colon == std::string_view::npos ? std::string(text) : std::string(text.substr(0, colon));
  LoggerSpec s;
  if (kind == "cloudlog") s.kind = LoggerKind::cloudlog;
  else if (kind == "wavelog") s.kind = LoggerKind::wavelog;
  else return fail("expected cloudlog:URL, wavelog:URL or none; found '" + std::string(text.substr(0, 40)) + "'");
  if (colon == std::string_view::npos || colon + 1 == text.size())
    return fail(kind + ": the logger's URL is missing (" + kind + ":https://log.example.org)");
  std::string url(text.substr(colon + 1));
  const std::string low = text::lower(url);
  const std::size_t scheme = low.starts_with("https://") ? 8 : low.starts_with("http://") ? 7 : 0;
  if (scheme == 0) return fail("'" + redact::url_credentials(url.substr(0, 80)) + "' is not an http:// or https:// URL");
  for (const char c : url)
    if (static_cast<unsigned char>(c) <= ' ' || c == '?' || c == '#' || static_cast<unsigned char>(c) >= 0x7f)
      return fail("'" + redact::url_credentials(url.substr(0, 80)) +
                  "': the base URL has no query, fragment, white space or control characters (the API's paths are "
                  "added to it)");
  if (url.ends_with('/')) url.pop_back();
  const std::size_t host_end = url.find('/', scheme);
  const std::string authority = url.substr(scheme, host_end == std::string::npos ? std::string::npos : host_end - scheme);
  const std::string host = authority.substr(authority.rfind('@') == std::string::npos ? 0 : authority.rfind('@') + 1);
  if (host.empty() || host.front() == ':') return fail("'" + redact::url_credentials(url) + "' has no host");
  s.base_url = url;
  r.spec = s;
  return r;
}

std::string logger_spec_text(const LoggerSpec& s) { return std::string(logger_kind_name(s.kind)) + ":" + s.base_url; }
std::string logger_display_url(const LoggerSpec& s) { return redact::url_credentials(s.base_url); }
std::string radio_url(const LoggerSpec& s) { return s.base_url + "/index.php/api/radio"; }
std::string qso_url(const LoggerSpec& s) { return s.base_url + "/index.php/api/qso"; }

std::string radio_body(std::string_view key, const RadioState& r) {
  ojson j;
  j["key"] = key;
  j["radio"] = "trakbox";
  j["frequency"] = std::to_string(r.uplink_hz);
  j["mode"] = r.mode;
  j["frequency_rx"] = std::to_string(r.downlink_hz);
  j["mode_rx"] = r.mode_rx;
  j["prop_mode"] = r.tracking ? "SAT" : "";
  j["sat_name"] = r.tracking ? r.sat_name : "";
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

bool radio_post_due(const std::optional<RadioPosted>& last, const RadioState& now_state, std::int64_t now) {
  if (!last) return now_state.tracking;  // idle from the start: nothing to tell
  const RadioState& was = last->state;
  if (!now_state.tracking) return was.tracking;  // once when tracking ends
  if (!was.tracking || was.sat_name != now_state.sat_name || was.mode != now_state.mode ||
      was.mode_rx != now_state.mode_rx)
    return true;
  if (std::llabs(now_state.uplink_hz - was.uplink_hz) > kRadioThresholdHz ||
      std::llabs(now_state.downlink_hz - was.downlink_hz) > kRadioThresholdHz)
    return true;
  return now - last->at >= kRadioRepostSeconds;
}

Qso for_logger(Qso q, std::vector<std::string>* changed) {
  const std::pair<const char*, std::string*> fields[] = {
      {"CALL", &q.call},         {"GRIDSQUARE", &q.grid},     {"RST_SENT", &q.rst_sent},
      {"RST_RCVD", &q.rst_rcvd}, {"APP_TRAKBOX_SAT", &q.sat_name}, {"SAT_NAME", &q.lotw_name},
      {"MODE", &q.mode},         {"BAND", &q.band},           {"BAND_RX", &q.band_rx},
      {"MY_GRIDSQUARE", &q.my_grid}, {"STATION_CALLSIGN", &q.station_call}, {"COMMENT", &q.note}};
  for (const auto& [name, value] : fields) {
    bool any = false;
    for (char& c : *value)
      if (c == '<' || c == '>') {
        c = c == '<' ? '(' : ')';
        any = true;
      }
    if (any && changed) changed->push_back(name);
  }
  return q;
}

std::string qso_body(std::string_view key, int station_profile_id, const Qso& q, std::vector<std::string>* changed) {
  ojson j;
  j["key"] = key;
  j["station_profile_id"] = std::to_string(station_profile_id);
  j["type"] = "adif";
  j["string"] = adif_record(for_logger(q, changed));
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

namespace {

using json = nlohmann::json;

// The logger's words on one line: HTML tags out (Cloudlog's messages carry <b> and <br>), white
// space folded, then the secret redacted (after the tags, so that none can split it; before
// anything is cut, so that no piece of it stays), at most `most` characters.
std::string plain(std::string_view s, std::string_view secret, std::size_t most = 200) {
  std::string out;
  bool tag = false, blank = false;
  for (const char c : s) {
    if (c == '<') tag = true;
    else if (c == '>' && tag) { tag = false; blank = true; }
    else if (!tag) {
      if (static_cast<unsigned char>(c) <= ' ' || c == 0x7f) { blank = true; continue; }
      if (blank && !out.empty()) out += ' ';
      blank = false;
      out += c;
    }
  }
  out = redact::secret(redact::text(out), secret);
  if (out.size() > most) out = out.substr(0, most - 3) + "...";
  return out;
}

std::string http_prefix(long status) { return status ? "HTTP " + std::to_string(status) + ": " : std::string(); }

// A member by reference (never copied: a reply may be anything under its size cap), or null.
const json* member(const json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}
bool is_text(const json* v, std::string_view text) { return v && v->is_string() && v->get_ref<const std::string&>() == text; }
std::optional<long long> whole(const json* v) {
  if (!v || !v->is_number_integer()) return std::nullopt;
  return v->get<long long>();
}

// The reply parsed under the nesting bound; `why` says what it is when it is not JSON.
json parse_reply(std::string_view body, std::string& why) { return json_limits::parse_bounded<json>(body, why); }

// A failed reply's reason ({"status":"failed","reason":...}), or what the body is.
std::string failure_text(long status, const json& j, std::string_view body, const std::string& why,
                         std::string_view secret) {
  if (const json* r = member(j, "reason"); r && r->is_string())
    return http_prefix(status) + plain(r->get_ref<const std::string&>(), secret);
  if (plain(body, secret).empty()) return http_prefix(status) + "an empty reply";
  if (why.starts_with("nested")) return http_prefix(status) + "not the logger's API reply: JSON " + why;
  return http_prefix(status) + "not the logger's API reply: " + plain(body, secret, 120);
}

// The non-empty messages of a reply, on one line ("; " between them), and whether every one of
// them says "duplicate" (Cloudlog: "... Duplicate"; Wavelog: "... Duplicate for <call>", the word
// translated in other languages: "Duplikat", "duplicado", "duplicato", "duplicaat" all begin the
// same way). A message that is not text counts as a refusal of its own.
struct Messages {
  std::string text;
  std::size_t count = 0, duplicates = 0;
};
Messages messages_of(const json& j, std::string_view secret) {
  Messages out;
  const json* m = member(j, "messages");
  if (!m || !m->is_array()) return out;
  for (const json& e : *m) {
    const std::string t = e.is_string() ? plain(e.get_ref<const std::string&>(), secret) : "(a message that is not text)";
    if (t.empty()) continue;
    ++out.count;
    if (text::lower(t).find("dupl") != std::string::npos) ++out.duplicates;
    if (out.text.size() < 200) out.text += (out.text.empty() ? "" : "; ") + t;
  }
  if (out.text.size() > 200) out.text = out.text.substr(0, 197) + "...";
  return out;
}

ReplyVerdict refused(std::string message) {
  ReplyVerdict v;
  v.message = std::move(message);
  return v;
}
ReplyVerdict done(bool duplicate = false, std::string message = {}) {
  ReplyVerdict v;
  v.accepted = true;
  v.duplicate = duplicate;
  v.message = std::move(message);
  return v;
}

// Cloudlog's Api.php qso(): 201 {"status":"created","imported_count":N,"messages":[...]}, N the
// records stored; a record refused leaves a message, a duplicate's ending in "Duplicate".
ReplyVerdict cloudlog_qso(long http_status, const json& j, std::string_view body, const std::string& why,
                          std::string_view secret) {
  if (http_status != 201 || !is_text(member(j, "status"), "created"))
    return refused(failure_text(http_status, j, body, why, secret));
  const auto count = whole(member(j, "imported_count"));
  const Messages m = messages_of(j, secret);
  if (!count) return refused("HTTP 201 without imported_count: not the logger's API reply");
  if (*count >= 1 && m.count == 0) return done();
  if (*count == 0 && m.count > 0 && m.duplicates == m.count) return done(true, m.text);
  return refused(m.count ? m.text : "the logger stored no record (imported_count " + std::to_string(*count) + ")");
}

// Wavelog's Api.php qso() (2.0.5): every record read into a list and stored with import_bulk, then
//  - 201 {"status":"created","adif_count":N,"adif_errors":0,"messages":[""]}: stored;
//  - 400 {"status":"abort","adif_count":N,"adif_errors":E,"messages":["", refusals]}: a record
//    refused, a duplicate among them ("Date/Time: ... Duplicate for <call>"): for our one record,
//    a duplicate is a record already there (sent before, its answer lost), so done.
// A Wavelog older than the fork's own reply answers as Cloudlog does (imported_count).
ReplyVerdict wavelog_qso(long http_status, const json& j, std::string_view body, const std::string& why,
                         std::string_view secret) {
  const auto read = whole(member(j, "adif_count")), errors = whole(member(j, "adif_errors"));
  if (!read || !errors) {
    if (member(j, "imported_count")) return cloudlog_qso(http_status, j, body, why, secret);
    if (http_status == 201 && is_text(member(j, "status"), "created"))
      return refused("HTTP 201 without adif_count and adif_errors: not Wavelog's API reply");
    return refused(failure_text(http_status, j, body, why, secret));
  }
  const Messages m = messages_of(j, secret);
  if (http_status == 201 && is_text(member(j, "status"), "created")) {
    if (*read >= 1 && *errors == 0) return done();
    return refused(m.count ? m.text : "the logger read " + std::to_string(*read) + " record(s) with " +
                                          std::to_string(*errors) + " error(s)");
  }
  if (http_status == 400 && is_text(member(j, "status"), "abort") && *read == 1 && *errors == 1 && m.count > 0 &&
      m.duplicates == m.count)
    return done(true, m.text);
  if (m.count) return refused(http_prefix(http_status) + m.text);
  return refused(failure_text(http_status, j, body, why, secret));
}

}  // namespace

ReplyVerdict judge_qso_reply(LoggerKind kind, long http_status, std::string_view body, std::string_view secret) {
  std::string why;
  const json j = parse_reply(body, why);
  return kind == LoggerKind::wavelog ? wavelog_qso(http_status, j, body, why, secret)
                                     : cloudlog_qso(http_status, j, body, why, secret);
}

// Both loggers' api/radio: {"status":"success"}; Cloudlog with 200, Wavelog with 200 or 201 as its
// versions go: any 2xx.
ReplyVerdict judge_radio_reply(long http_status, std::string_view body, std::string_view secret) {
  std::string why;
  const json j = parse_reply(body, why);
  if (http_status >= 200 && http_status < 300 && is_text(member(j, "status"), "success")) return done();
  return refused(failure_text(http_status, j, body, why, secret));
}

std::int64_t upload_backoff_s(int failures) {
  std::int64_t s = 30;
  for (int i = 1; i < failures && s < 1800; ++i) s *= 2;
  return std::min<std::int64_t>(s, 1800);
}

}  // namespace tb::logbook
