#include "station/station.h"

#include <algorithm>
#include <cctype>
#include <cmath>

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

std::optional<orbit::Observer> maidenhead_centre(std::string_view loc) {
  if (loc.size() != 4 && loc.size() != 6 && loc.size() != 8) return std::nullopt;
  const std::string u = text::upper(loc);
  auto in = [](char c, char lo, char hi) { return c >= lo && c <= hi; };
  if (!in(u[0], 'A', 'R') || !in(u[1], 'A', 'R') || !in(u[2], '0', '9') || !in(u[3], '0', '9')) return std::nullopt;
  // Field 20 x 10 degrees, square 2 x 1, subsquare 5' x 2.5' (24 letters), extended 30" x 15" (10 digits).
  double lon = -180.0 + (u[0] - 'A') * 20.0 + (u[2] - '0') * 2.0;
  double lat = -90.0 + (u[1] - 'A') * 10.0 + (u[3] - '0') * 1.0;
  double w = 2.0, h = 1.0;
  if (u.size() >= 6) {
    if (!in(u[4], 'A', 'X') || !in(u[5], 'A', 'X')) return std::nullopt;
    w /= 24.0;
    h /= 24.0;
    lon += (u[4] - 'A') * w;
    lat += (u[5] - 'A') * h;
  }
  if (u.size() == 8) {
    if (!in(u[6], '0', '9') || !in(u[7], '0', '9')) return std::nullopt;
    w /= 10.0;
    h /= 10.0;
    lon += (u[6] - '0') * w;
    lat += (u[7] - '0') * h;
  }
  return orbit::Observer{lat + h / 2.0, lon + w / 2.0, 0.0};
}

std::string maidenhead_locator(double lat_deg, double lon_deg) {
  // Shifted to 0..360 and 0..180, the poles and the antimeridian kept inside the last square.
  const double lon = std::clamp(lon_deg + 180.0, 0.0, 360.0 - 1e-9);
  const double lat = std::clamp(lat_deg + 90.0, 0.0, 180.0 - 1e-9);
  std::string l(6, ' ');
  l[0] = static_cast<char>('A' + static_cast<int>(lon / 20.0));
  l[1] = static_cast<char>('A' + static_cast<int>(lat / 10.0));
  l[2] = static_cast<char>('0' + static_cast<int>(std::fmod(lon, 20.0) / 2.0));
  l[3] = static_cast<char>('0' + static_cast<int>(std::fmod(lat, 10.0)));
  l[4] = static_cast<char>('a' + static_cast<int>(std::fmod(lon, 2.0) * 12.0));
  l[5] = static_cast<char>('a' + static_cast<int>(std::fmod(lat, 1.0) * 24.0));
  return l;
}

MaskEntry read_mask_entry(std::string_view typed) {
  const std::string_view t = text::trim(typed, text::kWhitespace);
  if (t.empty() || text::iequals(t, "none")) return {std::string(), {}};
  auto r = orbit::read_horizon_mask(t, "horizon mask");
  if (!r.mask) return {std::nullopt, r.error};
  return {r.mask->text(), {}};
}

std::string describe_mask(const StationConfig& st) {
  const auto m = st.mask();
  return m ? m->describe() : std::string("none");
}

}  // namespace tb::station
