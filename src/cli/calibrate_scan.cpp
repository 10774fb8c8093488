// The sun-noise scan from the command line (cli/calibrate_scan.h).
#include "cli/calibrate_scan.h"

#include <netdb.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/attach_client.h"
#include "cli/options.h"
#include "orbit/sky.h"
#include "rotator/adc_model.h"
#include "util/json_limits.h"
#include "util/text.h"

namespace tb::app {
namespace {

using nlohmann::json;

constexpr const char* kHolder = "sun scan";  // live/station_command.cpp's scan_goto

// A receiver's level over its TCP remote control: "l STRENGTH" answers a number (dBFS for GQRX, dB
// over S9 for rigctld). Blocking, with a 3 s timeout each way.
class LevelReader {
 public:
  explicit LevelReader(const std::string& spec) {
    const auto f = text::split(spec, ':');
    coarse_ = !f.empty() && f[0] == "rigctld";
    if (f.size() != 3 || (f[0] != "gqrx" && !coarse_)) {
      error_ = "--receiver '" + spec + "': expected gqrx:HOST:PORT or rigctld:HOST:PORT";
      return;
    }
    connect(std::string(f[1]), std::string(f[2]));
  }
  ~LevelReader() {
    if (fd_ >= 0) ::close(fd_);
  }
  LevelReader(const LevelReader&) = delete;
  LevelReader& operator=(const LevelReader&) = delete;
  const std::string& error() const { return error_; }
  bool coarse() const { return coarse_; }

  std::optional<double> level() {
    const std::string ask = "l STRENGTH\n";
    if (::send(fd_, ask.data(), ask.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(ask.size())) return fail("send");
    std::string line;
    char c = 0;
    while (line.size() < 64) {
      if (::recv(fd_, &c, 1, 0) != 1) return fail("no answer");
      if (c == '\n') break;
      line += c;
    }
    const auto v = text::parse_double(text::trim(line, text::kWhitespace));
    if (!v) return fail("answered '" + line + "', not a level");
    return v;
  }

 private:
  void connect(const std::string& host, const std::string& port) {
    addrinfo hints{};
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (::getaddrinfo(host.c_str(), port.c_str(), &hints, &found) != 0 || !found) {
      error_ = "the receiver " + host + ":" + port + ": no such address";
      return;
    }
    fd_ = ::socket(found->ai_family, found->ai_socktype, found->ai_protocol);
    timeval tv{3, 0};
    if (fd_ >= 0) {
      ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
      ::setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    }
    if (fd_ < 0 || ::connect(fd_, found->ai_addr, found->ai_addrlen) != 0)
      error_ = "the receiver " + host + ":" + port + " does not answer (GQRX: Tools > Remote control)";
    ::freeaddrinfo(found);
  }
  std::nullopt_t fail(const std::string& why) {
    error_ = "the receiver: " + why;
    return std::nullopt;
  }
  int fd_ = -1;
  bool coarse_ = false;
  std::string error_;
};

// The station, asked through its socket.
struct Station {
  std::string socket;
  std::string error;

  std::optional<json> status() {
    bool not_running = false;
    const auto text = station_request(socket, "calibrate", "status", not_running);
    std::string why;
    json doc = text ? json_limits::parse_bounded<json>(*text, why) : json();
    if (!doc.is_object() || !doc.contains("antenna")) {
      error = "no status from the station at " + socket;
      return std::nullopt;
    }
    return doc;
  }
  std::optional<std::string> ask(const std::string& line) {
    bool not_running = false;
    auto answer = station_request(socket, "calibrate", line, not_running);
    if (!answer) error = "the station at " + socket + " does not answer";
    return answer;
  }
};

orbit::UtcTime time_of(const json& st) { return orbit::parse_iso8601(st.at("time").get<std::string>()).value(); }

orbit::Observer observer_of(const json& st) {
  const json& s = st.at("station");
  return {s.at("lat_deg").get<double>(), s.at("lon_deg").get<double>(), s.at("height_m").get<double>()};
}

// Why the scan must stop now (standby, another holder), or nothing.
std::optional<std::string> interrupted(const json& st, bool moved) {
  if (st.value("standby", false)) return "standby";
  if (!moved) return std::nullopt;
  const std::string label = st.at("control").at("antenna").at("label").get<std::string>();
  if (label != kHolder) return "the antenna was taken (" + label + ": a Stop, a move or a client)";
  return std::nullopt;
}

struct Scan {
  SunScanRequest req;
  Station station;
  LevelReader receiver;
  orbit::Observer where;
  std::vector<rotator::ScanSample> samples;
  int skipped = 0;
  orbit::UtcTime first{}, last{};
  std::string stopped;  // why the scan ended early

  explicit Scan(const SunScanRequest& r) : req(r), station{r.socket, ""}, receiver(r.receiver) {}

  // Sends the antenna to the point; false when it must stop (stopped says why) or the limits moved
  // the point (skipped).
  bool go(const rotator::ScanPoint& p, bool& skip) {
    const auto st = station.status();
    if (!st) return fail(station.error);
    if (const auto why = interrupted(*st, !samples.empty() || skipped > 0)) return fail(*why);
    const orbit::LookAngles sun = orbit::body_look(orbit::Body::sun, where, time_of(*st));
    if (sun.el_deg < 2.0) return fail(fmt::format("the Sun is at {:.1f} deg elevation", sun.el_deg));
    const rotator::AzEl want = rotator::scan_target({sun.az_deg, sun.el_deg}, p);
    const auto answer = station.ask(fmt::format("calibrate goto {:.4f} {:.4f}", want.az, want.el));
    if (!answer) return fail(station.error);
    double az = 0.0, el = 0.0;
    if (std::sscanf(answer->c_str(), "ok: commanded %lf %lf", &az, &el) != 2) return fail(*answer);
    skip = rotator::azimuth_distance(az, want.az) > 0.01 || std::abs(el - want.el) > 0.01;
    return true;
  }

