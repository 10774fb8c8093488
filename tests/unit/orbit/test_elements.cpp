// The NASA two- and three-line format (fields, checksums, Alpha-5, Vallado's SGP4-VER.TLE against
// python-sgp4, every problem located), files read by detection, and gpredict's files.
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


// ---------------------------------------------------------------------------------------------
// NASA format

TEST_CASE("NASA: ISS field values match the literal text") {
  const ParseResult r = parse_nasa(lines({kIss1, kIss2}));
  REQUIRE(r.ok());
  REQUIRE(r.sets.size() == 1);
  const Elements& e = r.sets[0];
  CHECK(e.name.empty());
  CHECK(e.label() == "25544");
  CHECK(e.catalog_number == 25544);
  CHECK(e.classification == 'U');
  CHECK(e.international_designator == "98067A");
  CHECK(e.epoch_year == 2008);
  CHECK(e.epoch_day == 264.51782528);
  CHECK(e.ndot_over_2 == -0.00002182);
  CHECK(e.nddot_over_6 == 0.0);
  CHECK(e.bstar == -0.11606e-4);
  CHECK(e.ephemeris_type == 0);
  CHECK(e.element_set_number == 292);
  CHECK(e.inclination_deg == 51.6416);
  CHECK(e.raan_deg == 247.4627);
  CHECK(e.eccentricity == 0.0006703);
  CHECK(e.arg_perigee_deg == 130.5360);
  CHECK(e.mean_anomaly_deg == 325.0288);
  CHECK(e.mean_motion_rev_per_day == 15.72125391);
  CHECK(e.revolution_number == 56353);
  CHECK(e.source == ElementFormat::nasa);
  // Day 264 of 2008 (a leap year) is September 20; .51782528 day = 12:25:40.104192.
  CHECK(e.epoch() == from_civil(2008, 9, 20, 12, 25, 40.104192));
}

TEST_CASE("NASA: checksums of known lines") {
  CHECK(nasa_checksum(kIss1) == 7);
  CHECK(nasa_checksum(kIss2) == 7);
  CHECK(nasa_checksum("1 07530U 74089B   12256.61218065 -.00000027  00000-0  10000-3 0  4795") == 5);
  CHECK(nasa_checksum("2 07530 101.4099 250.4681 0012001 109.6272 250.6089 12.53591141731001") == 1);
}

TEST_CASE("NASA: three-line forms, CRLF, trailing blanks, comments and text after column 69") {
  const std::string text = "# a comment line\r\n"
                           "\r\n"
                           "0 ISS (ZARYA)\r\n" +
                           std::string(kIss1) + "   \r\n" + kIss2 + "      0.0      1440.0        360.00\r\n" +
                           "\r\n"
                           "   # an indented comment\r\n"
                           "NOAA 18                 \r\n"
                           // explicit plus signs, zero-padded angles
                           "1 28654U 05018A   18020.89662949 +.00000491 +00000-0 +21026-3 0  9991\r\n"
                           "2 28654 099.1634 053.2197 0014486 177.6703 182.4537 14.12364350652899\r\n";
  const ParseResult r = parse_nasa(text, "keps.txt");
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 2);
  CHECK(r.sets[0].name == "ISS (ZARYA)");
  CHECK(r.sets[0].label() == "ISS (ZARYA)");
  CHECK(r.sets[0].revolution_number == 56353);
  const Elements& noaa = r.sets[1];
  CHECK(noaa.name == "NOAA 18");
  CHECK(noaa.ndot_over_2 == 0.00000491);
  CHECK(noaa.nddot_over_6 == 0.0);
  CHECK(noaa.bstar == 0.21026e-3);
  CHECK(noaa.inclination_deg == 99.1634);
  CHECK(noaa.raan_deg == 53.2197);
  CHECK(noaa.epoch_year == 2018);
}

