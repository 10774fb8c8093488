// Planning tools (issue 47): the passes both of two stations see, overlaps between passes, and the
// iCalendar writer's RFC 5545 rules (CRLF, folding at 75 octets, TEXT escapes).
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "orbit/pass_tools.h"
#include "support/gpredict_sets.h"
#include "pass_places.h"

using namespace tb::orbit;

using namespace tb::testing::pass_places;

namespace {

const Elements& iss() {
  static const Elements e = [] {
    for (const Elements& s : tb::testing::gpredict_catalogue_sets())
      if (s.catalog_number == 25544) return s;
    FAIL("ISS (25544) is not in gpredict's sets");
    return Elements{};
  }();
  return e;
}

const Observer kMunich{48.1375, 11.5755, 520.0};   // JN58td

}  // namespace

TEST_CASE("mutual_passes: a station with itself is its own passes; antipodes share none") {
  const Sgp4 sat(iss());
  const auto own = find_passes(sat, kDarmstadt, kDay0, kDay1);
  const auto same = mutual_passes(sat, kDarmstadt, kDarmstadt, kDay0, kDay1);
  REQUIRE(own.size() == same.size());
  REQUIRE_FALSE(own.empty());
  for (std::size_t i = 0; i < own.size(); ++i) {
    CHECK(same[i].aos == own[i].aos);
    CHECK(same[i].los == own[i].los);
    CHECK(same[i].tca == own[i].tca);
    CHECK(same[i].max_el_deg == own[i].max_el_deg);
  }
  // 16,500 km apart: ISS's footprint (about 2,300 km in radius at -2 deg) never covers both.
  CHECK(mutual_passes(sat, kDarmstadt, kSydney, kDay0, kDay1).empty());
}

TEST_CASE("mutual_passes: Darmstadt and Munich (JN58td): only the times both have ISS above -2 deg") {
  const Sgp4 sat(iss());
  const auto a = find_passes(sat, kDarmstadt, kDay0, kDay1);
  const auto b = find_passes(sat, kMunich, kDay0, kDay1);
  const auto both = mutual_passes(sat, kDarmstadt, kMunich, kDay0, kDay1);
  REQUIRE_FALSE(both.empty());
  CHECK(both.size() <= std::min(a.size(), b.size()));
  for (const Pass& p : both) {
    CHECK(p.aos < p.los);
    // Half a second inside each end, both stations see it.
    for (const UtcTime t : {add_seconds(p.aos, 0.5), add_seconds(p.los, -0.5)}) {
      CHECK(observe(sat, kDarmstadt, t).look.el_deg >= kAosThresholdDeg);
      CHECK(observe(sat, kMunich, t).look.el_deg >= kAosThresholdDeg);
    }
    // Each end is one station's AOS or LOS.
    bool aos_found = false, los_found = false;
    for (const auto* list : {&a, &b})
      for (const Pass& q : *list) {
        aos_found = aos_found || q.aos == p.aos;
        los_found = los_found || q.los == p.los;
      }
    CHECK(aos_found);
    CHECK(los_found);
    CHECK(p.max_el_deg >= observe(sat, kDarmstadt, p.aos).look.el_deg - 1e-9);
  }
  // A minimum maximum elevation drops the shared times that stay low at the first station.
  PassOptions high;
  high.min_max_elevation_deg = 30.0;
  for (const Pass& p : mutual_passes(sat, kDarmstadt, kMunich, kDay0, kDay1, high)) CHECK(p.max_el_deg >= 30.0);
}

TEST_CASE("overlaps: passes whose [AOS, LOS] intersect name each other") {
  auto pass = [](int aos_min, int los_min) {
    Pass p;
    p.aos = add_minutes(kDay0, aos_min);
    p.los = add_minutes(kDay0, los_min);
    return p;
  };
  const std::vector<NamedPass> list{{"SO-50", pass(0, 10)}, {"AO-91", pass(5, 15)}, {"ISS", pass(20, 30)},
                                    {"RS-44", pass(30, 40)}};
  const auto o = overlaps(list);
  CHECK(o[0] == std::vector<int>{1});
  CHECK(o[1] == std::vector<int>{0});
  CHECK(o[2].empty());   // ISS's LOS is RS-44's AOS: touching is no overlap
  CHECK(o[3].empty());
}

TEST_CASE("iCalendar: content lines folded at 75 octets with CRLF, TEXT escaped, UTF-8 never split") {
  CHECK(ical_line("VERSION:2.0") == "VERSION:2.0\r\n");
  const std::string hundred(100, 'x');
  CHECK(ical_line(hundred) == std::string(75, 'x') + "\r\n " + std::string(25, 'x') + "\r\n");
  const std::string two_hundred(200, 'y');
  // 75, then 74 after each leading blank: 75 + 74 + 51.
  CHECK(ical_line(two_hundred) ==
        std::string(75, 'y') + "\r\n " + std::string(74, 'y') + "\r\n " + std::string(51, 'y') + "\r\n");
  // "°" is two octets (C2 B0): a fold that would fall between them moves before the C2.
  const std::string deg = std::string(74, 'a') + "\xc2\xb0" + "b";
  CHECK(ical_line(deg) == std::string(74, 'a') + "\r\n \xc2\xb0" + "b\r\n");
  CHECK(ical_text("ISS pass, max 45; a\\b\nc") == "ISS pass\\, max 45\\; a\\\\b\\nc");
}

TEST_CASE("iCalendar: one VEVENT a pass with UID, DTSTAMP, DTSTART and DTEND in UTC") {
  Pass p;
  p.aos = from_civil(2026, 5, 21, 13, 45, 12);
  p.tca = from_civil(2026, 5, 21, 13, 50, 0);
  p.los = from_civil(2026, 5, 21, 13, 55, 30);
  p.max_el_deg = 67.4;
  const std::string cal = ical_passes({{"ISS", p}}, from_civil(2026, 5, 21, 12, 0, 0), "PL02kj");
  CHECK(cal.rfind("BEGIN:VCALENDAR\r\nVERSION:2.0\r\nPRODID:", 0) == 0);
  CHECK(cal.find("UID:ISS-20260521T1345@trakbox\r\n") != std::string::npos);
  CHECK(cal.find("DTSTAMP:20260521T120000Z\r\n") != std::string::npos);
  CHECK(cal.find("DTSTART:20260521T134512Z\r\nDTEND:20260521T135530Z\r\n") != std::string::npos);
  CHECK(cal.find("SUMMARY:ISS pass\\, max 67 deg\r\n") != std::string::npos);
  CHECK(cal.substr(cal.size() - 15) == "END:VCALENDAR\r\n");
  // Every line at most 75 octets, every line end CRLF.
  std::size_t start = 0;
  while (start < cal.size()) {
    const std::size_t end = cal.find("\r\n", start);
    REQUIRE(end != std::string::npos);
    CHECK(end - start <= 75);
    CHECK(cal.substr(start, end - start).find('\n') == std::string::npos);
    start = end + 2;
  }
}
