// The test data files of the source tree (tests/data/...), read whole. A missing file throws, which
// fails the test case that asked for it with the file's name.
#pragma once
#include <stdexcept>
#include <string>

#include "test_paths.h"  // TRAKBOX_SOURCE_DIR
#include "util/files.h"

namespace tb::testing {

inline std::string read_test_data(const std::string& relative) {
  const std::string path = std::string(TRAKBOX_SOURCE_DIR "/tests/data/") + relative;
  auto text = files::read_whole_file(path);
  if (!text) throw std::runtime_error("test data file missing: " + path);
  return std::move(*text);
}

}  // namespace tb::testing
