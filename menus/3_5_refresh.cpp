// Menu 3-5: Refresh (trakbox's own; the 1994 TrakBox had no network). The element sources the
// database is refreshed from on a schedule, the interval, the last refresh, and "refresh now".
// Sources and interval are stored in the state (store::RefreshSettings); the downloads run in the
// background (tracker::ElementsRefresh), so nothing here waits for the network.
#include <cstdio>

#include <atomic>
#include <fstream>
#include <memory>
#include <sstream>

#include "menus/menus.h"
#include "store/settings.h"
#include "download/download.h"
#include "store/model.h"
#include "store/refresh.h"
#include "store/satnogs.h"
#include "tracker/elements_refresh.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "util/files.h"

namespace tb::menus {

namespace {

void show_refresh(term::Terminal& t, const store::RefreshSettings& r, const tracker::ElementsRefresh* live) {
  t.line("======= ELEMENT REFRESH =======");
  if (r.sources.empty()) t.line(" No element source: the database is refreshed only by hand (3-3).");
  for (std::size_t i = 0; i < r.sources.size(); ++i) t.line(" " + std::to_string(i + 1) + ". " + r.sources[i].url);
  char every[64];
  std::snprintf(every, sizeof every, " Every %.1f hours (at least 2).", r.interval_hours);
  t.line(every);
  if (live) {
    // A refresh running again after one that failed: the failure the status line shows is said too.
    if (live->running())
      t.line(" Refresh: running now" + (live->last_result().empty()
                                            ? std::string()
                                            : std::string("; the last one ") + (live->last_failed() ? "FAILED " : "ok ") +
                                                  live->last_result()));
    else if (!live->last_result().empty()) {
      t.line(std::string(" Last refresh: ") + (live->last_failed() ? "FAILED " : "ok ") + live->last_result());
      // What the operator can do about it (issue 30): the database is not left silently stale.
      if (live->last_failed()) {
        t.line(" The last good sets stay in use. Without a network: A with a file's path, 3-3, or");
        t.line(" trakbox --elements-url FILE; R tries again.");
      }
    }
    else t.line(" Last refresh: none since start");
  }
  t.line("A. Add a source (URL or file)   D. Delete a source   I. Interval   R. Refresh now");
  t.line("S. Frequencies from the SatNOGS DB (file or URL)   Q. Quit");
}

void add_source(term::Terminal& t, Services& s) {
  t.write("URL or file: ");
  t.flush();
  const std::string url = text::trimmed(read_line(t, store::kRefreshMaxUrl + 10));
  if (url.empty()) return;
  store::RefreshSettings next = s.model.refresh;
  if (const auto why = store::add_refresh_source(next, url)) {
    t.line("  Not added: " + *why);
    return;
  }
  if (!commit(t, s, store::bit(store::Area::other), "menu 3-5 source", [&](store::Model& m) { m.refresh = next; }))
    return;
  t.line("  Added. Sets of the database's satellites (by catalog number) will be taken from it.");
}

void delete_source(term::Terminal& t, Services& s) {
  const auto& sources = s.model.refresh.sources;
  if (sources.empty()) return;
  t.write("Delete which (1-" + std::to_string(sources.size()) + ")? ");
  t.flush();
  const std::string a = text::trimmed(read_line(t));
  const auto n = parse_integer(a);
  if (!n || *n < 1 || *n > static_cast<long>(sources.size())) {
    if (!a.empty()) t.line("  '" + a + "': enter a number from 1 to " + std::to_string(sources.size()));
    return;
  }
  (void)commit(t, s, store::bit(store::Area::other), "menu 3-5 source",
               [&](store::Model& m) { m.refresh.sources.erase(m.refresh.sources.begin() + (*n - 1)); });
}

void set_interval(term::Terminal& t, Services& s) {
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.1f", s.model.refresh.interval_hours);
  const store::Bounds b = store::bounds("refresh.interval_hours");
  const double hours = edit_number(t, "Hours between refreshes (2-720)", s.model.refresh.interval_hours, shown, b.lo, b.hi);
  (void)s.station.owner().set("refresh.interval_hours", hours, store::Origin::menus);
}

void refresh_now(term::Terminal& t, Services& s) {
  if (!s.station.refresh()) {
    t.line("  No refresh here.");
    return;
  }
  // Through the operations' one home: the same 10-minute limit per source as every front end.
  const tracker::OpResult done = tracker::StationOps(s.station).refresh_elements(tracker::ElementsRefresh::wall_now());
  if (!done.ok()) t.line("  Not started: " + *done.refusal);
  else t.line("  Refresh started: the result shows here, in the status line and in the log.");
}

// The text of a file or a URL. A download runs on a worker while the terminal keeps the station
// going (its key wait runs the event loop); any key cancels. The reason when there is no text.
std::optional<std::string> fetch(term::Terminal& t, const std::string& where, std::string& text) {
  if (where.starts_with("/")) {
    auto read = files::read_whole_file(where);
    if (!read) return "cannot read " + where;
    text = std::move(*read);
    return std::nullopt;
  }
  struct Shared {
    std::atomic<bool> done{false};
    download::DownloadResult result;
  };
  auto shared = std::make_shared<Shared>();
  download::Downloader worker;
  download::DownloadRequest r;
  r.url = where;
  r.total_timeout = std::chrono::seconds(60);
  r.max_bytes = 16u << 20;  // the whole transmitter list is a few MB
  worker.submit(r, [shared](download::DownloadResult res) {
    shared->result = std::move(res);
    shared->done = true;
  });
  t.line("  Downloading (any key cancels) ...");
  while (!shared->done) {
    const int k = t.read_key(std::chrono::milliseconds(200));
    if (k == term::kEndOfInput) throw InputClosed{};
    if (k != term::kTimeout) return std::string("cancelled");
  }
  if (!shared->result.ok) return shared->result.error;
  text = std::move(shared->result.body);
  return std::nullopt;
}

void satnogs(term::Terminal& t, Services& s) {
  t.write("SatNOGS transmitters, file or URL (Enter: db.satnogs.org): ");
  t.flush();
  std::string where = text::trimmed(read_line(t, 400));
  if (where.empty()) where = "https://db.satnogs.org/api/transmitters/?format=json";
  const bool replace = ask_yes_no(t, "Replace the records you entered yourself too ? [Y/N] ? ");
  std::string text;
  if (const auto why = fetch(t, where, text)) {
    t.line("  Nothing changed: " + *why);
    return;
  }
  store::Database db = s.model.db;
  const store::SatnogsImport r = store::import_satnogs(db, text, replace);
  if (!r.ok()) {
    t.line("  Nothing changed: " + where + ": " + r.error);
    return;
  }
  for (const auto& line : r.lines) t.line("  " + line);
  t.line("  " + std::to_string(r.without_transmitter) + " of the database's satellites without an active transmitter.");
  if (!r.report.changed) return;
  (void)commit(t, s, store::bit(store::Area::radio_entries), "SatNOGS import", [&](store::Model& m) { m.db = std::move(db); });
}

}  // namespace

void menu_3_5_refresh(term::Terminal& t, Services& s) {
  run_menu(t, [&] { show_refresh(t, s.model.refresh, s.station.refresh()); }, " Select: ", [&](char key) {
    switch (key) {
      case 'A': add_source(t, s); break;
      case 'D': delete_source(t, s); break;
      case 'I': set_interval(t, s); break;
      case 'R': refresh_now(t, s); break;
      case 'S': satnogs(t, s); break;
      case 'Q': return MenuStep::back;
      default: return MenuStep::unknown;
    }
    return MenuStep::again;
  });
}

}  // namespace tb::menus
