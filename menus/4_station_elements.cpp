// Menu 4: Update Station Elements. Each prompt shows the current value; Enter keeps it.
#include <cctype>
#include <cmath>
#include <cstdio>

#include "gps/monitor.h"
#include "menus/6_configuration.h"
#include "menus/menus.h"
#include "rotator/parking_mask.h"
#include "store/settings.h"
#include "menus/term/line_terminal.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {
namespace {
template <class... A>
std::string station_fmt(const char* f, A... v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, v...);
  return buf;
}
}  // namespace

namespace {
// A latitude or longitude: a signed number of degrees or one with its hemisphere's letter. With
// `locator_lon`, a Maidenhead locator is taken too (as `passes --station` takes it): its centre's
// latitude is the answer, its longitude goes to *locator_lon.
double edit_degrees(term::Terminal& t, std::string_view label, double current, char pos, char neg, double limit,
                    std::optional<double>* locator_lon = nullptr) {
  double result = current;
  edit_text(t, label, station_fmt("%+.3f", current), [&](const std::string& a) -> std::optional<std::string> {
    if (locator_lon)
      if (const auto centre = station::maidenhead_centre(a)) {
        result = centre->lat_deg;
        *locator_lon = centre->lon_deg;
        return std::nullopt;
      }
    const auto v = station::parse_hemisphere_degrees(a, pos, neg);
    if (!v) return "'" + a + "' is not a number of degrees (a sign, or " + std::string(1, pos) + " or " +
                   std::string(1, neg) + " after it)" + (locator_lon ? " nor a locator (JN18du)" : "");
    if (std::abs(*v) > limit) return a + station_fmt(" is out of range: expected %g to %g", -limit, limit);
    result = *v;
    return std::nullopt;
  });
  return result;
}
}  // namespace

