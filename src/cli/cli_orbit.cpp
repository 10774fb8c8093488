#include "cli/cli_orbit.h"
#include "cli/cli_orbit_internal.h"
#include "util/safe_text.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include "cli/cli_defaults.h"
#include "cli/cli_elements.h"
#include "cli/options.h"
#include "orbit/element_age.h"
#include "orbit/elements.h"
#include "orbit/horizon_mask.h"
#include "orbit/observe.h"
#include "orbit/sgp4_batch.h"
#include "orbit/sgp4.h"
#include "orbit/state_lines.h"
#include "store/model.h"
#include "util/format.h"
#include "util/closest.h"
#include "util/files.h"
#include "util/text.h"

namespace tb::app {
using namespace orbit_cli;

namespace orbit_cli {

// ---------------------------------------------------------------------------------------------
// Text helpers

void out(const std::string& s) { std::fwrite(s.data(), 1, s.size(), stdout); }

// A JSON string of printable UTF-8 whatever `s` holds (util/safe_text.h): "JSON" output is JSON.
std::string json_string(std::string_view raw) {
  const std::string s = text::safe_text(raw);
  std::string r = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\r': r += "\\r"; break;
      case '\t': r += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) r += printf_string("\\u%04x", static_cast<unsigned char>(c));
        else r += c;
    }
  }
  return r + "\"";
}

