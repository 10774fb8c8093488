// The AMSAT verbose format: its checksum, the reference block, the same set as in the NASA format,
// a bulletin around blocks, and the problems located.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "element_texts.h"
#include "orbit/elements.h"

using namespace tb::orbit;
using namespace elements_test;

TEST_CASE("AMSAT checksum: the reference block gives 288, the AMSAT-BB block 262") {
  auto block = split(kAo07Block);
  REQUIRE(block.size() == 13);
  block.pop_back();  // "Checksum:" itself is not summed
  CHECK(amsat_checksum(block) == 288);
  auto other = split(kAo07Amsat);
  other.pop_back();
  CHECK(amsat_checksum(other) == 262);
  CHECK(amsat_checksum({"+", "-", "x9"}) == 12);
}

TEST_CASE("AMSAT: the reference block") {
  const ParseResult r = parse_amsat(kAo07Block, "ao07.txt");
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 1);
  const Elements& e = r.sets[0];
  CHECK(e.source == ElementFormat::amsat);
  CHECK(e.name == "AO-07");
  CHECK(e.catalog_number == 7530);
  CHECK(e.epoch_year == 2014);
  CHECK(e.epoch_day == 365.96416624);
  CHECK(e.element_set_number == 157);
  CHECK(e.inclination_deg == 101.4991);
  CHECK(e.raan_deg == 341.4640);
  CHECK(e.eccentricity == 0.0011635);
  CHECK(e.arg_perigee_deg == 269.4368);
  CHECK(e.mean_anomaly_deg == 124.4812);
  CHECK(e.mean_motion_rev_per_day == 12.53610824);
  CHECK(e.ndot_over_2 == -4.5e-07);  // "Decay rate" is ndot/2
  CHECK(e.nddot_over_6 == 0.0);
  CHECK(e.bstar == 0.0);  // AMSAT sets carry no BSTAR
  CHECK(e.revolution_number == 83630);
  CHECK(e.epoch() == from_civil(2014, 12, 31, 23, 8, 23.963136));
}

TEST_CASE("AMSAT: the same satellite and epoch in both formats gives the same values") {
  const ParseResult nasa = parse_nasa(kAo07Nasa);
  const ParseResult amsat = parse_amsat(kAo07Amsat);
  REQUIRE(nasa.sets.size() == 1);
  REQUIRE(amsat.sets.size() == 1);
  CHECK(amsat.problems.empty());
  const Elements& n = nasa.sets[0];
  const Elements& a = amsat.sets[0];
  CHECK(a.name == n.name);
  CHECK(a.catalog_number == n.catalog_number);
  CHECK(a.epoch_year == n.epoch_year);
  CHECK(a.epoch_day == n.epoch_day);
  CHECK(a.element_set_number == n.element_set_number);
  CHECK(a.inclination_deg == n.inclination_deg);
  CHECK(a.raan_deg == n.raan_deg);
  CHECK(a.eccentricity == n.eccentricity);
  CHECK(a.arg_perigee_deg == n.arg_perigee_deg);
  CHECK(a.mean_anomaly_deg == n.mean_anomaly_deg);
  CHECK(a.mean_motion_rev_per_day == n.mean_motion_rev_per_day);
  CHECK(a.ndot_over_2 == n.ndot_over_2);
  CHECK(a.revolution_number == n.revolution_number);
}

TEST_CASE("AMSAT: a bulletin with text around two blocks, CRLF, varying whitespace") {
  std::string bulletin = "HR AMSAT ORBITAL ELEMENTS FOR AMATEUR SATELLITES IN AMSAT FORMAT\n"
                         "FROM WA5QGD FORT WORTH,TX    January 8, 2015\n"
                         "TO ALL RADIO AMATEURS BT\n"
                         "\n";
  bulletin += kAo07Block;
  bulletin += "\n";
  // The second block: tabs and other spacing, a beacon line, upper case labels, no units.
  bulletin += "Satellite:\tAO-07\n"
              "Catalog number:07530\n"
              "EPOCH TIME: 12256.61218065\n"
              "Element set:  479\n"
              "Inclination:\t101.4099\n"
              "RA of node:  250.4681   deg\n"
              "Eccentricity: .0012001\n"
              "Arg  of  perigee: 109.6272 deg\n"
              "Mean anomaly: 250.6089 deg\n"
              "Mean motion: 12.53591141 rev/day\n"
              "Decay rate: -2.7E-07 rev/day^2\n"
              "Epoch rev: 73100\n"
              "Beacon: 145.9775 MHz\n"
              "Checksum: 262\n"
              "/EX\n";
  std::string crlf;
  for (char c : bulletin) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  for (const std::string& text : {bulletin, crlf}) {
    const ParseResult r = parse_amsat(text, "bulletin.txt");
    for (const auto& p : r.problems) MESSAGE(p.message());
    CHECK(r.problems.empty());
    REQUIRE(r.sets.size() == 2);
    CHECK(r.sets[0].revolution_number == 83630);
    CHECK(r.sets[1].name == "AO-07");
    CHECK(r.sets[1].epoch_year == 2012);
    CHECK(r.sets[1].eccentricity == 0.0012001);
    CHECK(r.sets[1].arg_perigee_deg == 109.6272);
    CHECK(r.sets[1].ndot_over_2 == -2.7e-07);
    CHECK(r.sets[1].revolution_number == 73100);
    // auto-detection finds the blocks
    CHECK(parse_elements(text).sets.size() == 2);
  }
}

