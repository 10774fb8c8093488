// The serial CAT drivers over a pseudo-terminal pair standing in for the radio cable:
// socat -d -d pty,raw,echo=0 pty,raw,echo=0. The driver opens one end; the test plays the radio on
// the other, reads the bytes and decodes them back. Skipped (with a message) without socat.
#include <doctest/doctest.h>

#include <atomic>
#include <mutex>
#include <thread>

#include "radio/icom/link.h"
#include "radio/kenwood/link.h"
#include "radio/yaesu/link.h"
#include "support.h"

using tbtest::PtyPair;
using tbtest::PtyEnd;
using tbtest::eventually;
using namespace std::chrono_literals;
using namespace tb::radio;

namespace {

const WorkerTiming kFast{20ms, 100ms};

// Generous waits so a loaded machine (sanitizers, parallel tests) is not mistaken for a collision.
IcomOptions patient(IcomOptions o = {}) {
  o.echo_margin = 1000ms;
  o.reply_timeout = 1000ms;
  return o;
}

// The Icom side of the one-wire CI-V bus: every frame comes back as its echo; a radio that is
// addressed directly answers FB (or FA for the frames the test marks as refused).
class IcomBus {
 public:
  explicit IcomBus(const std::string& path) : end_(path) {
    thread_ = std::thread([this] { run(); });
  }
  ~IcomBus() {
    stop_ = true;
    thread_.join();
  }
  bool ok() const { return end_.ok(); }
  std::atomic<bool> echo{true};
  std::atomic<int> jam_next{0};          // this many frames get a jam code instead of their echo
  std::atomic<bool> refuse_modes{false}; // answer FA to 06 (mode) frames

  std::vector<Bytes> frames() {
    std::lock_guard lock(mu_);
    return frames_;
  }

 private:
  void run() {
    tbtest::read_civ_frames(end_, stop_, [this](const Bytes& f) {
      {
        std::lock_guard lock(mu_);
        frames_.push_back(f);
      }
      if (jam_next > 0) {
        --jam_next;
        end_.write({0xFE, 0xFE, 0xFC, 0xFC, 0xFC, 0xFD});   // the bus was jammed
        return;
      }
      if (!echo) return;
      end_.write(f);
      const auto frame = icom::decode_frame(f);
      if (frame && frame->to != icom::kBroadcast) {
        const bool ng = refuse_modes && frame->cmd == icom::kCmdSetMode;
        end_.write({0xFE, 0xFE, icom::kController, frame->to, ng ? icom::kNg : icom::kOk, 0xFD});
      }
    });
  }
  PtyEnd end_;
  std::atomic<bool> stop_{false};
  std::mutex mu_;
  std::vector<Bytes> frames_;
  std::thread thread_;
};

std::vector<Hz> frequencies_to(const std::vector<Bytes>& frames, std::uint8_t to) {
  std::vector<Hz> out;
  for (const auto& b : frames) {
    auto f = icom::decode_frame(b);
    if (f && f->to == to && f->from == icom::kController)
      if (auto hz = icom::decode_frequency(*f)) out.push_back(*hz);
  }
  return out;
}

// A Kenwood driver on a pty pair that is gone when this returns (socat ends: both ptys and their
// links disappear), after one frequency went through: the port the driver has open vanished.
std::unique_ptr<RadioDriver> kenwood_on_a_cable_that_goes(std::string& device, const WorkerTiming& timing) {
  PtyPair pair;
  REQUIRE(pair.ok());
  PtyEnd peer(pair.test_side());
  device = pair.radio_side();
  auto radio = make_kenwood_radio(device, {}, timing);
  radio->set_downlink_frequency(435'000'000);
  REQUIRE(radio->wait_idle(5000ms));
  CHECK(radio->status().connected);
  return radio;
}

}  // namespace

TEST_CASE("Icom CI-V over a pty: frequencies and modes to two radios, echo and FB read back" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  IcomBus bus(pair.test_side());
  REQUIRE(bus.ok());
  IcomOptions o;
  o.rx_address = icom::kIc475;   // downlink radio 14h
  o.tx_address = icom::kIc275;   // uplink radio 10h
  auto radio = make_icom_radio(pair.radio_side(), patient(o), kFast);

  radio->set_downlink_mode(Mode::usb);
  radio->set_uplink_mode(Mode::lsb);
  const std::vector<Hz> down{435'123'450, 435'123'440, 435'120'000, 435'110'010};
  const std::vector<Hz> up{145'950'000, 145'950'010, 145'960'000, 145'970'000};
  for (std::size_t i = 0; i < down.size(); ++i) {
    radio->set_downlink_frequency(down[i]);
    radio->set_uplink_frequency(up[i]);
    REQUIRE(radio->wait_idle(5000ms));
  }
  const auto st = radio->status();
  CHECK_FALSE(st.fault);
  CHECK(st.downlink_hz == down.back());
  CHECK(st.uplink_hz == up.back());
  CHECK(st.downlink_mode == Mode::usb);

  const auto frames = bus.frames();
  CHECK(frequencies_to(frames, 0x14) == down);
  CHECK(frequencies_to(frames, 0x10) == up);
  REQUIRE(frames.size() >= 2);
  CHECK(to_hex(frames[0]) == "FE FE 14 E0 06 01 FD");   // USB to the IC-475
  CHECK(to_hex(frames[1]) == "FE FE 10 E0 06 00 FD");   // LSB to the IC-275
  CHECK(to_hex(frames[2]) == "FE FE 14 E0 05 50 34 12 35 04 FD");
}

