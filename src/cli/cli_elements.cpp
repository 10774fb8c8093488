#include "cli/cli_elements.h"

#include <chrono>
#include <cstdio>
#include <optional>
#include <utility>

#include "orbit/sgp4.h"
#include "util/text.h"

namespace tb::app {
namespace {

using orbit::Elements;

const std::vector<OptionSpec>& element_specs() {
  static const std::vector<OptionSpec> specs = {
      {"to", "FORMAT", "write the sets to stdout as tle, omm-json, omm-xml, omm-csv or omm-kvn"},
      no_checksum_option(),
      {"time", "ISO8601", "the time ages are given at, UTC (default: now)"},
      {"help", "", "show this help"}};
  return specs;
}

std::string elements_usage() {
  return "usage: trakbox elements FILE... [--to tle|omm-json|omm-xml|omm-csv|omm-kvn] [--no-checksum]\n"
         "                        [--time ISO8601]\n\n"
         "Reads element files in any format trakbox knows (NASA 2/3-line TLE, AMSAT verbose, gpredict,\n"
         "CCSDS OMM as JSON, XML, CSV or KVN; detected from the content) and lists each set: name,\n"
         "catalog number, epoch, age at --time in days, format, and orbit (near-earth or deep-space,\n"
         "period). With --to, writes every set read to stdout in that format instead. Problems go to\n"
         "stderr naming file, line and object; the exit status is 1 when any set was refused or cannot\n"
         "be written (a TLE holds catalog numbers up to 339999).\n\noptions:\n" +
         describe_options(element_specs());
}

int usage_error(const ArgError& e) {
  std::fprintf(stderr, "trakbox elements: %s (see trakbox elements --help)\n", e.text().c_str());
  return kExitUsage;
}

std::string label(const Elements& e) {
  const std::string name(text::trim(e.name));
  return name.empty() ? std::to_string(e.catalog_number) : name + " (" + std::to_string(e.catalog_number) + ")";
}

enum class Target { tle, omm_json, omm_xml, omm_csv, omm_kvn };

std::optional<Target> target_of(std::string_view s) {
  constexpr std::pair<const char*, Target> kTargets[] = {{"tle", Target::tle},
                                                         {"omm-json", Target::omm_json},
                                                         {"omm-xml", Target::omm_xml},
                                                         {"omm-csv", Target::omm_csv},
                                                         {"omm-kvn", Target::omm_kvn}};
  for (const auto& [name, target] : kTargets)
    if (text::iequals(s, name)) return target;
  return std::nullopt;
}

// "near-earth, period 92.9 min" or the reason SGP4 cannot use the set.
std::string orbit_text(const Elements& e, bool& failed) {
  const orbit::Sgp4 sat(e);
  if (sat.init_error() != orbit::Sgp4Error::none) {
    failed = true;
    return std::string("SGP4 cannot use it: ") + orbit::describe(sat.init_error());
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s, period %.1f min", sat.deep_space() ? "deep-space" : "near-earth",
                sat.period_minutes());
  return buf;
}

// Each set of one file as a table row.
bool list_sets(const std::string& file, const std::vector<Elements>& sets, orbit::UtcTime at) {
  bool ok = true;
  std::printf("%s: %zu element set%s, ages at %s\n", file.c_str(), sets.size(), sets.size() == 1 ? "" : "s",
              orbit::format_iso8601(at, 0).c_str());
  if (sets.empty()) return ok;
  std::printf("  %-24s  %9s  %-27s  %9s  %-8s  %s\n", "NAME", "CATALOG", "EPOCH (UTC)", "AGE DAYS", "FORMAT", "ORBIT");
  for (const Elements& e : sets) {
    bool failed = false;
    const std::string orbit = orbit_text(e, failed);
    if (failed) {
      std::fprintf(stderr, "trakbox elements: %s: %s: %s\n", file.c_str(), label(e).c_str(), orbit.c_str());
      ok = false;
    }
    const double age_days = orbit::minutes_between(e.epoch(), at) / orbit::kMinutesPerDay;
    std::printf("  %-24s  %9d  %-27s  %+9.2f  %-8s  %s\n", e.name.empty() ? "-" : e.name.c_str(), e.catalog_number,
                orbit::format_iso8601(e.epoch(), 6).c_str(), age_days, orbit::describe(e.source), orbit.c_str());
  }
  return ok;
}

// The sets in the target format; nothing when one cannot be written (told on stderr).
std::optional<std::string> convert(const std::vector<Elements>& sets, Target target) {
  switch (target) {
    case Target::omm_json: return orbit::format_omm(sets, orbit::OmmEncoding::json);
    case Target::omm_xml: return orbit::format_omm(sets, orbit::OmmEncoding::xml);
    case Target::omm_csv: return orbit::format_omm(sets, orbit::OmmEncoding::csv);
    case Target::omm_kvn: return orbit::format_omm(sets, orbit::OmmEncoding::kvn);
    case Target::tle: break;
  }
  std::string out;
  bool ok = true;
  for (const Elements& e : sets) {
    if (const auto why = orbit::nasa_unwritable(e)) {
      std::fprintf(stderr, "trakbox elements: %s: no TLE: %s\n", label(e).c_str(), why->c_str());
      ok = false;
      continue;
    }
    out += orbit::format_nasa(e);
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace

OptionSpec no_checksum_option() {
  return {"no-checksum", "", "accept NASA sets whose line checksum is wrong (each one is warned about)"};
}

orbit::ParseOptions checked_options(bool verify_checksums) {
  orbit::ParseOptions o;
  o.verify_checksums = verify_checksums;
  return o;
}

void report_problems(const std::vector<orbit::ParseProblem>& problems, std::FILE* to) {
  for (const orbit::ParseProblem& p : problems) {
    std::fprintf(to, "trakbox: %s: %s%s\n", p.warning ? "warning" : "error", p.message().c_str(),
                 !p.warning && p.field == "checksum" ? " (set refused; --no-checksum accepts it)" : "");
  }
}

void report_accepted_checksums(std::string_view text, const std::string& file, std::FILE* to) {
  const orbit::ParseResult strict = orbit::parse_elements(text, file, checked_options(true));
  for (orbit::ParseProblem p : strict.problems) {
    if (p.field != "checksum") continue;
    p.warning = true;  // message() ends "(warning: set accepted)"
    std::fprintf(to, "trakbox: warning: %s\n", p.message().c_str());
  }
}

int run_elements(std::vector<std::string> args) {
  const ParseOutcome po = parse_options(args, element_specs());
  if (po.error) return usage_error(*po.error);
  const ParsedOptions& parsed = po.options;
  if (parsed.has("help")) {
    std::fputs(elements_usage().c_str(), stdout);
    return kExitOk;
  }
  if (parsed.positional().empty()) return usage_error({"FILE", "missing; expected one or more element files"});
  std::optional<Target> target;
  if (const auto to = parsed.value("to")) {
    target = target_of(*to);
    if (!target) return usage_error({"--to", "expected tle, omm-json, omm-xml, omm-csv or omm-kvn, found '" + *to + "'"});
  }
  orbit::UtcTime at = std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
  if (const auto t = parsed.value("time")) {
    const auto parsed_time = orbit::parse_iso8601(*t);
    if (!parsed_time)
      return usage_error({"--time", "expected ISO8601 UTC (YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS[.fff]][Z]), found '" + *t + "'"});
    at = *parsed_time;
  }
  const bool verify = !parsed.has("no-checksum");

  bool ok = true;
  std::vector<Elements> all;
  for (const std::string& file : parsed.positional()) {
    const orbit::ParseResult r = orbit::load_elements_file(file, checked_options(verify));
    report_problems(r.problems, stderr);
    if (!r.ok()) ok = false;
    if (!verify) {
      // Read again with checksums checked, only to name the sets --no-checksum let pass.
      std::vector<orbit::ParseProblem> accepted;
      for (orbit::ParseProblem& p : orbit::load_elements_file(file, checked_options(true)).problems) {
        if (p.field != "checksum") continue;
        p.warning = true;
        accepted.push_back(std::move(p));
      }
      report_problems(accepted, stderr);
    }
    if (target) all.insert(all.end(), r.sets.begin(), r.sets.end());
    else if (!list_sets(file, r.sets, at)) ok = false;
  }
  if (target) {
    const auto text = convert(all, *target);
    if (!text) return kExitFailure;
    std::fwrite(text->data(), 1, text->size(), stdout);
  }
  return ok ? kExitOk : kExitFailure;
}

}  // namespace tb::app
