#include "web/api_log.h"

#include <nlohmann/json.hpp>

#include "logbook/adif.h"
#include "tracker/log_json.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "util/text.h"

namespace tb::web {
namespace {

using json = nlohmann::json;

Response reply(int status, const json& j) {
  Response r;
  r.status = status;
  r.body = j.dump(-1, ' ', false, json::error_handler_t::replace);
  return r;
}
Response refuse(int status, const std::string& sentence) { return reply(status, {{"error", sentence}}); }

// ?since=2026-12-01 (or a time, or "today": the station clock's UTC day); 0 when absent; nullopt
// when malformed.
std::optional<std::int64_t> since_of(const std::string& target, std::int64_t station_now) {
  const auto s = query_param(target, "since");
  if (!s) return std::nullopt;
  if (s->empty()) return 0;
  if (*s == "today") return station_now - ((station_now % 86400) + 86400) % 86400;
  return logbook::parse_utc(*s);
}

std::optional<std::int64_t> id_of(const json& b) {
  const auto it = b.find("id");
  if (it == b.end() || !it->is_number_integer()) return std::nullopt;
  return it->get<std::int64_t>();
}

}  // namespace

bool is_log_path(const std::string& path) {
  return path == "/api/v1/log" || path == "/api/v1/log.adi" || path.rfind("/api/v1/log/", 0) == 0;
}

Response log_get(tracker::StationLoop& station, const std::string& path, const std::string& target,
                 std::int64_t wall_now_unix, const std::string& version) {
  tracker::LogOps ops(station);
  std::string why;
  logbook::Logbook* b = ops.book(why);
  if (!b) return refuse(409, why);
  const auto now = std::chrono::floor<std::chrono::seconds>(station.clock().now()).time_since_epoch().count();
  const auto since = since_of(target, now);
  if (!since) return refuse(400, "since: expected a UTC date like 2026-12-01, a time like 2026-12-01T21:00Z, or today");
  const auto qsos = b->list(*since);
  if (path == "/api/v1/log.adi") {
    const logbook::AdifExport e = logbook::write_adif(qsos, version.empty() ? "unknown" : version, wall_now_unix);
    Response r;
    r.content_type = "text/plain; charset=us-ascii";
    r.body = e.text;
    r.headers.emplace_back("Content-Disposition", "attachment; filename=\"trakbox.adi\"");
    if (!e.warnings.empty()) r.headers.emplace_back("X-Trakbox-Warnings", std::to_string(e.warnings.size()));
    return r;
  }
  if (path != "/api/v1/log") return refuse(404, "no such endpoint");
  json list = json::array();
  for (const auto& q : qsos) list.push_back(tracker::qso_json(q));
  return reply(200, {{"qsos", std::move(list)}, {"summary", tracker::log_summary(ops)}});
}

Response log_post(tracker::StationLoop& station, const std::string& path, const json& body) {
  tracker::LogOps ops(station);
  std::string why;
  logbook::Logbook* b = ops.book(why);
  if (!b) return refuse(409, why);
  if (path == "/api/v1/log") {
    tracker::LogRequest req;
    req.source = logbook::Source::web;
    if (auto e = tracker::log_request_from_json(body, req)) return refuse(400, *e);
    const tracker::LogResult r = ops.log(req);
    if (!r.ok()) return refuse(409, *r.refusal);
    return reply(200, {{"ok", true}, {"qso", tracker::qso_json(r.qso)}});
  }
  const auto id = id_of(body);
  if (!id) return refuse(400, "id: the QSO's number is expected ({\"id\": 3})");
  if (path == "/api/v1/log/edit") {
    auto q = b->get(*id);
    if (!q || q->deleted) return refuse(404, "id: no QSO " + std::to_string(*id) + " in the log");
    if (auto e = tracker::apply_edit_json(body, *q)) return refuse(400, *e);
    const logbook::Added a = b->edit(*id, *q);
    if (!a.ok()) return refuse(409, a.error);
    return reply(200, {{"ok", true}, {"qso", tracker::qso_json(*b->get(*id))}});
  }
  if (path == "/api/v1/log/delete") {
    const logbook::Added a = b->remove(*id);
    if (!a.ok()) return refuse(404, a.error);
    return reply(200, {{"ok", true}, {"id", *id}});
  }
  return refuse(404, "no such endpoint");
}

}  // namespace tb::web
