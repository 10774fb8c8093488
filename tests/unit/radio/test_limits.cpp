// A feature a radio lacks (issue 48): LinkError::Action::lacks is a limit learnt once, in the
// status's `limits` and the log, never a fault, a failure or a reconnect; the uplink of a radio
// that has none is marked (no_uplink) so the status says "not sent".
#include <doctest/doctest.h>

#include <mutex>
#include <string>
#include <vector>

#include "radio/worker.h"
#include "support.h"

using namespace tb::radio;
using namespace std::chrono_literals;

namespace {

// A receiver: the downlink only, no tone encoder.
class ReceiverLink final : public RadioLink {
 public:
  std::string describe() const override { return "a receiver at 127.0.0.1:7356"; }
  std::string name() const override { return "RX"; }
  void open() override { ++opens; }
  void close() noexcept override {}
  void set_frequency(Link l, Hz hz) override {
    if (l == Link::uplink) throw LinkError("no uplink", "RX carries no uplink: not sent (--uplink-radio)");
    std::lock_guard lock(mu);
    tuned.push_back(hz);
  }
  void set_mode(Link l, Mode) override {
    if (l == Link::uplink) throw LinkError("no uplink", "RX carries no uplink: not sent (--uplink-radio)");
  }
  void send_raw(const std::string&) override {}
  void set_ctcss_tone(int tenths) override {
    if (tenths > 0) throw LinkError("no CTCSS", "RX has no CTCSS encoder: tone not sent");
  }
  std::mutex mu;
  std::vector<Hz> tuned;
  int opens = 0;
};

// A receiver with a recorder that records only while its DSP runs (GQRX's rule).
class RecorderLink final : public RadioLink {
 public:
  std::string describe() const override { return "a recorder at 127.0.0.1:7356"; }
  std::string name() const override { return "RX"; }
  void open() override {}
  void close() noexcept override {}
  void set_frequency(Link, Hz) override {}
  void set_mode(Link, Mode) override {}
  void send_raw(const std::string&) override {}
  std::string records() const override { return "audio"; }
  Recording record(Record what) override {
    std::lock_guard lock(mu);
    asked.push_back(what);
    if (what != Record::off && !dsp) return {Record::off, true, "not recording: DSP off", "refused"};
    return {what, true, {}, "recording"};
  }
  std::mutex mu;
  bool dsp = false;
  std::vector<Record> asked;
};

}  // namespace

TEST_CASE("A recording the receiver refuses is a limit in the status, not a fault; a later start takes") {
  auto link = std::make_unique<RecorderLink>();
  RecorderLink& rx = *link;
  WorkerRadio radio(std::move(link), {10ms, 40ms});
  radio.set_downlink_frequency(436'795'000);
  radio.set_recording(Record::audio);
  REQUIRE(radio.wait_idle(2000ms));
  RadioStatus s = radio.status();
  CHECK(s.recorder.can == "audio");
  CHECK(s.recorder.receiver == "RX");
  CHECK(s.recorder.now == Record::off);
  CHECK(s.recorder.refused == "not recording: DSP off");
  CHECK(s.recorder.answers == 1);
  CHECK(s.limits == "RX: not recording: DSP off");
  CHECK_FALSE(s.fault);
  CHECK(s.failures == 0);
  {
    std::lock_guard lock(rx.mu);
    rx.dsp = true;
  }
  radio.set_recording(Record::audio);
  REQUIRE(radio.wait_idle(2000ms));
  s = radio.status();
  CHECK(s.recorder.now == Record::audio);
  CHECK(s.recorder.read_back);
  CHECK(s.recorder.refused.empty());
  CHECK(s.limits.empty());   // the refusal was the only limit: it went with the start that took
  radio.set_recording(Record::off);
  REQUIRE(radio.wait_idle(2000ms));
  s = radio.status();
  CHECK(s.recorder.now == Record::off);
  CHECK(s.recorder.answers == 3);
  std::lock_guard lock(rx.mu);
  CHECK(rx.asked == std::vector<Record>{Record::audio, Record::audio, Record::off});
}

TEST_CASE("A radio without a recorder: a start is a limit learnt once (no recorder), never a fault") {
  WorkerRadio radio(std::make_unique<ReceiverLink>(), {10ms, 40ms});
  radio.set_recording(Record::audio);
  REQUIRE(radio.wait_idle(2000ms));
  const RadioStatus s = radio.status();
  CHECK(s.recorder.can.empty());
  CHECK(s.limits == "RX: no recorder");
  CHECK_FALSE(s.fault);
  CHECK(s.failures == 0);
}

TEST_CASE("A lacking feature is a limit learnt once: no fault, no failure, no reconnect") {
  auto link = std::make_unique<ReceiverLink>();
  ReceiverLink& rx = *link;
  WorkerRadio radio(std::move(link), {10ms, 40ms});
  radio.set_ctcss_tone(670);
  for (Hz f = 0; f < 20; ++f) {   // a pass's worth of updates, each with an uplink
    radio.set_downlink_frequency(436'795'000 + f * 100);
    radio.set_uplink_frequency(145'850'000 - f * 30);
    radio.set_uplink_mode(Mode::fm);
    REQUIRE(radio.wait_idle(2000ms));
  }
  const RadioStatus s = radio.status();
  CHECK(s.limits == "RX: no CTCSS, no uplink");
  CHECK(s.no_uplink);
  CHECK_FALSE(s.fault);
  CHECK(s.message.empty());
  CHECK(s.failures == 0);
  CHECK(s.connected);
  CHECK(s.connects == 1);
  CHECK(rx.opens == 1);
  CHECK(s.downlink_hz == 436'796'900);
  CHECK_FALSE(s.uplink_hz);
  std::lock_guard lock(rx.mu);
  CHECK(rx.tuned.size() == 20);
}