TEST_CASE("NASA: files joined with cat keep a byte-order mark inside; it is dropped from every line, never part of a name") {
  const std::string bom = "\xEF\xBB\xBF";
  const std::string text = bom + "ISS (ZARYA)\n" + kIss1 + "\n" + kIss2 + "\n" + bom + "ISS AGAIN\n" + kIss1 + "\n" + kIss2 +
                           "\n" + bom + kIss1 + "\n" + kIss2 + "\n";
  const ParseResult r = parse_nasa(text, "joined.txt");
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 3);
  CHECK(r.sets[0].name == "ISS (ZARYA)");
  CHECK(r.sets[1].name == "ISS AGAIN");
  CHECK(r.sets[2].name.empty());
  // Found by fuzz_elements: a name line "<BOM>1 07530..." was a name on reading but, written first
  // in a file, its mark became the file's and the line read back as a line 1. Now it is a line 1 on
  // reading too (a broken one, reported), and the set after it is read unnamed.
  const ParseResult odd = parse_nasa("# x\n" + bom + "1 07530oderate drag case\n" + kIss1 + "\n" + kIss2 + "\n", "odd.txt");
  REQUIRE(odd.sets.size() == 1);
  CHECK(odd.sets[0].name.empty());
  REQUIRE(odd.problems.size() == 1);
  CHECK(odd.problems[0].line == 2);
  MESSAGE(odd.problems[0].message());
}

TEST_CASE("NASA: an ndot/2 that fills all 10 columns (the sign's too) is written back as read") {
  // Found by fuzz_elements: "2700000421" was read (10 digits, no point) but written as stars.
  std::string l1 = "1 09880U 77102A   06092.15615748 2700000421  00000-0  10000-3 1  981";
  l1 += static_cast<char>('0' + nasa_checksum(l1));
  std::string l2 = "2 09880  64.5968 349.3786 9754032 270.0229  15.3320  4.0081361411238";
  l2 += static_cast<char>('0' + nasa_checksum(l2));
  const ParseResult r = parse_nasa(l1 + "\n" + l2 + "\n", "big.txt");
  REQUIRE(r.problems.empty());
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].ndot_over_2 == 2700000421.0);
  const std::string text = format_nasa(r.sets[0]);
  CHECK(text.substr(33, 10) == "2700000421");
  const ParseResult again = parse_nasa(text, "again.txt");
  REQUIRE(again.sets.size() == 1);
  CHECK(again.sets[0].ndot_over_2 == 2700000421.0);
}

TEST_CASE("NASA: implied-decimal exponent fields") {
  // The same ISS line with other nddot/6 and BSTAR texts; checksums recomputed.
  auto with = [](std::string_view nddot, std::string_view bstar) {
    std::string l1 = kIss1;
    l1.replace(44, 8, nddot);
    l1.replace(53, 8, bstar);
    l1[68] = static_cast<char>('0' + nasa_checksum(l1));
    const ParseResult r = parse_nasa(lines({l1, kIss2}));
    REQUIRE_MESSAGE(r.sets.size() == 1, l1);
    return r.sets[0];
  };
  CHECK(with(" 28098-4", " 00000+0").nddot_over_6 == 0.28098e-4);
  CHECK(with("-30915-6", "+00000-0").nddot_over_6 == -0.30915e-6);
  CHECK(with(" 00000-0", " 13519-0").bstar == 0.13519);
  CHECK(with(" 00000-0", "-18209+0").bstar == -0.18209);
  CHECK(with(" 00000-0", "+21026-3").bstar == 0.21026e-3);
  CHECK(with(" 00000-0", " 10000-9").bstar == 1e-10);
  CHECK(with(" 00000-0", "        ").bstar == 0.0);  // blank: not given
}

