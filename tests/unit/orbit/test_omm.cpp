// CCSDS OMM in its four encodings against the TLEs they were made from. The files of tests/data/omm
// were written by python-sgp4 (scripts/make-omm-fixtures.py), not by trakbox.
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR

#include <cmath>
#include <string>
#include <vector>

#include "orbit/elements.h"

using namespace tb::orbit;

namespace {

const std::string kDir = std::string(TRAKBOX_SOURCE_DIR) + "/tests/data/omm/";

ParseResult load(const std::string& name) { return load_elements_file(kDir + name); }

bool near_rel(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)); }

// The same satellite: numbers the OMM text writes with the TLE's digits compare exactly, the others
// (python-sgp4 converts BSTAR and the mean motion derivatives) within 1e-12; the epoch within 1 us.
void check_same(const Elements& omm, const Elements& tle, int catalog) {
  INFO("catalog " << catalog << " " << tle.name);
  CHECK(omm.catalog_number == catalog);
  CHECK(omm.name == tle.name);
  CHECK(omm.international_designator == tle.international_designator);
  CHECK(omm.classification == tle.classification);
  CHECK(omm.element_set_number == tle.element_set_number);
  CHECK(omm.revolution_number == tle.revolution_number);
  CHECK(omm.mean_motion_rev_per_day == tle.mean_motion_rev_per_day);
  CHECK(omm.eccentricity == tle.eccentricity);
  CHECK(omm.inclination_deg == tle.inclination_deg);
  CHECK(omm.raan_deg == tle.raan_deg);
  CHECK(omm.arg_perigee_deg == tle.arg_perigee_deg);
  CHECK(omm.mean_anomaly_deg == tle.mean_anomaly_deg);
  CHECK(near_rel(omm.bstar, tle.bstar, 1e-12));
  CHECK(near_rel(omm.ndot_over_2, tle.ndot_over_2, 1e-12));
  CHECK(near_rel(omm.nddot_over_6, tle.nddot_over_6, 1e-12));
  CHECK(omm.epoch_year == tle.epoch_year);
  CHECK(std::abs(omm.epoch_day - tle.epoch_day) * 86400e6 <= 1.0);
}

const ParseResult& sources() {
  static const ParseResult r = load("sources.tle");
  return r;
}

ParseProblem only_problem(const ParseResult& r) {
  REQUIRE(r.problems.size() == 1);
  return r.problems.front();
}

// One ISS object in KVN with `line` (a "KEY = value" line, or empty) put in place of the line
// starting with the same keyword, or dropped when `line` is only the keyword.
std::string iss_kvn(const std::string& replace = "") {
  std::string text =
      "CCSDS_OMM_VERS = 2.0\n"
      "COMMENT a comment line\n"
      "OBJECT_NAME = ISS (ZARYA)\n"
      "OBJECT_ID = 1998-067A\n"
      "CENTER_NAME = EARTH\n"
      "REF_FRAME = TEME\n"
      "TIME_SYSTEM = UTC\n"
      "MEAN_ELEMENT_THEORY = SGP4\n"
      "EPOCH = 2026-05-21T03:57:45.045216\n"
      "MEAN_MOTION = 15.49291753 [rev/day]\n"
      "ECCENTRICITY = 0.0007529\n"
      "INCLINATION = 51.6328 [deg]\n"
      "RA_OF_ASC_NODE = 73.8715\n"
      "ARG_OF_PERICENTER = 81.3651\n"
      "MEAN_ANOMALY = 278.819\n"
      "EPHEMERIS_TYPE = 0\n"
      "CLASSIFICATION_TYPE = U\n"
      "NORAD_CAT_ID = 25544\n"
      "ELEMENT_SET_NO = 999\n"
      "REV_AT_EPOCH = 56756\n"
      "BSTAR = 0.00011282\n"
      "MEAN_MOTION_DOT = 5.835e-05\n"
      "MEAN_MOTION_DDOT = 0.0\n";
  if (replace.empty()) return text;
  const std::string key = replace.substr(0, replace.find(' '));
  const auto at = text.find("\n" + key + " ") + 1;
  const auto end = text.find('\n', at);
  text.replace(at, end - at + 1, replace == key ? "" : replace + "\n");
  return text;
}

}  // namespace

TEST_CASE("OMM: every encoding reads to the numbers of the TLE it was made from") {
  REQUIRE(sources().ok());
  REQUIRE(sources().sets.size() == 3);
  const int catalogs[] = {25544, 43700, 8195};
  struct Group {
    const char* prefix;
    int first;  // 0: the TLE's own numbers
  };
  for (const Group g : {Group{"sources", 0}, Group{"n100123", 100123}, Group{"n800123456", 800123456}}) {
    const std::pair<const char*, ElementFormat> encodings[] = {{".json", ElementFormat::omm_json},
                                                               {"-spacetrack.json", ElementFormat::omm_json},
                                                               {".csv", ElementFormat::omm_csv},
                                                               {".xml", ElementFormat::omm_xml},
                                                               {".kvn", ElementFormat::omm_kvn}};
    for (const auto& [suffix, format] : encodings) {
      const std::string file = std::string(g.prefix) + suffix;
      INFO(file);
      const ParseResult r = load(file);
      CHECK(r.problems.empty());
      REQUIRE(r.sets.size() == 3);
      for (int i = 0; i < 3; ++i) {
        check_same(r.sets[i], sources().sets[i], g.first ? g.first + i : catalogs[i]);
        CHECK(r.sets[i].source == format);
      }
    }
  }
}

