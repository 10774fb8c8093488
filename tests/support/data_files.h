// The test data files of the source tree (tests/data/...), read whole. A missing file throws, which
// fails the test case that asked for it with the file's name.
#pragma once
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "test_paths.h"  // TRAKBOX_SOURCE_DIR

namespace tb::testing {

inline std::string read_test_data(const std::string& relative) {
  const std::string path = std::string(TRAKBOX_SOURCE_DIR "/tests/data/") + relative;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("test data file missing: " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace tb::testing
