#include "live/log_requests.h"

#include <malloc.h>

#include <atomic>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "live/build_info.h"
#include "util/json_limits.h"
#include "live/station_app.h"
#include "logbook/adif.h"
#include "logbook/log_page.h"
#include "tracker/elements_refresh.h"
#include "tracker/log_json.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "util/safe_text.h"

namespace tb::app {

using nlohmann::json;

namespace {

// A request longer than this can only be an import (the others are a line of options).
constexpr std::size_t kSmallRequest = 64 * 1024;

std::optional<std::int64_t> since_of(const json& j) {
  const auto it = j.find("since");
  if (it == j.end() || it->is_null()) return 0;
  if (!it->is_string()) return std::nullopt;
  return logbook::parse_utc(it->get<std::string>());
}

// The page a list or export asks: since, the cursor after which it starts, how many; an error
// naming the field.
struct PageAsk {
  std::int64_t since = 0;
  logbook::Cursor after;
  bool first = true;
  std::size_t limit = kSocketPage;
  std::string error;
};

PageAsk page_ask(const json& j) {
  PageAsk a;
  const auto since = since_of(j);
  if (!since) return a.error = "since: expected a UTC date like 2026-12-01", a;
  a.since = *since;
  if (const auto it = j.find("after"); it != j.end() && !it->is_null()) {
    const auto c = it->is_string() ? logbook::parse_cursor(it->get<std::string>()) : std::nullopt;
    if (!c) return a.error = "after: expected the cursor a page gave as \"next\"", a;
    a.after = *c;
    a.first = false;
  }
  if (const auto it = j.find("limit"); it != j.end() && !it->is_null()) {
    if (!it->is_number_unsigned() || it->get<std::size_t>() < 1 || it->get<std::size_t>() > kSocketPage)
      return a.error = "limit: expected 1 to " + std::to_string(kSocketPage) + " QSOs", a;
    a.limit = it->get<std::size_t>();
  }
  return a;
}

json next_of(const logbook::Page& p) { return p.next ? json(*p.next) : json(nullptr); }

}  // namespace

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

json log_export(const logbook::Logbook& b, const json& request, std::int64_t now) {
  const PageAsk a = page_ask(request);
  if (!a.error.empty()) return {{"error", a.error}};
  const logbook::Page p = logbook::read_page(b, a.since, a.after, a.limit);
  std::vector<std::string> warnings;
  std::string text = logbook::adif_page(p.qsos, a.first, kVersion, now, warnings);
  return {{"ok", true}, {"adif", std::move(text)}, {"warnings", warnings}, {"next", next_of(p)}};
}

json log_list(const logbook::Logbook& b, const json& request) {
  const PageAsk a = page_ask(request);
  if (!a.error.empty()) return {{"error", a.error}};
  const logbook::Page p = logbook::read_page(b, a.since, a.after, a.limit);
  json list = json::array();
  for (const auto& q : p.qsos) list.push_back(tracker::qso_json(q));
  return {{"ok", true}, {"qsos", std::move(list)}, {"next", next_of(p)}};
}

// The records an import left out, the first kMaxSkippedShown of them named.
json skipped_json(const std::vector<logbook::AdifSkipped>& skipped) {
  constexpr std::size_t kMaxSkippedShown = 20;
  json list = json::array();
  for (std::size_t k = 0; k < skipped.size() && k < kMaxSkippedShown; ++k)
    list.push_back({{"record", skipped[k].record}, {"call", skipped[k].call}, {"why", skipped[k].why}});
  return list;
}

json log_import(logbook::Logbook& b, const std::string& adif) {
  logbook::Imported i;
  logbook::AdifRead r = logbook::read_adif(adif);
  if (!r.ok()) return {{"error", "import: " + r.error + "; nothing was stored"}};
  i = b.import(r.qsos);
  if (!i.error.empty()) return {{"error", "import: " + i.error + "; nothing was stored"}};
  return {{"ok", true}, {"added", i.added}, {"duplicates", i.duplicates}, {"skipped", r.skipped.size()},
          {"skipped_records", skipped_json(r.skipped)}};
}

// The import's thread: one at a time; what it found is posted back to the loop.
struct LogRequests::Worker {
  std::thread thread;
  std::atomic<bool> busy{false};
};

LogRequests::LogRequests(StationApp& app) : app_(app), worker_(std::make_shared<Worker>()) {}

LogRequests::~LogRequests() {
  if (worker_->thread.joinable()) worker_->thread.join();
}

void LogRequests::handle(const std::string& request, std::function<void(std::string)> reply) {
  const auto answer = [&reply](const json& j) { reply(j.dump(-1, ' ', false, json::error_handler_t::replace)); };
  try {
    if (request.size() > kSmallRequest) return import(request, std::move(reply));
    std::string not_json;
    const json j = json_limits::parse_bounded<json>(request, not_json);
    if (j.is_discarded()) return answer({{"error", "the request is not JSON: " + not_json}});
    if (!j.is_object() || !j.contains("action") || !j["action"].is_string())
      return answer({{"error", "expected {\"action\": \"add\"|\"list\"|\"export\"|\"import\", ...}"}});
    const std::string action = j["action"].get<std::string>();
    if (action == "import") return import(request, std::move(reply));
    tracker::LogOps ops(app_.station());
    std::string why;
    logbook::Logbook* b = ops.book(why);
    if (!b) return answer({{"error", why}});
    if (action == "add") {
      tracker::LogRequest req;
      req.source = logbook::Source::cli;
      const std::string call = j.value("call", json()).is_string() ? text::safe_text(j["call"].get<std::string>().substr(0, 20)) : "";
      std::optional<std::string> refusal = tracker::log_request_from_json(j, req);
      tracker::LogResult r;
      if (!refusal) r = ops.log(req), refusal = r.refusal;
      if (refusal) {
        app_.log().warn("socket: logging a QSO with {} refused for trakbox log add: {}", call, *refusal);
        return answer({{"error", *refusal}});
      }
      app_.log().info("socket: QSO {} {} {} {} logged by trakbox log add", r.qso.id, r.qso.call, r.qso.sat_name,
                      logbook::utc_text(r.qso.time_on));
      json done{{"ok", true}, {"qso", tracker::qso_json(r.qso)}};
      if (r.warning) done["warning"] = *r.warning;
      return answer(done);
    }
    if (action == "list") return answer(log_list(*b, j));
    if (action == "export") return answer(log_export(*b, j, tracker::ElementsRefresh::wall_now()));
    return answer({{"error", "action: '" + text::safe_text(action.substr(0, 20)) + "' is not add, list, export or import"}});
  } catch (const std::exception& e) {
    answer({{"error", std::string("the request could not be handled: ") + e.what()}});
  }
}

void LogRequests::import(std::string request, std::function<void(std::string)> reply) {
  const auto refuse = [this, &reply](const std::string& why) {
    app_.log().warn("socket: an import refused for trakbox log import: {}", why);
    reply(json{{"error", why}}.dump(-1, ' ', false, json::error_handler_t::replace));
  };
  std::string why;
  const logbook::Logbook* b = tracker::LogOps(app_.station()).book(why);
  if (!b) return refuse(why);
  if (worker_->busy) return refuse("import: another import is under way; nothing was stored (try again when it is done)");
  const std::string path = b->path();
  if (worker_->thread.joinable()) worker_->thread.join();  // the last one, done (busy is false)
  worker_->busy = true;
  const std::size_t bytes = request.size();
  app_.log().info("socket: an import of {} bytes started for trakbox log import (on a worker thread)", bytes);
  auto done = [w = worker_, reply = std::move(reply), &log = app_.log(), bytes](json result) {
    w->busy = false;
    if (result.contains("error"))
      log.warn("socket: an import of {} bytes refused for trakbox log import: {}", bytes, result["error"].get<std::string>());
    else
      log.info("socket: {} QSOs imported ({} already in the log, {} records not satellite QSOs skipped) by trakbox "
               "log import", result.value("added", 0), result.value("duplicates", 0), result.value("skipped", 0));
    reply(result.dump(-1, ' ', false, json::error_handler_t::replace));
  };
  worker_->thread = std::thread([req = std::move(request), path, done = std::move(done), &io = app_.io()]() mutable {
    json result;
    try {
      std::string adif;
      {
        std::string why;
        json j = json_limits::parse_bounded<json>(req, why);
        std::string().swap(req);
        if (j.is_discarded() || !j.is_object() || j.value("action", json()) != "import")
          result = {{"error", "only an import may be longer than " + std::to_string(kSmallRequest / 1024) + " kB"}};
        else if (!j.contains("adif") || !j["adif"].is_string())
          result = {{"error", "import: the file's text is expected (\"adif\")"}};
        else
          adif = std::move(j["adif"].get_ref<std::string&>());
      }
      if (result.is_null()) {
        std::string error;
        auto book = logbook::Logbook::open(path, error);  // this thread's own connection
        result = book ? log_import(*book, adif) : json{{"error", "import: " + error + "; nothing was stored"}};
      }
    } catch (const std::exception& e) {
      result = {{"error", std::string("import: ") + e.what() + "; nothing was stored"}};
    }
    malloc_trim(0);  // what the file and its records took goes back to the system, not just to the heap
    boost::asio::post(io, [done = std::move(done), result = std::move(result)]() mutable { done(std::move(result)); });
  });
}

}  // namespace tb::app