namespace {
// The horizon mask (issue 57): the current one shown briefly (what `trakbox status` says of it), a
// new one typed on one line in any form the mask reader takes, or none. A malformed entry is said
// with the reader's sentence and asked again; Enter keeps the mask. Returns station.horizon_mask's
// text ("" for none). The answer may be longer than a screen line: the terminal wraps it.
std::string edit_mask(term::Terminal& t, const station::StationConfig& st) {
  t.line("  Horizon mask: AZ EL pairs joined by ';' (0 5; 214 25; 263 5), a step list");
  t.line("  AZ EL AZ ... AZ (0 0 190 25 230 0 360), or none; Enter keeps it");
  if (!st.horizon_mask.empty() && st.horizon_mask.size() <= 150)
    for (const auto& l : cfg::wrap_words("now " + st.horizon_mask, 76, "")) t.line("  " + l);
  const store::Setting& setting = *store::find_setting("station.horizon_mask");
  for (;;) {
    t.write("Horizon mask       : " + station::describe_mask(st) + "  ");
    t.flush();
    const std::string answer = text::trimmed(read_line(t, setting.max_len));
    if (t.last_line_had_non_ascii()) {
      t.line("  only ASCII characters are taken here; not changed");
      continue;
    }
    if (answer.empty()) return st.horizon_mask;
    const station::MaskEntry entry = station::read_mask_entry(answer);
    std::string why = entry.error;
    if (entry.text && entry.text->size() > setting.max_len)  // more than the state keeps
      why = "horizon mask: " + std::to_string(entry.text->size()) + " characters, more than the " +
            std::to_string(setting.max_len) + " kept";
    else if (entry.text) return *entry.text;
    for (const auto& l : cfg::wrap_words(why + "; not changed", 76, "")) t.line("  " + l);
  }
}

void edit_station_elements(term::Terminal& t, Services& s) {
  station::StationConfig st = s.model.station;  // edited as a copy, committed at the end
  const station::StationConfig before = s.model.station;
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
  // trakbox's hint (issue 30): which sign is north and east (PREDICT counts longitude west), and
  // that N, S, E, W after the number work too.
  t.line("  (+ north/- south, + east/- west; 48.85N, 2.35E, 122.4W; or a locator JN18du)");
  std::optional<double> locator_lon;
  st.lat_deg = edit_degrees(t, "Latitude  [deg]   ", st.lat_deg, 'N', 'S', 90.0, &locator_lon);
  if (locator_lon) {
    // A locator gives both: its centre; Enter at the longitude keeps it.
    st.lon_deg = *locator_lon;
    t.line(station_fmt("  locator: the centre of its square, %.6f %c %.6f %c", std::abs(st.lat_deg), st.lat_deg < 0 ? 'S' : 'N',
               std::abs(st.lon_deg), st.lon_deg < 0 ? 'W' : 'E'));
  }
  st.lon_deg = edit_degrees(t, "Longitude [deg]   ", st.lon_deg, 'E', 'W', 180.0);
  const store::Bounds height = store::bounds("station.height_m");  // the settings table's range
  st.height_m = edit_number(t, "Height    [m]     ", st.height_m, station_fmt("%.3f", st.height_m), height.lo, height.hi);
  t.line("  Rotor start: where the azimuth rotator's stop is (turn it fully counter-");
  t.line("  clockwise and read its dial): N for a stop at north (a GS-232 reporting");
  t.line("  0-360 or 0-450, a SPID), S for one at south");
  const std::string rs = edit_text(t, "Rotor start [N/S] ", station::to_string(st.rotor_start),
                                   [](const std::string& a) -> std::optional<std::string> {
                                     const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(a[0])));
                                     if (c != 'N' && c != 'S') return "N (North) or S (South)";
                                     return std::nullopt;
                                   });
  st.rotor_start = std::toupper(static_cast<unsigned char>(rs[0])) == 'N' ? station::RotorStart::north
                                                                          : station::RotorStart::south;
  t.line("  COM port baud rate: the speed of the serial line these menus run on (--tty),");
  t.line("  1200 to 19200; not the radio's or the rotator's (--radio, --rotator)");
  st.com_baud = edit_int(t, "COM port baud rate", st.com_baud, 1200, 19200);
  while (!term::valid_terminal_baud(st.com_baud)) {
    t.line("  1200, 2400, 4800, 9600 or 19200");
    st.com_baud = edit_int(t, "COM port baud rate", 9600, 1200, 19200);
  }
  st.horizon_mask = edit_mask(t, st);
  station::GpsSettings gs = s.model.gps;
  if (g) {
    const std::string follow = edit_text(t, "Follow GPS [Y/N]  ", gs.follow ? "Y" : "N",
                                         [](const std::string& a) -> std::optional<std::string> {
                                           const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(a[0])));
                                           if (c != 'Y' && c != 'N') return "Y (the position follows the receiver) or N";
                                           return std::nullopt;
                                         });
    gs.follow = std::toupper(static_cast<unsigned char>(follow[0])) == 'Y';
    const store::Bounds b = store::bounds("gps.threshold_m");
    gs.threshold_m = edit_number(t, "GPS threshold [m] ", gs.threshold_m, station_fmt("%.0f", gs.threshold_m), b.lo, b.hi);
  }
  if (st.lat_deg != s.model.station.lat_deg || st.lon_deg != s.model.station.lon_deg ||
      st.height_m != s.model.station.height_m) {
    gs.position_from_gps = false;  // typed in
    gs.position_time.reset();
  }
  // Through the one door: the station reconfigures (the rotor start changes how the antenna's
  // travel maps to the compass; the pass cache searches the new place's passes) and saves.
  if (!commit(t, s, store::bit(store::Area::position) | store::bit(store::Area::station) |
                        store::bit(store::Area::rotator) | store::bit(store::Area::gps),
              "menu 4", [&](store::Model& m) {
                m.station = st;
                m.gps = gs;
              }))
    return;
  s.station.apply_gps_position();  // following: the confirmed fix, now
  if (const auto& failed = s.station.save_failure()) {
    t.bell();
    t.line("State not saved: " + *failed);
    return;
  }
  // Said, not silent (issue 30): what was stored, in words an operator checks at a glance.
  const station::StationConfig& saved = s.model.station;
  t.line(station_fmt("Station saved: %s  %.3f %c  %.3f %c  %.0f m  rotor start %s", saved.callsign.c_str(),
             std::abs(saved.lat_deg), saved.lat_deg < 0 ? 'S' : 'N', std::abs(saved.lon_deg),
             saved.lon_deg < 0 ? 'W' : 'E', saved.height_m, station::to_string(saved.rotor_start)));
  if (saved.horizon_mask != before.horizon_mask) t.line("Horizon mask: " + station::describe_mask(saved));
  // The parking position is the operator's and stays; below the mask it is said (issue 57).
  if (const auto w = rotator::parking_mask_warning(s.model.rotator, saved.mask().get())) {
    t.bell();
    for (const auto& l : cfg::wrap_words("WARNING: " + *w + " (menu 6-4 sets the parking position)", 78, ""))
      t.line(l);
  }
}
}  // namespace

void menu_4_station_elements(term::Terminal& t, Services& s) {
  // Esc at any prompt leaves as Q does in the other menus: nothing typed so far is kept (the
  // station is edited as a copy and stored only after the last prompt).
  try {
    EscapeLeaves esc(t);
    edit_station_elements(t, s);
  } catch (const Escaped&) {
    t.line("Station not changed.");
  }
}

}  // namespace tb::menus
