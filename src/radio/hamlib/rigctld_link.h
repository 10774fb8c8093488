// One radio behind a rigctld daemon (--radio rigctld:HOST:PORT, the Gpredict-style set-up), spoken
// to in rigctld's own line protocol over TCP rather than through Hamlib's NET rigctl backend, so
// that every command, every reply and every error code is trakbox's to read:
//   - each link is read back (`f` and `i`, or `f VFO` per VFO), so dial follow works with one radio;
//   - a refused tone, mode or satellite-mode command is reported and dropped: Doppler goes on; only a
//     broken connection (closed, no reply in time, a reply that is not rigctld's) reconnects;
//   - where the links land is checked, not assumed (a radio that puts the split frequency on the
//     receive VFO would otherwise carry both links on VFO A without a word).
//
// Which VFO carries which link, chosen at open from what the daemon reports:
//   rigctld --vfo (`\chk_vfo` answers 1) and Main and Sub in `\get_vfo_list`: downlink on Sub, uplink
//     on Main (`F Sub hz`, `F Main hz`), as the IC-910H and IC-9700 run in satellite mode; when the
//     radio has satellite mode (`u Main SATMODE` answers), it is switched on first (`U Main SATMODE 1`).
//   rigctld --vfo without Main/Sub: downlink on VFOA, uplink on VFOB with split on (`S VFOA 1 VFOB`).
//   rigctld without --vfo: split on the current VFO, as Gpredict does: `S 1 VFOB`, downlink `F`/`f`,
//     uplink `I`/`i`. After the first uplink the radio is read back: split off, or the downlink
//     VFO now holding the uplink, means the radio cannot carry the two links this way; the uplink
//     is then refused (reported once) instead of being sent onto the downlink's VFO.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "radio/hamlib/hamlib_radio.h"
#include "radio/worker.h"

namespace tb::radio {

// What the program at the other end is: rigctld itself, or a receiver that speaks a part of its
// protocol (GQRX's remote control, SDR++'s rigctl server: --radio gqrx / sdrpp). A receiver gets
// plain one-letter commands without a VFO (no `\chk_vfo` hand-shake: its answer is the first `f`),
// carries no uplink and no tone (each said once as a limit, never a fault), and may keep one
// client: GQRX closes the first connection when a second arrives, SDR++ serves the next only
// after the first ends. Its answers to refusals are positive (`RPRT 1`), a refusal all the same.
struct RigctldPeer {
  std::string name = "rigctld";   // "GQRX", "SDR++": the log's and the status's word for it
  bool receiver = false;          // one link (the downlink), no tone, no split, no hand-shake
  bool one_client = false;        // another program's connection takes the peer from trakbox
  // Its recorder (--record): AOS/LOS start and stop the audio recorder (GQRX, SDR++); GQRX reads it
  // back (`u RECORD`), says at `u ?` what `u` reads (RECORD IQRECORD DSP ...) and, when IQRECORD is
  // among them, records IQ (`U IQRECORD 1|0`).
  bool audio_recorder = false;
  bool iq_recorder = false;       // when the probe finds it
  bool reads_recorder = false;    // `u ?` / `u RECORD` answered (GQRX); SDR++ answers only RPRT
};

class RigctldLink final : public RadioLink {
 public:
  // host:port as --radio rigctld:HOST:PORT gives it (the last ':' separates the port).
  RigctldLink(std::string address, HamlibVfoScheme scheme, RigctldPeer peer = {},
              std::chrono::milliseconds timeout = std::chrono::milliseconds(1500));
  std::string name() const override { return peer_.name; }
  ~RigctldLink() override;
  std::string describe() const override;
  void open() override;
  void close() noexcept override;
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;   // one rigctld command line; the reply is read
  bool can_read(Link l) const override;
  Hz read_frequency(Link link) override;
  void set_ctcss_tone(int tenths_hz) override;
  void check() override;
  std::string records() const override;
  Recording record(Record what) override;

  // How the links are carried once open.
  enum class Carry { split, vfo_ab, main_sub };
  Carry carry() const { return carry_; }
  bool satellite_mode() const { return satmode_on_; }

 private:
  // One command, its reply: `lines` value lines, or an `RPRT n` line. Returns the value lines (none
  // for a set command answered RPRT 0). A negative RPRT throws a LinkError built by `refused`; a
  // transport failure throws LinkError(reconnect).
  struct Reply {
    std::vector<std::string> lines;
    int rprt = 0;   // 0, or the daemon's negative error code
  };
  Reply ask(const std::string& command, int lines);
  void write_all(const std::string& text);
  std::string read_line();
  [[noreturn]] void transport(const std::string& what);
  // An RPRT error for a command: frequency commands are retried (the radio may answer next time)
  // unless Hamlib calls the code a soft one (the radio or backend refused the value); everything
  // else (tone, mode, satellite mode, split) is reported and dropped.
  // `lacking` names the feature a refusal shows the radio lacks ("no CTCSS", "no mode CW"): a
  // capability learnt (LinkError::Action::lacks) rather than a refused command.
  [[noreturn]] void refused(const std::string& what, int rprt, bool frequency, const std::string& lacking = {});
  [[noreturn]] void no_uplink_of_receiver() const;
  std::string vfo_arg(Link l) const;     // "Sub " / "Main " / "VFOA " ... in --vfo mode, else ""
  void ensure_split();
  void verify_split(Hz uplink_hz);

  void open_receiver();
  void probe_recorder();                        // GQRX: `u ?` names what `u` reads
  // GQRX: `u NAME` read as 0 / 1 (nothing when it is not among what `u ?` listed, or refused).
  std::optional<bool> read_function(const char* name);
  Recording start_recording(Record what);
  Recording stop_recording();
  // The peer closed an established connection: a one-client peer taken by another program.
  [[noreturn]] void taken();

  RigctldPeer peer_;
  bool answered_ = false;                       // this connection has had a valid reply
  int takeovers_ = 0;                           // knocked off in a row (one-client peer)
  std::chrono::steady_clock::time_point opened_at_{};
  std::string address_, host_;
  int port_ = 0;
  HamlibVfoScheme scheme_;
  std::chrono::milliseconds timeout_;
  int fd_ = -1;
  std::string inbuf_;
  bool vfo_mode_ = false;
  Carry carry_ = Carry::split;
  bool satmode_on_ = false;
  bool split_on_ = false;
  bool split_verified_ = false;
  std::optional<std::string> uplink_refused_;   // why the uplink cannot be carried
  std::optional<Hz> last_down_;                 // the downlink frequency last set
  bool announced_ = false;                      // the carry chosen was logged (first open)
  std::vector<std::string> functions_;          // what GQRX's `u ?` listed at open
  Record started_ = Record::off;                // the recorder trakbox started (stopped at LOS)
};

}  // namespace tb::radio
