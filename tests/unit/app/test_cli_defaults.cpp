// The forms of station, time and frequency the command line takes (issue 30, item 3 and 11).
// Maidenhead centres are worked by hand from the locator definition (field 20 x 10 deg, square
// 2 x 1 deg, subsquare 5' x 2.5', extended square 30" x 15"): JN18du lies 0+2*1+3*(5/60) deg east
// and -90+130+8+20*(2.5/60) deg north at its south-west corner; the centre adds half a subsquare.
#include <doctest/doctest.h>

#include <cctype>

#include "cli/cli_defaults.h"
#include "station/station.h"

using namespace tb::app;
using tb::orbit::UtcTime;

namespace {
UtcTime at(const char* iso) { return *tb::orbit::parse_iso8601(iso); }
}  // namespace

TEST_CASE("Maidenhead locators: the centre of the square") {
  const auto jn18du = maidenhead_centre("JN18du");
  REQUIRE(jn18du);
  CHECK(jn18du->lat_deg == doctest::Approx(48.0 + 20.0 * 2.5 / 60.0 + 1.25 / 60.0).epsilon(1e-12));  // 48.854167
  CHECK(jn18du->lon_deg == doctest::Approx(2.0 + 3.0 * 5.0 / 60.0 + 2.5 / 60.0).epsilon(1e-12));     // 2.291667
  CHECK(jn18du->lat_deg == doctest::Approx(48.854167).epsilon(1e-7));
  CHECK(jn18du->lon_deg == doctest::Approx(2.291667).epsilon(1e-6));
  const auto fn31pr = maidenhead_centre("fn31PR");  // W1AW, Newington CT
  REQUIRE(fn31pr);
  CHECK(fn31pr->lat_deg == doctest::Approx(41.729167).epsilon(1e-7));
  CHECK(fn31pr->lon_deg == doctest::Approx(-72.708333).epsilon(1e-7));
  const auto jn18 = maidenhead_centre("JN18");
  REQUIRE(jn18);
  CHECK(jn18->lat_deg == doctest::Approx(48.5));
  CHECK(jn18->lon_deg == doctest::Approx(3.0));
  const auto ext = maidenhead_centre("JN18du45");
  REQUIRE(ext);
  CHECK(ext->lon_deg == doctest::Approx(2.25 + 4 * 0.5 / 60.0 + 0.25 / 60.0));  // 2.2875
  CHECK(ext->lat_deg == doctest::Approx(48.0 + 50.0 / 60.0 + 5 * 0.25 / 60.0 + 0.125 / 60.0));
  CHECK_FALSE(maidenhead_centre("JN1"));
  CHECK_FALSE(maidenhead_centre("SN18du"));  // fields are A-R
  CHECK_FALSE(maidenhead_centre("JN18dy"));  // subsquares are A-X
  CHECK_FALSE(maidenhead_centre("48.85"));
}

TEST_CASE("Maidenhead locators of a position (status --json's station.locator, issue 39)") {
  // Paris (48.8566 N, 2.3522 E): 2.3522 = 2 + 4*(5/60) + 0.019 -> J, 1, e; 48.8566 = 48 + 20*(2.5/60) + 0.0233 -> N, 8, u.
  CHECK(tb::station::maidenhead_locator(48.8566, 2.3522) == "JN18eu");
  CHECK(tb::station::maidenhead_locator(41.714775, -72.727260) == "FN31pr");  // W1AW
  CHECK(tb::station::maidenhead_locator(27.391, 128.657) == "PL47hj");  // the factory station: 308.657 E+180, 117.391 N+90
  CHECK(tb::station::maidenhead_locator(-90.0, -180.0) == "AA00aa");
  CHECK(tb::station::maidenhead_locator(90.0, 180.0) == "RR99xx");
  // Each centre is inside its own locator.
  for (const char* loc : {"JN18du", "FN31pr", "QF56od", "AA00aa", "RR99xx"}) {
    const auto c = maidenhead_centre(loc);
    REQUIRE(c);
    std::string want(loc);
    for (std::size_t i = 0; i < 2; ++i) want[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(want[i])));
    for (std::size_t i = 4; i < 6; ++i) want[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(want[i])));
    CHECK(tb::station::maidenhead_locator(c->lat_deg, c->lon_deg) == want);
  }
}

