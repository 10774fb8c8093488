// The satellite radios of 2026 over a socat pty pair, each against a responder written here from
// the documented protocol (docs/radio.md, "The radios of 2026"; Icom's IC-9700 CI-V reference; Hamlib's ft847.c and
// ft817.c): exact bytes of a pass's first update, a Doppler update, a dial turn read back,
// satellite mode on and off, CTCSS; frames per update counted. Skipped without socat.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <thread>

#include "radio/cat.h"
#include "radio/factory.h"
#include "responders.h"
#include "support.h"

namespace doctest {
template <>
struct StringMaker<std::vector<std::string>> {
  static String convert(const std::vector<std::string>& v) {
    std::string s = "{";
    for (const auto& x : v) s += (s.size() > 1 ? " | " : "") + x;
    return (s + "}").c_str();
  }
};
}  // namespace doctest

using namespace tb::radio;
using namespace std::chrono_literals;
using tbtest::eventually;
using tbtest::PtyEnd;
using tbtest::PtyPair;
using tbtest::Ic9700;
using tbtest::Ts2000;
using tbtest::Yaesu5;

namespace {

const WorkerTiming kFastWorker{20ms, 100ms, 50ms};

DriverTiming patient_timing() {
  DriverTiming t;
  t.worker = kFastWorker;
  t.yaesu_byte_gap = 1ms;
  t.icom_echo_margin = 1000ms;   // patient: a loaded machine is no collision
  t.icom_reply_timeout = 1000ms;
  // These tests compare each radio's commands from the first byte: without the connect's read
  // (WorkerTiming::ask_at_connect), which tests/integration/silent_links.py and the satellite
  // radios' integration tests run on.
  t.worker.ask_at_connect = false;
  return t;
}

std::vector<std::string> hex_all(const std::vector<Bytes>& frames) {
  std::vector<std::string> out;
  for (const auto& f : frames) out.push_back(to_hex(f));
  return out;
}

// A pass's first update (RS-44: USB down on 435, LSB up on 145), as apply() sends it.
void rs44_first_update(RadioDriver& radio) {
  radio.set_mode(Link::downlink, Mode::usb);
  radio.set_frequency(Link::downlink, 435'643'780);
  radio.set_mode(Link::uplink, Mode::lsb);
  radio.set_frequency(Link::uplink, 145'963'730);
  REQUIRE(radio.wait_idle(10000ms));
}

// SO-50 selected with its 67.0 Hz tone: the tone, then each link's mode and frequency.
void so50_first_update(RadioDriver& radio) {
  radio.set_ctcss_tone(670);
  radio.set_mode(Link::downlink, Mode::fm);
  radio.set_frequency(Link::downlink, 436'795'000);
  radio.set_mode(Link::uplink, Mode::fm);
  radio.set_frequency(Link::uplink, 145'850'000);
  REQUIRE(radio.wait_idle(10000ms));
}

int count_cmd(const std::vector<Bytes>& frames, std::uint8_t cmd) {
  int n = 0;
  for (const auto& b : frames)
    if (auto f = icom::decode_frame(b); f && f->cmd == cmd && f->from == icom::kController) ++n;
  return n;
}

}  // namespace