TEST_CASE("Icom CI-V over a pty: collision (jam instead of echo) is retried" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  IcomBus bus(pair.test_side());
  IcomOptions o;
  o.collision_wait = 5ms;
  auto radio = make_icom_radio(pair.radio_side(), patient(o), kFast);   // broadcast 00: no reply expected
  bus.jam_next = 2;
  radio->set_downlink_frequency(145'950'000);
  REQUIRE(radio->wait_idle(5000ms));
  CHECK_FALSE(radio->status().fault);
  CHECK(radio->status().downlink_hz == 145'950'000);
  const auto frames = bus.frames();
  REQUIRE(frames.size() == 3);   // sent three times: two jammed, the third clean
  for (const auto& f : frames) CHECK(to_hex(f) == "FE FE 00 E0 05 00 00 95 45 01 FD");
}

TEST_CASE("Icom CI-V over a pty: no echo is the fault \"interface not echoing\", then it recovers" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  IcomBus bus(pair.test_side());
  bus.echo = false;
  auto radio = make_icom_radio(pair.radio_side(), patient(), kFast);
  radio->set_downlink_frequency(435'000'000);
  REQUIRE(eventually([&] { return radio->status().fault; }));
  CHECK(radio->status().message.find("interface not echoing") != std::string::npos);
  CHECK(radio->status().connected);
  CHECK_FALSE(radio->status().downlink_hz);
  bus.echo = true;   // the interface is plugged in
  REQUIRE(radio->wait_idle(5000ms));
  CHECK_FALSE(radio->status().fault);
  CHECK(radio->status().downlink_hz == 435'000'000);
}

TEST_CASE("Icom CI-V over a pty: a refused command (FA) is reported and dropped" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  IcomBus bus(pair.test_side());
  bus.refuse_modes = true;
  IcomOptions o;
  o.rx_address = 0x60;
  o.tx_address = 0x60;
  o.band_select = IcomBandSelect::main_tx_sub_rx;   // an IC-910 in satellite mode
  auto radio = make_icom_radio(pair.radio_side(), patient(o), kFast);
  radio->set_downlink_mode(Mode::fm);
  REQUIRE(radio->wait_idle(5000ms));
  CHECK(radio->status().fault);
  CHECK(radio->status().message.find("refused FE FE 60 E0 06 05 FD (NG)") != std::string::npos);
  radio->set_downlink_frequency(435'000'000);
  radio->set_uplink_frequency(145'900'000);
  REQUIRE(radio->wait_idle(5000ms));
  CHECK_FALSE(radio->status().fault);
  std::vector<std::string> hex;
  for (const auto& f : bus.frames()) hex.push_back(to_hex(f));
  REQUIRE(hex.size() == 6);
  CHECK(hex[0] == "FE FE 60 E0 07 D1 FD");   // sub band: the downlink
  CHECK(hex[1] == "FE FE 60 E0 06 05 FD");   // refused, not retried
  CHECK(hex[2] == "FE FE 60 E0 07 D1 FD");
  CHECK(hex[3] == "FE FE 60 E0 05 00 00 00 35 04 FD");
  CHECK(hex[4] == "FE FE 60 E0 07 D0 FD");   // main band: the uplink
  CHECK(hex[5] == "FE FE 60 E0 05 00 00 90 45 01 FD");
}

TEST_CASE("Kenwood over a pty: FA/FB and MD read back" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  PtyEnd peer(pair.test_side());
  REQUIRE(peer.ok());
  auto radio = make_kenwood_radio(pair.radio_side(), {}, kFast);
  radio->set_downlink_mode(Mode::usb);
  radio->set_uplink_mode(Mode::lsb);
  const std::vector<Hz> down{435'123'450, 435'123'000, 435'100'000};
  for (Hz hz : down) {
    radio->set_downlink_frequency(hz);
    REQUIRE(radio->wait_idle(5000ms));
  }
  radio->set_uplink_frequency(145'950'000);
  radio->send_raw("STX;");   // host mode S
  REQUIRE(radio->wait_idle(5000ms));
  CHECK_FALSE(radio->status().fault);

  std::string text;
  for (auto b = peer.read(4096, 500ms); !b.empty(); b = peer.read(4096, 200ms)) text.append(b.begin(), b.end());
  const auto cmds = kenwood::split_commands(text);
  const std::vector<std::string> expected{"FN0;", "MD2;", "FN1;", "MD1;", "FN0;",
                                          "FA00435123450;", "FA00435123000;", "FA00435100000;",
                                          "FB00145950000;", "STX;"};
  CHECK(cmds == expected);
  std::vector<Hz> decoded;
  for (const auto& c : cmds)
    if (auto f = kenwood::decode_frequency(c); f && f->vfo == kenwood::Vfo::a) decoded.push_back(f->hz);
  CHECK(decoded == down);
}