std::string csv_field(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string r = "\"";
  for (const char c : s) {
    if (c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

std::string choice_label(const Elements& e) {
  const std::string name(text::trim(e.name));
  return name.empty() ? std::to_string(e.catalog_number) : name + " (" + std::to_string(e.catalog_number) + ")";
}

void warn_stale(const char* command, const Elements& e, UtcTime first, UtcTime last) {
  for (const UtcTime t : {first, last}) {
    const std::string w = orbit::element_age(e, t).warning();
    if (w.empty()) continue;
    std::fprintf(stderr, "trakbox %s: warning: %s: %s at %s\n", command, choice_label(e).c_str(), w.c_str(),
                 orbit::format_iso8601(t, 0).c_str());
    return;
  }
}

std::string manual_time(UtcTime t, int decimals) {
  const std::string iso = orbit::format_iso8601(t, decimals);  // 2018-01-21T03:37:10[.fff]Z
  std::string s = iso.substr(0, iso.size() - 1);
  s[4] = '/';
  s[7] = '/';
  s[10] = ' ';
  return s;
}

}  // namespace orbit_cli

namespace {

using text::lower;

// Digits of seconds needed to show every time start + i * step exactly: 0, 3 or 6.
int seconds_decimals(UtcTime start, std::chrono::microseconds step) {
  const auto us_of = [](std::int64_t v) { return ((v % 1000000) + 1000000) % 1000000; };
  const std::int64_t a = us_of(start.time_since_epoch().count()), b = us_of(step.count());
  if (a == 0 && b == 0) return 0;
  if (a % 1000 == 0 && b % 1000 == 0) return 3;
  return 6;
}

// ---------------------------------------------------------------------------------------------
// Element files and satellite selection

const char* const kElementsHelp =
    "an element file (NASA 2/3-line, AMSAT verbose, gpredict .sat/satellites.dat, or OMM JSON/XML/CSV/KVN)";

struct LoadedElements {
  std::vector<Elements> sets;
  std::optional<ArgError> error;
  // With `defer`: what would have been reported on stderr, for the caller to report or sum up.
  std::vector<orbit::ParseProblem> problems;
};

// Problems the caller deferred: every one when the chosen satellites were not found, else one line
// (the sets it refused are other satellites than the ones asked for; issue 30: Vallado's file made
// the README's propagate example print three checksum errors for sets it never used).
void report_deferred(const LoadedElements& l, const std::string& path, bool chosen) {
  if (l.problems.empty()) return;
  if (!chosen) {
    report_problems(l.problems, stderr);
    return;
  }
  // Warnings are about sets that were taken, perhaps the one asked for: said in full.
  std::vector<orbit::ParseProblem> warnings;
  for (const auto& p : l.problems)
    if (p.warning) warnings.push_back(p);
  report_problems(warnings, stderr);
  std::string lines;
  int refused = 0;
  for (const auto& p : l.problems)
    if (!p.warning) {
      ++refused;
      lines += (lines.empty() ? "" : ", ") + std::to_string(p.line) + (p.field.empty() ? "" : " (" + p.field + ")");
    }
  if (refused > 0)
    std::fprintf(stderr, "trakbox: note: %s: %d other set(s) refused, at line %s (trakbox elements FILE lists them)\n",
                 path.c_str(), refused, lines.c_str());
}

LoadedElements load_elements(const std::string& path, bool verify_checksums, bool defer = false) {
  LoadedElements r;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    r.error = ArgError{"ELEMENTS", "'" + path + "' is a folder; expected " + kElementsHelp};
    return r;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    r.error = ArgError{"ELEMENTS", "cannot read '" + path + "': " + std::strerror(errno) + "; expected " + kElementsHelp};
    return r;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    r.error = ArgError{"ELEMENTS", "cannot read '" + path + "'"};
    return r;
  }
  // parse_elements recognises the format (OMM encodings, AMSAT blocks, gpredict keys, NASA lines).
  orbit::ParseResult parsed = orbit::parse_elements(text, path, checked_options(verify_checksums));
  if (defer) r.problems = parsed.problems;
  else report_problems(parsed.problems, stderr);
  if (!verify_checksums && !defer) report_accepted_checksums(text, path, stderr);
  if (parsed.sets.empty()) {
    r.error = ArgError{"ELEMENTS", "no usable element set in '" + path + "'; expected " + kElementsHelp};
    return r;
  }
  r.sets = std::move(parsed.sets);
  return r;
}

std::string list_choices(const std::vector<Elements>& sets) {
  constexpr std::size_t kMax = 30;
  std::string s;
  for (std::size_t i = 0; i < sets.size() && i < kMax; ++i) s += (i ? ", " : "") + choice_label(sets[i]);
  if (sets.size() > kMax) s += printf_string(", ... (%zu more)", sets.size() - kMax);
  return s;
}

}  // namespace

std::optional<std::size_t> match_sat(const std::vector<Elements>& sets, const std::string& key, std::string& why) {
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < sets.size(); ++i)
    if (sets[i].name == key) hits.push_back(i);
  if (hits.empty()) {
    const std::string k = lower(text::trim(key));
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (!k.empty() && lower(text::trim(sets[i].name)) == k) hits.push_back(i);
  }
  if (hits.empty()) {
    std::optional<std::int64_t> number = to_int64(key);
    if (!number && key.size() == 5) {
      const int n = orbit::decode_catalog_number(key);
      if (n >= 0) number = n;
    }
    if (number)
      for (std::size_t i = 0; i < sets.size(); ++i)
        if (sets[i].catalog_number == *number) hits.push_back(i);
  }
  if (hits.empty()) {
    std::vector<std::string> names;
    for (const Elements& e : sets) names.emplace_back(text::trim(e.name));
    why = "no element set named or numbered '" + key + "'" + text::did_you_mean(key, names) + "; the file holds " +
          list_choices(sets);
    return std::nullopt;
  }
  // Different satellites under one name (rocket bodies: "SL-8 R/B") need the catalog number;
  // several sets of one satellite (successive epochs) resolve to the newest.
  std::size_t best = hits.front();
  for (const std::size_t i : hits) {
    if (sets[i].catalog_number != sets[best].catalog_number) {
      std::string list;
      for (const std::size_t k : hits) list += (list.empty() ? "" : ", ") + choice_label(sets[k]);
      why = "'" + key + "' names several satellites (" + list + "); give the catalog number";
      return std::nullopt;
    }
    if (sets[i].epoch() > sets[best].epoch()) best = i;
  }
  if (hits.size() > 1)
    std::fprintf(stderr, "trakbox: warning: --sat %s: %zu element sets match; using the newest, epoch %s\n",
                 key.c_str(), hits.size(), orbit::format_iso8601(sets[best].epoch(), 3).c_str());
  return best;
}

