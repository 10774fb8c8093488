// One line of Vallado's test output (testcpp.cpp, tcppver.out): minutes from epoch, position (km)
// and velocity (km/s) in TEME, as " %16.8f %16.8f %16.8f %16.8f %12.9f %12.9f %12.9f\n". The
// `propagate` command writes it; the benchmark BM_PropagateLine* compares it with printf.
#pragma once
#include <string>

#include "orbit/sgp4.h"
#include "util/text.h"

namespace tb::orbit {

// Appends the line to `out`, the same characters printf gives (util/text.h append_fixed).
inline void append_state_line(std::string& out, double tsince_min, const StateVector& s) {
  out += ' ';
  text::append_fixed(out, tsince_min, 16, 8);
  for (double r : s.r_km) {
    out += ' ';
    text::append_fixed(out, r, 16, 8);
  }
  for (double v : s.v_km_s) {
    out += ' ';
    text::append_fixed(out, v, 12, 9);
  }
  out += '\n';
}

}  // namespace tb::orbit
