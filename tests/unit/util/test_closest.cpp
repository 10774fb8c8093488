// util/closest.h: the satellite an operator meant ("did you mean RS-44?").
#include <doctest/doctest.h>

#include "util/closest.h"

using tb::text::closest_name;
using tb::text::did_you_mean;
using tb::text::edit_distance;

TEST_CASE("A name typed without its punctuation or case is the database's name") {
  const std::vector<std::string> names{"ISS", "RS-44", "SO-50", "AO-91", "IO-117", "FO-29"};
  CHECK(closest_name("RS44", names) == "RS-44");
  CHECK(closest_name("rs 44", names) == "RS-44");
  CHECK(closest_name("so50", names) == "SO-50");
  CHECK(did_you_mean("RS44", names) == "; did you mean RS-44?");
}

TEST_CASE("A near miss is suggested; a name near two or near none is not") {
  const std::vector<std::string> names{"ISS", "RS-44", "SO-50", "AO-91", "AO-92", "IO-117"};
  CHECK(closest_name("IO-171", names) == "IO-117");   // two letters swapped: distance 2
  CHECK(closest_name("AO-93", names) == std::nullopt);  // AO-91 and AO-92 both one away
  CHECK(closest_name("QO-100", names) == std::nullopt);
  CHECK(closest_name("ISX", names) == "ISS");           // short names: one letter off at most
  CHECK(closest_name("IXX", names) == std::nullopt);
  CHECK(closest_name("", names) == std::nullopt);
  CHECK(did_you_mean("NOPE-1", names).empty());
}

TEST_CASE("Edit distance as Levenshtein's, stopped past the limit") {
  CHECK(edit_distance("KITTEN", "SITTING", 5) == 3);   // the textbook example
  CHECK(edit_distance("RS44", "RS44", 2) == 0);
  CHECK(edit_distance("A", "ABCDEF", 2) == 3);          // past the limit: limit + 1
}
