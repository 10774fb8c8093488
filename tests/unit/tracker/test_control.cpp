// tracker::Control (tracker/control.h): who holds the antenna and the radio, on a hand-moved clock.
#include <doctest/doctest.h>

#include "tracker/control.h"

using namespace tb;
using tracker::Control;
using tracker::HolderKind;
using tracker::Requester;
using tracker::Resource;

namespace {

orbit::UtcTime at(int s) { return orbit::from_civil(2026, 5, 21, 12, 0, 0) + std::chrono::seconds(s); }

const Requester gpredict{HolderKind::rotctld, "rotctld 127.0.0.1:51234"};
const Requester logger{HolderKind::rigctld, "rigctld 127.0.0.1:40000"};
const Requester phone{HolderKind::web, "web 192.168.1.20"};

}  // namespace

TEST_CASE("an outside client's move holds the antenna only; silence of --handback hands it back to tracking") {
  Control c;  // --handback 30
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  const auto a = c.request(Resource::antenna, gpredict, at(0));
  CHECK(a.granted);
  REQUIRE(a.changes.size() == 1);
  CHECK(a.changes[0].from.kind == HolderKind::tracking);
  CHECK(a.changes[0].to.kind == HolderKind::rotctld);
  CHECK(a.changes[0].to.label == "rotctld 127.0.0.1:51234");
  CHECK(a.changes[0].to.since == at(0));
  CHECK(c.holder(Resource::radio).kind == HolderKind::tracking);  // the radio is held separately
  CHECK_FALSE(c.tracking_drives(Resource::antenna));
  CHECK(c.tracking_drives(Resource::radio));
  // Polls keep it: a P again (no change) at 20, a line heard at 45.
  CHECK(c.request(Resource::antenna, gpredict, at(20)).changes.empty());
  c.heard(gpredict.label, at(45));
  CHECK(c.tick(at(74)).empty());  // 29 s of silence
  const auto back = c.tick(at(75));  // 30 s
  REQUIRE(back.size() == 1);
  CHECK(back[0].from.kind == HolderKind::rotctld);
  CHECK(back[0].to.kind == HolderKind::tracking);
  CHECK(back[0].why == "rotctld 127.0.0.1:51234 silent 30 s");
  CHECK(c.tracking_drives(Resource::antenna));
}

TEST_CASE("a disconnect hands back what the client held, and only that; handback 0 never by silence") {
  Control c({0, std::nullopt});
  c.request(Resource::antenna, gpredict, at(0));
  c.request(Resource::radio, logger, at(1));
  CHECK(c.tick(at(100000)).empty());
  const auto gone = c.left(logger.label, at(200));
  REQUIRE(gone.size() == 1);
  CHECK(gone[0].resource == Resource::radio);
  CHECK(gone[0].why == "rigctld 127.0.0.1:40000 disconnected");
  CHECK(c.holder(Resource::antenna).kind == HolderKind::rotctld);
  CHECK(c.left(gpredict.label, at(201)).size() == 1);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
}

TEST_CASE("the operator takes the antenna back after one confirmation; the hold returns to what held before") {
  Control c;
  // The operator held it (a goto from the page); Gpredict takes it; when Gpredict goes the page's hold is back.
  c.request(Resource::antenna, phone, at(0));
  CHECK(c.holder(Resource::antenna).kind == HolderKind::web);
  c.request(Resource::antenna, gpredict, at(5));
  const auto ask = c.request(Resource::antenna, phone, at(6));
  CHECK_FALSE(ask.granted);
  REQUIRE(ask.confirm);
  CHECK(ask.confirm->label == "rotctld 127.0.0.1:51234");
  CHECK(c.holder(Resource::antenna).kind == HolderKind::rotctld);  // nothing changed
  const auto back = c.left(gpredict.label, at(7));
  REQUIRE(back.size() == 1);
  CHECK(back[0].to.kind == HolderKind::web);
  CHECK(back[0].to.since == at(7));
  // Confirmed: the operator hands it to tracking.
  c.request(Resource::antenna, gpredict, at(8));
  const auto yes = c.request(Resource::antenna, phone, at(9), true, true);
  CHECK(yes.granted);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  CHECK(c.left(gpredict.label, at(10)).empty());  // it holds nothing any more
}

TEST_CASE("--exclusive refuses another client while one holds; without it the latest takes it") {
  const Requester other{HolderKind::rotctld, "rotctld 127.0.0.1:60000"};
  Control open;
  open.request(Resource::antenna, gpredict, at(0));
  CHECK(open.request(Resource::antenna, other, at(1)).granted);
  CHECK(open.holder(Resource::antenna).label == "rotctld 127.0.0.1:60000");

  Control only({30, HolderKind::rotctld});
  only.request(Resource::antenna, gpredict, at(0));
  const auto no = only.request(Resource::antenna, other, at(1));
  CHECK_FALSE(no.granted);
  CHECK(no.refusal == "rotctld 127.0.0.1:51234 holds the antenna (--exclusive rotctld)");
  CHECK(only.holder(Resource::antenna).label == "rotctld 127.0.0.1:51234");
  // The operator still can, after the confirmation.
  CHECK(only.request(Resource::antenna, phone, at(2), true).granted);
}

