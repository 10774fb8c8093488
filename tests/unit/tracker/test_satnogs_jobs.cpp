// tracker/satnogs_jobs.h: the SatNOGS Network's /api/jobs/ answer (the JobSerializer's fields) into
// reservation windows; a malformed answer is refused as a whole, naming the job.
#include <doctest/doctest.h>

#include "tracker/satnogs_jobs.h"

using namespace tb;

namespace {
orbit::UtcTime at(int h, int m, int s) { return orbit::from_civil(2026, 12, 2, h, m, 0) + std::chrono::seconds(s); }

const char* kTwoJobs = R"([
 {"id": 12345679, "start": "2026-12-02T11:00:00Z", "end": "2026-12-02T11:08:00Z", "ground_station": 5024,
  "tle0": "ISS", "tle1": "1 25544U ...", "tle2": "2 25544 ...", "frequency": 437800000, "mode": "AFSK1k2",
  "transmitter": "vutsrqponmlkjihgfedcba", "baud": 1200.0, "max_altitude": 23.0, "norad_cat_id": 25544},
 {"id": 12345678, "start": "2026-12-02T10:11:12Z", "end": "2026-12-02T10:21:40Z", "ground_station": 5024,
  "tle0": "AO-91", "tle1": "1 43017U ...", "tle2": "2 43017 ...", "frequency": 145960000, "mode": "FM",
  "transmitter": "abcdefghijklmnopqrstuv", "baud": 0.0, "max_altitude": 61.3, "norad_cat_id": 43017}])";
}  // namespace

TEST_CASE("satnogs: the jobs URL, anonymous and per station") {
  CHECK(tracker::satnogs_jobs_url("https://network.satnogs.org", 42) ==
        "https://network.satnogs.org/api/jobs/?ground_station=42");
  CHECK(tracker::satnogs_jobs_url("http://127.0.0.1:8000/", 5024) == "http://127.0.0.1:8000/api/jobs/?ground_station=5024");
  // Issue 56 item 10: a user and password in --satnogs-url were sent as Basic auth and shown in
  // status' satnogs.url. The request is anonymous: they are dropped, neither sent nor shown.
  CHECK(tracker::satnogs_jobs_url("http://bob:PW@127.0.0.1:8000", 7) == "http://127.0.0.1:8000/api/jobs/?ground_station=7");
  CHECK(tracker::satnogs_jobs_url("https://bob@network.example/net/", 7) ==
        "https://network.example/net/api/jobs/?ground_station=7");
  CHECK(tracker::satnogs_jobs_url("https://a:p@ss@host", 7) == "https://host/api/jobs/?ground_station=7");
  CHECK(tracker::satnogs_jobs_url("https://host/path@x", 7) == "https://host/path@x/api/jobs/?ground_station=7");
}

TEST_CASE("satnogs: two jobs become two windows in start order; a job over is dropped") {
  const auto j = tracker::parse_satnogs_jobs(kTwoJobs, at(10, 0, 0));
  REQUIRE_FALSE(j.error);
  REQUIRE(j.windows.size() == 2);
  CHECK(j.windows[0].kind == "satnogs");
  CHECK(j.windows[0].id == "12345678");
  CHECK(j.windows[0].start == at(10, 11, 12));
  CHECK(j.windows[0].end == at(10, 21, 40));
  CHECK(j.windows[0].satellite == "AO-91");
  CHECK(j.windows[0].note == "FM 145960000 Hz");
  CHECK(j.windows[1].id == "12345679");
  CHECK(j.windows[1].note == "AFSK1k2 437800000 Hz");
  // The job's elements are kept with its window (issue 57: its pass is planned with them).
  CHECK(j.windows[0].tle1 == "1 43017U ...");
  CHECK(j.windows[0].tle2 == "2 43017 ...");
  CHECK(j.windows[1].tle1 == "1 25544U ...");
  const auto later = tracker::parse_satnogs_jobs(kTwoJobs, at(10, 21, 40));
  REQUIRE(later.windows.size() == 1);
  CHECK(later.windows[0].id == "12345679");
  CHECK(tracker::parse_satnogs_jobs("[]", at(10, 0, 0)).windows.empty());
}

TEST_CASE("satnogs: a malformed answer is refused whole, naming the job") {
  CHECK(tracker::parse_satnogs_jobs("<html>", at(10, 0, 0)).error == "the jobs answer is not a JSON list");
  CHECK(tracker::parse_satnogs_jobs(R"({"detail":"throttled"})", at(10, 0, 0)).error == "the jobs answer is not a JSON list");
  const auto no_end = tracker::parse_satnogs_jobs(
      R"([{"id":1,"start":"2026-12-02T10:11:12Z","end":"2026-12-02T10:21:40Z","tle0":"A","frequency":1,"mode":"FM"},
          {"id":2,"start":"2026-12-02T10:30:00Z","tle0":"B","frequency":1,"mode":"FM"}])",
      at(10, 0, 0));
  CHECK(no_end.error == "job 2 (id 2): \"start\" and \"end\" must be ISO 8601 times, the end after the start");
  CHECK(no_end.windows.empty());
  const auto no_id = tracker::parse_satnogs_jobs(R"([{"id":"x"}])", at(10, 0, 0));
  CHECK(no_id.error == "job 1: no whole-number \"id\"");
  const auto no_mode = tracker::parse_satnogs_jobs(
      R"([{"id":7,"start":"2026-12-02T10:11:12Z","end":"2026-12-02T10:21:40Z","tle0":"A","frequency":1}])", at(10, 0, 0));
  CHECK(no_mode.error == "job 1 (id 7): needs \"tle0\", \"frequency\" and \"mode\"");
}
