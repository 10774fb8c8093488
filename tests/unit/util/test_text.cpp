#include "util/text.h"

#include <doctest/doctest.h>

using namespace tb::text;

TEST_CASE("trim takes blanks (or the given characters) off both ends only") {
  CHECK(trim("  a b\t") == "a b");
  CHECK(trim("\t \t").empty());
  CHECK(trim("").empty());
  CHECK(trim("\r\nx \n") == "\r\nx \n");
  CHECK(trim("\r\nx \n", kWhitespace) == "x");
  CHECK(trim_left("  x  ") == "x  ");
  CHECK(trim_right("  x  ") == "  x");
}

TEST_CASE("lower, upper and iequals change ASCII letters only") {
  CHECK(lower("AbC-9\xC4") == "abc-9\xC4");
  CHECK(upper("aBc_z") == "ABC_Z");
  CHECK(iequals("Status?", "STATUS?"));
  CHECK_FALSE(iequals("STATUS", "STATUS?"));
}

TEST_CASE("split keeps empty pieces") {
  CHECK(split("a,,b", ',') == std::vector<std::string_view>{"a", "", "b"});
  CHECK(split("", ',') == std::vector<std::string_view>{""});
  CHECK(split("x,", ',') == std::vector<std::string_view>{"x", ""});
}

TEST_CASE("parse_double reads the whole string or nothing") {
  CHECK(parse_double("145.95") == 145.95);
  CHECK(parse_double("+2") == 2.0);
  CHECK(parse_double("-3.5e2") == -350.0);
  CHECK(parse_double(".5") == 0.5);
  CHECK_FALSE(parse_double(""));
  CHECK_FALSE(parse_double("+"));
  CHECK_FALSE(parse_double("++1"));
  CHECK_FALSE(parse_double("+-1"));
  CHECK_FALSE(parse_double(" 1"));
  CHECK_FALSE(parse_double("1 "));
  CHECK_FALSE(parse_double("inf"));
  CHECK_FALSE(parse_double("nan"));
  CHECK_FALSE(parse_double("1e999"));
  CHECK_FALSE(parse_double("0x10"));
}

TEST_CASE("parse_integer reads the whole string as the type asked for") {
  CHECK(parse_integer("42") == 42);
  CHECK(parse_integer("+7") == 7);
  CHECK(parse_integer("-7") == -7);
  CHECK(parse_integer<int>("800123456") == 800123456);
  CHECK_FALSE(parse_integer<int>("99999999999"));
  CHECK_FALSE(parse_integer("4.0"));
  CHECK_FALSE(parse_integer("+-1"));
  CHECK_FALSE(parse_integer(""));
}
