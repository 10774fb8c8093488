#include "web/api_log.h"

#include <memory>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "logbook/adif.h"
#include "logbook/log_page.h"
#include "tracker/log_json.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "util/safe_text.h"
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
Response refuse(int status, const std::string& sentence) {
  Response r = reply(status, {{"error", sentence}});
  r.why = sentence;
  return r;
}

// ?since=2026-12-01 (or a time, or "today": the station clock's UTC day); 0 when absent; nullopt
// when malformed.
std::optional<std::int64_t> since_of(const std::string& target, std::int64_t station_now) {
  const auto s = query_param(target, "since");
  if (!s) return std::nullopt;
  if (s->empty()) return 0;
  if (*s == "today") return station_now - ((station_now % 86400) + 86400) % 86400;
  return logbook::parse_utc(*s);
}

// ?limit=N (1..kMaxPage; absent: kDefaultPage); nullopt when malformed or out of range.
std::optional<std::size_t> limit_of(const std::string& target) {
  const auto s = query_param(target, "limit");
  if (!s) return std::nullopt;
  if (s->empty()) return logbook::kDefaultPage;
  const auto n = text::parse_integer<long long>(*s);
  if (!n || *n < 1 || static_cast<std::size_t>(*n) > logbook::kMaxPage) return std::nullopt;
  return static_cast<std::size_t>(*n);
}

std::optional<logbook::Cursor> after_of(const std::string& target) {
  const auto s = query_param(target, "after");
  if (!s) return std::nullopt;
  if (s->empty()) return logbook::Cursor{};
  return logbook::parse_cursor(*s);
}

std::optional<std::int64_t> id_of(const json& b) {
  const auto it = b.find("id");
  if (it == b.end() || !it->is_number_integer()) return std::nullopt;
  return it->get<std::int64_t>();
}

// The ADIF export in pieces: one page of the log per piece, read when the client has taken the
// piece before (the station's loop never holds more than a page of it, nor builds it in one go).
struct AdifStream {
  tracker::StationLoop* station;
  std::int64_t since = 0, created = 0;
  std::string version;
  logbook::Cursor cursor;
  bool first = true, done = false;
  std::vector<std::string> warnings;

  std::string next() {
    if (done) return {};
    std::string why;
    const logbook::Logbook* b = tracker::LogOps(*station).book(why);
    if (!b) {
      spdlog::error("web: the ADIF export stopped: {}", why);
      done = true;
      return {};
    }
    const logbook::Page p = logbook::read_page(*b, since, cursor, logbook::kDefaultPage);
    std::string text = logbook::adif_page(p.qsos, first, version, created, warnings);
    first = false;
    if (p.next) cursor = *logbook::parse_cursor(*p.next);
    else done = true;
    return text;
  }
};

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
  if (path == "/api/v1/log.adi") {
    auto s = std::make_shared<AdifStream>();
    s->station = &station;
    s->since = *since;
    s->created = wall_now_unix;
    s->version = version.empty() ? "unknown" : version;
    Response r;
    r.content_type = "text/plain; charset=us-ascii";
    r.headers.emplace_back("Content-Disposition", "attachment; filename=\"trakbox.adi\"");
    r.stream = [s] { return s->next(); };
    r.trailers = [s] {
      return std::vector<std::pair<std::string, std::string>>{{"X-Trakbox-Warnings", std::to_string(s->warnings.size())}};
    };
    return r;
  }
  if (path != "/api/v1/log") return refuse(404, "no such endpoint");
  const auto limit = limit_of(target);
  if (!limit) return refuse(400, "limit: expected a number of QSOs from 1 to " + std::to_string(logbook::kMaxPage));
  const auto after = after_of(target);
  if (!after) return refuse(400, "after: expected the cursor a page gave as \"next\" (like 1796161460.42)");
  const logbook::Page p = logbook::read_page(*b, *since, *after, *limit);
  json list = json::array();
  for (const auto& q : p.qsos) list.push_back(tracker::qso_json(q));
  return reply(200, {{"qsos", std::move(list)},
                     {"next", p.next ? json(*p.next) : json(nullptr)},
                     {"limit", *limit},
                     {"summary", tracker::log_summary(ops)}});
}

Response log_post(tracker::StationLoop& station, const std::string& path, const json& body, const std::string& who) {
  tracker::LogOps ops(station);
  std::string why;
  logbook::Logbook* b = ops.book(why);
  const auto refused = [&](int status, const std::string& what, const std::string& sentence) {
    spdlog::warn("web: {} refused for {} ({}): {}", what, who, status, sentence);
    return refuse(status, sentence);
  };
  const std::string call = body.contains("call") && body["call"].is_string() ? body["call"].get<std::string>() : "";
  if (path == "/api/v1/log") {
    const std::string what = call.empty() ? std::string("logging a QSO") : "logging a QSO with " + text::safe_text(call.substr(0, 20));
    if (!b) return refused(409, what, why);
    tracker::LogRequest req;
    req.source = logbook::Source::web;
    if (auto e = tracker::log_request_from_json(body, req)) return refused(400, what, *e);
    const tracker::LogResult r = ops.log(req);
    if (!r.ok()) return refused(409, what, *r.refusal);
    spdlog::info("web: QSO {} {} {} {} logged by {}", r.qso.id, r.qso.call, r.qso.sat_name,
                 logbook::utc_text(r.qso.time_on), who);
    json done{{"ok", true}, {"qso", tracker::qso_json(r.qso)}};
    if (r.warning) done["warning"] = *r.warning;
    return reply(200, done);
  }
  const auto id = id_of(body);
  const std::string what = path == "/api/v1/log/edit" ? "editing QSO " : "deleting QSO ";
  if (!id) return refused(400, what + "(no id)", "id: the QSO's number is expected ({\"id\": 3})");
  const std::string which = what + std::to_string(*id);
  if (!b) return refused(409, which, why);
  if (path == "/api/v1/log/edit") {
    auto q = b->get(*id);
    if (!q || q->deleted) return refused(404, which, "id: no QSO " + std::to_string(*id) + " in the log");
    if (auto e = tracker::apply_edit_json(body, *q)) return refused(400, which + " " + q->call, *e);
    const logbook::Added a = b->edit(*id, *q);
    if (!a.ok()) return refused(409, which + " " + q->call, a.error);
    const auto now = b->get(*id);
    spdlog::info("web: QSO {} {} edited by {} (now version {}; {})", *id, now->call, who, now->version,
                 text::safe_text(body.dump(-1, ' ', true, json::error_handler_t::replace).substr(0, 160)));
    return reply(200, {{"ok", true}, {"qso", tracker::qso_json(*now)}});
  }
  if (path == "/api/v1/log/delete") {
    const auto old = b->get(*id);
    const logbook::Added a = b->remove(*id);
    if (!a.ok()) return refused(404, which, a.error);
    spdlog::info("web: QSO {} {} {} deleted by {}", *id, old ? old->call : "", old ? logbook::utc_text(old->time_on) : "",
                 who);
    return reply(200, {{"ok", true}, {"id", *id}});
  }
  return refuse(404, "no such endpoint");
}

}  // namespace tb::web
