// Menu 4: Update Station Elements. Each prompt shows the current value; Enter keeps it.
#include <cctype>
#include <cstdio>

#include "gps/monitor.h"
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
  const gps::Monitor* g = s.station.gps();
  if (g || s.model.gps.position_from_gps) {
    const auto& gs = s.model.gps;
    t.line(std::string("Position from      ") +
           (gs.position_from_gps ? "GPS fix of " + (gs.position_time ? orbit::format_iso8601(*gs.position_time) : "?")
                                 : std::string("typed in")));
    t.line("GPS receiver      " + (g ? g->source() + ": " + g->describe() : std::string("none (--gps)")));
  }
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
  station::GpsSettings gs = s.model.gps;
  if (g) {
    const std::string follow = edit_text(t, "Follow GPS [Y/N]  ", gs.follow ? "Y" : "N",
                                         [](const std::string& a) -> std::optional<std::string> {
                                           const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(a[0])));
                                           if (c != 'Y' && c != 'N') return "Y (the position follows the receiver) or N";
                                           return std::nullopt;
                                         });
    gs.follow = std::toupper(static_cast<unsigned char>(follow[0])) == 'Y';
    gs.threshold_m = edit_number(t, "GPS threshold [m] ", gs.threshold_m, fmt("%.0f", gs.threshold_m),
                                 station::kGpsThresholdMinM, station::kGpsThresholdMaxM);
  }
  if (st.lat_deg != s.model.station.lat_deg || st.lon_deg != s.model.station.lon_deg ||
      st.height_m != s.model.station.height_m) {
    gs.position_from_gps = false;  // typed in
    gs.position_time.reset();
  }
  s.model.station = st;
  s.model.gps = gs;
  s.station.reconfigure();
  s.station.apply_gps_position();  // following: the confirmed fix, now  // the rotor start changes how the antenna's travel maps to the compass
  save_or_report(t, s);
}

}  // namespace tb::menus