  // Waits for the rotator to arrive and settle; false when it must stop.
  bool arrive() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    std::optional<orbit::UtcTime> arrived;
    while (std::chrono::steady_clock::now() < deadline) {
      const auto st = station.status();
      if (!st) return fail(station.error);
      if (const auto why = interrupted(*st, true)) return fail(*why);
      const bool there = st->at("antenna").value("on_target", false);
      if (there && !arrived) arrived = time_of(*st);
      if (!there) arrived.reset();
      if (arrived && orbit::minutes_between(*arrived, time_of(*st)) * 60.0 >= req.settle_s) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return fail("the rotator did not arrive within 2 minutes");
  }

  // The levels there, and the reading and the Sun at that moment.
  bool sample() {
    std::vector<double> levels;
    for (int k = 0; k < req.readings; ++k) {
      const auto v = receiver.level();
      if (!v) return fail(receiver.error());
      levels.push_back(*v);
    }
    const auto st = station.status();
    if (!st) return fail(station.error);
    const json& pos = st->at("antenna").at("position");
    if (pos.is_null()) return fail("the rotator's position is not known");
    const orbit::UtcTime t = time_of(*st);
    const orbit::LookAngles sun = orbit::body_look(orbit::Body::sun, where, t);
    samples.push_back({{pos.at("az_deg").get<double>(), pos.at("el_deg").get<double>()},
                       {sun.az_deg, sun.el_deg},
                       rotator::average_level_db(levels)});
    last = t;
    return true;
  }

  bool fail(const std::string& why) {
    stopped = why;
    return false;
  }
};

int report(Scan& s, const rotator::ScanFit& fit) {
  const double seconds = orbit::minutes_between(s.first, s.last) * 60.0;
  std::printf("sun scan: %zu points (%d skipped at the limits), %d used by the fit, %.0f s of station time\n",
              s.samples.size(), s.skipped, fit.points_used, seconds);
  std::printf("  peak at %+.2f / %+.2f deg from the computed Sun (cross-elevation / elevation)\n", fit.peak_x_deg,
              fit.peak_y_deg);
  std::printf("  correction az %+.2f el %+.2f deg\n", fit.correction.az_deg, fit.correction.el_deg);
  std::printf("  Sun noise %.2f dB over cold sky (%.1f%s); -3 dB beamwidth %.2f x %.2f deg; fit rms %.2f dB\n",
              fit.peak_over_cold_db, fit.cold_sky_db, s.receiver.coarse() ? " dB, rigctld's S-meter: coarse" : " dBFS",
              fit.beamwidth_x_deg, fit.beamwidth_y_deg, fit.rms_db);
  if (!s.req.store) {
    std::printf("not stored: run again with --store, or peak the antenna there and trakbox calibrate sun\n");
    return kExitOk;
  }
  const auto answer = s.station.ask(fmt::format("calibrate store-scan {} {:.6f} {:.6f}", orbit::format_iso8601(s.last),
                                                fit.correction.az_deg, fit.correction.el_deg));
  if (!answer) return kExitFailure;
  const bool ok = answer->rfind("ok:", 0) == 0;
  std::fputs((*answer + "\n").c_str(), ok ? stdout : stderr);
  return ok ? kExitOk : kExitFailure;
}

}  // namespace

int run_sun_scan(const SunScanRequest& request) {
  const rotator::ScanPattern plan = rotator::scan_pattern(request.shape, 2.0 * request.beam_deg, request.beam_deg / 4.0);
  if (!plan.ok()) {
    std::fprintf(stderr, "trakbox calibrate: --beam %g: %s\n", request.beam_deg, plan.error.c_str());
    return kExitUsage;
  }
  Scan s(request);
  if (!s.receiver.error().empty()) {
    std::fprintf(stderr, "trakbox calibrate: %s\n", s.receiver.error().c_str());
    return kExitFailure;
  }
  const auto st = s.station.status();
  if (!st) {
    std::fprintf(stderr, "trakbox calibrate: %s (the scan needs the running station)\n", s.station.error.c_str());
    return kExitFailure;
  }
  s.where = observer_of(*st);
  s.first = time_of(*st);
  for (const rotator::ScanPoint& p : plan.points) {
    bool skip = false;
    if (!s.go(p, skip)) break;
    if (skip) {
      ++s.skipped;
      continue;
    }
    if (!s.arrive() || !s.sample()) break;
  }
  if (!s.stopped.empty()) {
    std::fprintf(stderr, "trakbox calibrate: the scan stopped after %zu points: %s; nothing stored\n", s.samples.size(),
                 s.stopped.c_str());
    return kExitFailure;
  }
  const rotator::ScanFit fit = rotator::fit_scan(s.samples);
  if (!fit.ok()) {
    std::fprintf(stderr, "trakbox calibrate: no fit from %zu points: %s; nothing stored\n", s.samples.size(),
                 fit.error.c_str());
    return kExitFailure;
  }
  return report(s, fit);
}

}  // namespace tb::app