TEST_CASE("standby: both held by standby, outside clients refused, the operator must turn it off") {
  Control c;
  c.request(Resource::antenna, gpredict, at(0));
  const auto on = c.set_standby(true, at(1));
  CHECK(on.size() == 2);
  CHECK(c.standby());
  const auto no = c.request(Resource::antenna, gpredict, at(2));
  CHECK_FALSE(no.granted);
  CHECK(no.refusal == "the station is in standby: the antenna is not available");
  CHECK(c.request(Resource::radio, phone, at(2)).refusal == "the station is in standby: turn standby off first");
  CHECK(c.left(gpredict.label, at(3)).empty());
  const auto off = c.set_standby(false, at(4));
  CHECK(off.size() == 2);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  CHECK(c.holder(Resource::radio).kind == HolderKind::tracking);
}

TEST_CASE("a SatNOGS window: tracking yields at its start, a rotctld client holds under its name, back at its end") {
  Control c;
  c.set_windows({{"satnogs", "12345678", at(100), at(700), "AO-91", "", "", ""}});
  CHECK(c.tick(at(99)).empty());
  const auto begin = c.tick(at(100));
  REQUIRE(begin.size() == 2);
  CHECK(begin[0].to.kind == HolderKind::satnogs);
  CHECK(begin[0].to.label == "SatNOGS observation 12345678 AO-91");
  CHECK(begin[0].to.until == at(700));
  CHECK(c.tick(at(101)).empty());  // once
  const auto client = c.request(Resource::antenna, gpredict, at(120));
  CHECK(client.granted);
  CHECK(c.holder(Resource::antenna).label == "SatNOGS observation 12345678 AO-91 (rotctld 127.0.0.1:51234)");
  // The operator is asked to confirm inside the window.
  CHECK(c.request(Resource::radio, phone, at(130)).confirm);
  c.left(gpredict.label, at(140));
  CHECK(c.holder(Resource::antenna).kind == HolderKind::satnogs);  // the window's own hold again
  const auto end = c.tick(at(700));
  CHECK(end.size() == 2);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  CHECK(c.holder(Resource::radio).kind == HolderKind::tracking);
}

TEST_CASE("a SatNOGS job that leaves the calendar ends its hold at once, not at its old end (issue 56)") {
  Control c;
  c.set_windows({{"satnogs", "777", at(100), at(700), "ISS", "", "", ""}});
  REQUIRE(c.tick(at(100)).size() == 2);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::satnogs);
  c.set_windows({});  // the next poll's answer: the job was cancelled
  const auto back = c.tick(at(200));
  REQUIRE(back.size() == 2);
  CHECK(back[0].why == "its window was cancelled");
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  CHECK(c.holder(Resource::radio).kind == HolderKind::tracking);
  CHECK(c.tick(at(201)).empty());
}

TEST_CASE("a connectionless sender (PstRotator) is handed back by silence even under --handback 0") {
  Control c({0, std::nullopt});
  const tracker::Requester pst{HolderKind::pstrotator, "pstrotator 127.0.0.1:12001"};
  CHECK(c.request(Resource::antenna, pst, at(0)).granted);
  CHECK(c.tick(at(tracker::kConnectionlessHandbackS - 1)).empty());
  const auto back = c.tick(at(tracker::kConnectionlessHandbackS));
  REQUIRE(back.size() == 1);
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  // A connected client under --handback 0 keeps it until it leaves.
  CHECK(c.request(Resource::antenna, gpredict, at(100)).granted);
  CHECK(c.tick(at(100000)).empty());
  CHECK(c.holder(Resource::antenna).kind == HolderKind::rotctld);
}

TEST_CASE("take back holds: a client sending P every second is refused until --handback after the operator's last action") {
  Control c;  // --handback 30
  CHECK(c.request(Resource::antenna, gpredict, at(0)).granted);
  CHECK(c.request(Resource::antenna, phone, at(5)).confirm);                  // asked first
  CHECK(c.request(Resource::antenna, phone, at(6), true, true).granted);      // Take back, confirmed
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  for (int t = 7; t < 36; ++t) {
    const auto a = c.request(Resource::antenna, gpredict, at(t));
    CHECK_FALSE(a.granted);
    CHECK(a.refusal->find("the operator took the antenna back") == 0);
  }
  CHECK(c.holder(Resource::antenna).kind == HolderKind::tracking);
  CHECK(c.request(Resource::antenna, phone, at(20), false, true).granted);  // the operator acts again
  CHECK_FALSE(c.request(Resource::antenna, gpredict, at(49)).granted);
  CHECK(c.request(Resource::antenna, gpredict, at(50)).granted);            // 30 s after the last action
}

TEST_CASE("kind names round-trip") {
  for (const char* k : {"tracking", "menus", "web", "host", "rotctld", "rigctld", "satrak", "satnogs", "pstrotator", "standby"})
    CHECK(tracker::kind_name(*tracker::kind_named(k)) == k);
  CHECK_FALSE(tracker::kind_named("gpredict"));
  CHECK(tracker::is_outside(HolderKind::pstrotator));
  CHECK(tracker::is_operator(HolderKind::host));
}
