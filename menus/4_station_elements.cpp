// Menu 4: Update Station Elements. Each prompt shows the current value; Enter keeps it.
#include <cctype>
#include <cmath>
#include <cstdio>

#include "menus/menus.h"
#include "menus/term/line_terminal.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {
namespace {
template <class... A>
std::string fmt(const char* f, A... v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, v...);
  return buf;
}
}  // namespace

namespace {
// A latitude or longitude: a signed number of degrees or one with its hemisphere's letter.
double edit_degrees(term::Terminal& t, std::string_view label, double current, char pos, char neg, double limit) {
  double result = current;
  edit_text(t, label, fmt("%+.3f", current), [&](const std::string& a) -> std::optional<std::string> {
    const auto v = station::parse_hemisphere_degrees(a, pos, neg);
    if (!v) return "'" + a + "' is not a number of degrees (a sign, or " + std::string(1, pos) + " or " +
                   std::string(1, neg) + " after it)";
    if (std::abs(*v) > limit) return a + fmt(" is out of range: expected %g to %g", -limit, limit);
    result = *v;
    return std::nullopt;
  });
  return result;
}
}  // namespace

void menu_4_station_elements(term::Terminal& t, Services& s) {
  station::StationConfig st = s.model.station;  // edited as a copy, committed at the end
  t.line("====== Update Station Element =======");
  st.callsign = edit_text(t, "Callsign          ", st.callsign, [](const std::string& a) -> std::optional<std::string> {
    if (a.size() > 10) return "a callsign has at most 10 characters";
    for (char c : a)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '/' && c != '-') return "letters, digits, / and - only";
    return std::nullopt;
  });
  for (auto& c : st.callsign) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  // trakbox's hint (issue 30): which sign is north and east (PREDICT counts longitude west), and
  // that N, S, E, W after the number work too.
  t.line("  (+ north / - south, + east / - west; or 48.85N, 2.35E, 122.4W)");
  st.lat_deg = edit_degrees(t, "Latitude  [deg]   ", st.lat_deg, 'N', 'S', 90.0);
  st.lon_deg = edit_degrees(t, "Longitude [deg]   ", st.lon_deg, 'E', 'W', 180.0);
  st.height_m = edit_number(t, "Height    [m]     ", st.height_m, fmt("%.3f", st.height_m), -500.0, 9000.0);
  const std::string rs = edit_text(t, "Rotor start [N/S] ", station::to_string(st.rotor_start),
                                   [](const std::string& a) -> std::optional<std::string> {
                                     const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(a[0])));
                                     if (c != 'N' && c != 'S') return "N (North) or S (South)";
                                     return std::nullopt;
                                   });
  st.rotor_start = std::toupper(static_cast<unsigned char>(rs[0])) == 'N' ? station::RotorStart::north
                                                                          : station::RotorStart::south;
  st.com_baud = edit_int(t, "COM port baud rate", st.com_baud, 1200, 19200);
  while (!term::valid_terminal_baud(st.com_baud)) {
    t.line("  1200, 2400, 4800, 9600 or 19200");
    st.com_baud = edit_int(t, "COM port baud rate", 9600, 1200, 19200);
  }
  s.model.station = st;
  s.station.reconfigure();  // the rotor start changes how the antenna's travel maps to the compass
  if (const auto err = s.save()) {
    t.bell();
    t.line("State not saved: " + *err);
    return;
  }
  // Said, not silent (issue 30): what was stored, in words an operator checks at a glance.
  t.line(fmt("Station saved: %s  %.3f %c  %.3f %c  %.0f m  rotor start %s", st.callsign.c_str(), std::abs(st.lat_deg),
             st.lat_deg < 0 ? 'S' : 'N', std::abs(st.lon_deg), st.lon_deg < 0 ? 'W' : 'E', st.height_m,
             station::to_string(st.rotor_start)));
}

}  // namespace tb::menus
