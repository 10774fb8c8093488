// The element texts the element tests share (test_elements*.cpp): CelesTrak's ISS lines, Vallado's
// SGP4-VER.TLE, AO-07 in both formats, and the helpers that read, build and edit texts and compare
// what was parsed.
#pragma once
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SGP4_DATA_DIR, ...

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/elements.h"

namespace elements_test {

using namespace tb::orbit;

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE_MESSAGE(in.good(), "cannot read " << path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline const std::string kSgp4Ver = std::string(TRAKBOX_SGP4_DATA_DIR) + "/SGP4-VER.TLE";

// CelesTrak's ISS example, as quoted in the brief and in many SGP4 texts.
inline constexpr const char* kIss1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
inline constexpr const char* kIss2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

inline std::string lines(std::initializer_list<std::string_view> ls, const char* eol = "\n") {
  std::string s;
  for (auto l : ls) {
    s += l;
    s += eol;
  }
  return s;
}

inline void check_problem(const ParseProblem& p, int line, int column, const std::string& field, const std::string& found,
                          const std::string& expected) {
  CHECK(p.line == line);
  CHECK(p.column == column);
  CHECK(p.field == field);
  CHECK(p.found == found);
  CHECK(p.expected == expected);
  CHECK_FALSE(p.warning);
}

inline const Elements* find(const ParseResult& r, int catalog) {
  for (const Elements& e : r.sets)
    if (e.catalog_number == catalog) return &e;
  return nullptr;
}

// The block of docs/element-formats.md (reference/element-formats.md), checksum 288.
inline constexpr const char* kAo07Block = "Satellite: AO-07\n"
                                          "Catalog number: 07530\n"
                                          "Epoch time:      14365.96416624\n"
                                          "Element set:     157\n"
                                          "Inclination:      101.4991 deg\n"
                                          "RA of node:       341.4640 deg\n"
                                          "Eccentricity:    0.0011635\n"
                                          "Arg of perigee:   269.4368 deg\n"
                                          "Mean anomaly:     124.4812 deg\n"
                                          "Mean motion:   12.53610824 rev/day\n"
                                          "Decay rate:       -4.5e-07 rev/day^2\n"
                                          "Epoch rev:           83630\n"
                                          "Checksum:              288\n";

// AO-07 on 2012-09-12 in both formats, as posted to AMSAT-BB (i8CVS, 2012-09-19) to show how the
// AMSAT block is derived from the two lines; the AMSAT generator's checksum is 262.
inline constexpr const char* kAo07Nasa = "AO-07\n"
                                         "1 07530U 74089B   12256.61218065 -.00000027  00000-0  10000-3 0  4795\n"
                                         "2 07530 101.4099 250.4681 0012001 109.6272 250.6089 12.53591141731001\n";
inline constexpr const char* kAo07Amsat = "Satellite: AO-07\n"
                                          "Catalog number: 07530\n"
                                          "Epoch time:      12256.61218065\n"
                                          "Element set:     479\n"
                                          "Inclination:      101.4099 deg\n"
                                          "RA of node:       250.4681 deg\n"
                                          "Eccentricity:    0.0012001\n"
                                          "Arg of perigee:   109.6272 deg\n"
                                          "Mean anomaly:     250.6089 deg\n"
                                          "Mean motion:   12.53591141 rev/day\n"
                                          "Decay rate:       -2.7e-07 rev/day^2\n"
                                          "Epoch rev:           73100\n"
                                          "Checksum:              262\n";

inline std::vector<std::string_view> split(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const auto nl = text.find('\n');
    out.push_back(text.substr(0, nl));
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
  }
  return out;
}

inline std::string replace_line(std::string text, std::string_view from, std::string_view to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  return text;
}

// Every field a NASA set carries, compared exactly.
// The fields the AMSAT format carries (no designator, classification, nddot, BSTAR, type); the NASA
// format carries them too.
inline void check_same_amsat_values(const Elements& a, const Elements& b) {
  CHECK(a.name == b.name);
  CHECK(a.catalog_number == b.catalog_number);
  CHECK(a.epoch_year == b.epoch_year);
  CHECK(a.epoch_day == b.epoch_day);
  CHECK(a.ndot_over_2 == b.ndot_over_2);
  CHECK(a.element_set_number == b.element_set_number);
  CHECK(a.inclination_deg == b.inclination_deg);
  CHECK(a.raan_deg == b.raan_deg);
  CHECK(a.eccentricity == b.eccentricity);
  CHECK(a.arg_perigee_deg == b.arg_perigee_deg);
  CHECK(a.mean_anomaly_deg == b.mean_anomaly_deg);
  CHECK(a.mean_motion_rev_per_day == b.mean_motion_rev_per_day);
  CHECK(a.revolution_number == b.revolution_number);
}

inline void check_same_nasa_values(const Elements& a, const Elements& b) {
  check_same_amsat_values(a, b);
  CHECK(a.classification == b.classification);
  CHECK(a.international_designator == b.international_designator);
  CHECK(std::signbit(a.ndot_over_2) == std::signbit(b.ndot_over_2));
  CHECK(a.nddot_over_6 == b.nddot_over_6);
  CHECK(a.bstar == b.bstar);
  CHECK(a.ephemeris_type == b.ephemeris_type);
}

inline Elements only_set(const ParseResult& r) {
  for (const auto& p : r.problems) MESSAGE(p.message());
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 1);
  return r.sets[0];
}

}  // namespace elements_test