TEST_CASE("OMM: the Alpha-5 TLE and the OMM of 100123 are the same set") {
  const ParseResult tle = load("n100123.tle");
  REQUIRE(tle.sets.size() == 3);
  CHECK(tle.sets[0].catalog_number == 100123);
  check_same(load("n100123.kvn").sets.at(0), tle.sets[0], 100123);
}

TEST_CASE("OMM: the epoch in both ISO forms, with and without fraction and Z") {
  auto epoch_of = [](const std::string& epoch) {
    const ParseResult r = parse_elements(iss_kvn("EPOCH = " + epoch));
    REQUIRE_MESSAGE(r.sets.size() == 1, epoch);
    return std::pair{r.sets[0].epoch_year, r.sets[0].epoch_day};
  };
  // 2026-05-21 is day 31 + 28 + 31 + 30 + 21 = 141; 03:57:45.045216 is 14265.045216 s.
  CHECK(epoch_of("2026-05-21T00:00:00") == std::pair{2026, 141.0});
  CHECK(epoch_of("2026-05-21T12:00:00Z") == std::pair{2026, 141.5});
  CHECK(epoch_of("2026-141T12:00:00.000Z") == std::pair{2026, 141.5});
  CHECK(epoch_of("2024-12-31T18:00:00") == std::pair{2024, 366.75});  // a leap year
  CHECK(std::abs(epoch_of("2026-05-21T03:57:45.045216").second - (141.0 + 14265.045216 / 86400.0)) < 1e-12);
}

TEST_CASE("OMM: what is not SGP4 mean elements is refused, naming object, keyword and line") {
  SUBCASE("SGP4-XP") {
    const ParseResult r = parse_elements(iss_kvn("MEAN_ELEMENT_THEORY = SGP4-XP"), "iss.kvn");
    CHECK(r.sets.empty());
    const ParseProblem& p = only_problem(r);
    CHECK(p.message() ==
          "iss.kvn:8:0: object 1 (ISS (ZARYA) 25544): MEAN_ELEMENT_THEORY: found 'SGP4-XP', expected SGP4 (only "
          "SGP4 mean elements are SGP4 input; SGP4-XP is not)");
  }
  SUBCASE("REF_FRAME GCRF, in XML") {
    std::string xml = format_omm({sources().sets[0]}, OmmEncoding::xml);
    const auto at = xml.find("<REF_FRAME>TEME");
    REQUIRE(at != std::string::npos);
    xml.replace(at, 15, "<REF_FRAME>GCRF");
    const ParseResult r = parse_elements(xml, "iss.xml");
    CHECK(r.sets.empty());
    const ParseProblem& p = only_problem(r);
    CHECK(p.field == "REF_FRAME");
    CHECK(p.found == "GCRF");
    CHECK(p.object == "object 1 (ISS (ZARYA) 25544)");
    CHECK(p.line == 11);
    CHECK(p.expected == "TEME (SGP4 elements are in the TEME frame)");
  }
  SUBCASE("the other keywords") {
    CHECK(only_problem(parse_elements(iss_kvn("CENTER_NAME = MARS"))).field == "CENTER_NAME");
    CHECK(only_problem(parse_elements(iss_kvn("TIME_SYSTEM = TAI"))).field == "TIME_SYSTEM");
    const ParseProblem& p = only_problem(parse_elements(iss_kvn("EPHEMERIS_TYPE = 4")));
    CHECK(p.field == "EPHEMERIS_TYPE");
    CHECK(p.found == "4");
    CHECK(p.line == 16);
  }
  SUBCASE("a missing MEAN_MOTION, in JSON: the object's line") {
    const std::string json =
        "[\n{\"OBJECT_NAME\": \"A\", \"NORAD_CAT_ID\": 1, \"EPOCH\": \"2026-01-01T00:00:00\"},\n"
        "{\"OBJECT_NAME\": \"B\", \"NORAD_CAT_ID\": 2}\n]";
    const ParseResult r = parse_elements(json, "x.json");
    REQUIRE(r.problems.size() == 2);
    CHECK(r.problems[0].message() ==
          "x.json:2:0: object 1 (A 1): MEAN_MOTION: found nothing, expected the keyword with a number (it is required)");
    CHECK(r.problems[1].message() ==
          "x.json:3:0: object 2 (B 2): EPOCH: found nothing, expected the keyword with a UTC time (it is required)");
  }
  SUBCASE("a bad EPOCH, in CSV; the other rows still load") {
    std::string csv = format_omm(sources().sets, OmmEncoding::csv);
    const auto at = csv.find("2026-05-21T05:45");  // QO-100, row 2 on line 3
    REQUIRE(at != std::string::npos);
    csv.replace(at, 10, "2026-13-21");
    const ParseResult r = parse_elements(csv, "x.csv");
    CHECK(r.sets.size() == 2);
    const ParseProblem& p = only_problem(r);
    CHECK(p.line == 3);
    CHECK(p.field == "EPOCH");
    CHECK(p.found == "2026-13-21T05:45:18.919584");
    CHECK(p.object == "object 2 (QO-100 43700)");
  }
  SUBCASE("numbers out of range, a keyword twice, a line without '='") {
    CHECK(only_problem(parse_elements(iss_kvn("ECCENTRICITY = 1.2"))).expected == "number in [0, 1)");
    CHECK(only_problem(parse_elements(iss_kvn("MEAN_MOTION = fast"))).field == "MEAN_MOTION");
    CHECK(only_problem(parse_elements(iss_kvn("NORAD_CAT_ID = 1234567890"))).field == "NORAD_CAT_ID");
    const ParseProblem& twice = only_problem(parse_elements(iss_kvn() + "BSTAR = 0.1\n"));
    CHECK(twice.field == "BSTAR");
    CHECK(twice.line == 24);
    CHECK(only_problem(parse_elements(iss_kvn("BSTAR oops"))).field == "KVN line");
  }
  SUBCASE("a malformed OBJECT_ID is left out with a warning") {
    const ParseResult r = parse_elements(iss_kvn("OBJECT_ID = UNKNOWN"));
    REQUIRE(r.sets.size() == 1);
    CHECK(r.sets[0].international_designator.empty());
    CHECK(only_problem(r).warning);
    CHECK(r.ok());
  }
}

