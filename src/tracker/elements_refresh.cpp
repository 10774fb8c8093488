#include "tracker/elements_refresh.h"

#include <spdlog/spdlog.h>

#include "download/download.h"
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "orbit/element_age.h"
#include "orbit/elements.h"
#include "orbit/time.h"
#include "station/clock.h"
#include "store/model.h"
#include "store/refresh.h"

namespace tb::tracker {

struct ElementsRefresh::Outcome {
  std::string url;
  download::DownloadResult result;
};

namespace {

// An absolute file name is read through libcurl too, as file://.
std::string transfer_url(const std::string& url) { return url.starts_with("/") ? "file://" + url : url; }

// The first line of a body that is not element data, for the message.
std::string first_line(const std::string& body) {
  std::string line = body.substr(0, std::min<std::size_t>(body.find_first_of("\r\n"), 60));
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
  return line;
}

}  // namespace

ElementsRefresh::ElementsRefresh(store::ModelOwner& owner, Post post, std::function<void()> changed)
    : owner_(owner), model_(owner.model()), post_(std::move(post)), changed_(std::move(changed)) {}

ElementsRefresh::~ElementsRefresh() = default;

std::int64_t ElementsRefresh::wall_now() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void ElementsRefresh::poll(std::int64_t now_unix) {
  if (pending_ == 0 && store::refresh_due(model_.refresh, now_unix)) start(now_unix);
}

std::optional<std::string> ElementsRefresh::refresh_now(std::int64_t now_unix) {
  if (model_.refresh.sources.empty()) return std::string("no element source is configured (menu 3-5 or --elements-url)");
  if (pending_ > 0) return std::string("a refresh is running");
  start(now_unix);
  return std::nullopt;
}

orbit::UtcTime ElementsRefresh::station_now() const {
  if (station_clock_) return station_clock_->now();
  return std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
}

std::optional<orbit::UtcTime> ElementsRefresh::manual_next(orbit::UtcTime now) const {
  std::optional<orbit::UtcTime> next;
  for (const auto& source : model_.refresh.sources)
    for (const auto& [url, at] : manual_)
      if (url == source.url && at + kManualEvery > now && (!next || at + kManualEvery > *next)) next = at + kManualEvery;
  return next;
}

void ElementsRefresh::note_manual(orbit::UtcTime now) {
  std::erase_if(manual_, [&](const auto& m) {
    return std::none_of(model_.refresh.sources.begin(), model_.refresh.sources.end(),
                        [&](const store::RefreshSource& s) { return s.url == m.first; });
  });
  for (const auto& source : model_.refresh.sources) {
    const auto it = std::find_if(manual_.begin(), manual_.end(), [&](const auto& m) { return m.first == source.url; });
    if (it == manual_.end()) manual_.emplace_back(source.url, now);
    else it->second = now;
  }
}

std::string refresh_status_text(const RefreshState& s) {
  const std::string todo = ", SEE MENU 3-5";
  if (!s.stale_days) {
    if (s.running || !s.attempted) return "";
    if (s.failed) return "ELEMENTS NOT REFRESHED" + todo;
    if (s.updated > 0) return "ELEMENTS " + std::to_string(s.updated) + " UPDATED";
    return "";
  }
  char old[48];
  std::snprintf(old, sizeof old, "ELEMENTS %.0f DAYS OLD", *s.stale_days);
  if (!s.has_sources) return old + std::string(", NO REFRESH SOURCE") + todo;
  if (s.running) return old + std::string(", REFRESHING");
  if (!s.attempted && s.next_in_hours) {
    char next[64];
    if (*s.next_in_hours < 1.0)
      std::snprintf(next, sizeof next, ", NEXT REFRESH IN %.0f MIN", std::max(1.0, std::ceil(*s.next_in_hours * 60.0)));
    else
      std::snprintf(next, sizeof next, ", NEXT REFRESH IN %.0f H", std::ceil(*s.next_in_hours));
    return old + std::string(next) + todo;
  }
  if (!s.attempted) return old + std::string(", NO REFRESH SINCE START") + todo;
  if (s.failed) return old + std::string(", REFRESH FAILED") + todo;
  return old + std::string(", SOURCE HAS NO NEWER") + todo;
}

std::string ElementsRefresh::status_word(orbit::UtcTime now) const {
  RefreshState st;
  st.has_sources = !model_.refresh.sources.empty();
  st.running = pending_ > 0;
  st.attempted = !last_result_.empty();
  st.failed = last_failed_;
  st.updated = last_updated_;
  std::optional<double> youngest;
  for (const auto& sat : model_.db.satellites) {
    const orbit::ElementAge age = orbit::element_age(sat.elements, now);
    if (!age.stale()) return refresh_status_text(st);  // one current set: the database is usable
    if (!youngest || std::abs(age.days) < std::abs(*youngest)) youngest = age.days;
  }
  st.stale_days = youngest;
  if (!st.attempted && !st.running) {
    const auto left_s = store::seconds_until_refresh(model_.refresh, wall_now());
    if (left_s && *left_s > 0) st.next_in_hours = static_cast<double>(*left_s) / 3600.0;
  }
  return refresh_status_text(st);
}

void ElementsRefresh::start(std::int64_t now_unix) {
  if (!downloader_) downloader_ = std::make_unique<download::Downloader>();
  (void)owner_.edit(store::bit(store::Area::other), "refresh attempt", store::Origin::refresh,
                    [&](store::Model& m) { m.refresh.last_attempt_unix = now_unix; });  // kept across restarts
  outcomes_.clear();
  pending_ = static_cast<int>(model_.refresh.sources.size());
  for (const store::RefreshSource& src : model_.refresh.sources) {
    download::DownloadRequest r;
    r.url = transfer_url(src.url);
    r.allow_file = true;
    r.if_none_match = src.etag;
    r.if_modified_since = src.last_modified;
    r.total_timeout = timeout_;
    r.connect_timeout = std::min(timeout_, std::chrono::milliseconds(10000));
    r.max_bytes = 8u << 20;  // a whole CelesTrak group as XML is a few MB at most
    spdlog::info("elements: refreshing from {}", src.url);
    std::weak_ptr<int> alive = alive_;
    downloader_->submit(std::move(r), [this, alive, url = src.url](download::DownloadResult res) {
      post_([this, alive, url, res = std::move(res)]() mutable {
        if (alive.expired()) return;
        finished(url, std::move(res));
      });
    });
  }
}

void ElementsRefresh::finished(const std::string& url, download::DownloadResult r) {
  outcomes_.push_back(Outcome{url, std::move(r)});
  if (--pending_ == 0) complete();
}

void ElementsRefresh::complete() {
  std::vector<orbit::Elements> sets;
  std::vector<std::string> failures;
  int not_modified = 0;
  store::RefreshSettings settings = model_.refresh;
  for (Outcome& o : outcomes_) {
    const download::DownloadResult& r = o.result;
    store::RefreshSource* src = nullptr;
    for (auto& s : settings.sources)
      if (s.url == o.url) src = &s;
    if (!r.ok) {
      failures.push_back(r.error);
      continue;
    }
    if (r.not_modified) {
      ++not_modified;
      spdlog::info("elements: {}: not modified since the last refresh", o.url);
      continue;
    }
    const orbit::ParseResult parsed = orbit::parse_elements(r.body, o.url);
    if (parsed.sets.empty() || !parsed.ok()) {
      // "No GP data found" and any other body that is not element data: a failed update.
      std::string why = parsed.sets.empty() ? "no element sets in the answer ('" + first_line(r.body) + "')"
                                            : parsed.problems.front().message();
      failures.push_back(o.url + ": " + why);
      continue;
    }
    sets.insert(sets.end(), parsed.sets.begin(), parsed.sets.end());
    if (src) {
      src->etag = r.etag;
      src->last_modified = r.last_modified;
    }
  }
  store::Database db = model_.db;
  const store::RefreshReport report = store::apply_refresh(db, sets);
  for (const auto& c : report.updated)
    spdlog::info("elements: {} ({}) updated: epoch {} -> {}", c.name, c.catalog_number, orbit::format_iso8601(c.old_epoch),
                 orbit::format_iso8601(c.new_epoch));
  for (const auto& f : failures) spdlog::warn("elements: refresh failed: {}; the last good sets are kept", f);
  last_updated_ = static_cast<int>(report.updated.size());
  last_failed_ = !failures.empty();
  settings.last_attempt_failed = last_failed_;  // kept: a retry comes sooner
  const store::EditResult kept = owner_.edit(
      (report.updated.empty() ? 0 : store::bit(store::Area::elements)) | store::bit(store::Area::other),
      report.updated.empty() ? "refresh settings" : "elements", store::Origin::refresh, [&](store::Model& m) {
        m.db = std::move(db);
        m.refresh = settings;
      });
  if (!kept.ok()) {
    spdlog::warn("elements: the refreshed sets were not stored: {}", *kept.refusal);
    last_failed_ = true;
  }
  last_result_ = report.summary();
  if (not_modified) last_result_ += ", " + std::to_string(not_modified) + " source(s) not modified";
  if (!failures.empty()) last_result_ += "; " + std::to_string(failures.size()) + " source(s) failed: " + failures.front();
  spdlog::info("elements: refresh done: {}", last_result_);
  changed_();
}

}  // namespace tb::tracker
