#include "station/station.h"

#include <cctype>

#include "util/text.h"

namespace tb::station {
const char* to_string(RotorStart r) { return r == RotorStart::north ? "North" : "South"; }
std::optional<double> parse_hemisphere_degrees(std::string_view item, char pos, char neg) {
  std::string s(text::trim(item));
  if (s.empty()) return std::nullopt;
  const char last = static_cast<char>(std::toupper(static_cast<unsigned char>(s.back())));
  double sign = 1.0;
  if (last == pos || last == neg) {
    sign = last == neg ? -1.0 : 1.0;
    s = std::string(text::trim(std::string_view(s).substr(0, s.size() - 1)));
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) return std::nullopt;  // 48.85S or -48.85, not both
  }
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' || s[0] == '+' || s[0] == '.'))
    return std::nullopt;
  const auto v = text::parse_double(s);
  if (!v) return std::nullopt;
  return sign * *v;
}

}  // namespace tb::station
