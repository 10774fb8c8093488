// The horizon mask (orbit/horizon_mask.h): the three file forms read, interpolation round the
// circle and steps, and bad files refused naming the line and what is wrong. The expected
// elevations are worked by hand from the points (linear in azimuth: el = a + (b - a) * f).
#include <doctest/doctest.h>

#include "orbit/horizon_mask.h"

using tb::orbit::HorizonMask;
using tb::orbit::read_horizon_mask;

TEST_CASE("horizon mask: pairs per line (N.I.N.A .hrz), comments and blank lines, interpolated round the circle") {
  const auto r = read_horizon_mask("# roof to the south-west\n"
                                   "0 5\n"
                                   "\n"
                                   "200   5   # the roof begins\n"
                                   "214\t25\n"
                                   "262 25\n"
                                   "280 5\n",
                                   "roof.hrz");
  REQUIRE_MESSAGE(r.mask, r.error);
  const HorizonMask& m = *r.mask;
  CHECK(m.kind() == HorizonMask::Kind::interpolated);
  CHECK(m.points().size() == 5);
  CHECK(m.at(100.0) == doctest::Approx(5.0));
  CHECK(m.at(207.0) == doctest::Approx(15.0));   // half way from 200/5 to 214/25
  CHECK(m.at(240.0) == doctest::Approx(25.0));
  CHECK(m.at(271.0) == doctest::Approx(15.0));   // half way from 262/25 to 280/5
  CHECK(m.at(320.0) == doctest::Approx(5.0));    // 280/5 round to 0/5
  CHECK(m.at(-100.0) == doctest::Approx(m.at(260.0)));
  CHECK(m.at(620.0) == doctest::Approx(m.at(260.0)));
  CHECK(m.min_el() == doctest::Approx(5.0));
  CHECK(m.max_el() == doctest::Approx(25.0));
  CHECK(m.describe() == "interpolated, 5 points, 5.0..25.0 deg");
}

TEST_CASE("horizon mask: across north the last point joins the first") {
  // 300/10 to 60/30 spans 120 deg through north: at 0 it is 10 + 20 * 60/120 = 20.
  const auto r = read_horizon_mask("60 30\n300 10\n");
  REQUIRE(r.mask);
  CHECK(r.mask->at(0.0) == doctest::Approx(20.0));
  CHECK(r.mask->at(330.0) == doctest::Approx(15.0));
  CHECK(r.mask->at(180.0) == doctest::Approx(20.0));  // 60/30 to 300/10: half way
}

TEST_CASE("horizon mask: a CSV with its header") {
  const auto r = read_horizon_mask("az,el\n0,2\n90, 12.5\n180,2\n270,2\n");
  REQUIRE_MESSAGE(r.mask, r.error);
  CHECK(r.mask->kind() == HorizonMask::Kind::interpolated);
  CHECK(r.mask->at(45.0) == doctest::Approx(7.25));
  CHECK(r.mask->at(135.0) == doctest::Approx(7.25));
}

TEST_CASE("horizon mask: the VLBI Field System's step list AZ EL AZ EL ... AZ is stepped") {
  const auto r = read_horizon_mask("* \n# FS mask\n0 5 214 25 262 5\n360\n");
  CHECK_FALSE(r.mask);  // '*' is not a number: named
  CHECK(r.error == "horizon mask line 1: '*' is not a number");
  const auto s = read_horizon_mask("0 5 214 25 262 5\n360\n");
  REQUIRE_MESSAGE(s.mask, s.error);
  const HorizonMask& m = *s.mask;
  CHECK(m.kind() == HorizonMask::Kind::stepped);
  CHECK(m.at(0.0) == doctest::Approx(5.0));
  CHECK(m.at(213.9) == doctest::Approx(5.0));
  CHECK(m.at(214.0) == doctest::Approx(25.0));
  CHECK(m.at(261.9) == doctest::Approx(25.0));
  CHECK(m.at(262.0) == doctest::Approx(5.0));
  CHECK(m.at(359.9) == doctest::Approx(5.0));
  CHECK(m.min_el() == doctest::Approx(5.0));
  CHECK(m.describe() == "stepped, 3 steps, 5.0..25.0 deg");
}

TEST_CASE("horizon mask: bad files are refused naming the line and what") {
  CHECK(read_horizon_mask("0 5\n90 x\n", "m.hrz").error == "m.hrz line 2: 'x' is not a number");
  CHECK(read_horizon_mask("0 5\n400 5\n", "m.hrz").error == "m.hrz line 2: azimuth 400 is outside 0..360");
  CHECK(read_horizon_mask("0 5\n90 95\n", "m.hrz").error == "m.hrz line 2: elevation 95 is outside -90..90");
  CHECK(read_horizon_mask("0 5\n90 5\n45 5\n", "m.hrz").error ==
        "m.hrz line 3: azimuth 45 does not follow 90 (azimuths increase)");
  CHECK(read_horizon_mask("0,5,7\n", "m.csv").error == "m.csv line 1: 3 fields where a CSV line has az,el");
  CHECK(read_horizon_mask("0 5 214 25\n", "fs").error ==
        "fs line 1: a step list ends with an azimuth (AZ EL AZ EL ... AZ): 4 numbers");
  CHECK(read_horizon_mask("# nothing\n\n", "m.hrz").error ==
        "m.hrz: no points (AZ EL per line, or a step list AZ EL ... AZ)");
  CHECK(read_horizon_mask("90\n", "fs").error == "fs line 1: a step list needs at least AZ EL AZ");
}

TEST_CASE("horizon mask: text() is one line the reader takes back (the stored setting's form)") {
  const auto r = read_horizon_mask("0 5\n214 25\n262 25.5\n263 5\n");
  REQUIRE(r.mask);
  CHECK(r.mask->text() == "0 5; 214 25; 262 25.5; 263 5");
  const auto back = read_horizon_mask(r.mask->text());
  REQUIRE_MESSAGE(back.mask, back.error);
  CHECK(*back.mask == *r.mask);
  const auto s = read_horizon_mask("0 5 214 25 262 5\n360\n");
  REQUIRE(s.mask);
  CHECK(s.mask->text() == "0 5 214 25 262 5 360");
  const auto s_back = read_horizon_mask(s.mask->text());
  REQUIRE(s_back.mask);
  CHECK(*s_back.mask == *s.mask);
  // In the joined form a refusal names the pair.
  CHECK(read_horizon_mask("0 5; 400 25").error == "horizon mask pair 2: azimuth 400 is outside 0..360");
  // The shared mask of a stored text: the same object while the text is the same.
  const auto a = tb::orbit::shared_horizon_mask("0 5; 214 25; 262 25; 263 5");
  REQUIRE(a);
  CHECK(a == tb::orbit::shared_horizon_mask("0 5; 214 25; 262 25; 263 5"));
  CHECK(a->at(230.0) == doctest::Approx(25.0));
  CHECK_FALSE(tb::orbit::shared_horizon_mask(""));
  CHECK_FALSE(tb::orbit::shared_horizon_mask("0 5; 400 25"));
}
