// The problems of a station-file parse as text, one a line: what the station-file tests print
// when a parse they expect to succeed does not.
#pragma once
#include <string>

#include "store/station_file.h"

namespace tb::testing {

inline std::string problems_text(const store::StationFileParse& r) {
  std::string s;
  for (const auto& p : r.problems) s += p.message() + "\n";
  return s;
}

}  // namespace tb::testing