namespace {

// The sets named by --sat (in command-line order), or the only set of the file. With allow_all,
// no --sat selects every set.
std::vector<Elements> select_sats(const std::vector<Elements>& sets, const std::vector<std::string>& keys,
                                  bool allow_all, const std::string& path, OptionReader& in) {
  std::vector<Elements> chosen;
  if (keys.empty()) {
    if (sets.size() == 1 || allow_all) return sets;
    in.fail("ELEMENTS", printf_string("'%s' holds %zu element sets; choose one with --sat NAME|NUMBER: ", path.c_str(),
                                  sets.size()) + list_choices(sets));
    return chosen;
  }
  for (const std::string& key : keys) {
    std::string why;
    const auto i = match_sat(sets, key, why);
    if (!i) {
      in.fail("--sat", why);
      return {};
    }
    chosen.push_back(sets[*i]);
  }
  return chosen;
}

}  // namespace

namespace orbit_cli {

OptionSpec repeatable(OptionSpec spec) {
  spec.repeatable = true;
  return spec;
}

std::optional<orbit::Observer> read_station(OptionReader& in, StoredStation& stored) {
  const auto text = in.text("station", false, "");
  if (!text) {
    const auto o = stored.station();
    if (!o) in.fail("--station", "missing, and " + stored.error());
    return o;
  }
  const Parsed<orbit::Observer> p = parse_station_text(*text);
  if (!p.value) in.fail("--station", p.error);
  return p.value;
}

std::shared_ptr<const orbit::HorizonMask> read_horizon_mask_option(OptionReader& in, const ParsedOptions& parsed,
                                                                   StoredStation& stored) {
  const auto file = in.text("horizon-mask", false, "");
  if (!file) {
    if (parsed.has("station")) return nullptr;
    const store::Model* m = stored.model();
    return m ? m->station.mask() : nullptr;
  }
  if (*file == "none") return nullptr;
  const auto content = files::read_whole_file(*file);
  if (!content) {
    in.fail("--horizon-mask", "cannot read " + *file);
    return nullptr;
  }
  auto read = orbit::read_horizon_mask(*content, *file);
  if (!read.mask) {
    in.fail("--horizon-mask", read.error);
    return nullptr;
  }
  return std::make_shared<const orbit::HorizonMask>(std::move(*read.mask));
}

std::optional<UtcTime> read_time(OptionReader& in, std::string_view name, UtcTime now) {
  const auto text = in.text(name, false, "");
  if (!text) return now;
  const Parsed<UtcTime> p = parse_time_text(*text, now);
  if (!p.value) in.fail(OptionReader::option_label(name), p.error);
  return p.value;
}

UtcTime wall_now() {
  return std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
}

orbit::EarthOrientation read_dut1(OptionReader& in) {
  const auto v = in.number("dut1", false, "S, UT1-UTC in seconds (-1 < S < 1)", Range{-1.0, 1.0, true, true});
  return {v.value_or(0.0)};
}

OutputFormat read_format(OptionReader& in) {
  const bool csv = in.flag("csv"), json = in.flag("json");
  if (csv && json) in.fail("--json", "expected at most one of --csv and --json");
  return csv ? OutputFormat::csv : json ? OutputFormat::json : OutputFormat::table;
}

std::string usage(const Command& c) {
  return std::string("usage: trakbox ") + c.name + " " + c.synopsis + "\n\n" + c.description + "\n\noptions:\n" +
         describe_options(c.specs);
}

int usage_error(const Command& c, const ArgError& e) {
  std::fprintf(stderr, "trakbox %s: %s (see trakbox %s --help)\n", c.name, e.text().c_str(), c.name);
  return kExitUsage;
}

CommandRun::CommandRun(const Command& c, const std::vector<std::string>& args) : command(c) {
  ParseOutcome po = parse_options(args, c.specs);
  if (po.error) {
    done = usage_error(c, *po.error);
    return;
  }
  parsed = std::move(po.options);
  if (parsed.has("help")) {
    out(usage(c));
    done = kExitOk;
    return;
  }
  const auto& pos = parsed.positional();
  if (pos.empty() && !c.stored_database)
    done = usage_error(c, {"ELEMENTS", std::string("missing; expected ") + kElementsHelp});
  else if (pos.size() > 1) done = usage_error(c, {pos[1], "unexpected argument (ELEMENTS is given once)"});
  else if (!pos.empty()) path = pos[0];
  if (const auto dir = parsed.value("state")) stored = StoredStation(std::filesystem::path(*dir));
}

std::vector<std::string> CommandRun::sat_keys() const {
  std::vector<std::string> keys;
  for (const std::string& k : parsed.values("sat"))
    if (!bodies_allowed || !orbit::parse_body(k)) keys.push_back(k);
  return keys;
}

std::vector<orbit::Body> CommandRun::bodies() const {
  std::vector<orbit::Body> found;
  if (!bodies_allowed) return found;
  for (const std::string& k : parsed.values("sat"))
    if (const auto b = orbit::parse_body(k)) found.push_back(*b);
  return found;
}

std::optional<int> CommandRun::load_sats(bool allow_all, std::vector<Elements>& sats) {
  if (!in.ok()) return error(*in.error());
  // Only SUN and MOON asked for: no elements needed.
  if (!bodies().empty() && sat_keys().empty()) return std::nullopt;
  if (path.empty()) return load_stored(allow_all, sats);
  const bool named = !sat_keys().empty();
  // With --no-checksum every accepted set's checksum is named: nothing is deferred then.
  const bool verify = !parsed.has("no-checksum");
  // `trakbox passes RS-44`: no file of that name, but a satellite of the stored database is.
  if (!std::filesystem::exists(path) && path.find('/') == std::string::npos && path.find('.') == std::string::npos)
    if (const auto sets = stored.database()) {
      std::vector<std::string> names;
      for (const Elements& e : *sets) names.emplace_back(text::trim(e.name));
      if (const auto meant = text::closest_name(path, names))
        return error({path, "no such element file; to name a satellite of the database: --sat " + *meant +
                                " (trakbox " + std::string(command.name) + " --sat " + *meant + ")"});
    }
  const LoadedElements loaded = load_elements(path, verify, named && verify);
  if (loaded.error) {
    report_deferred(loaded, path, false);
    return error(*loaded.error);
  }
  sats = select_sats(loaded.sets, sat_keys(), allow_all, path, in);
  report_deferred(loaded, path, in.ok());
  if (!in.ok()) return error(*in.error());
  return std::nullopt;
}

std::optional<int> CommandRun::load_stored(bool allow_all, std::vector<Elements>& sats) {
  const auto keys = sat_keys();
  const auto sets = keys.empty() ? stored.tracking_list() : stored.database();
  if (!sets) return error({"ELEMENTS", "missing, and " + stored.error()});
  if (sets->empty()) return error({"ELEMENTS", "missing, and the stored database is empty (" + stored.source() + ")"});
  if (keys.empty()) {
    sats = allow_all ? *sets : std::vector<Elements>{sets->front()};
    return std::nullopt;
  }
  sats = select_sats(*sets, keys, allow_all, "the stored database (" + stored.source() + ")", in);
  if (!in.ok()) return error(*in.error());
  return std::nullopt;
}

}  // namespace orbit_cli

