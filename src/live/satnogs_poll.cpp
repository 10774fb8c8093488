#include "live/satnogs_poll.h"

#include <cstdio>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <spdlog/spdlog.h>

#include "live/station_app.h"
#include "download/download.h"
#include "store/model.h"
#include "tracker/satnogs_jobs.h"
#include "tracker/station_loop.h"

namespace tb::app {

struct SatnogsPoll::Impl {
  boost::asio::io_context& io;
  tracker::StationLoop& station;
  std::string url;
  int station_id = 0;
  std::chrono::milliseconds timeout;
  boost::asio::steady_timer timer{io};
  download::Downloader downloader;
  std::shared_ptr<int> alive = std::make_shared<int>(0);
  std::optional<std::string> problem;
  std::string last_poll;
  std::size_t jobs = 0;

  Impl(boost::asio::io_context& i, tracker::StationLoop& s, std::string u, int id, std::chrono::milliseconds t)
      : io(i), station(s), url(tracker::satnogs_jobs_url(u, id)), station_id(id), timeout(t) {}

  void poll() {
    download::DownloadRequest r;
    r.url = url;  // anonymous: no user, no token, no Authorization header
    r.total_timeout = timeout;
    r.connect_timeout = std::min(timeout, std::chrono::milliseconds(10000));
    r.max_bytes = 1u << 20;
    std::weak_ptr<int> a = alive;
    downloader.submit(std::move(r), [this, a](download::DownloadResult res) {
      boost::asio::post(io, [this, a, res = std::move(res)] {
        if (!a.expired()) finished(res);
      });
    });
    timer.expires_after(std::chrono::seconds(tracker::kSatnogsPollSeconds));
    timer.async_wait([this, a](const boost::system::error_code& ec) {
      if (!ec && !a.expired()) poll();
    });
  }

  void finished(const download::DownloadResult& res) {
    const orbit::UtcTime now = station.now();
    last_poll = orbit::format_iso8601(now);
    if (!res.ok) {
      fail(res.error);
      return;
    }
    if (res.status != 200) {
      fail("HTTP " + std::to_string(res.status));
      return;
    }
    tracker::SatnogsJobs jobs = tracker::parse_satnogs_jobs(res.body, now);
    if (jobs.error) {
      fail(*jobs.error);
      return;
    }
    if (problem) spdlog::info("satnogs: {} answers again", url);
    problem.reset();
    jobs_count(jobs.windows.size());
    station.set_satnogs_windows(std::move(jobs.windows));
    publish();
  }

  void publish() { station.set_satnogs_state({station_id, url, jobs, last_poll, problem}); }

  void jobs_count(std::size_t n) {
    if (n != jobs) spdlog::info("satnogs: station {}: {} upcoming observation(s)", station_id, n);
    jobs = n;
  }

  void fail(const std::string& why) {
    const std::string text = "SatNOGS jobs of station " + std::to_string(station_id) + ": " + why +
                             " (the last good list is kept)";
    if (problem != text) spdlog::warn("satnogs: {}", text);
    problem = text;
    publish();
  }
};

SatnogsPoll::SatnogsPoll(boost::asio::io_context& io, tracker::StationLoop& station, std::string base_url,
                         int station_id, std::chrono::milliseconds timeout)
    : impl_(std::make_unique<Impl>(io, station, std::move(base_url), station_id, timeout)) {
  impl_->publish();
  impl_->poll();
}

SatnogsPoll::~SatnogsPoll() {
  impl_->alive.reset();
  impl_->timer.cancel();
}

// --satnogs-station: the station's SatNOGS calendar (live/satnogs_poll.h), and the warning when the
// SatNOGS flowgraph's rigctl port (4532) is trakbox's rigctld's too.
std::unique_ptr<SatnogsPoll> start_satnogs(StationApp& app, std::optional<int> rigctld_port,
                                           std::chrono::seconds timeout, spdlog::logger& log) {
  const store::Sharing& sh = app.model().sharing;
  if (sh.satnogs_station <= 0) return nullptr;
  if (rigctld_port && *rigctld_port == 4532) {
    const char* why = "--rigctld-port 4532 with --satnogs-station: the SatNOGS flowgraph listens for Doppler on "
                      "4532 too; give trakbox's rigctld another port (docs/sharing.md)";
    log.warn("{}", why);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", why);
  }
  log.info("satnogs: reading the jobs of station {} every {} minutes", sh.satnogs_station,
           tracker::kSatnogsPollSeconds / 60);
  if (const std::string& u = sh.satnogs_url; u.find('@') != std::string::npos &&
                                              u.find('@') < u.find_first_of("/?#", u.find("://") + 3)) {
    const char* why = "--satnogs-url: the user and password in the URL are not used: the jobs are read anonymously "
                      "(docs/security.md)";
    log.warn("{}", why);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", why);
  }
  return std::make_unique<SatnogsPoll>(app.io(), app.station(),
                                       sh.satnogs_url.empty() ? tracker::kSatnogsNetworkUrl : sh.satnogs_url,
                                       sh.satnogs_station, timeout);
}

}  // namespace tb::app