TEST_CASE("NASA: two-digit years pivot at 57") {
  auto year_of = [](std::string_view yy) {
    std::string l1 = kIss1;
    l1.replace(18, 2, yy);
    l1[68] = static_cast<char>('0' + nasa_checksum(l1));
    const ParseResult r = parse_nasa(lines({l1, kIss2}));
    REQUIRE(r.sets.size() == 1);
    return r.sets[0].epoch_year;
  };
  CHECK(year_of("57") == 1957);
  CHECK(year_of("99") == 1999);
  CHECK(year_of("00") == 2000);
  CHECK(year_of("56") == 2056);
}

TEST_CASE("Alpha-5 catalog numbers") {
  CHECK(decode_catalog_number("25544") == 25544);
  CHECK(decode_catalog_number("00005") == 5);
  CHECK(decode_catalog_number(" 5560") == 5560);
  CHECK(decode_catalog_number("A0000") == 100000);
  CHECK(decode_catalog_number("E8493") == 148493);
  CHECK(decode_catalog_number("H9999") == 179999);
  CHECK(decode_catalog_number("J0000") == 180000);  // I is skipped
  CHECK(decode_catalog_number("P0000") == 230000);  // O is skipped
  CHECK(decode_catalog_number("Z9999") == 339999);
  CHECK(decode_catalog_number("I0000") == -1);
  CHECK(decode_catalog_number("O0000") == -1);
  CHECK(decode_catalog_number("a0000") == -1);
  CHECK(decode_catalog_number("A12B4") == -1);
  CHECK(decode_catalog_number("2554") == -1);
  CHECK(decode_catalog_number("     ") == -1);
  CHECK(encode_catalog_number(5) == "00005");
  CHECK(encode_catalog_number(99999) == "99999");
  CHECK(encode_catalog_number(100000) == "A0000");
  CHECK(encode_catalog_number(148493) == "E8493");
  CHECK(encode_catalog_number(180000) == "J0000");
  CHECK(encode_catalog_number(339999) == "Z9999");
  CHECK(encode_catalog_number(340000).empty());
  CHECK(encode_catalog_number(-1).empty());
  for (int n : {0, 1, 99999, 100000, 123456, 179999, 180000, 229999, 230000, 339999})
    CHECK(decode_catalog_number(encode_catalog_number(n)) == n);

  const ParseResult r = parse_nasa("1 E8493U 18099A   18263.50000000  .00000100  00000-0  10000-4 0  9992\n"
                                   "2 E8493  97.7000 300.1234 0011000  90.0000 270.0000 15.00000000 12348\n");
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].catalog_number == 148493);
  CHECK(r.sets[0].label() == "148493");
}

// ---------------------------------------------------------------------------------------------
// Vallado's verification set (Debian python3-sgp4)

TEST_CASE("SGP4-VER.TLE: all 33 sets parse with checksums off") {
  ParseOptions lax;
  lax.verify_checksums = false;
  const ParseResult r = parse_nasa(read_text(kSgp4Ver), "SGP4-VER.TLE", lax);
  for (const auto& p : r.problems) MESSAGE(p.message());
  CHECK(r.problems.empty());
  CHECK(r.sets.size() == 33);
}

TEST_CASE("SGP4-VER.TLE: 33333, 33334 and 33335 fail their checksums on purpose") {
  const ParseResult r = parse_nasa(read_text(kSgp4Ver), "SGP4-VER.TLE");
  CHECK(r.sets.size() == 30);
  REQUIRE(r.problems.size() == 3);
  // Line 1 of each reuses another satellite's line 1 with a new number and the old checksum.
  check_problem(r.problems[0], 100, 69, "checksum", "4", "checksum 2");  // 33333
  check_problem(r.problems[1], 103, 69, "checksum", "9", "checksum 6");  // 33334
  check_problem(r.problems[2], 106, 69, "checksum", "0", "checksum 3");  // 33335
  CHECK(r.problems[0].message() == "SGP4-VER.TLE:100:69: checksum: found '4', expected checksum 2");
  CHECK(find(r, 33333) == nullptr);
  CHECK(find(r, 33334) == nullptr);
  CHECK(find(r, 33335) == nullptr);
  CHECK_FALSE(r.ok());

  // 11801, the original STR#3 SDP4 case: no designator, no ephemeris type.
  const Elements* e = find(r, 11801);
  REQUIRE(e != nullptr);
  CHECK(e->international_designator.empty());
  CHECK(e->ephemeris_type == 0);
  CHECK(e->element_set_number == 1);
  CHECK(e->revolution_number == 1);
  CHECK(e->bstar == 0.14311e-1);
}

