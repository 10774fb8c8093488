// PassMemo (tracker/pass_memo.h): a status document's next passes are searched once and kept until
// the pass has set, the elements change, the station moves or the clock goes back; a search that
// found nothing is tried again after kRetry.
#include <doctest/doctest.h>

#include <chrono>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "tracker/pass_memo.h"

using namespace tb;
using std::chrono::minutes;

namespace {

const orbit::UtcTime kNoon = orbit::from_civil(2026, 5, 21, 12, 0, 0);
const orbit::Observer kHere{27.391, 128.657, 50.0};  // the factory station

orbit::Elements sat(int catalog, double epoch_day) {
  orbit::Elements e;
  e.catalog_number = catalog;
  e.epoch_year = 2026;
  e.epoch_day = epoch_day;
  return e;
}

orbit::Pass pass_from(orbit::UtcTime aos, minutes length) {
  orbit::Pass p;
  p.aos = aos;
  p.tca = aos + length / 2;
  p.los = aos + length;
  p.max_el_deg = 40.0;
  return p;
}

// A search that counts its calls and finds a 10-minute pass an hour after the time it is asked at.
struct Counting {
  int calls = 0;
  orbit::UtcTime asked{};
  tracker::PassMemo::Search at(orbit::UtcTime now) {
    return [this, now]() -> std::optional<orbit::Pass> {
      ++calls;
      asked = now;
      return pass_from(now + minutes(60), minutes(10));
    };
  }
};

}  // namespace

TEST_CASE("a pass is searched once and kept until its LOS") {
  tracker::PassMemo memo;
  Counting s;
  const auto el = sat(25544, 140.5);
  const auto first = memo.get(el, kHere, kNoon, s.at(kNoon));
  REQUIRE(first);
  CHECK(first->aos == kNoon + minutes(60));
  for (int m = 1; m <= 70; ++m)
    CHECK(memo.get(el, kHere, kNoon + minutes(m), s.at(kNoon + minutes(m)))->aos == first->aos);
  CHECK(s.calls == 1);
  CHECK(memo.searches() == 1);
  // One second past its LOS: the next is searched.
  const auto after = kNoon + minutes(70) + std::chrono::seconds(1);
  CHECK(memo.get(el, kHere, after, s.at(after))->aos == after + minutes(60));
  CHECK(s.calls == 2);
}

TEST_CASE("new elements, or the clock set back, search again; other satellites are kept apart") {
  tracker::PassMemo memo;
  Counting s;
  memo.get(sat(25544, 140.5), kHere, kNoon, s.at(kNoon));
  memo.get(sat(43017, 140.1), kHere, kNoon, s.at(kNoon));
  CHECK(s.calls == 2);
  memo.get(sat(25544, 140.5), kHere, kNoon + minutes(5), s.at(kNoon + minutes(5)));
  CHECK(s.calls == 2);
  memo.get(sat(25544, 141.0), kHere, kNoon + minutes(5), s.at(kNoon + minutes(5)));  // a refresh
  CHECK(s.calls == 3);
  const auto back = kNoon - minutes(30);  // menu 5
  CHECK(memo.get(sat(25544, 141.0), kHere, back, s.at(back))->aos == back + minutes(60));
  CHECK(s.calls == 4);
  CHECK(s.asked == back);
  memo.get(sat(43017, 140.1), kHere, kNoon + minutes(1), s.at(kNoon + minutes(1)));
  CHECK(s.calls == 4);
}

TEST_CASE("the station moved: searched again from the new place") {
  tracker::PassMemo memo;
  Counting s;
  const auto el = sat(25544, 140.5);
  memo.get(el, kHere, kNoon, s.at(kNoon));
  memo.get(el, kHere, kNoon + minutes(1), s.at(kNoon + minutes(1)));
  CHECK(s.calls == 1);
  const orbit::Observer moved{52.52, 13.40, 34.0};  // menu 4, or a GPS fix followed
  memo.get(el, moved, kNoon + minutes(2), s.at(kNoon + minutes(2)));
  CHECK(s.calls == 2);
  memo.get(el, moved, kNoon + minutes(3), s.at(kNoon + minutes(3)));
  CHECK(s.calls == 2);
}

TEST_CASE("no pass found: nothing is kept for kRetry, then it is searched again") {
  tracker::PassMemo memo;
  int calls = 0;
  const auto none = [&calls]() -> std::optional<orbit::Pass> {
    ++calls;
    return std::nullopt;
  };
  const auto el = sat(43700, 140.0);
  CHECK_FALSE(memo.get(el, kHere, kNoon, none));
  CHECK_FALSE(memo.get(el, kHere, kNoon + tracker::PassMemo::kRetry - std::chrono::seconds(1), none));
  CHECK(calls == 1);
  CHECK_FALSE(memo.get(el, kHere, kNoon + tracker::PassMemo::kRetry, none));
  CHECK(calls == 2);
}