TEST_CASE("Element files that are empty or not text say so, whatever the format would have been") {
  const ParseProblem& empty = only_problem(parse_elements("", "e.tle"));
  CHECK(empty.message() == "e.tle:0:0: file: found nothing, expected element sets (the file is empty)");
  CHECK(only_problem(parse_elements(" \r\n\n", "e.tle")).expected == "element sets (the file is empty)");
  const ParseProblem& binary = only_problem(parse_elements(std::string("{\"a\n\0\x01", 6), "b.json"));
  CHECK(binary.message() == "b.json:2:0: file: found 'a NUL byte at offset 4', expected text (this is not a text file)");
  CHECK(only_problem(parse_elements("\x01\x02\x03\x04\x05 1 25544")).expected == "text (this is not a text file)");
}

TEST_CASE("OMM writers: every encoding reads back to the same numbers") {
  const std::vector<Elements>& sets = sources().sets;
  for (const auto encoding : {OmmEncoding::json, OmmEncoding::xml, OmmEncoding::csv, OmmEncoding::kvn}) {
    const std::string text = format_omm(sets, encoding);
    const ParseResult r = parse_elements(text, "<written>");
    INFO(text);
    CHECK(r.problems.empty());
    REQUIRE(r.sets.size() == sets.size());
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const Elements& a = r.sets[i];
      const Elements& b = sets[i];
      check_same(a, b, b.catalog_number);
      CHECK(a.bstar == b.bstar);  // the writer keeps every digit
      CHECK(a.ndot_over_2 == b.ndot_over_2);
      CHECK(a.nddot_over_6 == b.nddot_over_6);
    }
  }
  // CelesTrak's layout: the first keys, numbers unquoted.
  CHECK(format_omm({sets[0]}, OmmEncoding::json)
            .starts_with("[{\"OBJECT_NAME\":\"ISS (ZARYA)\",\"OBJECT_ID\":\"1998-067A\",\"EPOCH\":\"2026-05-21T03:57:45."
                         "045216\",\"MEAN_MOTION\":15.49291753,\"ECCENTRICITY\":0.0007529,"));
  // And back to the TLE, digit for digit.
  const ParseResult json = parse_elements(format_omm(sets, OmmEncoding::json));
  std::string tle;
  for (const Elements& e : json.sets) tle += format_nasa(e);
  std::string original;
  for (const Elements& e : sets) original += format_nasa(e);
  CHECK(tle == original);
}

TEST_CASE("format_nasa writes no catalog number a TLE cannot hold, and says why") {
  Elements e = sources().sets[0];
  e.catalog_number = 800123456;
  CHECK(format_nasa(e).empty());
  CHECK(nasa_unwritable(e) ==
        "catalog number 800123456 does not fit a TLE (at most 339999, Alpha-5 Z9999); write it as OMM");
  e.catalog_number = 339999;
  CHECK(!nasa_unwritable(e));
  CHECK(format_nasa(e, false).substr(0, 8) == "1 Z9999U");
  e.catalog_number = 100123;
  CHECK(format_nasa(e, false).substr(0, 8) == "1 A0123U");
  e.epoch_year = 2057;
  CHECK(format_nasa(e).empty());
  CHECK(nasa_unwritable(e) == "epoch year 2057 does not fit a TLE's two digits (1957-2056)");
}
