#include "logbook/logger.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>

#include "logbook/adif.h"
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

std::string qso_body(std::string_view key, int station_profile_id, const Qso& q) {
  ojson j;
  j["key"] = key;
  j["station_profile_id"] = std::to_string(station_profile_id);
  j["type"] = "adif";
  j["string"] = adif_record(q);
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

namespace {

// The logger's words on one line: HTML tags out (Cloudlog's messages carry <b> and <br>), white
// space folded, at most 200 characters.
std::string plain(std::string_view s) {
  std::string out;
  bool tag = false, blank = false;
  for (const char c : s) {
    if (c == '<') tag = true;
    else if (c == '>' && tag) { tag = false; blank = true; }
    else if (!tag) {
      if (static_cast<unsigned char>(c) <= ' ') { blank = true; continue; }
      if (blank && !out.empty()) out += ' ';
      blank = false;
      out += c;
    }
  }
  if (out.size() > 200) out = out.substr(0, 197) + "...";
  return out;
}

std::string http_prefix(long status) { return status ? "HTTP " + std::to_string(status) + ": " : std::string(); }

// A failed reply's reason ({"status":"failed","reason":...}), or what the body is.
std::string failure_text(long status, const nlohmann::json& j, std::string_view body) {
  if (j.is_object() && j.value("reason", nlohmann::json()).is_string())
    return http_prefix(status) + plain(j["reason"].get<std::string>());
  if (plain(body).empty()) return http_prefix(status) + "an empty reply";
  return http_prefix(status) + "not the logger's API reply: " + plain(body.substr(0, 120));
}

}  // namespace

ReplyVerdict judge_qso_reply(long http_status, std::string_view body) {
  ReplyVerdict v;
  const nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (http_status != 201 || !j.is_object() || j.value("status", nlohmann::json()) != "created") {
    v.message = failure_text(http_status, j, body);
    return v;
  }
  const auto count = j.value("imported_count", nlohmann::json());
  std::string messages;
  bool duplicate = false;
  if (const auto m = j.value("messages", nlohmann::json()); m.is_array())
    for (const auto& e : m) {
      const std::string t = e.is_string() ? plain(e.get<std::string>()) : plain(e.dump());
      if (t.empty()) continue;
      if (t.ends_with("Duplicate")) duplicate = true;
      messages += (messages.empty() ? "" : "; ") + t;
    }
  if (!count.is_number_integer()) {
    v.message = "HTTP 201 without imported_count: not the logger's API reply";
    return v;
  }
  if (count.get<long long>() >= 1 && messages.empty()) {
    v.accepted = true;
    return v;
  }
  if (count.get<long long>() == 0 && duplicate) {
    v.accepted = v.duplicate = true;
    v.message = plain(messages);
    return v;
  }
  v.message = messages.empty() ? "the logger stored no record (imported_count " + std::to_string(count.get<long long>()) + ")"
                               : plain(messages);
  return v;
}

ReplyVerdict judge_radio_reply(long http_status, std::string_view body) {
  ReplyVerdict v;
  const nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (http_status == 200 && j.is_object() && j.value("status", nlohmann::json()) == "success") {
    v.accepted = true;
    return v;
  }
  v.message = failure_text(http_status, j, body);
  return v;
}

std::int64_t upload_backoff_s(int failures) {
  std::int64_t s = 30;
  for (int i = 1; i < failures && s < 1800; ++i) s *= 2;
  return std::min<std::int64_t>(s, 1800);
}

}  // namespace tb::logbook
