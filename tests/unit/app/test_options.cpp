// The command-line option parser (cli/options.h): the shape of a command line, the strict number
// conversions, typed reading with ranges, and the one-line errors the orbit commands print.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "cli/cli_orbit.h"
#include "cli/options.h"

using namespace tb::app;

namespace {

using Args = std::vector<std::string>;

// What `trakbox propagate`, `schedule` and `passes` take, in miniature.
const std::vector<OptionSpec> kSpecs = {
    {"sat", "NAME|NUMBER", "satellite by name or number", true},
    {"start", "MIN", "first time"},
    {"step", "SECONDS", "seconds between rows"},
    {"csv", "", "comma-separated values"},
    {"help", "", "show this help"},
};

ParseOutcome parse(const Args& args, const std::vector<OptionSpec>& specs = kSpecs) {
  return parse_options(args, specs);
}

// The error's one line, or "" when the parse succeeded.
std::string error_of(const Args& args, const std::vector<OptionSpec>& specs = kSpecs) {
  const ParseOutcome po = parse(args, specs);
  return po.error ? po.error->text() : "";
}

// What f() writes to stderr (file descriptor 2), and its result.
template <class F>
std::pair<int, std::string> capture_stderr(F f) {
  std::fflush(stderr);
  std::FILE* tmp = std::tmpfile();
  REQUIRE(tmp);
  const int saved = ::dup(2);
  ::dup2(::fileno(tmp), 2);
  const int rc = f();
  std::fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  std::rewind(tmp);
  std::string text;
  char buf[512];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, tmp)) > 0) text.append(buf, n);
  std::fclose(tmp);
  return {rc, text};
}

}  // namespace

TEST_CASE("Exit codes") {
  CHECK(kExitOk == 0);
  CHECK(kExitFailure == 1);
  CHECK(kExitUsage == 2);
}

TEST_CASE("--name value and --name=value give the same value") {
  for (const Args& args : {Args{"--start", "10"}, Args{"--start=10"}}) {
    const ParseOutcome po = parse(args);
    REQUIRE_FALSE(po.error);
    CHECK(po.options.has("start"));
    CHECK(po.options.value("start") == "10");
    CHECK(po.options.values("start") == std::vector<std::string>{"10"});
    CHECK(po.options.positional().empty());
  }
  // "=" splits at the first one; the value may be empty or hold more "=".
  CHECK(parse({"--start=a=b"}).options.value("start") == "a=b");
  CHECK(parse({"--start="}).options.value("start") == "");
}

TEST_CASE("The word after an option that takes a value is its value, negative numbers included") {
  const ParseOutcome po = parse({"--start", "-1440", "--step", "-.5", "--sat", "-x"});
  REQUIRE_FALSE(po.error);
  CHECK(po.options.value("start") == "-1440");
  CHECK(po.options.value("step") == "-.5");
  CHECK(po.options.value("sat") == "-x");
  // Only a word starting with "--" is not taken: such a value needs the --name=value form.
  CHECK(parse({"--start=--5"}).options.value("start") == "--5");
}

TEST_CASE("Flags, absent options and positional arguments") {
  const ParseOutcome po = parse({"iss.tle", "--csv", "-7", "-.5", "-", "", "more"});
  REQUIRE_FALSE(po.error);
  CHECK(po.options.has("csv"));
  CHECK(po.options.value("csv") == "");  // a flag is present with an empty value
  CHECK_FALSE(po.options.has("start"));
  CHECK(po.options.value("start") == std::nullopt);
  CHECK(po.options.values("sat").empty());
  CHECK(po.options.positional() == Args{"iss.tle", "-7", "-.5", "-", "", "more"});
}

TEST_CASE("-- ends the options: every later word is positional") {
  const ParseOutcome po = parse({"--csv", "--", "--start", "-x", "--"});
  REQUIRE_FALSE(po.error);
  CHECK(po.options.has("csv"));
  CHECK_FALSE(po.options.has("start"));
  CHECK(po.options.positional() == Args{"--start", "-x", "--"});
}

