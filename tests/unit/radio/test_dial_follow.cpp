// Dial follow on linear transponders: the spot in the satellite's frame, the passband mapping, the
// tolerance that tells the operator's turn of the dial from trakbox's own last command, and the
// drivers that read the dial back (simulated, the worker thread, two radios as one).
#include <doctest/doctest.h>

#include "radio/config.h"
#include "radio/doppler.h"
#include "satellites.h"
#include "radio/freqmode.h"
#include "radio/simulated.h"
#include "radio/two_radios.h"
#include "radio/worker.h"
#include "support.h"

using namespace tb::radio;
using tbtest::full_orbit;
using tbtest::rs44;

TEST_CASE("Dial follow: turning the downlink up 10 kHz on an inverting transponder moves the uplink down 10 kHz") {
  Tuner t(full_orbit());
  t.select(rs44());
  CHECK(t.dial_follow_active());
  const auto first = t.update(30.0, 0.0);
  CHECK(*first.downlink_hz == 435'640'000);
  CHECK(*first.uplink_hz == 145'965'000);
  t.dial_downlink(435'650'000, 0.0);
  CHECK(t.downlink_spot_hz() == 435'650'000);
  CHECK(t.uplink_spot_hz() == 145'955'000);
  const auto next = t.update(30.0, 0.0);
  CHECK_FALSE(next.downlink_hz);              // the radio is where the operator put it: nothing to send
  CHECK(*next.uplink_hz == 145'955'000);
}

TEST_CASE("Dial follow: with Doppler the spot is the satellite-frame frequency the radio hears") {
  Tuner t(full_orbit());
  t.select(rs44());
  const auto first = t.update(30.0, -5.0);   // approaching at 5 km/s
  CHECK(*first.downlink_hz == 435'647'270);
  CHECK(*first.uplink_hz == 145'962'570);
  t.dial_downlink(435'657'270, -5.0);        // the operator: +10 kHz on the downlink dial
  CHECK(t.downlink_spot_hz() == 435'650'004); // 435,657,270 / (1 + 5/c); 4 Hz of the 10 Hz rounding
  CHECK(t.uplink_spot_hz() == 145'954'996);
  const auto next = t.update(30.0, -5.0);
  CHECK_FALSE(next.downlink_hz);              // still where the operator put it: not sent again
  CHECK(*next.uplink_hz == 145'952'560);      // 10,010 Hz down
}

TEST_CASE("Dial follow: a normal transponder moves the uplink the same way; the uplink dial moves the downlink") {
  SatelliteRadio s = rs44();
  s.inverting = false;
  s.uplink_hz = 145'965'000;                  // up_lo + (435.640 - 435.610) = 145.965
  Tuner t(full_orbit());
  t.select(s);
  t.update(30.0, 0.0);
  t.dial_downlink(435'650'000, 0.0);
  CHECK(t.uplink_spot_hz() == 145'975'000);
  t.dial_uplink(145'945'000, 0.0);
  CHECK(t.uplink_spot_hz() == 145'945'000);
  CHECK(t.downlink_spot_hz() == 435'620'000);
  Tuner inv(full_orbit());
  inv.select(rs44());
  CHECK(inv.dial_uplink(145'975'000, 0.0));   // inverting: uplink +10 kHz, downlink -10 kHz
  CHECK(inv.downlink_spot_hz() == 435'630'000);
  // Up to one passband width (60 kHz) outside the passband is a turn; further is not.
  CHECK(inv.dial_downlink(435'730'000, 0.0));
  CHECK(inv.uplink_spot_hz() == 145'875'000);
  CHECK_FALSE(inv.dial_downlink(435'730'010, 0.0));
  CHECK_FALSE(inv.dial_uplink(435'640'000, 0.0));   // a radio that read the downlink's VFO
  CHECK(inv.downlink_spot_hz() == 435'730'000);
  CHECK(inv.uplink_spot_hz() == 145'875'000);
}

TEST_CASE("Dial follow: + and - move the spot of both links on a transponder, 0 takes them back") {
  Tuner t(full_orbit());
  t.select(rs44());
  t.rit_up();
  t.rit_up();
  CHECK(t.rit_hz() == 200);
  CHECK(t.downlink_spot_hz() == 435'640'200);
  CHECK(t.uplink_spot_hz() == 145'964'800);
  const auto c = t.update(30.0, 0.0);
  CHECK(*c.downlink_hz == 435'640'200);      // no RIT on top of the moved spot
  CHECK(*c.uplink_hz == 145'964'800);
  t.rit_zero();
  CHECK(t.downlink_spot_hz() == 435'640'000);
  CHECK(t.uplink_spot_hz() == 145'965'000);
  // Without passbands, or with dial follow off, + is the manual's RIT on the downlink only.
  RadioConfig off = full_orbit();
  off.dial_follow = false;
  Tuner r(off);
  r.select(rs44());
  CHECK_FALSE(r.dial_follow_active());
  r.rit_up();
  CHECK(r.downlink_spot_hz() == 435'640'100);
  CHECK(r.uplink_spot_hz() == 145'965'000);
}

