// trakbox next [SAT...]: PREDICT's `predict -p` for the station the menus know. The next pass of
// each satellite (the tracking list when none is named), one line each, soonest first; --watch
// redraws the lines every second with the time to AOS (or to LOS while a satellite is up).
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_defaults.h"
#include "cli/cli_elements.h"
#include "cli/cli_orbit.h"
#include "cli/cli_orbit_internal.h"
#include "cli/options.h"
#include "orbit/element_age.h"
#include "orbit/passes.h"
#include "orbit/sgp4.h"
#include "orbit/sky.h"
#include "util/text.h"

namespace tb::app {
namespace {

using orbit::UtcTime;

constexpr double kSearchDays = 10.0;

const std::vector<OptionSpec> kNextSpecs{
    {"station", "LAT,LON[,HEIGHT_M]|LOCATOR", "station (as for passes); default the stored station (menu 4)"},
    {"state", "DIR", "the state the menus keep (default as for the menus): station, database, tracking list"},
    {"elements", "FILE", "an element file instead of the stored database"},
    {"start", "ISO8601|now|+2h", "look from this time (default: now, or a station running on the state directory: its clock)"},
    {"min-el", "DEG", "only passes whose maximum elevation reaches DEG (default 0: a pass that never rises is no "
                      "pass)"},
    {"horizon-mask", "FILE|none", "a horizon mask file (as for passes); default the stored station's when --station "
                                  "is not given"},
    {"watch", "", "redraw every second with the time to AOS or LOS, until interrupted"},
    no_checksum_option(),
    {"help", "", "show this help"}};

const char* const kNextUsage =
    "usage: trakbox next [SAT...] [--station LAT,LON[,HEIGHT_M]|LOCATOR] [--state DIR] [--elements FILE]\n"
    "                    [--start ISO8601|now|+2h] [--min-el DEG] [--horizon-mask FILE|none]\n"
    "                    [--watch] [--no-checksum]\n"
    "\n"
    "The next pass of each satellite over the station, one line each, soonest first (PREDICT's -p):\n"
    "AOS (at -2.0 deg, the manual's rule) with its azimuth and the time until it, TCA with the maximum\n"
    "elevation, LOS with its azimuth. A satellite already up shows the pass it is in; one that stays up\n"
    "(geostationary) is 'always up', with no AOS or LOS. SAT is a name (any case) or catalog number of\n"
    "the database; without SAT, the tracking list (menu 3-2). Nothing within 10 days: 'no pass'.\n"
    "SAT may also be SUN or MOON (any case): their next rise (AOS), culmination (TCA) and set (LOS),\n"
    "of the centre seen from the station, geometric (no refraction); they need no elements.\n\noptions:\n";

struct Row {
  std::string name;
  std::optional<orbit::Pass> pass;
  std::string error;  // SGP4 could not propagate it
};

std::string clock_time(UtcTime t) { return orbit::format_iso8601(t, 0).substr(11, 8); }

std::string date_time(UtcTime t) {
  std::string s = orbit::format_iso8601(t, 0).substr(0, 19);
  s[4] = s[7] = '/';
  s[10] = ' ';
  return s;
}

std::string duration(std::chrono::microseconds d) {
  const long long s = std::max<long long>(0, std::chrono::duration_cast<std::chrono::seconds>(d).count());
  char b[32];
  if (s >= 86400) std::snprintf(b, sizeof b, "%lldd%02lldh", s / 86400, s % 86400 / 3600);
  else std::snprintf(b, sizeof b, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  return b;
}

std::vector<Row> compute(const std::vector<orbit::Elements>& sats, const std::vector<orbit::Body>& bodies,
                         const orbit::Observer& station, UtcTime from, const orbit::PassOptions& options) {
  std::vector<Row> rows;
  for (const orbit::Body b : bodies)
    rows.push_back({std::string(orbit::body_name(b)), orbit::next_body_pass(b, station, from, kSearchDays, options), ""});
  for (const orbit::Elements& e : sats) {
    Row r;
    r.name = std::string(text::trim(e.name));
    if (r.name.empty()) r.name = std::to_string(e.catalog_number);
    const orbit::Sgp4 sat(e);
    if (sat.init_error() != orbit::Sgp4Error::none) r.error = orbit::describe(sat.init_error());
    else r.pass = orbit::next_pass(sat, station, from, kSearchDays, options);
    rows.push_back(std::move(r));
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    if (!a.pass || !b.pass) return a.pass.has_value() && !b.pass.has_value();
    return a.pass->aos < b.pass->aos;
  });
  return rows;
}

// compact: the --watch form, within 80 columns (the date is in the header line above).
std::string line(const Row& r, UtcTime now, bool compact = false) {
  char b[200];
  if (compact && r.error.empty() && r.pass && !(r.pass->aos <= now && r.pass->up_at_end)) {
    const orbit::Pass& p = *r.pass;
    const bool up = p.aos <= now;
    const std::string when = up ? "UP, LOS in " + duration(p.los - now) : "in " + duration(p.aos - now);
    char los[32];
    if (p.up_at_end) std::snprintf(los, sizeof los, "LOS >%.0fd", kSearchDays);
    else std::snprintf(los, sizeof los, "LOS %s", clock_time(p.los).c_str());
    std::snprintf(b, sizeof b, "%-12.12s AOS %s az %3.0f max %4.1f %s %s", r.name.c_str(), clock_time(p.aos).c_str(),
                  p.aos_az_deg, p.max_el_deg, los, when.c_str());
    return b;
  }
  if (!r.error.empty()) {
    std::snprintf(b, sizeof b, "%-16.16s  sgp4 error: %s", r.name.c_str(), r.error.c_str());
  } else if (!r.pass) {
    std::snprintf(b, sizeof b, "%-16.16s  no pass within %.0f days", r.name.c_str(), kSearchDays);
  } else {
    const orbit::Pass& p = *r.pass;
    const bool up = p.aos <= now;
    if (up && p.up_at_end) {
      // Up now and still up at the end of the search: a geostationary satellite (or one that
      // stays in view): no LOS to invent.
      std::snprintf(b, sizeof b, "%-16.16s  always up: az %3.0f el %4.1f, no AOS or LOS within %.0f days", r.name.c_str(),
                    p.aos_az_deg, p.max_el_deg, kSearchDays);
    } else {
      const std::string when = up ? "UP, LOS in " + duration(p.los - now) : "in " + duration(p.aos - now);
      char los[64];
      if (p.up_at_end) std::snprintf(los, sizeof los, "LOS after %.0f days", kSearchDays);
      else std::snprintf(los, sizeof los, "LOS %s az %3.0f", clock_time(p.los).c_str(), p.los_az_deg);
      std::snprintf(b, sizeof b, "%-16.16s  AOS %s az %3.0f  TCA %s el %4.1f  %s  %s", r.name.c_str(),
                    date_time(p.aos).c_str(), p.aos_az_deg, clock_time(p.tca).c_str(), p.max_el_deg, los,
                    when.c_str());
    }
  }
  return b;
}

// Stale element sets, said once: one line for one set, one line with the range for several.
void warn_stale_once(const std::vector<orbit::Elements>& sats, UtcTime at) {
  std::vector<std::string> names;
  double lo = 1e300, hi = -1e300;
  std::string one;
  for (const orbit::Elements& e : sats) {
    const orbit::ElementAge age = orbit::element_age(e, at);
    if (!age.stale()) continue;
    names.push_back(std::string(text::trim(e.name)));
    lo = std::min(lo, age.days);
    hi = std::max(hi, age.days);
    one = age.warning();
  }
  if (names.empty()) return;
  if (names.size() == 1) {
    std::fprintf(stderr, "trakbox next: warning: %s: %s\n", names.front().c_str(), one.c_str());
    return;
  }
  std::fprintf(stderr, "trakbox next: warning: elements of %zu satellites are %.1f to %.1f days old, past the limit "
                       "of their orbits: positions are unreliable (refresh them: menu 3-5 or trakbox "
                       "--elements-url URL; or give --elements FILE here)\n",
               names.size(), lo, hi);
}

struct Size {
  int cols = 0, rows = 0;
};
Size terminal_size() {
  winsize w{};
  if (::ioctl(STDOUT_FILENO, TIOCGWINSZ, &w) != 0) return {};
  return {w.ws_col, w.ws_row};
}

// One redraw of --watch. On a terminal: within its width and height (a wrapped or scrolled line
// leaves a stale copy behind at the next redraw; issue 39), each line cleared to its end; on a pipe,
// blocks separated by a blank line.
std::string watch_screen(const std::string& head, const std::vector<Row>& rows, UtcTime now, bool tty) {
  const Size size = tty ? terminal_size() : Size{};
  auto fit = [&](std::string l) {
    if (tty && size.cols > 0 && l.size() > static_cast<std::size_t>(size.cols)) l.resize(static_cast<std::size_t>(size.cols));
    return l + (tty ? "\033[K\n" : "\n");
  };
  std::string screen = tty ? "\033[H" : "";
  screen += fit(head + ", " + date_time(now) + " UTC");
  int shown = 1;
  for (const Row& r : rows) {
    if (tty && size.rows > 0 && shown >= size.rows - 1) break;
    screen += fit(line(r, now, true));
    ++shown;
  }
  return screen + (tty ? "\033[J" : "\n");
}

int fail(const ArgError& e) {
  std::fprintf(stderr, "trakbox next: %s (see trakbox next --help)\n", e.text().c_str());
  return kExitUsage;
}

}  // namespace

int run_next(std::vector<std::string> args) {
  const ParseOutcome po = parse_options(args, kNextSpecs);
  if (po.error) return fail(*po.error);
  const ParsedOptions& o = po.options;
  if (o.has("help")) {
    std::fputs((kNextUsage + describe_options(kNextSpecs)).c_str(), stdout);
    return kExitOk;
  }
  StoredStation stored(o.value("state") ? std::optional<std::filesystem::path>(*o.value("state")) : std::nullopt);
  const UtcTime wall_start = std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
  OptionReader in(o);

  std::optional<orbit::Observer> station;
  if (const auto t = o.value("station")) {
    const Parsed<orbit::Observer> p = parse_station_text(*t);
    if (!p.value) return fail({"--station", p.error});
    station = p.value;
  } else if (!(station = stored.station())) {
    return fail({"--station", "missing, and " + stored.error()});
  }
  UtcTime start = o.value("start") ? wall_start : default_start(o.value("state"), "next");
  if (const auto t = o.value("start")) {
    const Parsed<UtcTime> p = parse_time_text(*t, wall_start);
    if (!p.value) return fail({"--start", p.error});
    start = *p.value;
  }
  orbit::PassOptions options;
  options.horizon_deg = orbit::kAosThresholdDeg;
  options.min_max_elevation_deg = 0.0;  // a pass that never rises above the horizon is no pass
  if (const auto v = in.number("min-el", false, "DEG, an elevation -90..90", Range{-90.0, 90.0}))
    options.min_max_elevation_deg = *v;
  options.mask = orbit_cli::read_horizon_mask_option(in, o, stored);  // AOS/LOS where the sky is clear
  if (!in.ok()) return fail(*in.error());

  // SUN and MOON among the names need no elements.
  std::vector<orbit::Body> bodies;
  std::vector<std::string> keys;
  for (const std::string& key : o.positional()) {
    if (const auto b = orbit::parse_body(key)) bodies.push_back(*b);
    else keys.push_back(key);
  }
  // The satellites: named ones from the database (or --elements), else the tracking list.
  std::vector<orbit::Elements> pool;
  std::string from;
  if (!bodies.empty() && keys.empty()) {
    // only bodies: nothing to load
  } else if (const auto file = o.value("elements")) {
    const orbit::ParseResult parsed = orbit::load_elements_file(*file, checked_options(!o.has("no-checksum")));
    report_problems(parsed.problems, stderr);
    if (parsed.sets.empty()) return fail({"--elements", "no usable element set in '" + *file + "'"});
    pool = parsed.sets;
    from = *file;
  } else {
    const auto sets = keys.empty() ? stored.tracking_list() : stored.database();
    if (!sets) return fail({"SAT", "no database: " + stored.error()});
    pool = *sets;
    from = stored.source();
  }
  std::vector<orbit::Elements> sats;
  for (const std::string& key : keys) {
    std::string why;
    const auto i = match_sat(pool, key, why);
    if (!i) return fail({key, why});
    sats.push_back(pool[*i]);
  }
  if (o.positional().empty()) sats = pool;
  if (sats.empty() && bodies.empty()) return fail({"SAT", "none given and the tracking list is empty (" + from + ")"});
  warn_stale_once(sats, start);
  char head[200];
  std::snprintf(head, sizeof head, "station %.4f, %.4f, %.0f m (%s)", station->lat_deg, station->lon_deg,
                station->height_m, o.value("station") ? "--station" : stored.source().c_str());
  const bool watch = o.has("watch");
  const bool tty = isatty(STDOUT_FILENO) != 0;
  std::vector<Row> rows = compute(sats, bodies, *station, start, options);
  while (true) {
    const UtcTime now = start + (std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now()) -
                                 wall_start);
    if (watch) {
      // A pass that ended gives way to the next one.
      bool ended = false;
      for (const Row& r : rows) ended = ended || (r.pass && r.pass->los < now);
      if (ended) rows = compute(sats, bodies, *station, now, options);
      const std::string screen = watch_screen(head, rows, now, tty);
      std::fputs(screen.c_str(), stdout);
      std::fflush(stdout);
      if (std::ferror(stdout)) return kExitFailure;  // the reader went away
      std::this_thread::sleep_for(std::chrono::seconds(1));
      continue;
    }
    std::printf("%s, from %s UTC\n", head, date_time(now).c_str());
    for (const Row& r : rows) std::printf("%s\n", line(r, now).c_str());
    break;
  }
  for (const Row& r : rows)
    if (!r.error.empty()) return kExitFailure;
  return kExitOk;
}

}  // namespace tb::app