TEST_CASE("IC-9700, echo on and off: satellite mode, Main down / Sub up, read-back, CTCSS, no select thrash" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  for (const bool echo : {false, true}) {
    CAPTURE(echo);
    PtyPair pair;
    REQUIRE(pair.ok());
    Ic9700 rig(pair.test_side(), echo);
    auto made = make_radio("ic9700:" + pair.radio_side(), RadioConfig{}, patient_timing());
    REQUIRE(made.driver);
    RadioDriver& radio = *made.driver;

    // A pass's first update (RS-44: USB down on 435, LSB up on 145), as apply() sends it.
    rs44_first_update(radio);
    CHECK_FALSE(radio.status().fault);
    CHECK(hex_all(rig.frames()) == std::vector<std::string>{
                                       "FE FE A2 E0 16 5A 01 FD",         // satellite mode on, first
                                       "FE FE A2 E0 07 D0 FD",            // Main: the downlink
                                       "FE FE A2 E0 06 01 FD",            // USB
                                       "FE FE A2 E0 05 80 37 64 35 04 FD",
                                       "FE FE A2 E0 07 D1 FD",            // Sub: the uplink
                                       "FE FE A2 E0 06 00 FD",            // LSB
                                       "FE FE A2 E0 05 30 37 96 45 01 FD"});
    CHECK(rig.satellite());
    CHECK(rig.frequency(icom::Band::main) == 435'643'780);
    CHECK(rig.frequency(icom::Band::sub) == 145'963'730);

    // Doppler updates: one select per band change, never more selects than frequencies.
    rig.clear();
    for (int i = 1; i <= 5; ++i) {
      radio.set_frequency(Link::downlink, 435'643'780 - 40 * i);
      radio.set_frequency(Link::uplink, 145'963'730 + 40 * i);
      REQUIRE(radio.wait_idle(10000ms));
    }
    const auto upd = rig.frames();
    CHECK(count_cmd(upd, 0x05) == 10);
    CHECK(count_cmd(upd, 0x07) == 10);   // one per band change, here every frequency: never more
    // The CAT line per update (both links): 36 bytes to the radio (2 selects of 7, 2 frequencies
    // of 11), 24 back (4 FB of 6), 36 more echoed on a CI-V bus: 60 bytes/s at one update a second
    // without the echo, 96 with it.
    std::size_t sent = 0;
    for (const auto& f : upd) sent += f.size();
    CHECK(sent == 5 * 36);
    CHECK(hex_all(upd)[0] == "FE FE A2 E0 07 D0 FD");
    CHECK(hex_all(upd)[1] == "FE FE A2 E0 05 40 37 64 35 04 FD");   // 435.643740

    // The dial turned on the radio: read back with 03 after the band select (the transceive frame
    // is not trusted), the guarded write dropped, the turn handed to the station.
    rig.clear();
    rig.turn(icom::Band::main, 10'000);
    radio.set_frequency_guarded(Link::downlink, 435'643'540, 60);
    REQUIRE(radio.wait_idle(10000ms));
    CHECK(radio.take_dial_turn(Link::downlink) == 435'653'580);
    CHECK(rig.frequency(icom::Band::main) == 435'653'580);       // not undone
    // (With the echo, the transceive frame crossing the select is a collision: the select goes
    // again. The idle check may read again: more 03s, never a 05.)
    const auto read = hex_all(rig.frames());
    REQUIRE(read.size() >= 2);
    CHECK(read[0] == "FE FE A2 E0 07 D0 FD");
    CHECK(std::find(read.begin(), read.end(), "FE FE A2 E0 03 FD") != read.end());
    CHECK(count_cmd(rig.frames(), 0x05) == 0);
    radio.set_frequency(Link::downlink, 435'653'580);   // unguarded again: no more idle reads
    REQUIRE(radio.wait_idle(10000ms));

    // The Sub (uplink) dial, with Main selected: read with 1C 03 (the transmit frequency), no select.
    rig.clear();
    rig.turn(icom::Band::sub, -5'000);
    radio.set_frequency_guarded(Link::uplink, 145'963'930, 60);
    REQUIRE(radio.wait_idle(10000ms));
    CHECK(radio.take_dial_turn(Link::uplink) == 145'958'930);
    const auto tx_read = hex_all(rig.frames());
    REQUIRE_FALSE(tx_read.empty());
    CHECK(tx_read.front() == "FE FE A2 E0 1C 03 FD");
    CHECK(count_cmd(rig.frames(), 0x07) == 0);
    radio.set_frequency(Link::uplink, 145'958'930);
    REQUIRE(radio.wait_idle(10000ms));
    CHECK(radio.status().reads_downlink);
    CHECK(radio.status().reads_uplink);

    // CTCSS on the uplink's band (Sub, selected already by the uplink's write): 1B 00 tone, TONE on.
    rig.clear();
    radio.set_ctcss_tone(670);
    REQUIRE(radio.wait_idle(10000ms));
    CHECK(hex_all(rig.frames()) == std::vector<std::string>{"FE FE A2 E0 1B 00 00 06 70 FD", "FE FE A2 E0 16 42 01 FD"});
    CHECK(rig.tone() == 670);
    rig.clear();
    radio.set_frequency(Link::downlink, 435'653'570);   // Main selected; a tone off selects Sub first
    radio.set_ctcss_tone(0);
    REQUIRE(radio.wait_idle(10000ms));
    CHECK(hex_all(rig.frames()) == std::vector<std::string>{"FE FE A2 E0 07 D0 FD", "FE FE A2 E0 05 70 35 65 35 04 FD",
                                                            "FE FE A2 E0 07 D1 FD", "FE FE A2 E0 16 42 00 FD"});
    CHECK(rig.tone() == 0);

    // Closing turns satellite mode off.
    rig.clear();
    made.driver.reset();
    REQUIRE(eventually([&] { return !rig.frames().empty(); }));
    CHECK(hex_all(rig.frames()).back() == "FE FE A2 E0 16 5A 00 FD");
    CHECK_FALSE(rig.satellite());
  }
}

TEST_CASE("IC-9700: a refused tone and a refused satellite mode are reported; Doppler goes on" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Ic9700 rig(pair.test_side(), false);
  rig.refuse_tone = true;
  rig.refuse_satmode = true;
  auto made = make_radio("ic9700:" + pair.radio_side(), RadioConfig{}, patient_timing());
  RadioDriver& radio = *made.driver;
  so50_first_update(radio);
  CHECK(radio.status().failures >= 1);   // the tone's NG was reported
  CHECK(rig.frequency(icom::Band::main) == 436'795'000);
  CHECK(rig.frequency(icom::Band::sub) == 145'850'000);
  CHECK_FALSE(radio.status().fault);     // the frequencies went through after it
  radio.set_frequency(Link::uplink, 145'850'100);
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(rig.frequency(icom::Band::sub) == 145'850'100);
  const auto frames = hex_all(rig.frames());
  CHECK(std::count(frames.begin(), frames.end(), "FE FE A2 E0 16 5A 01 FD") == 1);   // asked once, not every second
}

TEST_CASE("IC-9100 and IC-910H: their addresses and satellite-mode commands, Main up / Sub down" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  struct Case {
    const char* spec;
    std::uint8_t address;
    std::vector<std::string> first;
  };
  const Case cases[] = {
      {"ic9100:", 0x7C, {"FE FE 7C E0 16 5A 01 FD", "FE FE 7C E0 07 D1 FD", "FE FE 7C E0 06 01 FD", "FE FE 7C E0 05 80 37 64 35 04 FD",
                         "FE FE 7C E0 07 D0 FD", "FE FE 7C E0 06 00 FD", "FE FE 7C E0 05 30 37 96 45 01 FD"}},
      {"ic910h:", 0x60, {"FE FE 60 E0 1A 07 01 FD", "FE FE 60 E0 07 D1 FD", "FE FE 60 E0 06 01 FD", "FE FE 60 E0 05 80 37 64 35 04 FD",
                         "FE FE 60 E0 07 D0 FD", "FE FE 60 E0 06 00 FD", "FE FE 60 E0 05 30 37 96 45 01 FD"}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.spec);
    PtyPair pair;
    REQUIRE(pair.ok());
    Ic9700 rig(pair.test_side(), true, c.address);   // a CI-V bus: with the echo
    auto made = make_radio(std::string(c.spec) + pair.radio_side(), RadioConfig{}, patient_timing());
    rs44_first_update(*made.driver);
    CHECK(hex_all(rig.frames()) == c.first);
    CHECK(rig.frequency(icom::Band::sub) == 435'643'780);
    CHECK(rig.frequency(icom::Band::main) == 145'963'730);
  }
  // :maindown puts the downlink on Main.
  PtyPair pair;
  REQUIRE(pair.ok());
  Ic9700 rig(pair.test_side(), false, 0x7C);
  auto made = make_radio("ic9100:" + pair.radio_side() + ":maindown", RadioConfig{}, patient_timing());
  rs44_first_update(*made.driver);
  CHECK(rig.frequency(icom::Band::main) == 435'643'780);
  CHECK(rig.frequency(icom::Band::sub) == 145'963'730);
}

TEST_CASE("A model without a CTCSS encoder refuses a tone with a message, never silently" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  PtyEnd peer(pair.test_side());
  auto made = make_radio("ic910h:" + pair.radio_side(), RadioConfig{}, patient_timing());
  made.driver->set_ctcss_tone(670);
  // A limit of the radio, learnt once: in the status's limits and the log, never a fault or a failure.
  REQUIRE(eventually([&] { return !made.driver->status().limits.empty(); }));
  CHECK(made.driver->status().limits == made.driver->describe() + ": no CTCSS");
  CHECK_FALSE(made.driver->status().fault);
  CHECK(made.driver->status().failures == 0);
  // The families of menu 6-7 neither: a tone is refused with the same message, never dropped silently.
  for (const char* spec : {"kenwood:", "yaesu:", "icom:"}) {
    auto fam = make_radio(std::string(spec) + pair.radio_side(), RadioConfig{}, patient_timing());
    fam.driver->set_ctcss_tone(885);
    REQUIRE(eventually([&] { return fam.driver->status().limits.ends_with(": no CTCSS"); }));
  }
}

TEST_CASE("FT-847: CAT on, satellite mode, SAT RX / SAT TX opcodes, read-back, CTCSS, off at close" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Yaesu5 rig(pair.test_side());
  auto made = make_radio("ft847:" + pair.radio_side(), RadioConfig{}, patient_timing());
  RadioDriver& radio = *made.driver;
  rs44_first_update(radio);
  REQUIRE(eventually([&] { return rig.commands().size() >= 6; }));
  CHECK(rig.commands() == std::vector<std::string>{"00 00 00 00 00", "00 00 00 00 4E", "01 00 00 00 17",
                                                    "43 56 43 78 11", "00 00 00 00 27", "14 59 63 73 21"});
  rig.clear();
  radio.set_frequency(Link::uplink, 145'963'770);   // a Doppler update: one command
  REQUIRE(radio.wait_idle(10000ms));
  REQUIRE(eventually([&] { return rig.commands().size() >= 1; }));
  CHECK(rig.commands() == std::vector<std::string>{"14 59 63 77 21"});
  rig.clear();
  rig.turn(0x10, 10'000);   // the SAT RX dial
  radio.set_frequency_guarded(Link::downlink, 435'643'740, 60);
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(radio.take_dial_turn(Link::downlink) == 435'653'780);
  REQUIRE(eventually([&] { return rig.commands().size() >= 1; }));
  CHECK(rig.commands().front() == "00 00 00 00 13");
  radio.set_frequency(Link::downlink, 435'653'780);   // unguarded again: no more idle reads
  REQUIRE(radio.wait_idle(10000ms));
  REQUIRE(eventually([&] { return rig.commands().back() == "43 56 53 78 11"; }));
  rig.clear();
  radio.set_ctcss_tone(670);
  REQUIRE(radio.wait_idle(10000ms));
  REQUIRE(eventually([&] { return rig.commands().size() >= 2; }));
  CHECK(rig.commands() == std::vector<std::string>{"3F 00 00 00 2B", "4A 00 00 00 2A"});
  rig.clear();
  radio.set_ctcss_tone(671);   // not one of its 39 tones: refused with a message
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(radio.status().message == "the FT-847 has no CTCSS tone 67.1 Hz: not sent");
  CHECK(rig.commands().empty());
  made.driver.reset();
  REQUIRE(eventually([&] { return rig.commands().size() >= 2; }));
  CHECK(rig.commands() == std::vector<std::string>{"00 00 00 00 8E", "00 00 00 00 80"});
}

TEST_CASE("FT-817 pair: each radio one link on its VFO, read-back, tone on the uplink radio" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  tbtest::Ft817Pair pair(patient_timing());
  REQUIRE(pair.ok());
  Yaesu5 &down = *pair.down, &up = *pair.up;
  RadioDriver& radio = pair.radio();
  radio.set_mode(Link::downlink, Mode::usb);
  radio.set_frequency(Link::downlink, 435'643'780);
  radio.set_mode(Link::uplink, Mode::lsb);
  radio.set_frequency(Link::uplink, 145'963'730);
  radio.set_ctcss_tone(670);
  REQUIRE(radio.wait_idle(10000ms));
  REQUIRE(eventually([&] { return down.commands().size() >= 2; }));
  CHECK(down.commands() == std::vector<std::string>{"01 00 00 00 07", "43 56 43 78 01"});
  REQUIRE(eventually([&] { return up.commands().size() >= 4; }));
  CHECK(up.commands() == std::vector<std::string>{"00 00 00 00 07", "14 59 63 73 01", "06 70 06 70 0B", "4A 00 00 00 0A"});
  down.clear();
  down.turn(0x00, -5'000);
  radio.set_frequency_guarded(Link::downlink, 435'643'740, 60);
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(radio.take_dial_turn(Link::downlink) == 435'638'780);
  REQUIRE(eventually([&] { return down.commands().size() >= 1; }));
  CHECK(down.commands().front() == "00 00 00 00 03");
}

TEST_CASE("An FT-817 alone refuses the uplink with a message" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Yaesu5 rig(pair.test_side());
  auto made = make_radio("ft817:" + pair.radio_side(), RadioConfig{}, patient_timing());
  made.driver->set_frequency(Link::uplink, 145'900'000);
  REQUIRE(made.driver->wait_idle(10000ms));
  CHECK(made.driver->status().limits == made.driver->describe() + ": no uplink");
  CHECK(made.driver->status().no_uplink);
  CHECK_FALSE(made.driver->status().fault);
  CHECK(rig.commands().empty());
}

TEST_CASE("TS-2000: satellite mode SA, Main down (FA) / Sub up (FB), modes with CTRL, read-back, put back at close" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Ts2000 rig(pair.test_side());   // found as SatPC32 leaves it: SA0010000
  auto made = make_radio("ts2000:" + pair.radio_side(), RadioConfig{}, patient_timing());
  RadioDriver& radio = *made.driver;
  rs44_first_update(radio);
  REQUIRE(eventually([&] { return rig.commands().size() >= 10; }));
  CHECK(rig.commands() == std::vector<std::string>{"SA;", "FR;", "SA1010000;", "SA;", "MD2;", "FA00435643780;",
                                                    "SA1011000;", "MD1;", "SA1010000;", "FB00145963730;"});
  CHECK(rig.sa() == "1010000");
  CHECK(rig.band('M') == "MD2  TO0");   // USB on the downlink (Main)
  CHECK(rig.band('S') == "MD1  TO0");   // LSB on the uplink (Sub)
  CHECK(rig.frequency('A') == 435'643'780);
  CHECK(rig.frequency('B') == 145'963'730);
  CHECK(radio.status().reads_uplink);
  // A Doppler update: one command.
  rig.clear();
  radio.set_frequency(Link::uplink, 145'963'770);
  REQUIRE(radio.wait_idle(10000ms));
  REQUIRE(eventually([&] { return !rig.commands().empty(); }));
  CHECK(rig.commands() == std::vector<std::string>{"FB00145963770;"});
  // The operator turns the uplink dial: read back with FB;.
  rig.clear();
  rig.turn('B', 2'000);
  radio.set_frequency_guarded(Link::uplink, 145'963'810, 60);
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(radio.take_dial_turn(Link::uplink) == 145'965'770);
  REQUIRE(eventually([&] { return !rig.commands().empty(); }));
  CHECK(rig.commands().front() == "FB;");
  // Closed: the radio as it was found (SatPC32's exit string).
  rig.clear();
  made.driver.reset();
  REQUIRE(eventually([&] { return !rig.commands().empty() && rig.commands().back() == "SA0010000;"; }));
  CHECK(rig.sa() == "0010000");
}

TEST_CASE("TS-2000: VFO A in memory mode first goes to VFO; an SO-50 tone on Sub; a refused tone is reported, Doppler goes on" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Ts2000 rig(pair.test_side(), "0010110", '2');   // TRACE and REV on, VFO A on a memory
  auto made = make_radio("ts2000:" + pair.radio_side(), RadioConfig{}, patient_timing());
  RadioDriver& radio = *made.driver;
  so50_first_update(radio);
  REQUIRE(eventually([&] { return rig.commands().size() >= 16; }));
  CHECK(rig.commands() == std::vector<std::string>{"SA;", "FR;", "FR0;", "SA1010010;", "SA;",            // on, TRACE off
                                                    "SA1011010;", "TN01;", "TO1;", "TO;", "SA1010010;",  // the tone on Sub
                                                    "MD4;", "FA00436795000;", "SA1011010;", "MD4;", "SA1010010;",
                                                    "FB00145850000;"});
  CHECK(rig.band('S') == "MD4 TN01 TO1");
  CHECK(rig.band('M') == "MD4  TO0");
  CHECK_FALSE(radio.status().fault);
  made.driver.reset();
  REQUIRE(eventually([&] { return rig.commands().size() >= 20; }));
  const auto closing = rig.commands();
  CHECK(std::vector<std::string>(closing.end() - 4, closing.end()) ==
        std::vector<std::string>{"SA1011010;", "TO0;", "SA1010010;", "SA0010110;"});   // tone off, then as found

  // A radio that refuses the tone: reported with what it answered, the frequencies still go.
  PtyPair pair2;
  REQUIRE(pair2.ok());
  Ts2000 refusing(pair2.test_side());
  refusing.refuse_tone = true;
  auto made2 = make_radio("ts2000:" + pair2.radio_side(), RadioConfig{}, patient_timing());
  made2.driver->set_frequency(Link::downlink, 436'795'000);
  made2.driver->set_frequency(Link::uplink, 145'850'000);
  made2.driver->set_ctcss_tone(670);
  REQUIRE(made2.driver->wait_idle(10000ms));
  CHECK(made2.driver->status().failures == 1);
  CHECK(made2.driver->status().message == "the Kenwood TS-2000 refused the tone 67.0 Hz (TN01;TO1; answered ?;)");
  made2.driver->set_frequency(Link::uplink, 145'850'100);   // the next Doppler update goes on
  REQUIRE(made2.driver->wait_idle(10000ms));
  REQUIRE(eventually([&] { return refusing.frequency('B') == 145'850'100; }));
  CHECK(refusing.frequency('A') == 436'795'000);
  CHECK(refusing.sa() == "1010000");   // CTRL back on Main after the refusal
  made2.driver->set_ctcss_tone(693);   // 69.3 Hz: not one of its tones
  REQUIRE(made2.driver->wait_idle(10000ms));
  CHECK(made2.driver->status().message == "the Kenwood TS-2000 has no CTCSS tone 69.3 Hz: not sent");
}

TEST_CASE("TS-2000: Hamlib's simulator answers SA0; and takes no SA: reported once, VFO A down / VFO B up" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  Ts2000 rig(pair.test_side());
  rig.hamlib_sim = true;
  auto made = make_radio("ts2000:" + pair.radio_side(), RadioConfig{}, patient_timing());
  RadioDriver& radio = *made.driver;
  rs44_first_update(radio);
  radio.set_ctcss_tone(670);
  REQUIRE(radio.wait_idle(10000ms));
  CHECK(rig.frequency('A') == 435'643'780);
  CHECK(rig.frequency('B') == 145'963'730);
  const auto cmds = rig.commands();
  CHECK(std::count(cmds.begin(), cmds.end(), "SA1010000;") == 1);   // asked once, not every second
  CHECK(std::count(cmds.begin(), cmds.end(), "SA;") == 4);          // the first read and three to confirm
  // Outside satellite mode a mode reaches VFO B with FR1 (the TS-2000's VFO select, not the TS-790's FN).
  CHECK(std::find(cmds.begin(), cmds.end(), "FR1;") != cmds.end());
  CHECK(std::find(cmds.begin(), cmds.end(), "FN1;") == cmds.end());
  CHECK(std::find(cmds.begin(), cmds.end(), "TN01;") != cmds.end());
  CHECK_FALSE(radio.status().fault);
}

TEST_CASE("TS-2000 :mainup is refused: its satellite mode is driven Main down / Sub up only") {
  auto made = make_radio("ts2000:/dev/null:mainup", RadioConfig{}, patient_timing());
  CHECK(made.driver == nullptr);
  CHECK(made.error == "--radio \"ts2000:/dev/null:mainup\": \"mainup\": the Kenwood TS-2000's satellite mode is "
                      "driven with the downlink on Main (FA) and the uplink on Sub (FB) only");
  CHECK(make_radio("ts2000:/dev/null:maindown", RadioConfig{}, patient_timing()).driver != nullptr);
}