TEST_CASE("Dial follow: the tolerance is two tuning steps plus a second's Doppler change") {
  CHECK(dial_tolerance_hz(0.0) == 20);
  CHECK(dial_tolerance_hz(37.2) == 58);
  CHECK(dial_tolerance_hz(-37.2) == 58);
  // trakbox set 435,647,270; the radio reads back its own command, or one Doppler step off: no turn.
  CHECK_FALSE(dial_turned(435'647'270, 435'647'270, 58));
  CHECK_FALSE(dial_turned(435'647'328, 435'647'270, 58));
  CHECK_FALSE(dial_turned(435'647'212, 435'647'270, 58));
  // One more hertz, or a real turn of the dial: the operator's.
  CHECK(dial_turned(435'647'329, 435'647'270, 58));
  CHECK(dial_turned(435'657'270, 435'647'270, 58));
  CHECK(dial_turned(435'637'270, 435'647'270, 58));
  // The Tuner's tolerance follows its last two updates' Doppler.
  Tuner t(full_orbit());
  t.select(rs44());
  CHECK(t.dial_tolerance_downlink_hz() == 20);
  t.update(30.0, -5.0);
  t.update(30.0, -4.99);                      // 435.64 MHz * 0.01 / c = 14.53 Hz
  CHECK(t.dial_tolerance_downlink_hz() == 35);
  CHECK(t.dial_tolerance_uplink_hz() == 25);  // 145.965 MHz: 4.87 Hz
}

