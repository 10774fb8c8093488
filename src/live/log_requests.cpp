#include "live/log_requests.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "live/build_info.h"
#include "live/station_app.h"
#include "logbook/adif.h"
#include "tracker/elements_refresh.h"
#include "tracker/log_json.h"
#include "tracker/station_loop.h"

namespace tb::app {

using nlohmann::json;

std::unique_ptr<tracker::Logging> open_logging(StationApp& app, const std::filesystem::path& state_dir,
                                               const std::string& data_dir) {
  auto l = std::make_unique<tracker::Logging>();
  const std::string path = (state_dir / "logbook.sqlite").string();
  l->book = logbook::Logbook::open(path, l->open_error);
  if (!l->book) app.log().error("logbook: {}", l->open_error);
  l->names = logbook::load_lotw_names(data_dir + "/lotw-satellites.txt");
  if (!l->names.error.empty()) app.log().warn("logbook: LoTW names: {}", l->names.error);
  app.station().set_logging(l.get());
  return l;
}

// The socket's requests and the CLI's direct use share these on a logbook.
json log_export(const logbook::Logbook& b, std::int64_t since, std::int64_t now) {
  const logbook::AdifExport e = logbook::write_adif(b.list(since), kVersion, now);
  return {{"ok", true}, {"adif", e.text}, {"warnings", e.warnings}};
}

json log_import(logbook::Logbook& b, const std::string& adif) {
  const logbook::AdifRead r = logbook::read_adif(adif);
  if (!r.ok()) return {{"error", "import: " + r.error + "; nothing was stored"}};
  const logbook::Imported i = b.import(r.qsos);
  if (!i.error.empty()) return {{"error", "import: " + i.error + "; nothing was stored"}};
  return {{"ok", true}, {"added", i.added}, {"duplicates", i.duplicates}};
}

json log_list(const logbook::Logbook& b, std::int64_t since) {
  json list = json::array();
  for (const auto& q : b.list(since)) list.push_back(tracker::qso_json(q));
  return {{"ok", true}, {"qsos", std::move(list)}};
}

namespace {

std::optional<std::int64_t> since_of(const json& j) {
  const auto it = j.find("since");
  if (it == j.end() || it->is_null()) return 0;
  if (!it->is_string()) return std::nullopt;
  return logbook::parse_utc(it->get<std::string>());
}

json handle(StationApp& app, const json& j) {
  if (!j.is_object() || !j.contains("action") || !j["action"].is_string())
    return {{"error", "expected {\"action\": \"add\"|\"list\"|\"export\"|\"import\", ...}"}};
  const std::string action = j["action"].get<std::string>();
  tracker::LogOps ops(app.station());
  std::string why;
  logbook::Logbook* b = ops.book(why);
  if (!b) return {{"error", why}};
  if (action == "add") {
    tracker::LogRequest req;
    req.source = logbook::Source::cli;
    if (auto e = tracker::log_request_from_json(j, req)) return {{"error", *e}};
    const tracker::LogResult r = ops.log(req);
    if (!r.ok()) return {{"error", *r.refusal}};
    return {{"ok", true}, {"qso", tracker::qso_json(r.qso)}};
  }
  const auto since = since_of(j);
  if (!since) return {{"error", "since: expected a UTC date like 2026-12-01"}};
  if (action == "list") return log_list(*b, *since);
  if (action == "export") return log_export(*b, *since, tracker::ElementsRefresh::wall_now());
  if (action == "import") {
    if (!j.contains("adif") || !j["adif"].is_string()) return {{"error", "import: the file's text is expected (\"adif\")"}};
    return log_import(*b, j["adif"].get<std::string>());
  }
  return {{"error", "action: '" + action.substr(0, 20) + "' is not add, list, export or import"}};
}

}  // namespace

std::string log_socket_request(StationApp& app, const std::string& request) {
  json reply;
  try {
    const json j = json::parse(request, nullptr, false);
    reply = j.is_discarded() ? json{{"error", "the request is not JSON"}} : handle(app, j);
  } catch (const std::exception& e) {
    reply = {{"error", std::string("the request could not be handled: ") + e.what()}};
  }
  return reply.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace tb::app