namespace {

std::optional<std::int64_t> read_frequency(OptionReader& in, std::string_view name) {
  const auto text = in.text(name, false, "");
  if (!text) return std::nullopt;
  const Parsed<std::int64_t> p = parse_frequency_text(*text);
  if (!p.value) in.fail(OptionReader::option_label(name), p.error);
  return p.value;
}

// ---------------------------------------------------------------------------------------------
// propagate

const Command kPropagate{
    "propagate", "ELEMENTS [--sat NAME|NUMBER] --start MIN --stop MIN --step MIN [--no-checksum]",
    "Prints SGP4/SDP4 state vectors in the TEME frame, one line per time: minutes from epoch, x y z\n"
    "(km) and xdot ydot zdot (km/s), as Vallado's tcppver.out. The last line is --stop itself when\n"
    "the steps do not land on it. When propagation fails, a line '# sgp4 error N at tsince T min\n"
    "(UTC): meaning' ends the output and the exit status is 1.",
    {kSatOption,
     {"start", "MIN", "first time, minutes from the element-set epoch (may be negative)"},
     {"stop", "MIN", "last time, minutes from epoch (>= --start)"},
     {"step", "MIN", "minutes between lines (> 0)"},
     kNoChecksumOption,
     kHelpOption}};

}  // namespace

