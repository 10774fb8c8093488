#include "store/refresh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "store/json_fields.h"
#include "store/settings.h"

namespace tb::store {

using json = nlohmann::json;
using namespace json_fields;

namespace {

bool url_character(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u > 0x20 && u < 0x7F && c != '"' && c != '<' && c != '>' && c != '\\' && c != '^' && c != '`' &&
         c != '{' && c != '|' && c != '}';
}

std::string epoch_text(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02d %02d:%02d", c.year, c.month, c.day, c.hour, c.minute);
  return buf;
}

}  // namespace

std::optional<std::string> add_refresh_source(RefreshSettings& s, const std::string& url) {
  if (url.empty()) return std::string("no URL given");
  if (url.size() > kRefreshMaxUrl) return "a URL has at most " + std::to_string(kRefreshMaxUrl) + " characters";
  if (!std::all_of(url.begin(), url.end(), url_character))
    return "'" + url + "' has a blank or a character that does not belong in a URL";
  const bool scheme = url.starts_with("http://") || url.starts_with("https://") || url.starts_with("ftp://") ||
                      url.starts_with("ftps://") || url.starts_with("file:///");
  if (!scheme && url.front() != '/')
    return "'" + url + "' is neither an http(s)://, ftp(s):// or file:/// URL nor an absolute file name";
  for (const auto& have : s.sources)
    if (have.url == url) return std::nullopt;
  if (s.sources.size() >= kRefreshMaxSources)
    return "at most " + std::to_string(kRefreshMaxSources) + " element sources";
  s.sources.push_back(RefreshSource{url, "", ""});
  return std::nullopt;
}

std::optional<std::string> check_refresh_interval(double hours) {
  if (!std::isfinite(hours) || hours < kRefreshMinHours || hours > kRefreshMaxHours) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "expected %.0f to %.0f hours (element sources change at most every 2 hours)",
                  kRefreshMinHours, kRefreshMaxHours);
    return std::string(buf);
  }
  return std::nullopt;
}

std::optional<std::int64_t> seconds_until_refresh(const RefreshSettings& s, std::int64_t now_unix) {
  if (s.sources.empty()) return std::nullopt;
  if (s.last_attempt_unix <= 0 || now_unix < s.last_attempt_unix) return 0;  // never, or the clock went back
  double hours = std::max(s.interval_hours, kRefreshMinHours);
  if (s.last_attempt_failed) hours = std::min(hours, kRefreshRetryHours);
  const auto due = s.last_attempt_unix + static_cast<std::int64_t>(hours * 3600.0);
  return std::max<std::int64_t>(0, due - now_unix);
}

bool refresh_due(const RefreshSettings& s, std::int64_t now_unix) {
  const auto left = seconds_until_refresh(s, now_unix);
  return left && *left == 0;
}

std::string RefreshReport::summary() const {
  std::string out = std::to_string(updated.size()) + " updated";
  if (!updated.empty()) {
    out += " (";
    for (std::size_t i = 0; i < updated.size() && i < 3; ++i) {
      if (i) out += ", ";
      out += updated[i].name + " " + epoch_text(updated[i].new_epoch);
    }
    if (updated.size() > 3) out += ", ...";
    out += ")";
  }
  out += ", " + std::to_string(unchanged) + " unchanged";
  if (older) out += ", " + std::to_string(older) + " older than the database's";
  if (not_in_database) out += ", " + std::to_string(not_in_database) + " not in the database";
  return out;
}

RefreshReport apply_refresh(Database& db, const std::vector<orbit::Elements>& sets) {
  // The newest set per catalog number.
  std::map<int, const orbit::Elements*> newest;
  for (const auto& e : sets) {
    auto [it, fresh] = newest.emplace(e.catalog_number, &e);
    if (!fresh && e.epoch() > it->second->epoch()) it->second = &e;
  }
  RefreshReport r;
  std::map<int, bool> used;
  for (auto& sat : db.satellites) {
    const auto it = newest.find(sat.elements.catalog_number);
    if (it == newest.end()) continue;
    used[it->first] = true;
    const orbit::Elements& e = *it->second;
    const orbit::UtcTime old_epoch = sat.elements.epoch();
    if (e.epoch() < old_epoch) {
      ++r.older;
    } else if (e.epoch() == old_epoch) {
      ++r.unchanged;
    } else {
      const std::string name = sat.elements.name;
      sat.elements = e;
      sat.elements.name = name;
      r.updated.push_back(RefreshChange{name, e.catalog_number, old_epoch, e.epoch()});
    }
  }
  for (const auto& [number, e] : newest)
    if (!used.count(number)) ++r.not_in_database;
  return r;
}

json to_json(const RefreshSettings& s) {
  json sources = json::array();
  for (const auto& src : s.sources)
    sources.push_back({{"url", src.url}, {"etag", src.etag}, {"last_modified", src.last_modified}});
  return {{"sources", sources},
          {"interval_hours", s.interval_hours},
          {"last_attempt_unix", s.last_attempt_unix},
          {"last_attempt_failed", s.last_attempt_failed}};
}

RefreshSettings refresh_settings_from_json(const json& j, const std::string& w) {
  if (!j.is_object()) bad(w, "expected an object");
  RefreshSettings s;
  s.interval_hours = read_setting(j, "refresh.interval_hours").get<double>();
  s.last_attempt_unix = integer(j, w, "last_attempt_unix", 0, 1LL << 40);
  if (j.contains("last_attempt_failed")) s.last_attempt_failed = boolean(j, w, "last_attempt_failed");   // (since 2026-11)
  const json& list = field(j, w, "sources");
  if (!list.is_array()) bad(path(w, "sources"), "expected an array");
  if (list.size() > kRefreshMaxSources)
    bad(path(w, "sources"), "at most " + std::to_string(kRefreshMaxSources) + " sources");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string wi = path(w, "sources") + "[" + std::to_string(i) + "]";
    const std::string url = text(list[i], wi, "url", kRefreshMaxUrl);
    RefreshSettings probe;
    if (const auto why = add_refresh_source(probe, url)) bad(path(wi, "url"), *why);
    s.sources.push_back(RefreshSource{url, text(list[i], wi, "etag", 256), text(list[i], wi, "last_modified", 128)});
  }
  return s;
}

}  // namespace tb::store
