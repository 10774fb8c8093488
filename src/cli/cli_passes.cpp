// trakbox passes: the passes over the station of one or more satellites, as a table, CSV, JSON
// or polar plots (the front matter it shares with the other orbit commands: cli_orbit_internal.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_orbit.h"
#include "cli/cli_orbit_internal.h"
#include "cli/pass_plot.h"
#include "util/text.h"
#include "orbit/element_age.h"
#include "orbit/observe.h"
#include "orbit/pass_tools.h"
#include "orbit/passes.h"
#include "orbit/sgp4.h"
#include "orbit/sky.h"
#include "station/station.h"
#include "rotator/pass_plan.h"
#include "store/model.h"

namespace tb::app {
using namespace orbit_cli;

namespace {

const Command kPasses{
    "passes",
    "[ELEMENTS] [--sat NAME|NUMBER|SUN|MOON]... [--station LAT,LON[,HEIGHT_M]|LOCATOR]\n"
    "                      [--start ISO8601|now|+2h] [--hours H] [--min-el DEG] [--state DIR] [--dut1 S]\n"
    "                      [--with LAT,LON|LOCATOR] [--ics FILE] [--csv|--json] [--no-checksum]",
    "Passes over the station between --start and --start + --hours, sorted by AOS: AOS and LOS are\n"
    "the crossings of -2.0 deg elevation (the manual's AOS rule), TCA the time of maximum elevation.\n"
    "Without --sat, every satellite of the file. CSV and JSON columns: sat, aos_utc, tca_utc, los_utc,\n"
    "max_el_deg, aos_az_deg, los_az_deg. A pass already up at --start begins there; one still up at\n"
    "the end stops there (marked < and > in the table). Without ELEMENTS, the stored database (--state)\n"
    "and, without --sat, its tracking list; without --station the stored station; from now for 24 h.\n"
    "Only passes that rise above 0 deg are listed (--min-el raises that). --with a second station (a\n"
    "QSO partner's grid): only the times both stations have the satellite above -2.0 deg.\n"
    "--sat SUN and --sat MOON (any case) list the rises (AOS), culminations (TCA) and sets (LOS) of the\n"
    "Sun's and the Moon's centre in the same table: topocentric, geometric (no refraction), at -2.0 deg\n"
    "like passes; they need no elements, and take neither --with nor --plot.",
    {repeatable({"sat", "NAME|NUMBER|SUN|MOON", "satellite by name (exact, then any case) or catalog number; "
                                                "SUN or MOON for the body"}),
     kStationOption,
     kHorizonMaskOption,
     {"start", "ISO8601|now|+2h", "start of the window, UTC, now (the default), or now plus an amount (+2h)"},
     {"hours", "H", "length of the window in hours (> 0, at most 8784; default 24)"},
     {"min-el", "DEG", "only passes whose maximum elevation reaches DEG (default: those that rise above 0)"},
     {"with", "LAT,LON|LOCATOR", "a second station: only the times both see the satellite (AOS the later, LOS the earlier)"},
     {"ics", "FILE", "also write the passes to FILE as an iCalendar (RFC 5545), one event a pass"},
     kDut1Option,
     kCsvOption,
     {"json", "", "a JSON array of pass objects"},
     {"plot", "FILE", "draw each pass as a polar plot, PNG or SVG by FILE's extension (several passes: FILE-1.png, "
                      "...): track, AOS/TCA/LOS, the antenna's planned path for the stored rotator"},
     kStateOption,
     kNoChecksumOption,
     kHelpOption},
    true};

struct SatPass {
  std::string sat;
  orbit::Pass pass;
  std::size_t set = 0;  // index into the satellites' sets
  std::optional<double> there_max_el;  // --with: the partner's highest elevation over the shared time
};

// The partner's highest elevation over a shared pass (--with), sampled each second: what the other
// station sees while both see the satellite.
double there_max_elevation(const orbit::Sgp4& sat, const orbit::Observer& there, const orbit::Pass& p) {
  double best = -90.0;
  for (UtcTime t = p.aos; t <= p.los; t += std::chrono::seconds(1)) {
    const orbit::Observation o = orbit::observe(sat, there, t);
    if (o.ok()) best = std::max(best, o.look.el_deg);
  }
  return best;
}

// --plot FILE: each pass as a polar plot (pass_plot.h); FILE itself for one pass, FILE-N.EXT for
// several, each name listed on `said` (standard output after the table; standard error after JSON
// or CSV, which stay whole documents) so that no file is made unannounced. The antenna's plan is the
// stored rotator's (the factory one when no state is readable).
int plot_passes(const std::string& file, const std::vector<SatPass>& passes, const std::vector<Elements>& sats,
                const orbit::Observer& station, const std::shared_ptr<const orbit::HorizonMask>& mask,
                StoredStation& stored, std::FILE* said) {
  const store::Model* m = stored.model();
  const store::Model factory = store::factory_defaults();
  if (!m) m = &factory;
  const rotator::PassGeometry geometry = rotator::PassGeometry::from(rotator::AdcModel(m->rotator, m->station.rotor_start));
  const std::size_t dot = file.find_last_of('.');
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const SatPass& s = passes[i];
    PassPicture pic;
    pic.title = s.sat;
    pic.station = printf_string("station %.4f %c %.4f %c %.0f m", std::abs(station.lat_deg), station.lat_deg < 0 ? 'S' : 'N',
                                std::abs(station.lon_deg), station.lon_deg < 0 ? 'W' : 'E', station.height_m);
    pic.element_age = "elements age " + orbit::element_age(sats[s.set], s.pass.aos).text() + " at AOS";
    pic.pass = s.pass;
    pic.track = sample_pass(orbit::Sgp4(sats[s.set]), station, s.pass);
    pic.plan = rotator::plan_pass(pic.track, geometry, std::nullopt);
    pic.mask = mask;
    const std::string name = passes.size() == 1 || dot == std::string::npos
                                 ? file
                                 : file.substr(0, dot) + "-" + std::to_string(i + 1) + file.substr(dot);
    if (const auto err = write_pass_plot(pic, name)) {
      std::fprintf(stderr, "trakbox passes: --plot: %s\n", err->c_str());
      return kExitFailure;
    }
    if (i == 0 && passes.size() > 1)
      std::fprintf(said, "plot: %zu passes, one file each (%s is not written):\n", passes.size(), file.c_str());
    std::fprintf(said, "plot: %s  %s %s\n", name.c_str(), s.sat.c_str(), orbit::format_iso8601(s.pass.aos, 0).c_str());
  }
  if (passes.empty()) std::fprintf(said, "plot: no pass, no file\n");
  return kExitOk;
}

// --ics FILE: the passes as an iCalendar, written whole (store's atomic write is not needed: a
// calendar file is the operator's to import), announced on `said`.
int write_ics(const std::string& file, const std::vector<SatPass>& passes, const orbit::Observer& station,
              const std::optional<orbit::Observer>& with, std::FILE* said) {
  std::vector<orbit::NamedPass> named;
  for (const SatPass& s : passes) named.push_back({s.sat, s.pass});
  std::string where = station::maidenhead_locator(station.lat_deg, station.lon_deg);
  if (with) where += " and " + station::maidenhead_locator(with->lat_deg, with->lon_deg);
  const std::string body = orbit::ical_passes(named, wall_now(), where);
  std::FILE* f = std::fopen(file.c_str(), "wb");
  const bool ok = f && std::fwrite(body.data(), 1, body.size(), f) == body.size();
  if (f && std::fclose(f) != 0) f = nullptr;
  if (!ok || !f) {
    std::fprintf(stderr, "trakbox passes: --ics: %s cannot be written\n", file.c_str());
    return kExitFailure;
  }
  std::fprintf(said, "ics: %s  %zu passes\n", file.c_str(), passes.size());
  return kExitOk;
}

// The header line(s) with the sets' ages at the window's start: one per set for a few, else the range.
std::string elements_ages(const std::vector<Elements>& sats, UtcTime at) {
  if (sats.size() <= 4) {
    std::string out;
    for (const Elements& e : sats)
      out += printf_string("elements %s epoch %s, age %s\n", choice_label(e).c_str(),
                       orbit::format_iso8601(e.epoch(), 0).c_str(), orbit::element_age(e, at).text().c_str());
    return out;
  }
  double lo = 1e300, hi = -1e300;
  for (const Elements& e : sats) {
    const double days = orbit::element_age(e, at).days;
    lo = std::min(lo, days);
    hi = std::max(hi, days);
  }
  return printf_string("elements of %zu satellites, age %.1f to %.1f days at the start\n", sats.size(), lo, hi);
}

// What `passes` owes its reader about one set over the window: its age at the window's start and
// end when past the limit of its orbit (a warning), and where SGP4 stops working (an error: the
// passes after it are not known, and the command exits 1). False when SGP4 fails.
bool check_window(const Elements& e, const orbit::Sgp4& sat, UtcTime start, UtcTime stop) {
  const std::string label = choice_label(e);
  warn_stale("passes", e, start, stop);
  if (sat.init_error() != orbit::Sgp4Error::none) {
    std::fprintf(stderr, "trakbox passes: %s: sgp4 error %d: %s; no passes\n", label.c_str(),
                 static_cast<int>(sat.init_error()), orbit::describe(sat.init_error()));
    return false;
  }
  // The first moment it fails: every 10 minutes through the window (a decay may fail for a while
  // and then propagate again, so the ends are not enough), then to the second.
  UtcTime good = start, bad = start;
  bool failed = !sat.propagate(start).ok();
  for (UtcTime t = start; !failed && t < stop;) {
    good = t;
    t = std::min(stop, t + std::chrono::minutes(10));
    if (!sat.propagate(t).ok()) {
      failed = true;
      bad = t;
    }
  }
  if (!failed) return true;
  while (bad != start && std::chrono::duration_cast<std::chrono::seconds>(bad - good).count() > 1) {
    const UtcTime mid = good + (bad - good) / 2;
    (sat.propagate(mid).ok() ? good : bad) = mid;
  }
  const orbit::Sgp4Error err = sat.propagate(bad).error;
  std::fprintf(stderr, "trakbox passes: %s: sgp4 error %d at %s: %s; no passes from then on\n", label.c_str(),
               static_cast<int>(err), orbit::format_iso8601(bad, 0).c_str(), orbit::describe(err));
  return false;
}

// The table form: `header` (the station and window), the element sets' ages, one row a pass.
void print_table(const std::vector<SatPass>& passes, const std::string& header, const std::vector<Elements>& sats,
                 UtcTime start, bool bodies) {
  out(header);
  if (!sats.empty()) out(elements_ages(sats, start));
  if (bodies) out("SUN, MOON: the centre of the body seen from the station, geometric (no refraction)\n");
  const bool there = !passes.empty() && passes.front().there_max_el;
  out(printf_string("%-24s  %-20s  %-9s  %-9s  %6s  %6s  %6s  %8s", "SAT", "AOS (UTC)", "TCA", "LOS", "MAX EL",
                "AOS AZ", "LOS AZ", "DURATION") + (there ? "   THERE" : "") + "\n");
  for (const SatPass& s : passes) {
    const std::string aos = manual_time(s.pass.aos, 0), tca = manual_time(s.pass.tca, 0),
                      los = manual_time(s.pass.los, 0);
    const auto dur = std::chrono::duration_cast<std::chrono::seconds>(s.pass.los - s.pass.aos).count();
    out(printf_string("%-24.24s  %s%c  %s   %s%c  %6.1f  %6.1f  %6.1f  %5lld:%02lld", s.sat.c_str(), aos.c_str(),
                  s.pass.up_at_start ? '<' : ' ', tca.substr(11).c_str(), los.substr(11).c_str(),
                  s.pass.up_at_end ? '>' : ' ', s.pass.max_el_deg, s.pass.aos_az_deg, s.pass.los_az_deg,
                  static_cast<long long>(dur / 60), static_cast<long long>(dur % 60)) +
        (s.there_max_el ? printf_string("  %6.1f", *s.there_max_el) : std::string()) + "\n");
  }
  if (passes.empty()) out("no passes\n");
  bool bounded = false;
  for (const SatPass& s : passes) bounded = bounded || s.pass.up_at_start || s.pass.up_at_end;
  // A satellite that stays up (geostationary) has neither: its row spans the window, marked.
  if (bounded)
    out("< up already at the start of the window (no AOS in it); > still up at its end (no LOS in it)\n");
}

}  // namespace

