// A FlexRadio 6000/8000 over the SmartSDR TCP/IP API (--radio flex:HOST[:PORT][:duplex], port 4992),
// run by a WorkerRadio (worker.h). Slices are the links: the downlink on a receive slice, the
// uplink on the slice marked for transmit (`tx=1`).
//
// At connect: the radio's `V...` and `H...` lines, `sub slice all` (the status of every slice from
// then on) and `slice list`. The slices found are taken (the one marked tx=1 for the uplink, the
// first other one for the downlink); a link without one gets its own at its first frequency
// (`slice create freq=... mode=...`, the reply's data is its index), the uplink's then `tx=1`.
// With `:duplex` (a radio with two SCUs: FLEX-6600/6700/8600) full duplex is switched on at
// connect (`radio set full_duplex_enabled=1`), so the downlink is heard while transmitting.
//
// Each command waits for its `R<seq>|...` reply. A non-zero status is the radio refusing that
// command, never a lost link: a refused frequency is a band the radio lacks (no transverter for
// it: `no 70 cm`, learnt once; that band is not sent again on that link and not read back), a
// refused mode `no mode X`, a refused tx `no uplink`, a refused tone `no CTCSS`
// (LinkError::Action::lacks). Only a closed connection, a reply that does not come or a line that
// is not the API's reconnects.
//
// Read-back (dial follow): the slices' `S...|slice N RF_frequency=...` status lines (the operator
// turning the knob in SmartSDR or on a Maestro); a read sends `ping` and takes the status the
// radio sent before its reply, so the frequency read is the slice's at that moment.
#pragma once
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radio/flex/codec.h"
#include "radio/registry.h"
#include "radio/worker.h"

namespace tb::radio {

struct FlexOptions {
  std::string host = "127.0.0.1";
  int port = 4992;
  RadioRole role = RadioRole::both;   // one of two radios: its one link is the station's downlink or uplink
  bool full_duplex = false;           // :duplex: radio set full_duplex_enabled=1 at connect (both links)
  std::chrono::milliseconds timeout{1500};
};

class FlexLink final : public RadioLink {
 public:
  explicit FlexLink(FlexOptions options);
  ~FlexLink() override;
  std::string describe() const override;
  std::string name() const override { return "FlexRadio"; }
  void open() override;
  void close() noexcept override;
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& text) override;   // one API command (without C<seq>|); its reply read
  bool can_read(Link link) const override;
  Hz read_frequency(Link link) override;
  void set_ctcss_tone(int tenths_hz) override;
  void check() override;

 private:
  // The station's link a call of the worker is about (one of two radios: its one link).
  Link station(Link l) const;
  struct Leg {
    std::optional<int> slice;          // the slice carrying it
    Mode mode = Mode::none;            // the mode last asked (sent at the slice's creation)
    bool tx_set = false;               // the uplink slice marked tx=1 on this connection
    std::optional<std::string> lacks;  // the band refused ("70 cm"): not sent again, not read
  };
  Leg& leg(Link station_link) { return legs_[link_index(station_link)]; }
  const Leg& leg(Link station_link) const { return legs_[link_index(station_link)]; }

  flex::Reply ask(const std::string& body);   // a command and its reply (status lines taken meanwhile)
  void write_all(const std::string& text);
  std::string read_line();
  bool line_waiting(int wait_ms);             // a line is (or becomes) readable within wait_ms
  void take(const std::string& line);         // a status line (or anything else the radio says)
  void greeting();
  void find_slices();
  void ensure_slice(Link l, Hz hz);
  void ensure_tx(Link l);
  [[noreturn]] void transport(const std::string& what);
  [[noreturn]] void refused(const std::string& what, const flex::Reply& r, const std::string& lacking);
  // A frequency refused: the band is a limit of this link ("no 70 cm"), not sent again.
  [[noreturn]] void band_refused(Link s, Hz hz, const std::string& cmd, const flex::Reply& r);

  FlexOptions opt_;
  int fd_ = -1;
  std::string inbuf_;
  std::uint32_t seq_ = 0;
  std::uint32_t handle_ = 0;
  std::string version_;
  Leg legs_[2];
  std::map<int, Hz> slice_hz_;        // each slice's frequency as its status says
  std::map<int, bool> slice_tx_;      // ... and its tx flag
  int tone_ = 0;                      // the uplink's CTCSS tone (tenths of Hz), 0 off
  bool tone_pending_ = false;         // ... asked before the uplink had its slice
  bool announced_ = false;
  bool duplex_warned_ = false;
};

std::unique_ptr<RadioDriver> make_flex_radio(const FlexOptions& options, WorkerTiming timing = {});

}  // namespace tb::radio
