#include "util/text.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>

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

TEST_CASE("append_fixed writes what printf's %W.Pf writes, character for character") {
  auto printf_fixed = [](double v, int w, int p) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%*.*f", w, p, v);
    return std::string(buf);
  };
  auto fixed = [](double v, int w, int p) {
    std::string s;
    append_fixed(s, v, w, p);
    return s;
  };
  // Exact ties round to even as printf does, negative zero keeps its sign, wide values overflow the width.
  CHECK(fixed(0.125, 6, 2) == "  0.12");
  CHECK(fixed(0.375, 6, 2) == "  0.38");
  CHECK(fixed(-0.0, 12, 9) == "-0.000000000");
  CHECK(fixed(-1e-12, 12, 9) == "-0.000000000");
  CHECK(fixed(123456789.5, 4, 0) == "123456790");
  CHECK(fixed(7022.46529266, 16, 8) == "   7022.46529266");
  for (double v : {0.125, 0.375, -0.0, -1e-12, 123456789.5, 1e300, -1e300, 5e-324, 0.5, 1.5, 2.5, -2.5,
                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::max()})
    for (int p : {0, 2, 8, 9})
      CHECK(fixed(v, 16, p) == printf_fixed(v, 16, p));
  // The propagate command's ranges: positions to 1e5 km at %16.8f, velocities to 12 km/s at %12.9f,
  // times to 1e7 minutes; a fixed-seed generator, so every run tests the same 300,000 numbers.
  std::mt19937_64 gen(20261126);
  std::uniform_real_distribution<double> pos(-1e5, 1e5), vel(-12.0, 12.0), t(-1e7, 1e7);
  int differ = 0;
  for (int i = 0; i < 100000; ++i) {
    const double a = pos(gen), b = vel(gen), c = t(gen);
    differ += fixed(a, 16, 8) != printf_fixed(a, 16, 8);
    differ += fixed(b, 12, 9) != printf_fixed(b, 12, 9);
    differ += fixed(c, 16, 8) != printf_fixed(c, 16, 8);
  }
  CHECK(differ == 0);
  // Every binary exponent the fast path takes (|v| < 2^53) and the one beyond, mantissas at random,
  // at every precision it takes; exact ties (odd multiples of 2^-(P+1) are ties at P decimals,
  // as 10^P 2^-(P+1) = 5^P / 2), and values that round up into the next whole number.
  std::uniform_int_distribution<std::uint64_t> mantissa(0, (std::uint64_t{1} << 52) - 1);
  std::uniform_int_distribution<int> exponent(-1074, 54), precision(0, 9);
  for (int i = 0; i < 300000; ++i) {
    const int e = exponent(gen);
    const double v = std::ldexp(static_cast<double>(mantissa(gen) | (std::uint64_t{1} << 52)), e - 52);
    const int p = precision(gen);
    differ += fixed(i % 2 ? -v : v, 16, p) != printf_fixed(i % 2 ? -v : v, 16, p);
  }
  for (int p = 0; p <= 9; ++p)
    for (std::int64_t odd = 1; odd < 4000; odd += 2) {
      const double tie = std::ldexp(static_cast<double>(odd), -(p + 1));
      for (double v : {tie, -tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e9), 1e6 + tie})
        differ += fixed(v, 16, p) != printf_fixed(v, 16, p);
    }
  for (double v : {0.9999999999, 9.9999999995, 99999.999999999, 0x1p53 - 1.0, 0x1p53, 0x1p-1074, 4503599627370495.5})
    for (int p = 0; p <= 9; ++p) differ += fixed(v, 16, p) != printf_fixed(v, 16, p);
  CHECK(differ == 0);
}

TEST_CASE("trimmed: trim as a string of its own, any white space by default") {
  CHECK(tb::text::trimmed(" \t ISS \r\n") == "ISS");
  CHECK(tb::text::trimmed("  ") == "");
  CHECK(tb::text::trimmed("\tA B\t", " ") == "\tA B\t");   // only the characters given
}
