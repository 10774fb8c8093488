// Menu 2: Display Schedule. Choose from the tracking list like menu 1 (Enter: the one marked '*'),
// give a starting time and a time step, then read the position table a screenful at a time:
//
//   DATE       TIME      AZ/EL       Phase Doppler
//   1993/07/17 15:09:03  248.6/40.4    0.0   +7575
//           - 'Q' for abort 'S' for scroll
//
// P at the prompt shows the pass of the page's first time (in progress then, or the next within a
// day): one line in line mode; on a full screen the sky plot and ground track as the realtime
// display draws them, until a key, then the page again (the manual's prompt is kept as printed).
// The antennas are not moved and the tracker is left as it was: this is a calculation only.
// See docs/menus/2-3.md for how the manual's damaged example was read.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <variant>
#include <vector>

#include "menus/realtime_display.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

constexpr const char* kHeader = "DATE       TIME      AZ/EL       Phase Doppler";
constexpr const char* kMorePrompt = "        - 'Q' for abort 'S' for scroll ";
constexpr long kMaxStepMinutes = 10080;  // a week

orbit::UtcTime whole_seconds(orbit::UtcTime t) { return std::chrono::floor<std::chrono::seconds>(t); }

int days_in_year(int year) {
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return leap ? 366 : 365;
}

// "YYYY/MM/DD HH:MM:SS" (the form the prompt itself shows), years 1957 to 2100.
std::optional<orbit::UtcTime> parse_yyyymmdd_hhmmss(const std::string& s) {
  int yyyy, mo, dd, hh, mi, ss;
  char tail;
  if (std::sscanf(s.c_str(), "%d/%d/%d %d:%d:%d %c", &yyyy, &mo, &dd, &hh, &mi, &ss, &tail) != 6) return std::nullopt;
  if (yyyy < 1957 || yyyy > 2100 || mo < 1 || mo > 12 || dd < 1 || dd > 31 || hh < 0 || hh > 23 || mi < 0 || mi > 59 ||
      ss < 0 || ss > 59)
    return std::nullopt;
  char iso[32];
  std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT%02d:%02d:%02dZ", yyyy, mo, dd, hh, mi, ss);
  return orbit::parse_iso8601(iso);
}

// The answer to "Starting Day/Time ?": YY/MM/DD HH:MM:SS, YYYY/MM/DD HH:MM:SS, or the day of the
// year with its fraction (DDD.ddddd, like the element sets' epoch T0) in the clock's current year.
std::variant<orbit::UtcTime, std::string> parse_start(const std::string& a, orbit::UtcTime now) {
  const std::string form = "enter YY/MM/DD HH:MM:SS, a day of the year DDD.ddddd, or Enter for now";
  if (a.find('/') != std::string::npos) {
    if (const auto t = parse_yymmdd_hhmmss(a)) return *t;
    if (const auto t = parse_yyyymmdd_hhmmss(a)) return *t;
    return "'" + a + "' is not a date and time: " + form;
  }
  bool digits = !a.empty() && std::isdigit(static_cast<unsigned char>(a[0]));
  int points = 0;
  for (char c : a) {
    if (c == '.') ++points;
    else if (!std::isdigit(static_cast<unsigned char>(c))) digits = false;
  }
  const auto day = digits && points <= 1 ? parse_number(a) : std::nullopt;
  if (!day) return "'" + a + "' is not understood: " + form;
  const int year = orbit::to_civil(now).year;
  const int last = days_in_year(year);
  if (*day < 1.0 || *day >= last + 1.0)
    return "day " + a + " is not in " + std::to_string(year) + ": expected 1 to " + std::to_string(last) +
           ".99999 (the day of the year, fraction = time of day)";
  const auto t = orbit::from_year_day(year, *day);
  return std::chrono::round<std::chrono::seconds>(t);
}

orbit::UtcTime ask_start(term::Terminal& t, Services& s) {
  for (;;) {
    const orbit::UtcTime now = whole_seconds(s.clock.now());
    t.write(format_date(now) + " " + format_time(now) +
            " Starting Day/Time ? [YY/MM/DD HH:MM:SS] Day of the Year [T] >");
    t.flush();
    const std::string a = text::trimmed(read_line(t));
    if (a.empty()) return whole_seconds(s.clock.now());
    const auto r = parse_start(a, now);
    if (const auto* time = std::get_if<orbit::UtcTime>(&r)) return *time;
    t.line("  " + std::get<std::string>(r));
  }
}

