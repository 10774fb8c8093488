#include "gps/gpsd_client.h"

#include <gps.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>

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
    : endpoint_(std::move(endpoint)), post_(std::move(post)), sink_(std::move(sink)) {
  thread_ = std::thread([this] { run(); });
}

GpsdClient::~GpsdClient() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void GpsdClient::pause(int ms) const {
  for (int waited = 0; waited < ms && !stop_; waited += 50) std::this_thread::sleep_for(std::chrono::milliseconds(50));
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
    errno = 0;
    if (!gps_waiting(&data, 250000)) {
      if (errno != 0 && errno != EINTR && errno != EAGAIN) break;
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