TEST_CASE("stations: degrees with signs or hemispheres, blanks after commas, locators, optional height") {
  auto st = [](const char* t) { return parse_station_text(t); };
  auto p = st("48.85N,2.35E");
  REQUIRE(p.value);
  CHECK(p.value->lat_deg == 48.85);
  CHECK(p.value->lon_deg == 2.35);
  CHECK(p.value->height_m == 0.0);
  p = st("48.85S, 2.35W, 35");
  REQUIRE(p.value);
  CHECK(p.value->lat_deg == -48.85);
  CHECK(p.value->lon_deg == -2.35);
  CHECK(p.value->height_m == 35.0);
  p = st("32.259, -110.778, 842");
  REQUIRE(p.value);
  CHECK(p.value->lon_deg == -110.778);
  p = st("10,350,0");
  REQUIRE(p.value);
  CHECK(p.value->lon_deg == doctest::Approx(-10.0));
  p = st("JN18du, 35");
  REQUIRE(p.value);
  CHECK(p.value->lat_deg == doctest::Approx(48.854167).epsilon(1e-7));
  CHECK(p.value->height_m == 35.0);
  for (const char* bad : {"48.85", "-48.85N,2E", "91,0", "48.85N,2.35N", "48,2,3,4", "48,200E", "JN18du,x", ""}) {
    CAPTURE(bad);
    const auto b = st(bad);
    CHECK_FALSE(b.value);
    CHECK(b.error.find("Maidenhead") != std::string::npos);
  }
}

TEST_CASE("times: ISO 8601, now, and now plus or minus an amount") {
  const UtcTime now = at("2026-11-27T12:00:00Z");
  CHECK(*parse_time_text("now", now).value == now);
  CHECK(*parse_time_text("+2h", now).value == at("2026-11-27T14:00:00Z"));
  CHECK(*parse_time_text("-30m", now).value == at("2026-11-27T11:30:00Z"));
  CHECK(*parse_time_text("+1.5d", now).value == at("2026-11-29T00:00:00Z"));
  CHECK(*parse_time_text("+90s", now).value == at("2026-11-27T12:01:30Z"));
  CHECK(*parse_time_text("2026-05-21T00:00:00Z", now).value == at("2026-05-21T00:00:00Z"));
  for (const char* bad : {"+2x", "+h", "soon", "+-2h", "2026-13-01"}) {
    CAPTURE(bad);
    const auto b = parse_time_text(bad, now);
    CHECK_FALSE(b.value);
    CHECK(b.error.find("+2h") != std::string::npos);
  }
}

TEST_CASE("frequencies: hertz, MHz with a decimal point, or a unit") {
  CHECK(*parse_frequency_text("437800000").value == 437800000);
  CHECK(*parse_frequency_text("437.8").value == 437800000);
  CHECK(*parse_frequency_text("145.8MHz").value == 145800000);
  CHECK(*parse_frequency_text("437.8 MHz").value == 437800000);
  CHECK(*parse_frequency_text("145800kHz").value == 145800000);
  CHECK(*parse_frequency_text("2.4GHz").value == 2400000000);
  CHECK(*parse_frequency_text("10489.55").value == 10489550000);
  CHECK(*parse_frequency_text("0").value == 0);
  for (const char* bad : {"437800000.5", "abc", "437,8", "-437.8", "1.2.3", "MHz", "2000GHz"}) {
    CAPTURE(bad);
    const auto b = parse_frequency_text(bad);
    CHECK_FALSE(b.value);
    CHECK(b.error.find("437.8") != std::string::npos);
  }
}