TEST_CASE("-h is --help only where the command has --help") {
  const ParseOutcome po = parse({"-h"});
  REQUIRE_FALSE(po.error);
  CHECK(po.options.has("help"));
  CHECK(error_of({"-h"}, {{"start", "MIN", "first time"}}) == "-h: unknown option (options are written --name)");
}

TEST_CASE("A repeatable option keeps every value in order; value() is the last") {
  const ParseOutcome po = parse({"--sat", "ISS", "--sat=AO-07", "--sat", "25544"});
  REQUIRE_FALSE(po.error);
  CHECK(po.options.values("sat") == std::vector<std::string>{"ISS", "AO-07", "25544"});
  CHECK(po.options.value("sat") == "25544");
}

TEST_CASE("Shape errors: one line naming the argument, the first problem only") {
  CHECK(error_of({"--bogus"}) == "--bogus: unknown option");
  CHECK(error_of({"--bogus=1"}) == "--bogus: unknown option");
  CHECK(error_of({"--Start", "1"}) == "--Start: unknown option; did you mean --start?");  // names are case-sensitive
  CHECK(error_of({"-x"}) == "-x: unknown option (options are written --name)");
  CHECK(error_of({"-start", "1"}) == "-start: unknown option (options are written --name)");
  CHECK(error_of({"--start"}) == "--start: expected MIN after it");
  CHECK(error_of({"--step", "--csv"}) == "--step: expected SECONDS after it");
  CHECK(error_of({"--start", "1", "--start", "2"}) == "--start: given more than once");
  CHECK(error_of({"--csv", "--csv"}) == "--csv: given more than once");
  CHECK(error_of({"--csv=yes"}) == "--csv: takes no value, found 'yes'");
  CHECK(error_of({"--csv="}) == "--csv: takes no value, found ''");
  CHECK(error_of({"--bogus", "--start"}) == "--bogus: unknown option");  // the first one
  CHECK(error_of({"file", "--start", "1", "-y", "--zzz"}) == "-y: unknown option (options are written --name)");

  const ParseOutcome po = parse({"--bogus"});
  REQUIRE(po.error);
  CHECK(po.error->argument == "--bogus");
  CHECK(po.error->message == "unknown option");
  CHECK(error_of({"--start", "1", "file"}).empty());
  // A typo (within two edits) or the start of one option: the option meant (issue 39).
  CHECK(error_of({"--strat", "1"}) == "--strat: unknown option; did you mean --start?");
  CHECK(error_of({"--stp", "1"}) == "--stp: unknown option; did you mean --step?");
  CHECK(error_of({"--he"}) == "--he: unknown option");  // too short to guess
}

TEST_CASE("describe_options: one line per option, help aligned at column 27") {
  const std::vector<OptionSpec> specs = {
      {"start", "MIN", "first time"},
      {"sat", "NAME|NUMBER", "satellite", true},
      {"station", "LAT,LON,HEIGHT_M", "where"},
      {"csv", "", "comma-separated values"},
  };
  CHECK(describe_options(specs) ==
        "  --start MIN             first time\n"
        "  --sat NAME|NUMBER       satellite (repeatable)\n"
        "  --station LAT,LON,HEIGHT_M  where\n"
        "  --csv                   comma-separated values\n");
  CHECK(describe_options({}).empty());
}

TEST_CASE("to_double: the whole text, plain decimal, finite") {
  CHECK(to_double("1.5") == 1.5);
  CHECK(to_double("-2") == -2.0);
  CHECK(to_double("+3") == 3.0);
  CHECK(to_double(".5") == 0.5);
  CHECK(to_double("-.25") == -0.25);
  CHECK(to_double("1e3") == 1000.0);
  CHECK(to_double("2E-1") == 0.2);
  for (const char* bad : {"", " 1", "1 ", "1.5x", "abc", "0x10", "inf", "-inf", "nan", "NaN", "1e999", "--1", "e5",
                          "1,5"})
    CHECK_MESSAGE(to_double(bad) == std::nullopt, bad);
  CHECK(to_double(std::string(64, '1')).has_value());
  CHECK(to_double(std::string(65, '1')) == std::nullopt);  // longer than any sensible number
}