int run_passes(std::vector<std::string> args) {
  CommandRun run(kPasses, args);
  if (run.done) return *run.done;
  run.bodies_allowed = true;
  const std::vector<orbit::Body> bodies = run.bodies();
  OptionReader& in = run.in;
  const auto station = read_station(in, run.stored);
  const auto start = read_time(in, "start", run.parsed.has("start") ? wall_now() : default_start(run.parsed.value("state"), "passes"));
  const auto hours = in.number("hours", false, "H, a number of hours > 0 (at most 8784)", Range{0.0, 8784.0, true})
                         .value_or(24.0);
  const auto min_el = in.number("min-el", false, "DEG, an elevation -90..90", Range{-90.0, 90.0});
  const auto mask = read_horizon_mask_option(in, run.parsed, run.stored);
  std::optional<orbit::Observer> with;
  if (const auto w = in.text("with", false, "")) {
    const Parsed<orbit::Observer> p = parse_station_text(*w);
    if (!p.value) in.fail("--with", p.error);
    with = p.value;
  }
  const auto ics = in.text("ics", false, "");
  const orbit::EarthOrientation eo = read_dut1(in);
  const OutputFormat format = read_format(in);
  const auto plot = in.text("plot", false, "");
  // The name is checked before any work (issue 39): nothing is computed or printed for a name that
  // cannot be written.
  if (plot)
    if (const auto why = plot_name_problem(*plot)) in.fail("--plot", *why);
  if (!bodies.empty() && with) in.fail("--with", "takes satellites only, not SUN or MOON");
  if (!bodies.empty() && plot) in.fail("--plot", "draws satellites' passes only, not SUN's or MOON's");
  std::vector<Elements> sats;
  if (auto done = run.load_sats(true, sats)) return *done;

  const UtcTime stop = orbit::add_seconds(*start, hours * 3600.0);
  orbit::PassOptions options;
  options.horizon_deg = orbit::kAosThresholdDeg;
  // Passes that rise (a maximum of -0.4 deg is no pass to plan for), or above --min-el.
  options.min_max_elevation_deg = min_el ? *min_el : 1e-9;
  if (!with) options.mask = mask;  // a mutual pass is both places' plain horizons
  std::vector<SatPass> passes;
  int status = kExitOk;
  for (std::size_t set = 0; set < sats.size(); ++set) {
    const Elements& e = sats[set];
    const orbit::Sgp4 sat(e);
    if (!check_window(e, sat, *start, stop)) status = kExitFailure;
    if (sat.init_error() != orbit::Sgp4Error::none) continue;
    const std::string label = text::trim(e.name).empty() ? std::to_string(e.catalog_number) : std::string(text::trim(e.name));
    const auto found = with ? orbit::mutual_passes(sat, *station, *with, *start, stop, options)
                            : orbit::find_passes(sat, *station, *start, stop, options, eo);
    for (const orbit::Pass& p : found)
      passes.push_back({label, p, set, with ? std::optional<double>(there_max_elevation(sat, *with, p)) : std::nullopt});
  }
  for (const orbit::Body b : bodies)
    for (const orbit::Pass& p : orbit::find_body_passes(b, *station, *start, stop, options, eo))
      passes.push_back({std::string(orbit::body_name(b)), p, 0, std::nullopt});
  std::stable_sort(passes.begin(), passes.end(),
                   [](const SatPass& a, const SatPass& b) { return a.pass.aos < b.pass.aos; });

  auto iso3 = [](UtcTime t) { return orbit::format_iso8601(t, 3); };
  std::string header = printf_string(
      "station %.4f, %.4f, %.0f m%s  from %s for %g h  AOS/LOS at %.1f deg\n", station->lat_deg, station->lon_deg,
      station->height_m, run.parsed.has("station") ? "" : (" (" + run.stored.source() + ")").c_str(),
      orbit::format_iso8601(*start, 0).c_str(), hours, orbit::kAosThresholdDeg);
  if (options.mask) {
    header.pop_back();
    header += " and the horizon mask (" + options.mask->describe() + ")\n";
  }
  if (with)
    header += printf_string("with %.4f, %.4f (%s): only the times both see it; MAX EL is here's, THERE the partner's\n",
                            with->lat_deg, with->lon_deg,
                            station::maidenhead_locator(with->lat_deg, with->lon_deg).c_str());
  switch (format) {
    case OutputFormat::csv:
      out(std::string("sat,aos_utc,tca_utc,los_utc,max_el_deg,aos_az_deg,los_az_deg") + (with ? ",there_max_el_deg" : "") + "\n");
      for (const SatPass& s : passes)
        out(printf_string("%s,%s,%s,%s,%.4f,%.4f,%.4f", csv_field(s.sat).c_str(), iso3(s.pass.aos).c_str(),
                      iso3(s.pass.tca).c_str(), iso3(s.pass.los).c_str(), s.pass.max_el_deg, s.pass.aos_az_deg,
                      s.pass.los_az_deg) +
            (s.there_max_el ? printf_string(",%.4f", *s.there_max_el) : std::string()) + "\n");
      break;
    case OutputFormat::json:
      out("[");
      for (std::size_t i = 0; i < passes.size(); ++i) {
        const SatPass& s = passes[i];
        out(printf_string("%s\n  {\"sat\": %s, \"aos_utc\": %s, \"tca_utc\": %s, \"los_utc\": %s, \"max_el_deg\": %.4f, "
                      "\"aos_az_deg\": %.4f, \"los_az_deg\": %.4f",
                      i ? "," : "", json_string(s.sat).c_str(), json_string(iso3(s.pass.aos)).c_str(),
                      json_string(iso3(s.pass.tca)).c_str(), json_string(iso3(s.pass.los)).c_str(), s.pass.max_el_deg,
                      s.pass.aos_az_deg, s.pass.los_az_deg) +
            (s.there_max_el ? printf_string(", \"there_max_el_deg\": %.4f", *s.there_max_el) : std::string()) + "}");
      }
      out("\n]\n");
      break;
    case OutputFormat::table:
      print_table(passes, header, sats, *start, !bodies.empty());
      break;
  }
  std::fflush(stdout);
  if (ics && write_ics(*ics, passes, *station, with, format == OutputFormat::table ? stdout : stderr) != kExitOk)
    return kExitFailure;
  if (plot && plot_passes(*plot, passes, sats, *station, options.mask, run.stored, format == OutputFormat::table ? stdout : stderr) !=
                  kExitOk)
    return kExitFailure;
  return status;
}

}  // namespace tb::app
