#include "gps/gpsd_client.h"

#include <gps.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <thread>

#include "util/text.h"

namespace tb::gps {

std::optional<GpsdEndpoint> parse_gps_spec(const std::string& spec, std::string& error) {
  const auto parts = text::split(spec, ':');
  if (parts.empty() || parts[0] != "gpsd" || parts.size() > 3) {
    error = "expected gpsd, gpsd:HOST or gpsd:HOST:PORT; found '" + spec + "'";
    return std::nullopt;
  }
  GpsdEndpoint e;
  if (parts.size() >= 2) {
    if (parts[1].empty()) {
      error = "the host is empty in '" + spec + "'";
      return std::nullopt;
    }
    e.host = std::string(parts[1]);
  }
  if (parts.size() == 3) {
    const auto port = text::parse_integer<int>(parts[2]);
    if (!port || *port < 1 || *port > 65535) {
      error = "expected a TCP port 1 to 65535 after the host; found '" + std::string(parts[2]) + "'";
      return std::nullopt;
    }
    e.port = std::to_string(*port);
  }
  return e;
}

GpsdClient::GpsdClient(GpsdEndpoint endpoint, Post post, Sink sink)
    : endpoint_(std::move(endpoint)), post_(std::move(post)), sink_(std::move(sink)),
      wake_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  thread_ = std::thread([this] { run(); });
}

GpsdClient::~GpsdClient() {
  stop_ = true;
  const std::uint64_t one = 1;
  if (wake_ >= 0 && ::write(wake_, &one, sizeof one) < 0) {
    // cannot happen with a fresh eventfd; the thread's waits still end within their bounds
  }
  if (thread_.joinable()) thread_.join();
  if (wake_ >= 0) ::close(wake_);
}

// The thread sleeps in the kernel until its deadline or the stop, never in slices.
void GpsdClient::pause(int ms) const {
  if (wake_ < 0) {  // no eventfd (out of descriptors): the pause as one sleep
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    return;
  }
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (!stop_) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - std::chrono::steady_clock::now()).count();
    if (left <= 0) return;
    pollfd p{wake_, POLLIN, 0};
    ::poll(&p, 1, static_cast<int>(left));
  }
}

bool GpsdClient::wait_input(int gps_fd) const {
  pollfd p[2] = {{gps_fd, POLLIN, 0}, {wake_, POLLIN, 0}};
  while (!stop_) {
    if (::poll(p, wake_ >= 0 ? 2 : 1, wake_ >= 0 ? -1 : 1000) > 0 && (p[0].revents != 0)) return true;
  }
  return false;
}

void GpsdClient::run() {
  post_([s = sink_] { s.link(Link::connecting, {}); });
  while (!stop_) {
    // What gpsd sends is outside input: nothing it sends may end the station (issue 38). A session
    // that throws is a lost link, tried again like any other.
    try {
      if (!session()) return;
    } catch (const std::exception& e) {
      post_([s = sink_, why = std::string(e.what())] { s.link(Link::lost, why); });
    }
    pause(2000);
  }
}

namespace {
Report report_of(const gps_fix_t& f) {
  Report r;
  r.mode = f.mode;
  if (f.mode >= MODE_2D) {
    if (std::isfinite(f.latitude)) r.lat_deg = f.latitude;
    if (std::isfinite(f.longitude)) r.lon_deg = f.longitude;
  }
  if (f.mode >= MODE_3D) {
    if (std::isfinite(f.altHAE)) r.alt_m = f.altHAE;
    else if (std::isfinite(f.altMSL)) r.alt_m = f.altMSL;
  }
  if (f.time.tv_sec > 0)
    r.time = orbit::UtcTime(std::chrono::seconds(f.time.tv_sec) +
                            std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::nanoseconds(f.time.tv_nsec)));
  return r;
}
}  // namespace

bool GpsdClient::session() {
  gps_data_t data{};
  if (gps_open(endpoint_.host.c_str(), endpoint_.port.c_str(), &data) != 0) {
    const std::string why = gps_errstr(errno);
    post_([s = sink_, why] { s.link(Link::no_gpsd, why); });
    return !stop_;
  }
  gps_stream(&data, WATCH_ENABLE | WATCH_JSON, nullptr);
  post_([s = sink_] { s.link(Link::receiving, {}); });
  char message[4096];
  while (!stop_) {
    // What libgps holds already, else one wait in the kernel for gpsd's bytes or the stop.
    errno = 0;
    if (!gps_waiting(&data, 0)) {
      if (errno != 0 && errno != EINTR && errno != EAGAIN) break;
      if (!wait_input(data.gps_fd)) break;
      continue;
    }
    message[0] = '\0';
    if (gps_read(&data, message, sizeof message) < 0) break;
    if (std::strstr(message, "\"class\":\"TPV\"") && (data.set & MODE_SET)) {
      post_([s = sink_, r = report_of(data.fix)] { s.report(r); });
    } else if (std::strstr(message, "\"class\":\"DEVICES\"")) {
      post_([s = sink_, n = data.devices.ndevices] { s.devices(n); });
    } else if (std::strstr(message, "\"class\":\"DEVICE\"") && std::strstr(message, "\"activated\":0")) {
      post_([s = sink_] { s.devices(0); });
    } else if (std::strstr(message, "\"class\":\"DEVICE\"")) {
      post_([s = sink_] { s.devices(1); });
    }
  }
  gps_stream(&data, WATCH_DISABLE, nullptr);
  gps_close(&data);
  if (stop_) return false;
  post_([s = sink_] { s.link(Link::lost, "connection closed"); });
  return true;
}

}  // namespace tb::gps
