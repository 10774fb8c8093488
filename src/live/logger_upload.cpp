#include "live/logger_upload.h"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <spdlog/spdlog.h>

#include "download/download.h"
#include "live/station_app.h"
#include "store/model.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "util/redact.h"
#include "util/text.h"

namespace tb::app {

namespace {

std::string mode_name(radio::Mode m) { return m == radio::Mode::none ? std::string() : radio::to_string(m); }

// What the radio does now: the satellite followed while it is in range (the manual's AOS rule),
// its TQSL name, the links where the Tuner has them (the spot plus the Doppler of the last update,
// RF at the antenna) and the record's modes. Out of a pass: the last state, not tracking.
logbook::RadioState radio_now(tracker::StationLoop& st, const logbook::LotwNames& names,
                              const std::optional<logbook::RadioPosted>& last) {
  logbook::RadioState r;
  const tracker::SatNow* f = st.tracker().followed();
  const auto& sats = st.model().db.satellites;
  if (!f || !f->in_range || !f->obs.ok() || f->db_index < 0 || f->db_index >= static_cast<int>(sats.size())) {
    if (last) r = last->state;
    r.tracking = false;
    return r;
  }
  const radio::Tuner& t = st.tuner();
  const radio::Tuning& tu = t.last_tuning();
  r.tracking = true;
  r.sat_name = names.name(sats[static_cast<std::size_t>(f->db_index)].elements.catalog_number);
  r.uplink_hz = t.uplink_spot_hz() ? t.uplink_spot_hz() + std::llround(tu.uplink_doppler_hz) : 0;
  r.downlink_hz = t.downlink_spot_hz() ? t.downlink_spot_hz() + std::llround(tu.downlink_doppler_hz) : 0;
  r.mode = mode_name(t.satellite().uplink_mode);
  r.mode_rx = mode_name(t.satellite().downlink_mode);
  return r;
}

std::int64_t seconds_of(orbit::UtcTime t) {
  return std::chrono::floor<std::chrono::seconds>(t).time_since_epoch().count();
}

}  // namespace

struct LoggerUpload::Impl {
  boost::asio::io_context& io;
  tracker::StationLoop& station;
  tracker::Logging& logging;
  LoggerSettings s;
  boost::asio::steady_timer timer{io};
  download::Downloader downloader;
  std::shared_ptr<int> alive = std::make_shared<int>(0);
  bool busy = false;                          // one request at a time
  std::optional<logbook::RadioPosted> posted;  // the last radio state the logger accepted
  std::int64_t radio_retry_at = 0;            // after a failed radio post

  Impl(boost::asio::io_context& i, tracker::StationLoop& st, tracker::Logging& l, LoggerSettings set)
      : io(i), station(st), logging(l), s(std::move(set)) {
    logging.logger = tracker::LoggerStatus{std::string(logbook::logger_kind_name(s.spec.kind)),
                                           logbook::logger_display_url(s.spec), {}, {}, {}, {}};
  }
  ~Impl() { logging.logger.reset(); }

  tracker::LoggerStatus& status() { return *logging.logger; }
  std::int64_t now() const { return seconds_of(station.now()); }

  void tick() {
    std::weak_ptr<int> a = alive;
    timer.expires_after(std::chrono::seconds(1));
    timer.async_wait([this, a](const boost::system::error_code& ec) {
      if (!ec && !a.expired()) tick();
    });
    next();
  }

  // The next request, if none is in flight: a radio post that is due, else the first QSO due.
  void next() {
    if (busy) return;
    const std::int64_t t = now();
    const logbook::RadioState r = radio_now(station, logging.names, posted);
    if (t >= radio_retry_at && logbook::radio_post_due(posted, r, t)) return post_radio(r, t);
    if (!logging.book) return;
    for (const logbook::QueuedUpload& u : logging.book->upload_queue()) {
      if (u.next_try > t) continue;
      const auto q = logging.book->get(u.qso_id);
      if (!q || q->deleted) {  // deleted before it went: nothing to send
        spdlog::info("logger: QSO {} is no longer in the log; not uploaded", u.qso_id);
        logging.book->upload_done(u.qso_id);
        continue;
      }
      return post_qso(*q, u.attempts);
    }
  }