TEST_CASE("SGP4-VER.TLE: values agree with python-sgp4's twoline2rv") {
  // Computed once with Debian's python3-sgp4 (sgp4.api.Satrec.twoline2rv, not accelerated):
  // radians, rad/min, rad/min^2 and rad/min^3 as SGP4 takes them. Our values are converted with
  // the same factors python-sgp4 uses (deg2rad = pi/180, xpdotp = 1440/(2 pi)).
  struct Reference {
    int satnum;
    double epochdays, jdsatepoch, jdsatepochF, ndot, nddot, bstar, inclo, nodeo, ecco, argpo, mo, no_kozai;
    long revnum;
    int elnum;
    const char* intldesg;
  };
  const Reference refs[] = {
      {5, 179.78495062, 2451722.5, 0.78495062, 6.96919666594958e-13, 0.0, 2.8098e-05, 0.5980929187319208,
       6.08638547138321, 0.1859667, 5.790416027488515, 0.3373093125574321, 0.04722944544077857, 41366, 475,
       "58002B"},
      {11801, 230.29629788, 2444468.5, 0.29629788, 4.3363644592306274e-08, 0.0, 0.014310999999999999,
       0.8166674822761788, 4.021856443150141, 0.7318036, 0.8285461931652521, 0.1817184457298936,
       0.009971844782555844, 1, 1, ""},
      {16925, 151.67415771, 2453886.5, 0.67415771, 7.729123930575737e-08, -6.505214822700219e-16,
       0.00018784000000000002, 1.0836854045387911, 5.149138427074499, 0.5596327, 4.278836976884534,
       0.83721698888916, 0.021315351634602436, 14861, 448, "86065D"},
      {21897, 176.02341244, 2453911.5, 0.02341244, -3.8572988503277456e-11, 0.0, -0.00013525,
       1.0851567170982224, 3.4559194705569642, 0.742169, 4.4164893496600754, 0.351790309361229,
       0.00878206020192308, 10488, 304, "92011A"},
      {29141, 170.26783845, 2453905.5, 0.26783845, 3.030085476633745e-06, 0.0, 0.13519, 1.438653958467902,
       4.773269555352756, 0.0015848, 4.838269107355529, 1.4645633712137578, 0.06952270688786914, 682, 71,
       "85108AA"},
      {23333, 305.49999999, 2449657.5, 0.49999999, -5.240714689373807e-09, 5.674466379548983e-13, 0.0001,
       0.5017647066558498, 0.0413992098573055, 0.9728298, 0.5312084111369941, 0.02356194490192345,
       0.0003189367114872321, 7, 1, "94071A"},
  };
  constexpr double deg2rad = std::numbers::pi / 180.0;
  constexpr double xpdotp = 1440.0 / (2.0 * std::numbers::pi);
  const ParseResult r = parse_nasa(read_text(kSgp4Ver), "SGP4-VER.TLE");
  for (const Reference& ref : refs) {
    CAPTURE(ref.satnum);
    const Elements* e = find(r, ref.satnum);
    REQUIRE(e != nullptr);
    // python-sgp4 multiplies mantissa and power of ten; we convert the decimal text in one step.
    auto same = [](double a, double b) { return std::abs(a - b) <= 1e-15 * std::max(std::abs(a), std::abs(b)); };
    CHECK(e->epoch_day == ref.epochdays);
    CHECK(same(e->ndot_over_2 / (xpdotp * 1440.0), ref.ndot));
    CHECK(same(e->nddot_over_6 / (xpdotp * 1440.0 * 1440.0), ref.nddot));
    CHECK(same(e->bstar, ref.bstar));
    CHECK(e->inclination_deg * deg2rad == ref.inclo);
    CHECK(e->raan_deg * deg2rad == ref.nodeo);
    CHECK(e->eccentricity == ref.ecco);
    CHECK(e->arg_perigee_deg * deg2rad == ref.argpo);
    CHECK(e->mean_anomaly_deg * deg2rad == ref.mo);
    CHECK(e->mean_motion_rev_per_day / xpdotp == ref.no_kozai);
    CHECK(e->revolution_number == ref.revnum);
    CHECK(e->element_set_number == ref.elnum);
    CHECK(e->international_designator == ref.intldesg);
    // The epoch keeps microseconds: 1 us = 1.16e-11 day.
    const JulianDate jd = julian_date(e->epoch());
    CHECK(jd.whole == ref.jdsatepoch);
    CHECK(std::abs(jd.fraction - ref.jdsatepochF) < 6e-12);
  }
}

