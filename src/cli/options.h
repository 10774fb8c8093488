// A small command-line option parser for trakbox and its subcommands.
//
//   --name value   --name=value   --flag   positional arguments   --   (ends the options)
//
// The word after an option that takes a value is always that value, so negative numbers need no
// quoting: `--start -1440`, `--station -77.85,166.67,10` (a value that itself begins with "--" must
// use the `--name=--value` form). A word that starts with '-' and then a digit or '.' is a positional
// number; any other word starting with '-' that is not a known option is an error. `-h` means
// `--help` when the command has a "help" option.
//
// Every error names the argument and says what was expected; callers print it as one line and
// exit with kExitUsage. Parsing and conversion are separate: parse_options() checks the shape of
// the command line, OptionReader converts values with ranges and remembers the first error.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the command ran but could not finish (e.g. propagation failed)
inline constexpr int kExitUsage = 2;    // bad arguments or unusable input; nothing was done

struct OptionSpec {
  std::string name;        // long name without the dashes: "start"
  std::string value_name;  // "MIN", "LAT,LON,HEIGHT_M"; empty for a flag that takes no value
  std::string help;        // one line for --help
  bool repeatable = false; // may be given more than once (--sat A --sat B)
  bool takes_value() const { return !value_name.empty(); }
};

struct ArgError {
  std::string argument;  // "--step", "ELEMENTS", "-x"
  std::string message;   // "expected SECONDS, a number > 0; found 'abc'"
  std::string text() const { return argument + ": " + message; }
};

struct ParseOutcome;
class ParsedOptions;
ParseOutcome parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

class ParsedOptions {
 public:
  bool has(std::string_view name) const;
  // The value of an option given once (for a repeated option, the last one).
  std::optional<std::string> value(std::string_view name) const;
  // Every value of a repeatable option, in command-line order.
  std::vector<std::string> values(std::string_view name) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  friend ParseOutcome parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);
  std::map<std::string, std::vector<std::string>, std::less<>> values_;
  std::vector<std::string> positional_;
};

struct ParseOutcome {
  ParsedOptions options;
  std::optional<ArgError> error;  // the first problem; options is then incomplete
};

ParseOutcome parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

// "  --start MIN          minutes from epoch of the first line" -- one line per option.
std::string describe_options(const std::vector<OptionSpec>& specs);

// A subcommand's words and options ("trakbox settings set KEY VALUE --state DIR"): the words before
// the first --option, then the options parsed. read_subcommand returns the exit status when the
// command is done already: --help printed (`usage` and the options), or a bad option said on
// stderr as "trakbox NAME: ... (see trakbox NAME --help)".
struct Subcommand {
  std::vector<std::string> words;
  ParsedOptions options;
};
std::optional<int> read_subcommand(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                                   std::string_view name, std::string_view usage, Subcommand& out);

// Strict conversions: the whole text must be the number (no blanks, no trailing junk, finite).
std::optional<double> to_double(std::string_view text);
std::optional<std::int64_t> to_int64(std::string_view text);
// "1.5,-2,3e3" -> {1.5, -2, 3000}; nullopt when any item is not a number.
std::optional<std::vector<double>> to_double_list(std::string_view text, char separator = ',');

// Inclusive/exclusive bounds for a numeric option.
struct Range {
  std::optional<double> min, max;
  bool min_exclusive = false;
  bool max_exclusive = false;
  bool contains(double v) const;
};

// Typed access to parsed options. Each getter returns nullopt when the option is absent (and records
// an error if it was required) or invalid (error recorded); the first error is kept. `expected`
// describes an acceptable value for the message: "SECONDS, a number > 0".
class OptionReader {
 public:
  explicit OptionReader(const ParsedOptions& options) : options_(options) {}

  std::optional<std::string> text(std::string_view name, bool required, std::string_view expected);
  std::optional<double> number(std::string_view name, bool required, std::string_view expected,
                               const Range& range = {});
  std::optional<std::int64_t> integer(std::string_view name, bool required, std::string_view expected,
                                      const Range& range = {});
  bool flag(std::string_view name) const { return options_.has(name); }

  // Records an error (kept only if it is the first).
  void fail(std::string argument, std::string message);
  const std::optional<ArgError>& error() const { return error_; }
  bool ok() const { return !error_.has_value(); }

  // "--name"
  static std::string option_label(std::string_view name) { return "--" + std::string(name); }

 private:
  const ParsedOptions& options_;
  std::optional<ArgError> error_;
};

}  // namespace tb::app
