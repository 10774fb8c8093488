// StationOps' radio operations (issue 47): the passband position of a linear transponder, the
// operator's RX and TX offsets kept per satellite and mode, and the uplink's tone; each refused with
// the value named and nothing changed. RS-44's passbands are the shipped record's (435.610-435.670
// down, 145.935-145.995 up, inverting: up = 145.995 MHz - (down - 435.610 MHz)).
#include <doctest/doctest.h>

#include <cstdlib>

#include "radio/doppler.h"
#include "support/sim_station.h"
#include "tracker/operations.h"

using namespace tb;

namespace {

struct Pass : testing::StationFixture {
  // RS-44 a minute before its culmination of 10:58 UTC; ISS during its pass of 13:45-13:55 UTC.
  Pass(const std::string& name, orbit::UtcTime t) : StationFixture(t) {
    build_station();
    REQUIRE(ops().track(name).ok());
    run(3.0);
  }
  tracker::StationOps ops() { return tracker::StationOps(*station); }
  radio::Hz down() const { return *radio_sim->frequency(radio::Link::downlink); }
  radio::Hz up() const { return *radio_sim->frequency(radio::Link::uplink); }
};

Pass rs44() { return Pass("RS-44", orbit::from_civil(2026, 5, 21, 10, 57, 0)); }
Pass iss() { return Pass("ISS", orbit::from_civil(2026, 5, 21, 13, 47, 0)); }

}  // namespace

