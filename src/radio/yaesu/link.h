// The Yaesu CAT links (run by a WorkerRadio, see worker.h): 4800 bps 8N2 by default; 5-byte commands
// sent a byte at a time with a pause between. YaesuLink: the FT-736 (menu 6-7); Ft8xxLink: the
// FT-847 and FT-817/818. make_yaesu_radio() and make_ft8xx_radio() wrap them in a WorkerRadio.
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
#include "radio/yaesu/codec.h"

namespace tb::radio {

using std::chrono::milliseconds;

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

// Yaesu FT-847 (one radio, both links in its satellite mode) and FT-817/818/857/897 (one link each,
// the FT-817's commands).
struct Ft8xxOptions {
  enum class Model { ft847, ft817 } model = Model::ft847;
  std::string label = "FT-847";     // "FT-817", "FT-818" in messages
  milliseconds byte_gap{50};        // between bytes (Hamlib's FT-847 write delay is 50 ms)
  milliseconds reply_timeout{500};  // a read's 5-byte answer
  bool satellite_mode = true;       // FT-847 with both links: satellite mode, RX / TX VFOs
  int baud = 0;                     // 0: 4800
  std::vector<HzRange> bands;       // the bands it tunes (empty: not checked); outside: a limit learnt
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
  // A byte at a time, byte_gap after each; after a read command's last byte the reply is waited for
  // instead (the radio has taken the command when it answers).
  void send(std::span<const std::uint8_t> bytes, bool gap_after_last = true);
  SerialPort port_;
  Ft8xxOptions opt_;
  bool satellite_on_ = false;
  bool cat_on_ = false;            // FT-847: CAT on sent since open or since the radio last fell silent
  bool silent_ = false;            // a read got nothing at all
  bool woke_ = false;              // ... and a later one an answer (for answered_again)
};

std::unique_ptr<RadioDriver> make_yaesu_radio(const std::string& device, const YaesuOptions& o = {},
                                              WorkerTiming t = {});
std::unique_ptr<RadioDriver> make_ft8xx_radio(const std::string& device, const Ft8xxOptions& o, WorkerTiming t = {});

}  // namespace tb::radio
