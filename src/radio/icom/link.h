// The Icom CI-V link (run by a WorkerRadio, see worker.h): 1200 bps 8N2 by default; on a one-wire
// bus it reads back its own echo. make_icom_radio() wraps it in a WorkerRadio.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "radio/registry.h"
#include "radio/serial.h"
#include "radio/worker.h"
#include "radio/icom/codec.h"

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
  // The bands the radio tunes (empty: not checked): a frequency outside them is a band it lacks,
  // learnt once (LinkError::Action::lacks), as is the IC-905's 10 GHz band (from xvtr_from) when
  // its transverter is not fitted or the radio refuses it.
  std::vector<HzRange> bands;
  Hz xvtr_from = 0;
  bool transverter = false;
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
  void require_band(Link l, Hz hz);   // throws LinkError(lacks) for a band the radio lacks
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
  bool vfo_ab_ = false;                  // 07 D0/D1 refused or not followed: VFO A/B (07 00/01) instead
  bool band_refused_ = false;            // ... and VFO A/B refused too: no select until a connect
  std::optional<Hz> set_hz_[2];          // the frequency each link was last set to (acknowledged)
  bool off_band_[2] = {false, false};    // each link's last frequency was on a band it lacks (not read)
  bool xvtr_refused_ = false;            // the IC-905 refused its 10 GHz band (FA): not sent until a connect
  bool tx_read_refused_ = false;         // 1C 03 refused: the uplink read on its band instead
  bool silent_ = false;                  // the last exchange got no answer at all (none since)
  bool woke_ = false;                    // ... and then it answered (for answered_again)
};

std::unique_ptr<RadioDriver> make_icom_radio(const std::string& device, const IcomOptions& o = {},
                                             WorkerTiming t = {});

}  // namespace tb::radio