int run_propagate(std::vector<std::string> args) {
  CommandRun run(kPropagate, args);
  if (run.done) return *run.done;
  OptionReader& in = run.in;
  const auto start = in.number("start", true, "MIN, minutes from epoch");
  const auto stop = in.number("stop", true, "MIN, minutes from epoch");
  const auto step = in.number("step", true, "MIN, a number of minutes > 0", Range{0.0, std::nullopt, true});
  if (in.ok() && *stop < *start)
    in.fail("--stop", printf_string("expected MIN >= --start (%g), found '%s'", *start, run.parsed.value("stop")->c_str()));
  if (in.ok() && (*stop - *start) / *step > 1e7)
    in.fail("--step", "too small: more than 10000000 lines between --start and --stop");
  std::vector<Elements> sats;
  if (auto done = run.load_sats(false, sats)) return *done;

  const orbit::Sgp4 sat(sats.front());
  // Lines are gathered and written 64 kB at a time; numbers are formatted by text::append_fixed,
  // which gives printf's characters at a fraction of its cost (bench_sgp4 BM_PropagateLine*). The states
  // come 512 at a time from the batch propagator (orbit/sgp4_batch.h, vectorised).
  std::string buf;
  buf.reserve(1 << 17);
  auto flush = [&] {
    out(buf);
    buf.clear();
  };
  // Times start + i * step (multiplied, not summed, so no drift); a step that lands within
  // rounding of --stop counts as landing on it, so --stop is printed once.
  const double tol = 1e-9 * std::max(1.0, std::abs(*stop));
  constexpr std::size_t kBlock = 512;
  std::vector<double> times;
  std::vector<orbit::Propagation> states(kBlock);
  times.reserve(kBlock);
  std::int64_t i = 0;
  bool last = false;
  while (!last) {
    times.clear();
    while (times.size() < kBlock) {
      const double t = *start + static_cast<double>(i) * *step;
      if (t >= *stop - tol) {
        times.push_back(*stop);
        last = true;
        break;
      }
      times.push_back(t);
      ++i;
    }
    orbit::propagate_batch(sat, times, states);
    for (std::size_t k = 0; k < times.size(); ++k) {
      const orbit::Propagation& p = states[k];
      if (!p.ok()) {
        flush();
        out(printf_string("# sgp4 error %d at tsince %.8f min (%s): %s\n", static_cast<int>(p.error), times[k],
                      orbit::format_iso8601(orbit::add_minutes(sat.epoch(), times[k]), 6).c_str(),
                      orbit::describe(p.error)));
        return kExitFailure;
      }
      orbit::append_state_line(buf, times[k], p.state);
      if (buf.size() >= (1u << 16)) flush();
    }
  }
  flush();
  return kExitOk;
}

// ---------------------------------------------------------------------------------------------
// schedule

