// web::LiveFeed: the whole document first, then numbered merge patches of what changed, nothing when
// nothing did, the whole document again when a patch cannot say it; the viewer's request for it.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "web/live_feed.h"

using json = nlohmann::json;
using tb::web::LiveFeed;

TEST_CASE("LiveFeed: whole, then what changed, numbered") {
  LiveFeed feed;
  CHECK_FALSE(feed.full().has_value());
  const json first = json::parse(R"({"type":"state","status":{"time":"12:00:00","az":10.5},"sky":{"n":1}})");
  auto m = feed.next(first);
  REQUIRE(m.has_value());
  CHECK(json::parse(*m) == json::parse(R"({"type":"state","seq":1,"status":{"time":"12:00:00","az":10.5},"sky":{"n":1}})"));
  m = feed.next(json::parse(R"({"type":"state","status":{"time":"12:00:01","az":10.5},"sky":{"n":1}})"));
  REQUIRE(m.has_value());
  CHECK(json::parse(*m) == json::parse(R"({"type":"patch","seq":2,"patch":{"status":{"time":"12:00:01"}}})"));
  // Nothing changed: no message, and the number stays.
  CHECK_FALSE(feed.next(json::parse(R"({"type":"state","status":{"time":"12:00:01","az":10.5},"sky":{"n":1}})")));
  CHECK(feed.seq() == 2);
  // A member gone goes as null.
  m = feed.next(json::parse(R"({"type":"state","status":{"time":"12:00:02","az":10.5},"sky":{}})"));
  CHECK(json::parse(*m) == json::parse(R"({"type":"patch","seq":3,"patch":{"status":{"time":"12:00:02"},"sky":{"n":null}}})"));
  // The whole document as a viewer that asks gets it: the last one, with its number.
  CHECK(json::parse(*feed.full()) == json::parse(R"({"type":"state","seq":3,"status":{"time":"12:00:02","az":10.5},"sky":{}})"));
}

TEST_CASE("LiveFeed: a change no merge patch says, and forget, send the whole document") {
  LiveFeed feed;
  feed.next(json::parse(R"({"type":"state","status":{"az":1}})"));
  auto m = feed.next(json::parse(R"({"type":"state","status":{"az":null}})"));
  CHECK(json::parse(*m) == json::parse(R"({"type":"state","seq":2,"status":{"az":null}})"));
  feed.forget();
  CHECK_FALSE(feed.full().has_value());
  m = feed.next(json::parse(R"({"type":"state","status":{"az":null}})"));
  CHECK(json::parse(*m) == json::parse(R"({"type":"state","seq":3,"status":{"az":null}})"));
}

TEST_CASE("LiveFeed::asks_full: only {\"type\":\"full\"}") {
  CHECK(LiveFeed::asks_full(R"({"type":"full"})"));
  CHECK(LiveFeed::asks_full(R"( { "type" : "full" } )"));
  CHECK_FALSE(LiveFeed::asks_full(R"({"type":"fullx"})"));
  CHECK_FALSE(LiveFeed::asks_full(R"({"type":1})"));
  CHECK_FALSE(LiveFeed::asks_full(R"(["full"])"));
  CHECK_FALSE(LiveFeed::asks_full("{\"type\":\"full\""));
  CHECK_FALSE(LiveFeed::asks_full("\xff\xfe"));
  CHECK_FALSE(LiveFeed::asks_full(R"({"type":{"type":{"type":"full"}}})"));
  CHECK_FALSE(LiveFeed::asks_full(""));
}

TEST_CASE("shape_for_live: the list by position, without where each satellite is now, rounded") {
  json status = json::parse(R"({"time":"t","tracking_list":[
      {"name":"ISS","element_age_days":0.4092941780439815,"now":{"az_deg":344.19,"el_deg":8.2},"number":4,
       "next_pass":{"aos":"a","max_el_deg":22.29240559114098}},
      {"name":"AO-07","element_age_days":339.246793578044,"number":1,"next_pass":null}, 7]})");
  tb::web::shape_for_live(status);
  CHECK(status == json::parse(R"({"time":"t","tracking_list":{
      "0":{"name":"ISS","element_age_days":0.41,"number":4,"next_pass":{"aos":"a","max_el_deg":22.29}},
      "1":{"name":"AO-07","element_age_days":339.25,"number":1,"next_pass":null}, "2":7}})"));
  json lists = json::parse(R"({"radios":[{"radio":"a","tuning":{"downlink_dial_hz":1}},{"radio":"b"}],
      "tracking":{"mode":"single","satellites":[{"name":"ISS","az_deg":1.5}]}})");
  tb::web::shape_for_live(lists);
  CHECK(lists == json::parse(R"({"radios":{"0":{"radio":"a","tuning":{"downlink_dial_hz":1}},"1":{"radio":"b"}},
      "tracking":{"mode":"single","satellites":{"0":{"name":"ISS","az_deg":1.5}}}})"));
  json none = json::parse(R"({"tracking_list":null})");
  tb::web::shape_for_live(none);
  CHECK(none == json::parse(R"({"tracking_list":null})"));
}