TEST_CASE("Simulated radio: a guarded frequency keeps the operator's turn and reports it once") {
  SimulatedRadio r;
  r.set_frequency_guarded(Link::downlink, 435'640'000, 20);
  r.step(Link::downlink, 10'000);                       // the operator's dial
  r.set_frequency_guarded(Link::downlink, 435'640'010, 20);
  CHECK(*r.frequency(Link::downlink) == 435'650'000);   // not undone
  CHECK(*r.take_dial_turn(Link::downlink) == 435'650'000);
  CHECK_FALSE(r.take_dial_turn(Link::downlink));
  r.set_frequency_guarded(Link::downlink, 435'650'010, 20);
  CHECK(*r.frequency(Link::downlink) == 435'650'010);
  r.step(Link::downlink, 20);                            // within the tolerance: trakbox's own
  r.set_frequency_guarded(Link::downlink, 435'650'020, 20);
  CHECK(*r.frequency(Link::downlink) == 435'650'020);
  CHECK_FALSE(r.take_dial_turn(Link::downlink));
  r.step(Link::downlink, 5'000);                         // unguarded (host mode FD): set as told
  r.set_frequency(Link::downlink, 435'640'000);
  CHECK(*r.frequency(Link::downlink) == 435'640'000);
}

namespace {

// A radio link whose dial the test turns; it can be read back.
struct DialLink final : RadioLink {
  std::mutex mu;
  Hz dial[2] = {0, 0};
  int writes = 0;
  std::string describe() const override { return "dial link"; }
  void open() override {}
  void close() noexcept override {}
  void set_frequency(Link l, Hz hz) override {
    std::lock_guard lock(mu);
    dial[l == Link::downlink ? 0 : 1] = hz;
    ++writes;
  }
  void set_mode(Link, Mode) override {}
  void send_raw(const std::string&) override {}
  bool can_read(Link) const override { return true; }
  Hz read_frequency(Link l) override {
    std::lock_guard lock(mu);
    return dial[l == Link::downlink ? 0 : 1];
  }
  void turn(Link l, Hz hz) {
    std::lock_guard lock(mu);
    dial[l == Link::downlink ? 0 : 1] = hz;
  }
};

}  // namespace

TEST_CASE("Worker radio: a turn of the dial is seen while idle and the next guarded command does not undo it") {
  auto owned = std::make_unique<DialLink>();
  DialLink& link = *owned;
  WorkerTiming timing;
  timing.check_every = std::chrono::milliseconds(10);
  WorkerRadio radio(std::move(owned), timing);
  radio.set_frequency_guarded(Link::uplink, 145'962'570, 25);
  REQUIRE(tbtest::eventually([&] { return radio.status().uplink_hz == 145'962'570; }));
  CHECK(radio.status().reads_uplink);
  link.turn(Link::uplink, 145'972'570);
  REQUIRE(tbtest::eventually([&] { return radio.status().uplink_read_hz == 145'972'570; }));
  radio.set_frequency_guarded(Link::uplink, 145'962'580, 25);   // trakbox's next Doppler step
  REQUIRE(radio.wait_idle(std::chrono::milliseconds(2000)));
  CHECK(link.read_frequency(Link::uplink) == 145'972'570);
  CHECK(*radio.take_dial_turn(Link::uplink) == 145'972'570);
  CHECK_FALSE(radio.take_dial_turn(Link::uplink));
  radio.set_frequency_guarded(Link::uplink, 145'972'580, 25);   // from the new spot
  REQUIRE(tbtest::eventually([&] { return link.read_frequency(Link::uplink) == 145'972'580; }));
}

TEST_CASE("Two radios: each link on its own radio's VFO, faults named by radio") {
  auto down = std::make_unique<SimulatedRadio>();
  auto up = std::make_unique<SimulatedRadio>();
  SimulatedRadio& d = *down;
  SimulatedRadio& u = *up;
  TwoRadios two(std::move(down), std::move(up));
  CHECK(two.describe() == "downlink: simulated radio; uplink: simulated radio");
  two.set_mode(Link::uplink, Mode::lsb);
  two.set_frequency(Link::uplink, 145'965'000);
  two.set_frequency(Link::downlink, 435'640'000);
  CHECK(*u.frequency(Link::downlink) == 145'965'000);
  CHECK(*u.mode(Link::downlink) == Mode::lsb);
  CHECK_FALSE(u.frequency(Link::uplink));
  CHECK(*d.frequency(Link::downlink) == 435'640'000);
  RadioStatus s = two.status();
  CHECK(*s.downlink_hz == 435'640'000);
  CHECK(*s.uplink_hz == 145'965'000);
  CHECK_FALSE(s.fault);
  u.simulate_fault("no answer");
  s = two.status();
  CHECK(s.fault);
  CHECK(s.message == "uplink radio: no answer");
  d.simulate_fault("port closed");
  CHECK(two.status().message == "downlink radio: port closed; uplink radio: no answer");
  u.clear_fault();
  d.clear_fault();
  two.set_frequency_guarded(Link::uplink, 145'965'010, 20);
  u.step(Link::downlink, 10'000);
  two.set_frequency_guarded(Link::uplink, 145'965'020, 20);
  CHECK(*two.take_dial_turn(Link::uplink) == 145'975'010);
}

TEST_CASE("Freq/mode: passbands, inverting and CTCSS as options after the record") {
  const auto p = parse_freqmode("RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y\n"
                                "SO-50 436.795 145.850 fm fm cat no tone=67.0\n"
                                "FO-29 435.850 145.950 usb lsb cat no kr down=435.800-435.900 up=145.900-146.000 inv=y\n");
  REQUIRE(p.ok());
  REQUIRE(p.records.size() == 3);
  CHECK(p.records[0].radio == rs44());
  CHECK(p.records[1].radio.ctcss_tenths_hz == 670);
  CHECK(p.records[2].radio.reverse == ReverseAssignment::kenwood_vfo);
  CHECK(p.records[2].radio.uplink_high_hz == 146'000'000);
  CHECK(format_freqmode_line(p.records[0]) ==
        "RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y");
  CHECK(format_freqmode_line(p.records[1]) == "SO-50 436.795 145.850 fm fm cat no tone=67.0");
  CHECK(parse_freqmode(write_freqmode(p.records)).records == p.records);
  // A record without options writes as before.
  CHECK(format_freqmode_line(parse_freqmode("AO-27 436.795 145.850 fm fm cat no").records.at(0)) ==
        "AO-27 436.795 145.850 fm fm cat no");
}

TEST_CASE("Freq/mode: a bad option names itself and gives no record") {
  const auto p = parse_freqmode("RS-44 435.640 145.965 usb lsb cat no down=435.670-435.610 up=145.935-145.995\n"
                                "SO-50 436.795 145.850 fm fm cat no tone=6.7\n"
                                "X 436.795 145.850 fm fm cat no down=435.610-435.670\n"
                                "Y 436.795 145.850 fm fm cat no inv=maybe\n");
  CHECK(p.records.empty());
  REQUIRE(p.problems.size() == 4);
  CHECK(p.problems[0].message() ==
        "line 1, field 8 (option): found \"down=435.670-435.610\", expected down=LOW-HIGH in MHz, low first, "
        "such as 435.610-435.670");
  CHECK(p.problems[1].message() ==
        "line 2, field 8 (option): found \"tone=6.7\", expected tone=HZ, a CTCSS tone from 60.0 to 300.0 Hz "
        "such as tone=67.0");
  CHECK(p.problems[2].message() ==
        "line 3, field 8 (option): found \"down=\", expected both down=LOW-HIGH and up=LOW-HIGH for a transponder");
  CHECK(p.problems[3].line == 4);
}