TEST_CASE("Yaesu FT-736 over a pty: CAT on, satellite mode, 5-byte commands, CAT off on close" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  PtyPair pair;
  REQUIRE(pair.ok());
  PtyEnd peer(pair.test_side());
  REQUIRE(peer.ok());
  YaesuOptions o;
  o.byte_gap = 3ms;
  o.wide_fm = true;
  auto radio = make_yaesu_radio(pair.radio_side(), o, kFast);
  radio->set_downlink_mode(Mode::fm);
  radio->set_uplink_mode(Mode::fm);
  const std::vector<Hz> down{435'123'450, 435'120'000, 1'296'123'450};
  const std::vector<Hz> up{145'950'000, 145'960'000};
  const auto t0 = std::chrono::steady_clock::now();
  for (Hz hz : down) {
    radio->set_downlink_frequency(hz);
    REQUIRE(radio->wait_idle(5000ms));
  }
  for (Hz hz : up) {
    radio->set_uplink_frequency(hz);
    REQUIRE(radio->wait_idle(5000ms));
  }
  // Bytes are spaced: 9 commands of 5 bytes took at least 45 gaps.
  CHECK(std::chrono::steady_clock::now() - t0 >= 45 * 3ms);
  CHECK_FALSE(radio->status().fault);
  radio.reset();   // closing sends CAT off

  std::vector<std::uint8_t> bytes;
  for (auto b = peer.read(4096, 500ms); !b.empty(); b = peer.read(4096, 200ms))
    bytes.insert(bytes.end(), b.begin(), b.end());
  REQUIRE(bytes.size() % 5 == 0);
  std::vector<yaesu::Decoded> cmds;
  std::vector<std::string> hex;
  for (std::size_t i = 0; i < bytes.size(); i += 5) {
    yaesu::Command c{bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3], bytes[i + 4]};
    cmds.push_back(yaesu::decode(c));
    hex.push_back(to_hex(c));
  }
  using K = yaesu::Decoded::Kind;
  REQUIRE(cmds.size() == 10);
  CHECK(cmds[0].kind == K::cat_on);
  CHECK(cmds[1].kind == K::sat_on);
  CHECK(hex[2] == "88 00 00 00 17");   // downlink FM through the wide filter (FM-N position)
  CHECK(hex[3] == "08 00 00 00 27");   // uplink FM
  CHECK(hex[4] == "43 51 23 45 1E");
  CHECK(cmds[5].hz == 435'120'000);
  CHECK(hex[6] == "C9 61 23 45 1E");
  CHECK(cmds[6].hz == 1'296'123'450);
  CHECK(hex[7] == "14 59 50 00 2E");
  CHECK(cmds[8].target == yaesu::Target::sat_tx);
  CHECK(cmds[8].hz == 145'960'000);
  CHECK(cmds[9].kind == K::cat_off);
}

TEST_CASE("Serial driver: the cable goes away, the driver reports it and reopens" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  std::string device;
  auto radio = kenwood_on_a_cable_that_goes(device, kFast);
  radio->set_downlink_frequency(435'000'010);
  // Under load this write may still reach the dying pty; the fault follows either way.
  REQUIRE(eventually([&] { const auto s = radio->status(); return s.fault && !s.connected; }));
  radio->set_downlink_frequency(435'000'020);  // the port is gone now for certain
  CHECK(eventually([&] { return radio->status().pending >= 1; }));  // kept, to be sent when it is back
  radio.reset();   // shutting down with the port gone is bounded
}

TEST_CASE("Serial driver: an idle port that goes away is reported without a command being sent" * doctest::skip(tb::testing::skip_without({"socat"}))) {
  tb::testing::require_tools({"socat"});
  const WorkerTiming timing{20ms, 100ms, 50ms};
  std::string device;
  auto radio = kenwood_on_a_cable_that_goes(device, timing);
  // Nothing more is sent: the idle check sees the hang-up (or the missing link) by itself.
  REQUIRE(eventually([&] { const auto s = radio->status(); return s.fault && !s.connected; }));
  CHECK(radio->status().message.find(device) != std::string::npos);
  CHECK(radio->status().pending == 0);
  radio.reset();  // shutting down while it retries is bounded
}