// ---------------------------------------------------------------------------------------------
// NASA problems

TEST_CASE("NASA problems: wrong checksum, reported and parsing continues") {
  std::string bad = kIss1;
  bad[68] = '8';
  const ParseResult r = parse_nasa(lines({"ISS", bad, kIss2, "ISS again", kIss1, kIss2}), "iss.tle");
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 2, 69, "checksum", "8", "checksum 7");
  CHECK(r.problems[0].file == "iss.tle");
  CHECK(r.problems[0].message() == "iss.tle:2:69: checksum: found '8', expected checksum 7");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "ISS again");

  ParseOptions lax;
  lax.verify_checksums = false;
  CHECK(parse_nasa(lines({bad, kIss2}), "iss.tle", lax).sets.size() == 1);
}

TEST_CASE("NASA problems: a letter in a numeric field") {
  // Checksums are right for the damaged text, so the field itself is what is reported.
  ParseResult r = parse_nasa(lines({kIss1, "2 25544  51.6A16 247.4627 0006703 130.5360 325.0288 15.72125391563533"}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 2, 9, "inclination", " 51.6A16", "decimal number");
  CHECK(r.sets.empty());

  r = parse_nasa(lines({"1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  29A5", kIss2}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 1, 65, "element set number", " 29A", "digits 0-9");

  // Even with a wrong checksum, the field comes first.
  std::string l1 = kIss1;
  l1[19] = 'X';
  r = parse_nasa(lines({l1, kIss2}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 1, 19, "epoch year", "0X", "two digits 00-99");
}

TEST_CASE("NASA problems: missing line 2") {
  ParseResult r = parse_nasa(lines({"ISS (ZARYA)", kIss1, "ISS (ZARYA)", kIss1, kIss2}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 3, 1, "line 2", "ISS (ZARYA)", "line 2 after line 1");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "ISS (ZARYA)");

  r = parse_nasa(lines({kIss1, kIss2, kIss1}), "end.tle");
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 4, 1, "line 2", "", "line 2 after line 1");
  CHECK(r.problems[0].message() == "end.tle:4:1: line 2: found nothing, expected line 2 after line 1");
  CHECK(r.sets.size() == 1);
}

TEST_CASE("NASA problems: lines out of order") {
  const ParseResult r = parse_nasa(lines({"ISS", kIss2, kIss1, "", "ISS", kIss1, kIss2}));
  REQUIRE(r.problems.size() == 1);  // one problem for the swapped pair
  check_problem(r.problems[0], 2, 1, "line 1", kIss2, "line 1 before line 2");
  CHECK(r.sets.size() == 1);

  // Line 2 of one satellite before line 1 of another: two problems.
  const ParseResult other =
      parse_nasa(lines({kIss2, "1 07530U 74089B   12256.61218065 -.00000027  00000-0  10000-3 0  4795"}));
  REQUIRE(other.problems.size() == 2);
  check_problem(other.problems[0], 1, 1, "line 1", kIss2, "line 1 before line 2");
  check_problem(other.problems[1], 3, 1, "line 2", "", "line 2 after line 1");

  // A stray line 2 followed by a complete set: the set is kept.
  const ParseResult stray = parse_nasa(lines({kIss2, kIss1, kIss2}));
  REQUIRE(stray.problems.size() == 1);
  check_problem(stray.problems[0], 1, 1, "line 1", kIss2, "line 1 before line 2");
  CHECK(stray.sets.size() == 1);
}

TEST_CASE("NASA problems: catalog numbers of lines 1 and 2 disagree") {
  const ParseResult r =
      parse_nasa(lines({kIss1, "2 25545  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563538"}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 2, 3, "catalog number", "25545", "25544 as on line 1");
}

TEST_CASE("NASA problems: truncated lines") {
  const std::string cut = std::string(kIss1).substr(0, 57);
  ParseResult r = parse_nasa(lines({cut, kIss2}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 1, 54, "BSTAR", "-116", "69 columns (the line ends at column 57)");

  // Without its checksum column the line is complete when checksums are not verified.
  const std::string no_checksum = std::string(kIss2).substr(0, 68);
  r = parse_nasa(lines({kIss1, no_checksum}));
  REQUIRE(r.problems.size() == 1);
  check_problem(r.problems[0], 2, 69, "checksum", "", "69 columns (the line ends at column 68)");
  ParseOptions lax;
  lax.verify_checksums = false;
  CHECK(parse_nasa(lines({kIss1, no_checksum}), "<text>", lax).problems.empty());
}

TEST_CASE("NASA problems: ranges and separators") {
  auto line2_problem = [](std::string l2) {
    l2[68] = static_cast<char>('0' + nasa_checksum(l2));
    const ParseResult r = parse_nasa(lines({kIss1, l2}));
    REQUIRE(r.problems.size() == 1);
    CHECK(r.sets.empty());
    return r.problems[0];
  };
  std::string l2 = kIss2;
  l2.replace(8, 8, "180.0001");
  check_problem(line2_problem(l2), 2, 9, "inclination", "180.0001", "number in [0, 180]");
  l2 = kIss2;
  l2.replace(17, 8, "360.0000");
  check_problem(line2_problem(l2), 2, 18, "RAAN", "360.0000", "number in [0, 360)");
  l2 = kIss2;
  l2.replace(52, 11, " 0.00000000");
  check_problem(line2_problem(l2), 2, 53, "mean motion", " 0.00000000", "number >= 0.00000001");
  l2 = kIss2;
  l2.replace(52, 11, ".0000000014");  // more digits than the field's 8 decimals: it would write as 0
  check_problem(line2_problem(l2), 2, 53, "mean motion", ".0000000014", "number >= 0.00000001");
  l2 = kIss2;
  l2.replace(26, 7, "00067.3");
  check_problem(line2_problem(l2), 2, 27, "eccentricity", "00067.3", "7 digits (implied leading decimal point)");
  // The epoch day must exist in its year (2008 is a leap year, 2007 is not).
  {
    std::string l1 = kIss1;
    l1.replace(18, 14, "07366.51782528");
    l1[68] = static_cast<char>('0' + nasa_checksum(l1));
    const ParseResult r = parse_nasa(lines({l1, kIss2}));
    REQUIRE(r.problems.size() == 1);
    check_problem(r.problems[0], 1, 21, "epoch day", "366.51782528", "day of year in [1, 366)");
    l1.replace(18, 2, "08");
    l1[68] = static_cast<char>('0' + nasa_checksum(l1));
    CHECK(parse_nasa(lines({l1, kIss2})).sets.size() == 1);
  }
  // A field shifted by one column.
  l2 = "2 25544  51.6416  247.4627 0006703 130.5360 325.0288 15.72125391563537";
  check_problem(line2_problem(l2), 2, 26, "separator", "7", "blank");
}

TEST_CASE("Files: auto-detection and unreadable files") {
  const ParseResult vallado = load_elements_file(kSgp4Ver);
  CHECK(vallado.sets.size() == 30);
  CHECK(vallado.problems.size() == 3);
  CHECK(vallado.problems[0].file == kSgp4Ver);

  for (const std::string& path : {std::string("/nonexistent/keps.txt"), std::string("/")}) {
    const ParseResult r = load_elements_file(path);
    CHECK(r.sets.empty());
    REQUIRE(r.problems.size() == 1);
    CHECK(r.problems[0].file == path);
    CHECK(r.problems[0].line == 0);
    CHECK(r.problems[0].column == 0);
    CHECK(r.problems[0].field == "file");
    CHECK(r.problems[0].expected == "a readable file of element sets");
    CHECK_FALSE(r.problems[0].found.empty());  // the system's reason
  }

  CHECK(parse_elements(kAo07Block).sets[0].source == ElementFormat::amsat);
  CHECK(parse_elements(kAo07Nasa).sets[0].source == ElementFormat::nasa);
}

// ---------------------------------------------------------------------------------------------
// gpredict

TEST_CASE("gpredict: all 979 sets of satellites.dat load without a problem") {
  const std::string text = read_text(TRAKBOX_GPREDICT_SATDATA);
  const ParseResult r = parse_gpredict_satdata(text, "satellites.dat");
  for (const auto& p : r.problems) MESSAGE(p.message());
  CHECK(r.problems.empty());
  REQUIRE(r.sets.size() == 979);
  const Elements* iss = find(r, 25544);
  REQUIRE(iss != nullptr);
  CHECK(iss->name == "ISS (ZARYA)");
  CHECK(iss->international_designator == "98067A");
  const Elements* noaa = find(r, 28654);
  REQUIRE(noaa != nullptr);
  CHECK(noaa->name == "NOAA 18");
  CHECK(noaa->epoch_day == 20.89662949);
  CHECK(noaa->bstar == 0.12332e-4);
  CHECK(noaa->mean_motion_rev_per_day == 14.12364350);
  CHECK(noaa->revolution_number == 65289);
  // The loader recognises the format by itself.
  CHECK(load_elements_file(TRAKBOX_GPREDICT_SATDATA).sets.size() == 979);
}

TEST_CASE("gpredict problems carry the file's line and column") {
  const std::string text = "[25544]\n"                                  // 1
                           "VERSION=1.1\n"                              // 2
                           "NAME=ISS (ZARYA)\n"                         // 3
                           "NICKNAME=ISS\n"                             // 4
                           "TLE1=" + std::string(kIss1) + "\n" +        // 5
                           "TLE2=" + std::string(kIss2).substr(0, 68) + "8\n" +  // 6: bad checksum
                           "\n"                                         // 7
                           "[7530]\n"                                   // 8
                           "NAME=AO-07\n"                               // 9
                           "TLE1=1 07530U 74089B   12256.61218065 -.00000027  00000-0  10000-3 0  4795\n"
                           "\n"
                           "[28654]\n"                                  // 12
                           "NAME=NOAA 18\n"
                           "TLE1 = 1 28654U 05018A   18020.89662949 -.00000024  00000-0  12332-4 0  9995\n"
                           "TLE2 = 2 28654  99.1634  53.2197 0014486 177.6703 182.4537 14.12364350652899\n";
  const ParseResult r = parse_gpredict_satdata(text, "sat.dat");
  REQUIRE(r.problems.size() == 2);
  check_problem(r.problems[0], 6, 74, "checksum", "8", "checksum 7");
  check_problem(r.problems[1], 8, 0, "TLE2", "", "a TLE2= line in section [7530]");
  REQUIRE(r.sets.size() == 1);
  CHECK(r.sets[0].name == "NOAA 18");
  CHECK(r.sets[0].catalog_number == 28654);
  CHECK(parse_elements(text).sets.size() == 1);
}
