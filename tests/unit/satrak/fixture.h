// A whole simulated station with a Satrak unit on it, for the Satrak tests: the shipped database,
// a station in Tucson, the simulated rotator and radio, a RealTimeClock running on a time base the
// test moves by hand, and a TLE directory holding the shipped elements as amateur.txt.
#pragma once
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "orbit/passes.h"
#include "radio/simulated.h"
#include "rotator/simulated.h"
#include "rotator/satrak/commands.h"
#include "satrak/unit.h"
#include "support/shipped_model.h"
#include "support/sim_station.h"
#include "tracker/station_loop.h"

namespace satrak_test {
using namespace tb;
using namespace std::chrono_literals;
using satrak::Error;
namespace fs = std::filesystem;

// The unit logs every decision; the tests check them through the protocol instead.
inline const bool kQuietLog = [] {
  spdlog::set_level(spdlog::level::off);
  return true;
}();

using tb::testing::read_file;

inline void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
}

// A fresh directory under the system's temporary directory, removed afterwards.
struct TempDir {
  TempDir() {
    static int n = 0;
    path = fs::temp_directory_path() / ("trakbox-satrak-" + std::to_string(::getpid()) + "-" + std::to_string(++n));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  fs::path path;
};

inline store::Model tucson_model() {
  store::Model m = testing::shipped_model_in_tucson();
  m.station.rotor_start = station::RotorStart::north;
  m.rotor_control = true;
  return m;
}

// The first ISS pass from Tucson after t whose maximum lies between the bounds.
inline orbit::Pass iss_pass(const store::Model& m, orbit::UtcTime t, double min_max_el, double max_max_el = 90.0) {
  const auto sets = orbit::parse_nasa(read_file(TRAKBOX_SOURCE_DIR "/data/amateur.tle"), "amateur.tle");
  const orbit::Elements* iss = nullptr;
  for (const auto& e : sets.sets)
    if (e.name == "ISS") iss = &e;
  REQUIRE(iss);
  const orbit::Sgp4 sgp4(*iss);
  for (const auto& p : orbit::find_passes(sgp4, m.station.observer(), t, orbit::add_minutes(t, 3 * 1440.0))) {
    if (p.up_at_start) continue;
    if (p.max_el_deg < min_max_el || p.max_el_deg > max_max_el) continue;
    // Clear of north, the stop of the north-start rotator the tests use (a pass across the stop
    // is held there by the pass planner, by design).
    bool near_stop = false;
    for (double f = 0.0; f <= 1.0; f += 0.01) {
      const auto o = orbit::observe(sgp4, m.station.observer(),
                                    orbit::add_minutes(p.aos, f * orbit::minutes_between(p.aos, p.los)));
      const double az = o.look.az_deg;
      if (o.look.el_deg > -3.0 && (az < 15.0 || az > 345.0)) near_stop = true;
    }
    if (!near_stop) return p;
  }
  FAIL("no ISS pass found");
  return {};
}

inline orbit::Elements iss_elements() {
  const auto sets = orbit::parse_nasa(read_file(TRAKBOX_SOURCE_DIR "/data/amateur.tle"), "amateur.tle");
  for (const auto& e : sets.sets)
    if (e.name == "ISS") return e;
  FAIL("no ISS in the shipped data");
  return {};
}

inline double angle_diff(double a, double b) {
  double d = std::fmod(std::abs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

struct Acu {
  explicit Acu(orbit::UtcTime t0, satrak::Settings settings = {}, store::Model m = tucson_model())
      : base(t0), clock([this] { return base; }), owner(std::move(m)), tracker(model, clock) {
    tb::testing::SimulatedStation sim = tb::testing::simulated_station(owner, clock, tracker);
    rot = sim.rotator;
    loop = std::move(sim.loop);
    fs::create_directories(dir.path / "tle");
    fs::create_directories(dir.path / "images");
    fs::copy_file(TRAKBOX_SOURCE_DIR "/data/amateur.tle", dir.path / "tle" / "amateur.txt");
    loop->tick();
    make_unit(std::move(settings));
  }
  void make_unit(satrak::Settings settings) {
    unit.reset();
    satrak::UnitOptions o;
    o.tle_dir = dir.path / "tle";
    o.image_dir = dir.path / "images";
    o.version = "9.9.9";
    o.file_check = std::chrono::seconds(1);
    o.retry_after = std::chrono::seconds(60);
    o.download_timeout = std::chrono::milliseconds(5000);
    unit = std::make_unique<satrak::Unit>(io, *loop, model, clock, std::move(settings), o, satrak::UnitHooks{[this]() -> std::optional<std::string> {
      ++saves;
      return save_error;
    }});
  }

  std::string cmd(std::string_view payload) { return unit->handle(payload); }
  std::vector<std::string> fields(std::string_view payload) {
    const auto r = satrak::parse_payload(cmd(payload));
    REQUIRE(r);
    return r->fields;
  }
  // STATUS? field Xn (1-based), as the seed numbers them.
  std::string status(int n) { return fields("STATUS?").at(static_cast<std::size_t>(n - 1)); }
  double status_num(int n) { return std::stod(status(n)); }
  std::string errstatus(int n) { return fields("ERRSTATUS?").at(static_cast<std::size_t>(n - 1)); }

  // Time passes: the station and the unit tick every `dt`.
  void step(std::chrono::milliseconds dt = std::chrono::milliseconds(100)) {
    base += dt;
    loop->tick();
    unit->tick();
  }
  void run(std::chrono::milliseconds total, std::chrono::milliseconds dt = std::chrono::milliseconds(100)) {
    for (auto t = std::chrono::milliseconds(0); t < total; t += dt) step(dt);
  }
  void run_until(orbit::UtcTime t, std::chrono::milliseconds dt = std::chrono::milliseconds(100)) {
    while (clock.now() < t) step(dt);
  }
  const rotator::Status& rs() const { return loop->rotator().status(); }

  TempDir dir;
  orbit::UtcTime base;
  station::RealTimeClock clock;
  store::ModelOwner owner;
  store::Model& model = tb::testing::setup_model(owner);  // the test's hand on it for setting up
  tracker::Tracker tracker;
  rotator::SimulatedRotator* rot = nullptr;
  std::unique_ptr<tracker::StationLoop> loop;
  boost::asio::io_context io;
  std::unique_ptr<satrak::Unit> unit;
  int saves = 0;
  std::optional<std::string> save_error;  // what the next saves report (nullopt: they succeed)
};

// The scripted sessions' start (an ISS pass over the Tucson station follows within the hour).
inline const orbit::UtcTime kT0 = orbit::from_civil(2026, 5, 21, 12, 0, 0);

// A refusal as the unit answers it: "HEAD,ERR,CODE".
inline std::string err(std::string head, satrak::Error e) { return satrak::reply_error(head, e); }

// A time as TIME? and START_STOP_TIME? give it: H,M,S,D,Mo,Y.
inline std::string civil(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  return std::to_string(c.hour) + "," + std::to_string(c.minute) + "," + std::to_string(static_cast<int>(c.second)) + "," +
         std::to_string(c.day) + "," + std::to_string(c.month) + "," + std::to_string(c.year);
}

inline orbit::UtcTime whole_seconds(orbit::UtcTime t) { return std::chrono::floor<std::chrono::seconds>(t); }

// Where the ISS is from the model's station at t.
inline orbit::Observation iss_at(const store::Model& m, orbit::UtcTime t) {
  static const orbit::Sgp4 sgp4(iss_elements());
  return orbit::observe(sgp4, m.station.observer(), t);
}

}  // namespace satrak_test
