// The serial CAT links of menu 6-7 (run by a WorkerRadio, see worker.h):
//   Icom CI-V      1200 bps 8N2; reads back its own echo from the one-wire bus
//   Kenwood        4800 bps 8N2; TS-790/711/811 ASCII commands
//   Yaesu FT-736   4800 bps 8N2; 5-byte commands sent a byte at a time with a pause between
// make_icom_radio() and friends wrap them in a WorkerRadio.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>

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
  // The radios of 2026 (IC-9700, IC-9100, IC-910H; radio/registry.h). One radio carries both links
  // in its satellite mode: satellite_cmd/sub (16 5A, or 1A 07 on the IC-910H) switched on before the
  // first frequency, off at close; each link on its band (main_link on Main, the other on Sub),
  // a band selected only when it changes. 0: no satellite mode.
  std::uint8_t satellite_cmd = 0, satellite_sub = 0;
  Link main_link = Link::uplink;
  bool reads = false;            // 03 after the band select reads a link's frequency (dial follow)
  // 1C 03 reads the transmit frequency in satellite mode without a band select (IC-9700): the
  // uplink is read so, and no select goes back and forth between the two reads of a tick.
  bool reads_tx_1c03 = false;
  bool ctcss = false;            // 1B 00 tone and 16 42 TONE on the uplink's band
  std::string model;             // "IC-9700" in messages ("" for the family form)
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
  bool can_read(Link l) const override { return opt_.reads && address(l) != icom::kBroadcast; }
  Hz read_frequency(Link link) override;
  void set_ctcss_tone(int tenths_hz) override;
  bool answered_again() override { return std::exchange(woke_, false); }

  // One CI-V transaction: write, read the echo back (collision: wait and retry), then the reply
  // when the radio is addressed directly. Throws LinkError.
  void transact(const Bytes& frame, bool wait_reply);
  // Whether the interface echoes the controller's frames: found on the first exchange after each
  // open (the echo comes back, or the radio's answer comes first); nullopt until then.
  std::optional<bool> echo() const { return echo_; }

 private:
  enum class Expect { nothing, ack, data };
  // The transaction; for Expect::data the radio's answer with the same command.
  std::optional<icom::Frame> exchange(const Bytes& frame, Expect expect);
  std::optional<Bytes> read_frame(milliseconds timeout, bool& got_any);
  std::uint8_t address(Link l) const { return l == Link::downlink ? opt_.rx_address : opt_.tx_address; }
  bool expects_reply(std::uint8_t to) const { return opt_.expect_reply && to != icom::kBroadcast; }
  void select_band(Link l);
  void ensure_satellite_mode();
  void radio_silent();
  std::string who(std::uint8_t to) const;

  SerialPort port_;
  IcomOptions opt_;
  icom::FrameReader reader_;
  std::optional<bool> echo_;
  std::optional<icom::Band> selected_;   // the band last selected (unknown after open or a failure)
  // Faults stay local: each is asked once per connect (and again after the radio fell silent),
  // reported once, and the tuning goes on without it.
  bool satellite_asked_ = false;         // satellite mode asked since open
  bool satellite_on_ = false;            // ... and confirmed with FB
  bool satellite_warned_ = false;        // "not confirmed" said (kept over connects: said once)
  bool band_refused_ = false;            // 07 D0/D1 not acknowledged: not sent again until a connect
  bool tx_read_refused_ = false;         // 1C 03 refused: the uplink read on its band instead
  bool silent_ = false;                  // the last exchange got no answer at all (none since)
  bool woke_ = false;                    // ... and then it answered (for answered_again)
};

