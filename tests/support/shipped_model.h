// The data trakbox ships (data/amateur.tle and data/freqmode.txt) as a factory-default Model, for the
// tests that need a whole station with real satellites. Header-only; the including test program
// links tb_store (and what it pulls in) and defines TRAKBOX_SOURCE_DIR (tests/CMakeLists.txt).
#pragma once
#include <filesystem>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...
#include <fstream>
#include <sstream>
#include <string>

#include "orbit/elements.h"
#include "radio/freqmode.h"
#include "store/database.h"
#include "store/model.h"

namespace tb::testing {

// A whole file as it is (empty when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Factory defaults with the shipped database.
inline store::Model shipped_model() {
  store::Model m;
  const std::string dir = TRAKBOX_SOURCE_DIR "/data/";
  const auto sets = orbit::parse_nasa(read_file(dir + "amateur.tle"), "amateur.tle");
  const auto fm = radio::parse_freqmode(read_file(dir + "freqmode.txt"));
  m.db = store::make_database(sets.sets, fm.records);
  return m;
}

// The same with the station in Tucson (32.259 N, 110.778 W, 842 m), the manual's sample station.
inline store::Model shipped_model_in_tucson() {
  store::Model m = shipped_model();
  m.station.lat_deg = 32.259;
  m.station.lon_deg = -110.778;
  m.station.height_m = 842.0;
  return m;
}

}  // namespace tb::testing
