#include "tracker/log_json.h"

#include <nlohmann/json.hpp>

namespace tb::tracker {
namespace {

using nlohmann::json;

std::optional<std::string> text_field(const json& j, const char* key, std::string& out) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_string()) return std::string(key) + ": a string is expected";
  out = it->get<std::string>();
  if (out.size() > 500) return std::string(key) + ": at most 500 characters";
  return std::nullopt;
}

std::optional<std::string> time_field(const json& j, std::optional<std::int64_t>& out) {
  std::string t;
  if (auto e = text_field(j, "time_on", t)) return e;
  if (t.empty()) return std::nullopt;
  const auto v = logbook::parse_utc(t);
  if (!v) return "time_on: '" + t.substr(0, 40) + "' is not a UTC time (2026-12-01T21:44:20Z)";
  out = *v;
  return std::nullopt;
}

std::optional<std::string> power_field(const json& j, double& out) {
  const auto it = j.find("power_w");
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_number()) return std::string("power_w: a number of watts is expected");
  out = it->get<double>();
  return std::nullopt;
}

std::optional<std::string> only_keys(const json& j, std::initializer_list<const char*> keys) {
  for (const auto& [k, v] : j.items()) {
    bool known = false;
    for (const char* name : keys) known = known || k == name;
    if (!known) return "'" + k.substr(0, 40) + "': not a field of a QSO request";
  }
  return std::nullopt;
}

}  // namespace

json qso_json(const logbook::Qso& q) {
  return {{"id", q.id},
          {"version", q.version},
          {"deleted", q.deleted},
          {"call", q.call},
          {"grid", q.grid},
          {"rst_sent", q.rst_sent},
          {"rst_rcvd", q.rst_rcvd},
          {"time_on", logbook::utc_text(q.time_on).replace(10, 1, "T") + "Z"},
          {"sat_name", q.sat_name},
          {"lotw_name", q.lotw_name},
          {"norad", q.norad},
          {"mode", q.mode},
          {"submode", q.submode},
          {"uplink_hz", q.uplink_hz},
          {"downlink_hz", q.downlink_hz},
          {"uplink_tuned_hz", q.uplink_tuned_hz},
          {"downlink_tuned_hz", q.downlink_tuned_hz},
          {"band", q.band},
          {"band_rx", q.band_rx},
          {"sat_mode", logbook::sat_mode(q.uplink_hz, q.downlink_hz)},
          {"my_grid", q.my_grid},
          {"station_call", q.station_call},
          {"power_w", q.power_w},
          {"note", q.note},
          {"source", std::string(logbook::source_name(q.source))}};
}

std::optional<std::string> log_request_from_json(const json& j, LogRequest& r) {
  if (!j.is_object()) return std::string("the request must be a JSON object");
  if (auto e = only_keys(j, {"call", "grid", "rst_sent", "rst_rcvd", "note", "sat", "mode", "time_on", "power_w", "action"}))
    return e;
  for (const auto& [key, out] : {std::pair<const char*, std::string*>{"call", &r.call}, {"grid", &r.grid},
                                 {"rst_sent", &r.rst_sent}, {"rst_rcvd", &r.rst_rcvd}, {"note", &r.note},
                                 {"sat", &r.sat}, {"mode", &r.mode}})
    if (auto e = text_field(j, key, *out)) return e;
  if (auto e = time_field(j, r.time_on)) return e;
  return power_field(j, r.power_w);
}

std::optional<std::string> apply_edit_json(const json& j, logbook::Qso& q) {
  if (!j.is_object()) return std::string("the request must be a JSON object");
  if (auto e = only_keys(j, {"id", "call", "grid", "rst_sent", "rst_rcvd", "note", "mode", "time_on", "power_w", "action"}))
    return e;
  for (const auto& [key, out] : {std::pair<const char*, std::string*>{"call", &q.call}, {"grid", &q.grid},
                                 {"rst_sent", &q.rst_sent}, {"rst_rcvd", &q.rst_rcvd}, {"note", &q.note},
                                 {"mode", &q.mode}})
    if (auto e = text_field(j, key, *out)) return e;
  std::optional<std::int64_t> t;
  if (auto e = time_field(j, t)) return e;
  if (t) q.time_on = *t;
  return power_field(j, q.power_w);
}

json log_summary(const LogOps& ops) {
  std::string why;
  logbook::Logbook* b = ops.book(why);
  if (!b) {
    json j{{"open", false}, {"count", 0}, {"last", nullptr}, {"queue", 0}};
    if (ops.logging()) j["problem"] = why;  // a program without a logbook (a test's) has no problem
    return j;
  }
  json j{{"open", true}, {"count", b->count()}, {"queue", b->upload_queue_length()}};
  if (const auto last = b->last())
    j["last"] = {{"id", last->id}, {"call", last->call}, {"sat_name", last->sat_name},
                 {"time_on", logbook::utc_text(last->time_on).replace(10, 1, "T") + "Z"}};
  else
    j["last"] = nullptr;
  if (const auto& l = ops.logging()->logger) {
    j["logger"] = {{"kind", l->kind},
                   {"url", l->url},
                   {"queue", b->upload_queue_length()},
                   {"last_upload", l->last_upload.empty() ? json(nullptr) : json(l->last_upload)},
                   {"last_radio_post", l->last_radio_post.empty() ? json(nullptr) : json(l->last_radio_post)},
                   {"problem", l->problem ? json(*l->problem) : json(nullptr)},
                   {"radio_problem", l->radio_problem ? json(*l->radio_problem) : json(nullptr)}};
    if (l->problem) j["upload_problem"] = *l->problem;
  }
  return j;
}

}  // namespace tb::tracker