TEST_CASE("to_int64: digits with an optional sign, within 64 bits") {
  CHECK(to_int64("42") == 42);
  CHECK(to_int64("-7") == -7);
  CHECK(to_int64("+7") == 7);
  CHECK(to_int64("007") == 7);
  CHECK(to_int64("9223372036854775807") == std::numeric_limits<std::int64_t>::max());
  CHECK(to_int64("-9223372036854775808") == std::numeric_limits<std::int64_t>::min());
  for (const char* bad : {"", "-", "+", "1.0", "1e3", " 1", "1 ", "0x1", "9223372036854775808",
                          "-9223372036854775809", "+-1", "123456789012345678901"})
    CHECK_MESSAGE(to_int64(bad) == std::nullopt, bad);
}

TEST_CASE("to_double_list: every item a number") {
  CHECK(to_double_list("1.5,-2,3e3") == std::vector<double>{1.5, -2.0, 3000.0});
  CHECK(to_double_list("7") == std::vector<double>{7.0});
  CHECK(to_double_list("1;2", ';') == std::vector<double>{1.0, 2.0});
  for (const char* bad : {"", ",", "1,", ",1", "1,,2", "1, 2", "1;2", "a,b"})
    CHECK_MESSAGE(to_double_list(bad) == std::nullopt, bad);
}

TEST_CASE("Range: inclusive or exclusive bounds, either side optional") {
  const Range closed{0.0, 1.0};
  CHECK(closed.contains(0.0));
  CHECK(closed.contains(1.0));
  CHECK_FALSE(closed.contains(-0.001));
  CHECK_FALSE(closed.contains(1.001));
  const Range open{0.0, 1.0, true, true};
  CHECK_FALSE(open.contains(0.0));
  CHECK_FALSE(open.contains(1.0));
  CHECK(open.contains(0.5));
  const Range positive{0.0, std::nullopt, true};
  CHECK_FALSE(positive.contains(0.0));
  CHECK(positive.contains(1e300));
  const Range at_most{std::nullopt, 5.0};
  CHECK(at_most.contains(-1e300));
  CHECK(at_most.contains(5.0));
  CHECK_FALSE(at_most.contains(5.5));
  CHECK(Range{}.contains(-1e300));
  CHECK_FALSE(closed.contains(std::numeric_limits<double>::quiet_NaN()));
}

TEST_CASE("OptionReader: values within their ranges") {
  const ParseOutcome po = parse({"--start=-10.5", "--step", "30", "--sat", "ISS", "--csv"});
  REQUIRE_FALSE(po.error);
  OptionReader in(po.options);
  CHECK(in.number("start", true, "MIN") == -10.5);
  CHECK(in.integer("step", true, "SECONDS", Range{1.0, 60.0}) == 30);
  CHECK(in.number("step", true, "SECONDS", Range{30.0, 30.0}) == 30.0);
  CHECK(in.text("sat", true, "NAME") == "ISS");
  CHECK(in.flag("csv"));
  CHECK_FALSE(in.flag("help"));
  CHECK(OptionReader::option_label("start") == "--start");
  // Absent and not required: nothing, and no error.
  const ParseOutcome none = parse({});
  OptionReader empty(none.options);
  CHECK(empty.number("start", false, "MIN") == std::nullopt);
  CHECK(empty.integer("step", false, "SECONDS") == std::nullopt);
  CHECK(empty.text("sat", false, "NAME") == std::nullopt);
  CHECK(in.ok());
  CHECK(empty.ok());
  CHECK(empty.error() == std::nullopt);
}