TEST_CASE("AMSAT problems: checksum mismatch is a warning unless strict") {
  const std::string text = replace_line(kAo07Block, "Checksum:              288", "Checksum:              287");
  ParseResult r = parse_amsat(text, "ao07.txt");
  REQUIRE(r.problems.size() == 1);
  const ParseProblem& p = r.problems[0];
  CHECK(p.line == 13);
  CHECK(p.column == 24);
  CHECK(p.field == "Checksum");
  CHECK(p.found == "287");
  CHECK(p.expected == "checksum 288");
  CHECK(p.warning);
  CHECK(p.message() == "ao07.txt:13:24: Checksum: found '287', expected checksum 288 (warning: set accepted)");
  CHECK(r.sets.size() == 1);
  CHECK(r.ok());

  ParseOptions strict;
  strict.strict_amsat_checksum = true;
  r = parse_amsat(text, "ao07.txt", strict);
  REQUIRE(r.problems.size() == 1);
  CHECK_FALSE(r.problems[0].warning);
  CHECK(r.sets.empty());
  CHECK_FALSE(r.ok());

  // No checksum line at all.
  r = parse_amsat(replace_line(kAo07Block, "Checksum:              288\n", ""), "ao07.txt");
  REQUIRE(r.problems.size() == 1);
  CHECK(r.problems[0].line == 1);
  CHECK(r.problems[0].column == 0);
  CHECK(r.problems[0].field == "Checksum");
  CHECK(r.problems[0].found.empty());
  CHECK(r.problems[0].expected == "a 'Checksum:' line (288 for this block)");
  CHECK(r.problems[0].warning);
  CHECK(r.sets.size() == 1);
}

TEST_CASE("AMSAT problems: bad values and missing lines") {
  const std::string two = std::string("Keps\n\n") + kAo07Block + "\n" + kAo07Amsat;  // blocks at lines 3 and 17

  ParseResult r = parse_amsat(replace_line(two, "0.0011635", "1.0011635"), "b.txt");
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 9, 18, "Eccentricity", "1.0011635", "number in [0, 1)");
  REQUIRE(r.sets.size() == 1);  // the other block is still read
  CHECK(r.sets[0].epoch_year == 2012);

  r = parse_amsat(replace_line(two, "101.4991 deg", "101.49x1 deg"), "b.txt");
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 7, 19, "Inclination", "101.49x1", "decimal number");

  r = parse_amsat(replace_line(two, "Mean motion:   12.53610824 rev/day\n", ""), "b.txt");
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 3, 0, "Mean motion", "", "a 'Mean motion:' line in the block");
  CHECK(r.problems[0].message() ==
        "b.txt:3:0: Mean motion: found nothing, expected a 'Mean motion:' line in the block");
  CHECK(r.sets.size() == 1);

  // One damaged line each: where the problem is reported, and what was found and expected.
  struct Damage {
    const char *from, *to;
    int line, column;
    const char *field, *found, *expected;
  };
  for (const Damage& d : {
           Damage{"Epoch time:      12256.61218065", "Epoch time:      12367.61218065", 19, 18, "Epoch time",
                  "12367.61218065", "day of year in [1, 367)"},
           Damage{"Element set:     479", "Element set:     4x9", 20, 18, "Element set", "4x9", "digits 0-9"},
           Damage{"Mean motion:   12.53591141", "Mean motion:   -12.5359114", 26, 16, "Mean motion", "-12.5359114",
                  "number > 0"},
           Damage{"Epoch rev:           73100\n", "Epoch rev:           73100\nEpoch rev: 1\n", 29, 12, "Epoch rev",
                  "1", "one 'Epoch rev:' line in the block"},
       }) {
    CAPTURE(d.to);
    r = parse_amsat(replace_line(two, d.from, d.to), "b.txt");
    REQUIRE(r.problems.size() == 1);
    check_problem(r.problems[0], d.line, d.column, d.field, d.found, d.expected);
  }
}