  void send(const std::string& url, std::string body, std::function<void(const download::DownloadResult&)> done) {
    download::DownloadRequest r;
    r.url = url;
    r.method = "POST";
    r.body = std::move(body);
    r.content_type = "application/json";
    r.http_errors_fail = false;
    r.total_timeout = s.timeout;
    r.connect_timeout = std::min(s.timeout, std::chrono::milliseconds(10000));
    r.max_bytes = 1u << 20;
    busy = true;
    std::weak_ptr<int> a = alive;
    downloader.submit(std::move(r), [this, a, done = std::move(done)](download::DownloadResult res) {
      boost::asio::post(io, [this, a, done, res = std::move(res)] {
        if (a.expired()) return;
        busy = false;
        done(res);
        next();
      });
    });
  }

  void post_radio(const logbook::RadioState& r, std::int64_t t) {
    send(logbook::radio_url(s.spec), logbook::radio_body(s.key, r), [this, r, t](const download::DownloadResult& res) {
      const logbook::ReplyVerdict v = res.ok ? logbook::judge_radio_reply(res.status, res.body, s.key)
                                             : logbook::ReplyVerdict{false, false, redact::secret(res.error, s.key)};
      if (v.accepted) {
        posted = logbook::RadioPosted{r, t};
        status().last_radio_post = orbit::format_iso8601(station.now());
        if (status().radio_problem) spdlog::info("logger: the radio state is posted again");
        status().radio_problem.reset();
        return;
      }
      radio_retry_at = now() + logbook::upload_backoff_s(1);
      const std::string text = "radio state not posted: " + v.message;
      if (status().radio_problem != text) spdlog::warn("logger: {}", text);
      status().radio_problem = text;
    });
  }

