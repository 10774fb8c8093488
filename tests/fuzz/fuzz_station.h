// What the fuzz targets share: the shipped data (parsed once per process), a whole simulated station
// (the real Tracker and StationLoop on the simulated rotator and radio, a RealTimeClock on a time
// base the target moves), a scratch directory for the process, and the splitting of an input into
// lines. Everything a target builds from its input is built fresh for each input, so that one input
// always does the same thing (libFuzzer needs that to minimise and to replay a crash).
#pragma once
#include <optional>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <spdlog/spdlog.h>

#include "orbit/elements.h"
#include "station/clock.h"
#include "store/database.h"
#include "store/model.h"
#include "support/shipped_model.h"
#include "support/sim_station.h"

#ifndef TRAKBOX_SOURCE_DIR
#error "TRAKBOX_SOURCE_DIR must name the source tree (tests/fuzz/CMakeLists.txt defines it)"
#endif

namespace tb::fuzz {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// Every module logs its decisions through spdlog's default logger: off, or the fuzzer's output
// drowns and the executions slow down.
inline const bool kQuietLog = [] {
  spdlog::set_level(spdlog::level::off);
  return true;
}();

using testing::read_file;

inline void write_file(const fs::path& p, std::string_view text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

inline std::string data_file(const char* name) { return read_file(fs::path(TRAKBOX_SOURCE_DIR) / "data" / name); }

// The shipped database (tests/support/shipped_model.h), Tucson as the station, as the unit tests'
// fixtures have it. Parsed once; each station gets a copy.
inline const store::Model& shipped_model() {
  static const store::Model m = testing::shipped_model_in_tucson();
  return m;
}

// A directory for this process under the system's temporary directory, removed at exit. Targets
// that need files (the Satrak unit's TLE and image directories) make them below it once.
inline const fs::path& scratch_dir() {
  static const fs::path dir = [] {
    const fs::path p = fs::temp_directory_path() / ("trakbox-fuzz-" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(fs::temp_directory_path() / ("trakbox-fuzz-" + std::to_string(::getpid())), ec);
    });
    return p;
  }();
  return dir;
}

// 2026-05-21 12:00:00 UTC, the unit tests' usual start; the shipped elements are recent there.
inline orbit::UtcTime start_time() { return orbit::from_civil(2026, 5, 21, 12, 0, 0); }

// The model with rotor control as asked, as the station is to start on it.
inline store::Model with_rotor_control(store::Model m, bool on) {
  m.rotor_control = on;
  return m;
}

// The whole station, as the program builds it, on simulated hardware (tests/support/sim_station.h),
// rotor control as asked and a first reading taken. Rotor control is put in the model the station
// starts on (StationLoop's constructor enables or disables the rotator from it), not switched by
// StationLoop::set_rotor_control after the start: that is a named edit, which serializes and reads
// back the whole model with its database, and it was most of the cost of a station target's input
// (a third of fuzz_menus' time). The station starts in the same state either way.
struct Station : testing::StationFixture {
  explicit Station(store::Model m = shipped_model(), bool rotor_control = true)
      : StationFixture(start_time(), with_rotor_control(std::move(m), rotor_control)) {
    build_station();
    station->tick();  // a first reading
  }