TEST_CASE("StationOps: RS-44's passband moved +5 kHz: the downlink dial +5 kHz, the uplink -5 kHz") {
  Pass p = rs44();
  REQUIRE(p.station->tuner().downlink_spot_hz() == 435'640'000);
  const radio::Hz d0 = p.down(), u0 = p.up();
  const tracker::OpResult r = p.ops().tune_spot(435'645'000);
  REQUIRE(r.ok());
  CHECK(r.note == "spot 435645000 Hz down, 145960000 Hz up");
  CHECK_FALSE(r.model_changed);
  CHECK(p.station->tuner().uplink_spot_hz() == 145'960'000);
  p.run(1.0);
  // A second of Doppler change near culmination is well under 100 Hz on either link.
  CHECK(std::llabs(p.down() - (d0 + 5'000)) < 100);
  CHECK(std::llabs(p.up() - (u0 - 5'000)) < 100);

  const tracker::OpResult out = p.ops().tune_spot(435'700'000);
  REQUIRE_FALSE(out.ok());
  CHECK(*out.refusal == "spot 435700000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz");
  CHECK(p.station->tuner().downlink_spot_hz() == 435'645'000);
}

TEST_CASE("StationOps: an FM satellite has no passband to move; nothing tuned refuses every radio operation") {
  Pass p = iss();
  CHECK(p.ops().tune_spot(437'800'000).refusal.value() ==
        "ISS has no transponder passband (its freq/mode record gives no down=LOW-HIGH): its frequencies are fixed");
  testing::StationFixture idle;
  idle.build_station();
  tracker::StationOps ops(*idle.station);
  CHECK(ops.tune_spot(435'640'000).refusal.value() == "no satellite is tuned: track one first");
  CHECK(ops.tune_offsets(100, std::nullopt).refusal.value() == "no satellite is tuned: track one first");
  CHECK(ops.tune_tone(67.0).refusal.value() == "no satellite is tuned: track one first");
}

TEST_CASE("StationOps: RX and TX offsets move each link's dial, are kept per satellite and mode, 0 forgets") {
  Pass p = iss();
  const radio::Hz d0 = p.down(), u0 = p.up();
  const tracker::OpResult r = p.ops().tune_offsets(500, -300);
  REQUIRE(r.ok());
  CHECK(r.model_changed);
  CHECK(r.note == "RX offset +500 Hz, TX offset -300 Hz (ISS FM)");
  CHECK(p.model.radio.corrections.at("ISS FM") == 500);
  CHECK(p.model.radio.tx_corrections.at("ISS FM") == -300);
  p.run(1.0);
  // ISS's Doppler moves about 100 Hz a second on 437.8 MHz mid-pass; the FM step is 100 Hz.
  CHECK(std::llabs(p.down() - (d0 + 500)) <= 250);
  CHECK(std::llabs(p.up() - (u0 - 300)) <= 250);

  // Only the TX offset: the RX one stays.
  REQUIRE(p.ops().tune_offsets(std::nullopt, 120).ok());
  CHECK(p.station->tuner().rit_hz() == 500);
  CHECK(p.station->tuner().xit_hz() == 120);

  // Out of range: refused with the value, nothing changed.
  const store::Model before = p.model;
  CHECK(p.ops().tune_offsets(200'000, 0).refusal.value() == "RX offset 200000 Hz out of range: expected -100000 to 100000");
  CHECK(p.ops().tune_offsets(0, -100'001).refusal.value() == "TX offset -100001 Hz out of range: expected -100000 to 100000");
  CHECK(p.ops().tune_offsets(std::nullopt, std::nullopt).refusal.value() ==
        "no offset given: expected an RX or a TX offset in Hz");
  CHECK(p.model.radio == before.radio);

  // The reset.
  const tracker::OpResult zero = p.ops().tune_offsets(0, 0);
  REQUIRE(zero.ok());
  CHECK(zero.model_changed);
  CHECK_FALSE(p.model.radio.corrections.contains("ISS FM"));
  CHECK_FALSE(p.model.radio.tx_corrections.contains("ISS FM"));
}

TEST_CASE("Tuner: the kept TX correction is applied when the satellite is next selected") {
  radio::RadioConfig c;
  c.tx_corrections["ISS FM"] = -300;
  c.corrections["ISS FM"] = 200;
  radio::Tuner t(c);
  radio::SatelliteRadio sat;
  sat.downlink_hz = 437'800'000;
  sat.uplink_hz = 145'990'000;
  sat.downlink_mode = sat.uplink_mode = radio::Mode::fm;
  t.select(sat, "ISS");
  CHECK(t.xit_hz() == -300);
  CHECK(t.rit_hz() == 200);
  const radio::TuneCommands cmd = t.update(30.0, 0.0);   // no Doppler at range rate 0
  CHECK(cmd.downlink_hz == 437'800'200);
  CHECK(cmd.uplink_hz == 145'989'700);
  t.select(sat, "SO-50");
  CHECK(t.xit_hz() == 0);
}

TEST_CASE("StationOps: the tone is sent and stored in the satellite's record; a bad tone is refused") {
  Pass p = iss();
  const int iss_index = *p.model.db.find("ISS");
  const tracker::OpResult r = p.ops().tune_tone(141.3);
  REQUIRE(r.ok());
  CHECK(r.model_changed);
  CHECK(r.note == "ISS tone 141.3 Hz");
  CHECK(p.model.db.satellites[static_cast<std::size_t>(iss_index)].radio.ctcss_tenths_hz == 1413);
  CHECK(p.station->tuner().satellite().ctcss_tenths_hz == 1413);
  CHECK(p.ops().tune_tone(67.05).refusal.value() ==
        "tone 67.05 Hz: expected a CTCSS tone from 60.0 to 300.0 Hz (tenths, e.g. 67.0) or 0 for none");
  CHECK(p.ops().tune_tone(400).refusal.value() ==
        "tone 400 Hz: expected a CTCSS tone from 60.0 to 300.0 Hz (tenths, e.g. 67.0) or 0 for none");
  CHECK(p.model.db.satellites[static_cast<std::size_t>(iss_index)].radio.ctcss_tenths_hz == 1413);
  REQUIRE(p.ops().tune_tone(0).ok());
  CHECK(p.model.db.satellites[static_cast<std::size_t>(iss_index)].radio.ctcss_tenths_hz == 0);
}
