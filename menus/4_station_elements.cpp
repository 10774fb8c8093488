// Menu 4: Update Station Elements. Each prompt shows the current value; Enter keeps it.
#include <cctype>
#include <cstdio>

#include "menus/menus.h"
#include "menus/term/line_terminal.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {
namespace {
std::string fmt(const char* f, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
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
  st.lat_deg = edit_number(t, "Latitude  [deg]   ", st.lat_deg, fmt("%+.3f", st.lat_deg), -90.0, 90.0);
  st.lon_deg = edit_number(t, "Longitude [deg]   ", st.lon_deg, fmt("%+.3f", st.lon_deg), -180.0, 180.0);
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
  save_or_report(t, s);
}

}  // namespace tb::menus
