// The problems of a station-file parse as text, one a line: what the station-file tests print
// when a parse they expect to succeed does not.
#pragma once
#include <string>
#include <tuple>

#include "store/station_file.h"

namespace tb::testing {

inline std::string problems_text(const store::StationFileParse& r) {
  std::string s;
  for (const auto& p : r.problems) s += p.message() + "\n";
  return s;
}

// A rotator configuration's limits (menu 6-4, line 5 or 7 of a station file) as one value.
inline auto limits_of(const rotator::RotatorConfig& r) {
  return std::tuple(r.limits_enabled, r.az_limit_min, r.az_limit_max, r.el_limit_min, r.el_limit_max);
}

}  // namespace tb::testing