namespace {

const Command kSchedule{
    "schedule",
    "[ELEMENTS] [--sat NAME|NUMBER] [--station LAT,LON[,HEIGHT_M]|LOCATOR] [--start ISO8601|now|+2h]\n"
    "                        [--step SECONDS] --count N [--freq HZ|MHZ.] [--state DIR] [--dut1 S] [--csv|--json]\n"
    "                        [--no-checksum]",
    "The TrakBox menu-2 schedule: where one satellite is, seen from the station, at --count times\n"
    "--step seconds apart. Azimuth/elevation (deg), phase (256ths of an orbit), Doppler shift at\n"
    "--freq (Hz, + approaching), range (km), range rate (km/s, + receding), and the sub-satellite\n"
    "point (altitude km above the WGS-84 ellipsoid, latitude, longitude). CSV and JSON columns:\n"
    "utc, az_deg, el_deg, range_km, range_rate_km_s, alt_km, lat_deg, lon_deg, phase256, doppler_hz.\n"
    "Without ELEMENTS, the stored database (--state) and, without --sat, the first of its tracking list.",
    {kSatOption,
     kStationOption,
     {"start", "ISO8601|now|+2h", "first time, UTC (2018-01-21T03:37:10Z), now (the default), or now plus an "
                                  "amount (+2h, +30m, -1d)"},
     {"step", "SECONDS", "seconds between rows (> 0; default 60)"},
     {"count", "N", "number of rows (1..10000000)"},
     {"freq", "HZ|MHZ.", "downlink frequency for the Doppler column: hertz (437800000), MHz with a decimal "
                         "point (437.8), or with a unit (437.8MHz) (default: none, 0)"},
     kStateOption,
     kDut1Option,
     kCsvOption,
     {"json", "", "a JSON array of row objects"},
     kNoChecksumOption,
     kHelpOption},
    true};

}  // namespace

