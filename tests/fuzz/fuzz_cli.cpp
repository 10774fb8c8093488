// Command-line values: trakbox's option parser (app::parse_options with the program's own option
// table), the conversions and checks run_tracker makes before anything starts (OptionReader with
// its ranges, --clock, the --rotator / --radio / satrak: device specs), and the other readers of
// command-line text (to_double_list for --station, inet::parse_host_port for `trakbox satrak`).
// The orbit subcommands (propagate, schedule, passes) are not run: their work is what the values
// ask for (up to 10^7 lines), not a parser's.
//
// The input is the argument vector, words separated by NUL or LF (at most 32).
// Properties: every error names an argument and says what was expected; the parsed options hold
// what was given; a spec that parses is written back to one that parses the same.
#include "cli/options.h"
#include "app/tracker_app.h"
#include "fuzz_station.h"
#include "radio/factory.h"
#include "rotator/registry.h"
#include "rotator/factory.h"
#include "rotator/satrak/client.h"
#include "util/host_port.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = fuzz::as_text(data, size);
  std::vector<std::string> args;
  for (std::size_t i = 0; i <= input.size() && args.size() < 32;) {
    const std::size_t end = input.find_first_of(std::string_view("\0\n", 2), i);
    args.emplace_back(input.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i));
    if (end == std::string_view::npos) break;
    i = end + 1;
  }

  static const auto specs = app::tracker_option_specs();
  const app::ParseOutcome parsed = app::parse_options(args, specs);
  if (parsed.error) {
    TB_FUZZ_CHECK(!parsed.error->argument.empty() && !parsed.error->message.empty(), parsed.error->text());
  }
  const app::ParsedOptions& o = parsed.options;
  app::OptionReader r(o);
  (void)r.integer("baud", false, "1200, 2400, 4800, 9600 or 19200");
  (void)r.integer("standalone", false, "a selector position 1 to 15", app::Range{1, 15});
  if (const auto rate = r.number("clock-rate", false, "a rate > 0", app::Range{0.0, 10000.0, true}))
    TB_FUZZ_CHECK(*rate > 0.0 && *rate <= 10000.0, *o.value("clock-rate"));
  if (const auto ms = r.integer("tick-ms", false, "milliseconds", app::Range{100, 1000}))
    TB_FUZZ_CHECK(*ms >= 100 && *ms <= 1000, *o.value("tick-ms"));
  (void)r.integer("satrak-port", false, "a TCP port 0 to 65535", app::Range{0, 65535});
  (void)r.text("state", false, "DIR");
  if (r.error()) TB_FUZZ_CHECK(!r.error()->text().empty(), "empty error");

  if (const auto c = o.value("clock")) (void)orbit::parse_iso8601(*c);
  for (const auto& a : args) {
    (void)orbit::parse_iso8601(a);
    (void)app::to_double_list(a);
    (void)app::to_double(a);
    (void)app::to_int64(a);
    std::string error;
    if (const auto hp = inet::parse_host_port(a, error, satrak::kDefaultPort)) (void)hp->host;
    else TB_FUZZ_CHECK(!error.empty(), a);
    error.clear();
    const auto rot = rotator::parse_rotator(a);
    if (rot.choice.rotator) {
      const std::string back = rotator::to_string(*rot.choice.rotator);
      const auto again = rotator::parse_rotator(back);
      TB_FUZZ_CHECK(again.choice.rotator && *again.choice.rotator == *rot.choice.rotator, a + " -> " + back);
    } else if (!rot.choice.satrak) {
      TB_FUZZ_CHECK(!rot.error.empty(), a);
    }
    const auto rad = radio::parse_radio_spec(a);
    if (!rad.spec) TB_FUZZ_CHECK(!rad.error.empty(), a);
  }
  return 0;
}