struct KenwoodOptions {
  // Downlink on VFO A (FA), uplink on VFO B (FB). Outside satellite mode a mode is set on its VFO
  // with the VFO select (FN on the TS-790 family, FR on the TS-2000), which then selects VFO A again.
  milliseconds command_gap{0};    // pause after each command
  int baud = 0;                   // the port's speed; 0: the standard 4800 (kenwood_serial)
  bool reads = false;             // read back with FA; / FB; (TS-2000)
  milliseconds reply_timeout{500};
  std::string model = "Kenwood radio";  // in messages ("the Kenwood radio has ...")
  char vfo_select = 'N';          // FN0; / FN1; (TS-790/711/811); 'R': FR0; / FR1; (TS-2000)
  bool one_link = false;          // one of two radios: its one link on VFO A, whichever it is
  // The TS-2000's satellite mode (kenwood::Satellite): SA read, set before the first frequency
  // (VFO A first when FR; answers a memory), confirmed with SA; after `satellite_settle` (the radio
  // takes about 250 ms: OscarWatch-Tracker PR #10) up to `satellite_confirm_tries` times, and put
  // back as found at close. MD, TN and TO reach the uplink (Sub) with CTRL on Sub for the while.
  bool satellite_mode = false;
  milliseconds satellite_settle{250};
  int satellite_confirm_tries = 3;
  milliseconds satellite_confirm_gap{200};
  bool ctcss = false;             // TN / TO on the uplink (TS-2000)
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
  void close() noexcept override;   // the TS-2000: its tone off and SA as found
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }
  // FA; / FB; answer FA00435123450; (menu 6-7's TS-790 family does not read: reads off).
  bool can_read(Link) const override { return opt_.reads; }
  bool answered_again() override { return std::exchange(woke_, false); }
  Hz read_frequency(Link link) override;
  // The TS-2000: TN and TO on the uplink, confirmed with TO; (a refusal is reported, Doppler goes
  // on); the families of menu 6-7: refused with a message, no encoder trakbox sets.
  void set_ctcss_tone(int tenths_hz) override;

 private:
  void send(const std::string& command);
  // Sends a read and returns the answer starting with `prefix`, or a refusal (?; E; O;), whichever
  // comes first; nullopt when nothing came in reply_timeout. Other answers (Auto Information) are
  // passed over; what came before is thrown away first unless `discard` is false.
  std::optional<std::string> query(const std::string& command, std::string_view prefix, bool discard = true);
  kenwood::Vfo vfo_of(Link l) const { return l == Link::uplink && !opt_.one_link ? kenwood::Vfo::b : kenwood::Vfo::a; }
  void ensure_satellite_mode();
  // Runs `what` on the uplink's band: with CTRL on Sub (satellite mode) or VFO B selected, and CTRL
  // / VFO A back after, also when `what` throws; on a one-link radio as it is.
  template <class F> void on_uplink_band(F&& what);

  SerialPort port_;
  KenwoodOptions opt_;
  bool satellite_asked_ = false;             // once per open: a radio that refuses is not asked again
  bool satellite_on_ = false;                // confirmed on
  bool satellite_warned_ = false;            // "not switched on" said (once, over connects)
  bool silent_ = false;                      // the last read got no answer (switched off?)
  bool woke_ = false;                        // ... and then it answered (for answered_again)
  std::optional<kenwood::Satellite> found_;  // SA as found at the first ask (put back at close)
  bool tone_on_ = false;                     // TO1 sent since open
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
  void set_ctcss_tone(int tenths_hz) override;   // refused with a message: no encoder trakbox sets
  void check() override { port_.check(); }

 private:
  void send(std::span<const std::uint8_t> bytes);
  yaesu::Target target(Link l) const;
  SerialPort port_;
  YaesuOptions opt_;
};

// Yaesu FT-847 (one radio, both links in its satellite mode) and FT-817/818 (one link each).
struct Ft8xxOptions {
  enum class Model { ft847, ft817 } model = Model::ft847;
  std::string label = "FT-847";     // "FT-817", "FT-818" in messages
  milliseconds byte_gap{50};        // between bytes (Hamlib's FT-847 write delay is 50 ms)
  milliseconds reply_timeout{500};  // a read's 5-byte answer
  bool satellite_mode = true;       // FT-847 with both links: satellite mode, RX / TX VFOs
  int baud = 0;                     // 0: 4800
};

class Ft8xxLink final : public RadioLink {
 public:
  Ft8xxLink(std::string device, Ft8xxOptions options, SerialSettings serial);
  std::string describe() const override;
  void open() override;            // FT-847: CAT on
  void close() noexcept override;  // FT-847: satellite mode off (when it was on), CAT off
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }
  bool can_read(Link l) const override { return carries(l); }
  Hz read_frequency(Link link) override;
  bool answered_again() override { return std::exchange(woke_, false); }
  void set_ctcss_tone(int tenths_hz) override;

 private:
  bool carries(Link l) const;
  yaesu::Target target(Link l) const;
  void require(Link l) const;      // throws drop for a link this radio does not carry
  void ensure_satellite_mode();
  void send(std::span<const std::uint8_t> bytes);   // a byte at a time, byte_gap after each
  SerialPort port_;
  Ft8xxOptions opt_;
  bool satellite_on_ = false;
  bool cat_on_ = false;            // FT-847: CAT on sent since open or since the radio last fell silent
  bool silent_ = false;            // a read got nothing at all
  bool woke_ = false;              // ... and a later one an answer (for answered_again)
};

std::unique_ptr<RadioDriver> make_icom_radio(const std::string& device, const IcomOptions& o = {},
                                             WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_kenwood_radio(const std::string& device, const KenwoodOptions& o = {},
                                                WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_yaesu_radio(const std::string& device, const YaesuOptions& o = {},
                                              WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_ft8xx_radio(const std::string& device, const Ft8xxOptions& o, WorkerTiming t = {});

}  // namespace tb::radio
