// Issue 38, items 2 and 3: a name that is not valid UTF-8 (IS\xff\xfeS) in an element file aborted
// every start (nlohmann's type_error.316 when the state was saved), and names with escape sequences
// reached the terminal. parse_elements makes every name printable UTF-8 and says so, located.
#include <doctest/doctest.h>

#include <string>

#include "orbit/elements.h"

using namespace tb::orbit;

namespace {
const std::string R = "\xEF\xBF\xBD";  // U+FFFD
const std::string kL1 = "1 25544U 98067A   26141.16510469  .00005835  00000-0  11282-3 0  9994";
const std::string kL2 = "2 25544  51.6328  73.8715 0007529  81.3651 278.8190 15.49291753567565";
}  // namespace

TEST_CASE("element names: invalid UTF-8 is replaced, with a located warning (the repro)") {
  const std::string text = "# shipped\nIS\xff\xfeS\n" + kL1 + "\n" + kL2 + "\n";
  const ParseResult r = parse_elements(text, "amateur.tle");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "IS" + R + R + "S");
  CHECK(r.ok());
  REQUIRE(r.problems.size() == 1);
  CHECK(r.problems[0].warning);
  CHECK(r.problems[0].message() ==
        "amateur.tle:2:0: name: found 'IS\\xff\\xfeS', expected printable UTF-8 (kept as 'IS" + R + R + "S') (warning: set accepted)");
}

TEST_CASE("element names: escape sequences never reach a terminal") {
  const std::string evil = "\x1b[2J\x1b[31m EVIL \x1b]0;pwn\x07";
  const ParseResult r = parse_elements(evil + "\n" + kL1 + "\n" + kL2 + "\n", "evil.tle");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == R + "[2J" + R + "[31m EVIL " + R + "]0;pwn" + R);
  REQUIRE(r.problems.size() == 1);
  CHECK(r.problems[0].message().find('\x1b') == std::string::npos);
  CHECK(r.problems[0].line == 1);
}

TEST_CASE("element names: printable UTF-8 names are kept as they are, without a word") {
  const ParseResult r = parse_elements("ISS (ZARYA) \xc3\xa9\n" + kL1 + "\n" + kL2 + "\n", "ok.tle");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "ISS (ZARYA) \xc3\xa9");
  CHECK(r.problems.empty());
}

TEST_CASE("element names: OMM JSON names with control characters are cleaned too") {
  const std::string omm = R"([{"OBJECT_NAME":"A\u001bB","OBJECT_ID":"1998-067A","EPOCH":"2026-05-21T03:57:44.245216",
"MEAN_MOTION":15.49291753,"ECCENTRICITY":0.0007529,"INCLINATION":51.6328,"RA_OF_ASC_NODE":73.8715,
"ARG_OF_PERICENTER":81.3651,"MEAN_ANOMALY":278.819,"EPHEMERIS_TYPE":0,"CLASSIFICATION_TYPE":"U",
"NORAD_CAT_ID":25544,"ELEMENT_SET_NO":999,"REV_AT_EPOCH":56756,"BSTAR":0.00011282,"MEAN_MOTION_DOT":5.835e-05,
"MEAN_MOTION_DDOT":0}])";
  const ParseResult r = parse_elements(omm, "gp.json");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "A" + R + "B");
  CHECK(r.ok());
}