int run_schedule(std::vector<std::string> args) {
  CommandRun run(kSchedule, args);
  if (run.done) return *run.done;
  OptionReader& in = run.in;
  const auto station = read_station(in, run.stored);
  const auto start = read_time(in, "start", run.parsed.has("start") ? wall_now() : default_start(run.parsed.value("state"), "schedule"));
  // One row a minute unless asked otherwise (issue 39), as menu 2's schedule steps by default.
  const auto step_s = in.number("step", false, "SECONDS, a number > 0 (at most one day)", Range{0.0, 86400.0, true})
                          .value_or(60.0);
  const auto count = in.integer("count", true, "N, a whole number 1..10000000", Range{1.0, 1e7});
  const auto freq = read_frequency(in, "freq");
  const orbit::EarthOrientation eo = read_dut1(in);
  const OutputFormat format = read_format(in);
  std::chrono::microseconds step{0};
  if (in.ok()) {
    step = std::chrono::microseconds(std::llround(step_s * 1e6));
    if (step.count() <= 0) in.fail("--step", "expected SECONDS, at least one microsecond");
  }
  std::vector<Elements> sats;
  if (auto done = run.load_sats(false, sats)) return *done;
  if (sats.size() > 1) return run.error({"--sat", "expected one satellite for a schedule"});

  const orbit::Sgp4 sat(sats.front());
  warn_stale("schedule", sats.front(), *start, *start + step * (*count - 1));
  const int decimals = seconds_decimals(*start, step);
  const double f = freq ? static_cast<double>(*freq) : 0.0;

  if (format == OutputFormat::csv)
    out("utc,az_deg,el_deg,range_km,range_rate_km_s,alt_km,lat_deg,lon_deg,phase256,doppler_hz\n");
  if (format == OutputFormat::json) out("[");
  if (format == OutputFormat::table) {
    out(printf_string("%s  station %.4f, %.4f, %.0f m  elements epoch %s, age %s%s\n", choice_label(sats.front()).c_str(),
                  station->lat_deg, station->lon_deg, station->height_m,
                  orbit::format_iso8601(sats.front().epoch(), 0).c_str(),
                  orbit::element_age(sats.front(), *start).text().c_str(),
                  freq ? printf_string("  Doppler at %lld Hz", static_cast<long long>(*freq)).c_str() : ""));
    const int time_width = static_cast<int>(manual_time(*start, decimals).size());
    out(printf_string("%-*s  %-11s  %6s  %8s  %10s  %10s  %8s  %8s\n", time_width,
                  "DATE       TIME", "AZ/EL", "Phase", "Doppler", "Range km", "Alt km", "Lat deg", "Lon deg"));
  }
  int status = kExitOk;
  // The states come 512 at a time from the batch propagator (orbit/sgp4_batch.h).
  constexpr std::int64_t kBlock = 512;
  std::vector<double> tsince;
  std::vector<orbit::Propagation> states(kBlock);
  for (std::int64_t i = 0; i < *count; ++i) {
    const UtcTime t = *start + step * i;
    if (i % kBlock == 0) {
      tsince.clear();
      for (std::int64_t j = i; j < std::min(*count, i + kBlock); ++j)
        tsince.push_back(orbit::minutes_between(sat.epoch(), *start + step * j));
      orbit::propagate_batch(sat, tsince, states);
    }
    const orbit::Observation o = orbit::observe(sat, *station, t, states[static_cast<std::size_t>(i % kBlock)], eo);
    if (!o.ok()) {
      std::fprintf(stderr, "trakbox schedule: %s: sgp4 error %d at %s: %s; no positions from then on\n",
                   choice_label(sats.front()).c_str(), static_cast<int>(o.error),
                   orbit::format_iso8601(t, decimals).c_str(), orbit::describe(o.error));
      status = kExitFailure;
      break;
    }
    const double doppler = orbit::doppler_shift_hz(f, o.look.range_rate_km_s);
    switch (format) {
      case OutputFormat::csv:
        out(printf_string("%s,%.6f,%.6f,%.6f,%.9f,%.6f,%.6f,%.6f,%.4f,%.3f\n", orbit::format_iso8601(t, decimals).c_str(),
                      o.look.az_deg, o.look.el_deg, o.look.range_km, o.look.range_rate_km_s, o.sub_point.alt_km,
                      o.sub_point.lat_deg, o.sub_point.lon_deg, o.phase256, doppler));
        break;
      case OutputFormat::json:
        out(printf_string("%s\n  {\"utc\": %s, \"az_deg\": %.6f, \"el_deg\": %.6f, \"range_km\": %.6f, "
                      "\"range_rate_km_s\": %.9f, \"alt_km\": %.6f, \"lat_deg\": %.6f, \"lon_deg\": %.6f, "
                      "\"phase256\": %.4f, \"doppler_hz\": %.3f}",
                      i ? "," : "", json_string(orbit::format_iso8601(t, decimals)).c_str(), o.look.az_deg,
                      o.look.el_deg, o.look.range_km, o.look.range_rate_km_s, o.sub_point.alt_km, o.sub_point.lat_deg,
                      o.sub_point.lon_deg, o.phase256, doppler));
        break;
      case OutputFormat::table:
        out(printf_string("%s  %5.1f/%5.1f  %6.1f  %8s  %10.1f  %10.1f  %8.1f  %8.1f\n", manual_time(t, decimals).c_str(),
                      o.look.az_deg, o.look.el_deg, o.phase256,
                      freq ? printf_string("%+.0f", doppler).c_str() : "-", o.look.range_km, o.sub_point.alt_km,
                      o.sub_point.lat_deg, o.sub_point.lon_deg));
        break;
    }
  }
  if (format == OutputFormat::json) out("\n]\n");
  return status;
}

std::string orbit_commands_summary() {
  return "  propagate   SGP4 state vectors (TEME) from minutes after epoch, as Vallado's tcppver.out\n"
         "  schedule    the menu-2 table: look angles, phase, Doppler, range and sub-point at fixed steps\n"
         "  passes      AOS, TCA and LOS of passes over the station\n"
         "  next        the next pass of each satellite (the tracking list), one line each; --watch\n"
         "  elements    list the element sets of files (age, format, orbit), or convert them (--to)\n";
}

}  // namespace tb::app