  void post_qso(const logbook::Qso& q, int attempts) {
    const std::int64_t id = q.id;
    const std::string who = "QSO " + std::to_string(id) + " (" + q.call + ")";
    std::vector<std::string> changed;  // fields whose '<' or '>' the logger's ADIF parser could not take
    std::string body = logbook::qso_body(s.key, s.station_id, q, &changed);
    std::string note;
    for (const std::string& f : changed) note += (note.empty() ? "" : ", ") + f;
    if (!note.empty()) note = " ('<' and '>' in " + note + " sent as '(' and ')': the logger's ADIF parser ends a record at <eor>)";
    send(logbook::qso_url(s.spec), std::move(body),
         [this, id, who, attempts, note](const download::DownloadResult& res) {
           const logbook::ReplyVerdict v = res.ok ? logbook::judge_qso_reply(s.spec.kind, res.status, res.body, s.key)
                                                  : logbook::ReplyVerdict{false, false, redact::secret(res.error, s.key)};
           if (!logging.book) return;
           if (v.accepted) {
             logging.book->upload_done(id);
             status().last_upload = orbit::format_iso8601(station.now());
             spdlog::info("logger: {} uploaded{}{}", who, v.duplicate ? " (the logger had it already)" : "", note);
             status().problem.reset();
             return;
           }
           const std::int64_t wait = logbook::upload_backoff_s(attempts + 1);
           logging.book->upload_failed(id, now() + wait, v.message);
           const std::string text = who + " not uploaded: " + v.message + "; next try in " + std::to_string(wait) + " s";
           spdlog::warn("logger: {}", text);
           status().problem = text;
         });
  }
};

LoggerUpload::LoggerUpload(StationApp& app, tracker::Logging& logging, LoggerSettings settings)
    : impl_(std::make_unique<Impl>(app.io(), app.station(), logging, std::move(settings))) {
  logging.upload = true;
  logging.on_logged = [this] { wake(); };
  impl_->tick();
}

LoggerUpload::~LoggerUpload() {
  impl_->logging.upload = false;
  impl_->logging.on_logged = nullptr;
  impl_->alive.reset();
  impl_->timer.cancel();
}

void LoggerUpload::wake() {
  std::weak_ptr<int> a = impl_->alive;
  boost::asio::post(impl_->io, [this, a] {
    if (!a.expired()) impl_->next();
  });
}

std::optional<std::string> read_logger_key(const std::string& path, std::string& key, std::string& warning) {
  const std::string where = "--logger-key-file " + path + ": ";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return where + "cannot be read (" + std::strerror(errno) + ")";
  if (!S_ISREG(st.st_mode)) return where + "is not a file";
  if (st.st_size > 4096) return where + "is larger than 4096 bytes: not a key file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return where + "cannot be read (" + std::strerror(errno) + ")";
  std::string line;
  std::getline(in, line);
  key = text::trimmed(line);
  if (key.empty()) return where + "is empty: its first line is the logger's API key";
  for (const char c : key)
    if (static_cast<unsigned char>(c) < ' ' || static_cast<unsigned char>(c) == 0x7f)
      return where + "the key has control characters";
  if (st.st_mode & (S_IRGRP | S_IROTH))
    warning = where + "others may read the logger's key (chmod 600 " + path + ")";
  return std::nullopt;
}

std::optional<std::string> start_logger(StationApp& app, tracker::Logging& logging, std::chrono::seconds timeout,
                                        std::unique_ptr<LoggerUpload>& out) {
  spdlog::logger& log = app.log();
  const store::LoggerConfig& c = app.model().logger;
  if (c.spec.empty()) return std::nullopt;
  const logbook::LoggerSpecParse p = logbook::parse_logger_spec(c.spec);
  if (!p.spec) return p.error.empty() ? std::string("--logger: the stored logger is not cloudlog:URL or wavelog:URL") : p.error;
  if (c.key_file.empty()) return std::string("--logger: the logger's key is needed: --logger-key-file FILE");
  if (c.station_id <= 0)
    return std::string("--logger: the logger's station profile is needed: --logger-station-id N (Cloudlog's "
                       "station_profile_id)");
  LoggerSettings s{*p.spec, {}, c.station_id, std::chrono::duration_cast<std::chrono::milliseconds>(timeout)};
  std::string warning;
  if (auto err = read_logger_key(c.key_file, s.key, warning)) return err;
  if (!warning.empty()) {
    log.warn("{}", warning);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", warning.c_str());
  }
  log.info("logger: {} at {}, station profile {}; {} QSO(s) waiting", logbook::logger_kind_name(p.spec->kind),
           logbook::logger_display_url(*p.spec), c.station_id,
           logging.book ? logging.book->upload_queue_length() : 0);
  out = std::make_unique<LoggerUpload>(app, logging, std::move(s));
  return std::nullopt;
}

void logger_not_started(const store::LoggerConfig& c, tracker::Logging& logging, const std::string& why,
                        spdlog::logger& log) {
  const logbook::LoggerSpecParse p = logbook::parse_logger_spec(c.spec);
  tracker::LoggerStatus st;
  st.kind = p.spec ? std::string(logbook::logger_kind_name(p.spec->kind)) : "unknown";
  st.url = p.spec ? logbook::logger_display_url(*p.spec) : "";
  st.problem = "the logger did not start: " + why + "; QSOs are kept queued until it is mended and trakbox restarted";
  logging.upload = true;  // queue what is logged meanwhile
  logging.logger = st;
  log.warn("logger: {}", *st.problem);
  std::fprintf(stderr, "trakbox: WARNING: logger: %s\n", st.problem->c_str());
}

}  // namespace tb::app
