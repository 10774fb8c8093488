// The serial CAT links of menu 6-7 (run by a WorkerRadio, see worker.h):
//   Icom CI-V      1200 bps 8N2; reads back its own echo from the one-wire bus
//   Kenwood        4800 bps 8N2; TS-790/711/811 ASCII commands
//   Yaesu FT-736   4800 bps 8N2; 5-byte commands sent a byte at a time with a pause between
// make_icom_radio() and friends wrap them in a WorkerRadio.
#pragma once
#include <chrono>
#include <memory>
#include <string>

#include "radio/cat.h"
#include "radio/serial.h"
#include "radio/worker.h"

namespace tb::radio {

using std::chrono::milliseconds;

struct IcomOptions {
  std::uint8_t rx_address = icom::kBroadcast;   // downlink radio
  std::uint8_t tx_address = icom::kBroadcast;   // uplink radio
  IcomBandSelect band_select = IcomBandSelect::none;
  icom::FrequencyWidth width = icom::FrequencyWidth::five_bytes;
  // Echo: the frame's time on the wire plus this. No echo at all: "interface not echoing".
  milliseconds echo_margin{250};
  // A radio addressed directly (not 00) answers FB / FA; wait this long for it.
  milliseconds reply_timeout{300};
  bool expect_reply = true;      // (never for the broadcast address 00)
  int max_attempts = 4;          // collisions: tries before giving up
  milliseconds collision_wait{60};   // times the attempt number
  int baud = 0;                  // the port's speed; 0: CI-V's standard 1200 (icom_serial)
  static IcomOptions from(const RadioConfig& c);
};

class IcomLink final : public RadioLink {
 public:
  IcomLink(std::string device, IcomOptions options = {}, SerialSettings serial = icom_serial());
  std::string describe() const override;
  void open() override;
  void close() noexcept override;
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }

  // One CI-V transaction: write, read the echo back (collision: wait and retry), then the reply
  // when the radio is addressed directly. Throws LinkError.
  void transact(const Bytes& frame, bool wait_reply);

 private:
  std::optional<Bytes> read_frame(milliseconds timeout, bool& got_any);
  std::uint8_t address(Link l) const { return l == Link::downlink ? opt_.rx_address : opt_.tx_address; }
  void select_band(Link l);

  SerialPort port_;
  IcomOptions opt_;
  icom::FrameReader reader_;
};

struct KenwoodOptions {
  // Downlink on VFO A (FA), uplink on VFO B (FB). A mode is set on its VFO with FN, then FN0
  // selects the receive VFO again.
  milliseconds command_gap{0};    // pause after each command
  int baud = 0;                   // the port's speed; 0: the standard 4800 (kenwood_serial)
  static KenwoodOptions from(const RadioConfig& c) {
    KenwoodOptions o;
    o.baud = c.cat_baud;
    return o;
  }
};

class KenwoodLink final : public RadioLink {
 public:
  KenwoodLink(std::string device, KenwoodOptions options = {}, SerialSettings serial = kenwood_serial());
  std::string describe() const override;
  void open() override;
  void close() noexcept override;
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }

 private:
  void send(const std::string& command);
  SerialPort port_;
  KenwoodOptions opt_;
};

struct YaesuOptions {
  milliseconds byte_gap{50};      // between the bytes of a command (and after each command)
  bool satellite_mode = true;     // full duplex: downlink = satellite RX, uplink = satellite TX
  bool wide_fm = false;           // menu 6-7: FM filter changed for a wider one -> downlink FM-N (88)
  int baud = 0;                   // the port's speed; 0: the standard 4800 (yaesu_serial)
  static YaesuOptions from(const RadioConfig& c);
};

class YaesuLink final : public RadioLink {
 public:
  YaesuLink(std::string device, YaesuOptions options = {}, SerialSettings serial = yaesu_serial());
  std::string describe() const override;
  void open() override;            // CAT on, satellite mode on
  void close() noexcept override;  // CAT off
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }

 private:
  void send(std::span<const std::uint8_t> bytes);
  yaesu::Target target(Link l) const;
  SerialPort port_;
  YaesuOptions opt_;
};

std::unique_ptr<RadioDriver> make_icom_radio(const std::string& device, const IcomOptions& o = {},
                                             WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_kenwood_radio(const std::string& device, const KenwoodOptions& o = {},
                                                WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_yaesu_radio(const std::string& device, const YaesuOptions& o = {},
                                              WorkerTiming t = {});

}  // namespace tb::radio