TEST_CASE("OptionReader: missing and bad values, the first error kept") {
  auto first_error = [](const Args& args, auto read) {
    const ParseOutcome po = parse(args);
    REQUIRE_FALSE(po.error);
    OptionReader in(po.options);
    read(in);
    CHECK_FALSE(in.ok());
    return in.error() ? in.error()->text() : "";
  };
  CHECK(first_error({}, [](OptionReader& in) { CHECK(in.number("step", true, "SECONDS, a number > 0") == std::nullopt); }) ==
        "--step: missing; expected SECONDS, a number > 0");
  CHECK(first_error({}, [](OptionReader& in) { in.text("sat", true, "NAME|NUMBER"); }) ==
        "--sat: missing; expected NAME|NUMBER");
  CHECK(first_error({"--step", "abc"}, [](OptionReader& in) { in.number("step", true, "SECONDS, a number > 0"); }) ==
        "--step: expected SECONDS, a number > 0, found 'abc'");
  CHECK(first_error({"--step", "0"}, [](OptionReader& in) {
          in.number("step", true, "SECONDS, a number > 0", Range{0.0, std::nullopt, true});
        }) == "--step: expected SECONDS, a number > 0, found '0'");
  CHECK(first_error({"--step", "1.5"}, [](OptionReader& in) { in.integer("step", true, "N, a whole number"); }) ==
        "--step: expected N, a whole number, found '1.5'");
  CHECK(first_error({"--step", "11"}, [](OptionReader& in) { in.integer("step", false, "N, 1..10", Range{1.0, 10.0}); }) ==
        "--step: expected N, 1..10, found '11'");
  CHECK(first_error({"--step", "x", "--start", "y"}, [](OptionReader& in) {
          in.number("start", true, "MIN");
          in.number("step", true, "SECONDS");
          in.fail("ELEMENTS", "later");
        }) == "--start: expected MIN, found 'y'");
  CHECK(first_error({}, [](OptionReader& in) {
          in.fail("--stop", "expected MIN >= --start (0), found '-1'");
          in.fail("--step", "too small");
        }) == "--stop: expected MIN >= --start (0), found '-1'");
  // A bad value reads as nothing, so the caller never converts it.
  const ParseOutcome po = parse({"--step", "abc"});
  OptionReader in(po.options);
  CHECK(in.number("step", true, "SECONDS") == std::nullopt);
  REQUIRE(in.error());
  CHECK(in.error()->argument == "--step");
  CHECK(in.error()->message == "expected SECONDS, found 'abc'");
}

TEST_CASE("An orbit command prints one line for a usage error and exits with kExitUsage") {
  auto run = [](Args args) { return capture_stderr([&] { return run_propagate(args); }); };
  CHECK(run({"--bogus"}) ==
        std::pair<int, std::string>{kExitUsage, "trakbox propagate: --bogus: unknown option (see trakbox propagate --help)\n"});
  CHECK(run({"x.tle", "--stop", "1", "--step", "1"}) ==
        std::pair<int, std::string>{kExitUsage, "trakbox propagate: --start: missing; expected MIN, minutes from epoch "
                                                "(see trakbox propagate --help)\n"});
  CHECK(run({"--start", "0", "--stop", "1", "--step", "1"}).second ==
        "trakbox propagate: ELEMENTS: missing; expected an element file (NASA 2/3-line, AMSAT verbose, gpredict "
        ".sat/satellites.dat, or OMM JSON/XML/CSV/KVN) (see trakbox propagate --help)\n");
  CHECK(run({"a.tle", "b.tle"}).second ==
        "trakbox propagate: b.tle: unexpected argument (ELEMENTS is given once) (see trakbox propagate --help)\n");
  CHECK(run({"x.tle", "--start", "5", "--stop=1", "--step", "1"}).second ==
        "trakbox propagate: --stop: expected MIN >= --start (5), found '1' (see trakbox propagate --help)\n");
}
