// The Kenwood CAT link (run by a WorkerRadio, see worker.h): 4800 bps 8N2 by default; TS-790/711/811
// ASCII commands, and the TS-2000's satellite mode, read-back and tone. make_kenwood_radio() wraps it
// in a WorkerRadio.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "radio/serial.h"
#include "radio/worker.h"
#include "radio/kenwood/codec.h"

namespace tb::radio {

using std::chrono::milliseconds;

struct KenwoodOptions {
  // Downlink on VFO A (FA), uplink on VFO B (FB). Outside satellite mode a mode is set on its VFO
  // with the VFO select (FN on the TS-790 family, FR on the TS-2000), which then selects VFO A again.
  milliseconds command_gap{0};    // pause after each command
  int baud = 0;                   // the port's speed; 0: the standard 4800 (kenwood_serial)
  bool reads = false;             // read back with FA; / FB; (TS-2000)
  milliseconds reply_timeout{500};
  std::string model = "Kenwood radio";  // in messages ("the Kenwood radio has ...")
  std::string label = "Kenwood";        // in describe(): "Kenwood CAT on /dev/ttyUSB0" (the registry row's)
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

std::unique_ptr<RadioDriver> make_kenwood_radio(const std::string& device, const KenwoodOptions& o = {},
                                                WorkerTiming t = {});

}  // namespace tb::radio
