// Issue 18, item 6: the TrakBox manual never mentions the AMSAT "Checksum:" line, so a block without
// one is accepted (with a warning) even by the strict reading of a serial upload; a checksum that
// is there and wrong still rejects the block there.
#include <doctest/doctest.h>

#include <string>

#include "orbit/elements.h"
#include "support/gpredict_sets.h"

using namespace tb::orbit;

TEST_CASE("AMSAT: a block without 'Checksum:' is accepted with a warning; a wrong one is refused when strict") {
  const std::string block = format_amsat(tb::testing::iss_2018());
  const auto at = block.find("Checksum:");
  REQUIRE(at != std::string::npos);
  const std::string without = block.substr(0, at);
  ParseOptions strict;
  strict.strict_amsat_checksum = true;
  for (const ParseOptions& o : {ParseOptions{}, strict}) {
    const ParseResult r = parse_amsat(without, "upload", o);
    REQUIRE(r.sets.size() == 1);
    REQUIRE(r.problems.size() == 1);
    CHECK(r.problems[0].warning);
    CHECK(r.sets[0].catalog_number == tb::testing::iss_2018().catalog_number);
  }
  std::string wrong = block;
  const auto digits = wrong.find_first_of("0123456789", at);
  wrong[digits] = wrong[digits] == '9' ? '8' : static_cast<char>(wrong[digits] + 1);
  CHECK(parse_amsat(wrong, "upload", strict).sets.empty());
  CHECK(parse_amsat(wrong, "upload").sets.size() == 1);
}
