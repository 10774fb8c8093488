// What the orbit commands share inside src/app: cli_orbit.cpp (propagate, schedule, and the front
// matter every command has) and cli_passes.cpp (passes). Not for use beyond them.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/cli_defaults.h"
#include "cli/cli_elements.h"
#include "cli/options.h"
#include "orbit/elements.h"
#include "orbit/horizon_mask.h"
#include "orbit/observe.h"
#include "orbit/sky.h"
#include "util/format.h"

namespace tb::app::orbit_cli {

using orbit::Elements;
using orbit::UtcTime;
using text::printf_string;

// ---------------------------------------------------------------------------------------------
// Text helpers

void out(const std::string& s);  // to stdout, as is
std::string json_string(std::string_view s);
std::string csv_field(std::string_view s);
// "ISS (ZARYA) (25544)" or "25544".
std::string choice_label(const Elements& e);
// A warning on stderr when the set is past the age its orbit allows at `first` or `last` (the span
// a command computes over).
void warn_stale(const char* command, const Elements& e, UtcTime first, UtcTime last);
// "2018/01/21 03:37:10" (the manual's date and time), with `decimals` digits of seconds.
std::string manual_time(UtcTime t, int decimals);

enum class OutputFormat { table, csv, json };

// ---------------------------------------------------------------------------------------------
// The options several commands share, described once; each is read by the function below it.

inline const OptionSpec kSatOption{"sat", "NAME|NUMBER", "satellite by name (exact, then any case) or catalog number"};
inline const OptionSpec kHelpOption{"help", "", "show this help"};
inline const OptionSpec kNoChecksumOption = no_checksum_option();
OptionSpec repeatable(OptionSpec spec);

inline const OptionSpec kStationOption{"station", "LAT,LON[,HEIGHT_M]|LOCATOR",
                                       "station: degrees north, degrees east (or 48.85N,2.35E), metres above the "
                                       "WGS-84 ellipsoid (default 0), or a Maidenhead locator (JN18du); default the "
                                       "stored station (menu 4)"};
inline const OptionSpec kStateOption{"state", "DIR",
                                     "the state the menus keep (default as for the menus): its station, "
                                     "database and tracking list stand in for what is not given"};
// --station, else the stored station.
std::optional<orbit::Observer> read_station(OptionReader& in, StoredStation& stored);
inline const OptionSpec kHorizonMaskOption{
    "horizon-mask", "FILE|none",
    "a horizon mask (AZ EL per line, a CSV az,el, or a step list AZ EL ... AZ): AOS and LOS where the sky is "
    "clear; default the stored station's mask when --station is not given, none otherwise"};
// --horizon-mask FILE (read, a problem named with its file and line), `none`; else the stored
// station's mask when --station is not given. Nothing: the plain horizon.
std::shared_ptr<const orbit::HorizonMask> read_horizon_mask_option(OptionReader& in, const ParsedOptions& parsed,
                                                                   StoredStation& stored);
// --NAME as a time (ISO 8601, now, +2h), else now.
std::optional<UtcTime> read_time(OptionReader& in, std::string_view name, UtcTime now);
UtcTime wall_now();

inline const OptionSpec kDut1Option{"dut1", "S", "UT1-UTC in seconds (default 0)"};
orbit::EarthOrientation read_dut1(OptionReader& in);

inline const OptionSpec kCsvOption{"csv", "", "comma-separated values with a header line"};
// --csv, or --json (described by each command: what its array holds).
OutputFormat read_format(OptionReader& in);

// ---------------------------------------------------------------------------------------------
// Common front matter of every command: options, --help, one ELEMENTS argument.

struct Command {
  const char* name;
  const char* synopsis;
  const char* description;
  std::vector<OptionSpec> specs;
  bool stored_database = false;  // ELEMENTS may be left out: the stored database (--state)
};

std::string usage(const Command& c);
int usage_error(const Command& c, const ArgError& e);

// One run of a command: parses its words (`done` is then the exit code when --help or a usage error
// already finished it); the command reads its values through `in`, then load_sats() takes over.
struct CommandRun {
  CommandRun(const Command& c, const std::vector<std::string>& args);
  CommandRun(const CommandRun&) = delete;
  CommandRun& operator=(const CommandRun&) = delete;

  int error(const ArgError& e) const { return usage_error(command, e); }

  // Once the options are read: the first error among them, else ELEMENTS loaded and the sets --sat
  // chooses (allow_all: every set when no --sat is given) put in `sats`. Returns the exit code when
  // the command cannot go on.
  std::optional<int> load_sats(bool allow_all, std::vector<Elements>& sats);

  // No ELEMENTS: the stored database; without --sat its tracking list (all of it with allow_all,
  // else its first satellite).
  std::optional<int> load_stored(bool allow_all, std::vector<Elements>& sats);

  // The --sat values, less SUN and MOON when the command takes them (bodies_allowed): those are
  // in `bodies`, in command-line order, and need no elements.
  std::vector<std::string> sat_keys() const;
  std::vector<orbit::Body> bodies() const;
  bool bodies_allowed = false;

  const Command& command;
  ParsedOptions parsed;  // --no-checksum is read from here by load_sats
  StoredStation stored{std::nullopt};  // --state
  std::string path;  // ELEMENTS; empty: the stored database
  OptionReader in{parsed};
  std::optional<int> done;
};

}  // namespace tb::app::orbit_cli
