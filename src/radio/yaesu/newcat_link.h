// The Yaesu ASCII CAT link (run by a WorkerRadio, see worker.h) of the FT-991/991A, FTX-1, FT-710
// and FTdx10: 8N2, one link per radio. The downlink radio tunes VFO-A (FA, MD0); the uplink radio
// of a pair (--uplink-radio) VFO-B (FB), the VFO these radios retune while the mic is keyed
// (OscarWatch #23: on the FT-991A "only the B VFO allows for realtime CAT frequency control"). The
// radio's ID is asked once per connect and a different one said. make_newcat_radio() wraps it.
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
#include "radio/yaesu/newcat.h"

namespace tb::radio {

struct NewcatOptions {
  std::string label = "FT-991A";       // in messages
  std::vector<std::string> ids;        // the ID; answers it may give ("0570", "0670"); empty: not checked
  bool vfo_b = false;                  // the uplink radio of two: its link on VFO-B
  // VFO-B's mode: MD1 (the FTX-1's Sub), or, where MD reaches VFO-A only (FT-991, FT-710, FTdx10),
  // set on VFO-A and copied over with AB, VFO-B's frequency then sent again.
  bool mode_md1 = false;
  bool fm_dial_lock = false;           // FT-991: LK1 while its link is in FM, LK0 otherwise and at close
  bool ctcss = false;                  // FT-991: CN00nnn;CT02; (copied to VFO-B with AB)
  std::vector<HzRange> bands;          // outside: a band it lacks, learnt once
  std::chrono::milliseconds reply_timeout{500};
  int baud = 0;                        // 0: 4800
};

class NewcatLink final : public RadioLink {
 public:
  NewcatLink(std::string device, NewcatOptions options, SerialSettings serial);
  std::string describe() const override;
  void open() override;
  void close() noexcept override;      // the dial lock off when trakbox put it on
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  void check() override { port_.check(); }
  bool can_read(Link l) const override { return l == Link::downlink; }
  Hz read_frequency(Link link) override;
  void set_ctcss_tone(int tenths_hz) override;
  bool answered_again() override { return std::exchange(woke_, false); }

 private:
  newcat::Vfo vfo() const { return opt_.vfo_b ? newcat::Vfo::b : newcat::Vfo::a; }
  void require(Link l) const;          // one link: the other is a limit ("no uplink")
  void identify();                     // ID; once per connect (and after a silence)
  void send(const std::string& command);
  // Sends `command` and returns the answer starting with `prefix`, or "?;"; nullopt on silence.
  std::optional<std::string> query(const std::string& command, std::string_view prefix);
  void copy_to_b();                    // AB; and VFO-B's frequency again

  SerialPort port_;
  NewcatOptions opt_;
  bool identified_ = false;
  bool id_warned_ = false;
  bool locked_ = false;                // LK1 sent
  bool silent_ = false;
  bool woke_ = false;
  std::optional<Hz> hz_;               // the link's frequency last sent
};

std::unique_ptr<RadioDriver> make_newcat_radio(const std::string& device, const NewcatOptions& o, WorkerTiming t = {});

}  // namespace tb::radio