  // Time passes on the clock's base and the station ticks, as the event loop would.
  void step(std::chrono::milliseconds dt = 500ms) { StationFixture::step(dt); }
};

// The protocol targets' station (fuzz_host, fuzz_netctl), set up by the input's first byte: bit 1 set
// starts with rotor control off, bit 2 set with the tracker following the first satellite.
struct ProtocolStation : Station {
  explicit ProtocolStation(std::uint8_t mode) : Station(shipped_model(), (mode & 2) == 0) {
    if (mode & 4) tracker.track_single(0);
  }
};

// The input as lines (split at LF; a CR before it stays, the protocols deal with it), at most
// max_lines of them: a bound on the work one input can ask for.
inline std::vector<std::string_view> split_lines(std::string_view data, std::size_t max_lines) {
  std::vector<std::string_view> lines;
  while (!data.empty() && lines.size() < max_lines) {
    const std::size_t nl = data.find('\n');
    lines.push_back(data.substr(0, nl));
    if (nl == std::string_view::npos) break;
    data.remove_prefix(nl + 1);
  }
  return lines;
}

// Whether s carries no control character but those in `allowed`: what the protocol targets check of
// every reply, which goes onto a client's line.
inline bool no_control_but(std::string_view s, std::string_view allowed) {
  for (const unsigned char c : s)
    if (c < 0x20 && allowed.find(static_cast<char>(c)) == std::string_view::npos) return false;
  return true;
}

// What the protocol targets accept in a reply: host mode's lines end in CR LF; Hamlib's dump_caps
// has "Key:\tvalue" lines.
inline bool clean_host_reply(std::string_view s) { return no_control_but(s, "\r\n"); }
inline bool clean_hamlib_reply(std::string_view s) { return no_control_but(s, "\n\t"); }

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A protocol target's run: the input's first byte sets up the station and picks the variant, the
// rest is the lines. No station (false) for an empty input.
struct ProtocolRun {
  ProtocolRun(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    mode = data[0];
    input = as_text(data + 1, size - 1);
    st.emplace(mode);
  }
  explicit operator bool() const { return st.has_value(); }
  std::uint8_t mode = 0;
  std::string_view input;
  std::optional<ProtocolStation> st;
};

// A property a target checks beyond "no crash": a violation is reported and aborts, so libFuzzer
// keeps the input as a crash.
[[noreturn]] inline void violated(const char* what, std::string_view detail = {}) {
  std::fprintf(stderr, "\n*** fuzz property violated: %s\n%.*s\n", what, static_cast<int>(detail.size()),
               detail.data());
  std::abort();
}
#define TB_FUZZ_CHECK(cond, detail) \
  do {                              \
    if (!(cond)) ::tb::fuzz::violated(#cond, (detail)); \
  } while (0)

inline bool same_elements(const orbit::Elements& a, const orbit::Elements& b) {
  return a.name == b.name && a.catalog_number == b.catalog_number && a.classification == b.classification &&
         a.international_designator == b.international_designator && a.epoch_year == b.epoch_year &&
         a.epoch_day == b.epoch_day && a.ndot_over_2 == b.ndot_over_2 && a.nddot_over_6 == b.nddot_over_6 &&
         a.bstar == b.bstar && a.ephemeris_type == b.ephemeris_type && a.element_set_number == b.element_set_number &&
         a.inclination_deg == b.inclination_deg && a.raan_deg == b.raan_deg && a.eccentricity == b.eccentricity &&
         a.arg_perigee_deg == b.arg_perigee_deg && a.mean_anomaly_deg == b.mean_anomaly_deg &&
         a.mean_motion_rev_per_day == b.mean_motion_rev_per_day && a.revolution_number == b.revolution_number &&
         a.source == b.source;
}

inline bool same_database(const store::Database& a, const store::Database& b) {
  if (a.selected != b.selected || a.marked != b.marked || a.multi_count != b.multi_count ||
      a.satellites.size() != b.satellites.size())
    return false;
  for (std::size_t i = 0; i < a.satellites.size(); ++i)
    if (!(a.satellites[i].radio == b.satellites[i].radio) ||
        !same_elements(a.satellites[i].elements, b.satellites[i].elements))
      return false;
  return true;
}

// Whether two databases store the same: every field store::to_json writes of them (the elements,
// the working radio record, the modes and the chosen one, the tracking list). Doubles compare with
// ==, as same_elements does.
inline bool same_stored_database(const store::Database& a, const store::Database& b) {
  if (a.selected != b.selected || a.marked != b.marked || a.multi_count != b.multi_count ||
      a.satellites.size() != b.satellites.size())
    return false;
  for (std::size_t i = 0; i < a.satellites.size(); ++i) {
    const store::Satellite& x = a.satellites[i];
    const store::Satellite& y = b.satellites[i];
    if (!(x.radio == y.radio) || x.modes != y.modes || x.mode != y.mode || !same_elements(x.elements, y.elements))
      return false;
  }
  return true;
}

// What every target that drives a station checks at the end: the model it left is one the state
// file reads back (the program saves it; a value the reader refuses loses the whole state at the
// next start). The shipped database, when the input left it alone, is checked once, not every time:
// its JSON is most of the cost of the check, and of a whole run of a station target.
inline void check_model_reads_back(const store::Model& m, std::string_view input) {
  auto check = [&](const store::Model& model) {
    const nlohmann::json saved = store::to_json(model);
    try {
      const store::Model back = store::model_from_json(saved);
      TB_FUZZ_CHECK(store::to_json(back) == saved, input);
    } catch (const std::exception& e) {
      violated("the model left behind does not read back", std::string(e.what()) + "\n" + std::string(input));
    }
  };
  static const bool shipped_ok = (check(shipped_model()), true);
  (void)shipped_ok;
  if (!same_stored_database(m.db, shipped_model().db)) return check(m);
  store::Model without_db = m;
  without_db.db = store::Database{};
  check(without_db);
}

}  // namespace tb::fuzz