// "Min [1]:" / "Sec [0]:": Enter takes the default shown.
long ask_step_part(term::Terminal& t, const char* prompt, long fallback, long hi) {
  for (;;) {
    t.write(prompt);
    t.flush();
    const std::string a = text::trimmed(read_line(t));
    if (a.empty()) return fallback;
    const auto v = parse_integer(a);
    if (v && *v >= 0 && *v <= hi) return *v;
    t.line("  '" + a + "': expected a whole number from 0 to " + std::to_string(hi));
  }
}

long ask_step_seconds(term::Terminal& t) {
  for (;;) {
    const long minutes = ask_step_part(t, "Time Step Min [1]:", 1, kMaxStepMinutes);
    const long seconds = ask_step_part(t, "Sec [0]:", 0, 59);
    if (minutes * 60 + seconds > 0) return minutes * 60 + seconds;
    t.line("  The time step must be at least 1 second.");
  }
}

std::string format_schedule_row(const tracker::SatNow& n) {
  char el[16];
  std::snprintf(el, sizeof el, "%4.1f", n.obs.look.el_deg);
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s %s %6.1f/%-5s %5.1f %+7ld", format_date(n.obs.time).c_str(),
                format_time(n.obs.time).c_str(), n.obs.look.az_deg, el, std::floor(n.obs.phase256),
                std::lround(n.downlink_doppler_hz));
  return buf;
}

// P: the pass of the page (see the top of the file); `page` is shown again after a full screen's plot.
void show_pass(term::Terminal& t, Services& s, int db_index, orbit::UtcTime from, const std::vector<std::string>& page) {
  auto n = s.tracker.observe(db_index, from);
  if (!n) return;
  n->pass = s.tracker.pass_at(db_index, from);
  if (!n->pass) {
    t.line("  " + n->name + ": no pass within a day of " + format_date(from) + " " + format_time(from));
    return;
  }
  if (!t.full_screen()) return t.line("  " + describe_pass(n->name, *n->pass));
  t.clear();   // the plot needs the screen below its two lines
  t.line(describe_pass(n->name, *n->pass));
  t.write("        - any key to return to the schedule ");
  t.graphics(pass_graphics(s, *n));
  if (t.read_key() == term::kEndOfInput) throw InputClosed{};
  t.clear();
  t.line(kHeader);
  for (const auto& row : page) t.line(row);
}

}  // namespace

void menu_2_display_schedule(term::Terminal& t, Services& s) {
  const auto pick =
      choose_satellite(t, "     *** Tracking object satellite ***", tracking_list_names(s), s.model.db.marked);
  if (!pick) return;
  const int db_index = s.model.db.selected[static_cast<std::size_t>(*pick)];
  const orbit::UtcTime start = ask_start(t, s);
  const long step_s = ask_step_seconds(t);

  const int page = std::max(1, t.rows() - 2);  // the header and the prompt take a line each
  orbit::UtcTime when = start;
  for (;;) {
    t.line(kHeader);
    const orbit::UtcTime page_start = when;
    std::vector<std::string> shown;
    for (int row = 0; row < page; ++row, when += std::chrono::seconds(step_s)) {
      const auto n = s.tracker.observe(db_index, when);
      if (!n) return;  // the database changed under us: nothing to show
      if (!n->obs.ok()) {
        t.line(format_date(when) + " " + format_time(when) + " no position: " + orbit::describe(n->obs.error) +
               " (SGP4 error " + std::to_string(static_cast<int>(n->obs.error)) + "), end of the schedule");
        return;
      }
      shown.push_back(format_schedule_row(*n));
      // A time booked by a SatNOGS observation or the operator's reservation (issue 44) says so.
      if (const tracker::Window* w = s.station.control().window_at(when))
        shown.back() += w->kind == "satnogs" ? " SatNOGS " + w->id : std::string(" reserved");
      t.line(shown.back());
    }
    for (;;) {
      t.write(kMorePrompt);
      t.flush();
      const auto c = t.read_choice();
      if (!c) throw InputClosed{};
      if (*c == 'Q') return;
      if (*c == 'S') break;
      if (*c == 'P') show_pass(t, s, db_index, page_start, shown);
    }
  }
}

}  // namespace tb::menus
