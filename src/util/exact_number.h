// A number as a refusal quotes it (issue 46): the shortest text that reads back as the same double
// (std::to_chars), so 90.0000001 is refused as "90.0000001", never as %g's "90"; -0 is "0". And
// "AZ12.3 EL0.0", one decimal, with no "-0.0" for a value that rounds to zero.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace tb::text {

inline std::string exact_number(double v) {
  if (v == 0.0) return "0";  // -0 too
  char buf[40];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

// One decimal, a value that rounds to 0.0 (-0.04, -0) printed as 0.0.
inline std::string one_decimal(double v) {
  if (std::fabs(v) < 0.05) v = 0.0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

inline std::string az_el_text(double az, double el) { return "AZ" + one_decimal(az) + " EL" + one_decimal(el); }

}  // namespace tb::text
