// Hamlib radios: any of Hamlib's backends on a serial device (--radio hamlib:MODEL:DEVICE[:BAUD]).
// A rigctld daemon (--radio rigctld:HOST:PORT, model 2) gets make_hamlib_radio's RigctldLink
// (rigctld_link.h), which speaks rigctld's protocol itself. Hamlib calls block, so the link runs on
// a WorkerRadio's thread: faults are reported in status() and the link reconnects with backoff.
//
// Which VFO carries which link on a dual-band radio:
//   split    downlink on the current (RX) VFO with set_freq / set_mode, uplink on VFO B as the split
//            TX VFO (set_split_vfo ON VFOB, set_split_freq / set_split_mode).
//   main_sub downlink on the Sub band, uplink on Main (set_freq on RIG_VFO_SUB / RIG_VFO_MAIN), as
//            the IC-820H/821H/910H, IC-9700 and TS-2000 run in satellite mode. Where the backend has
//            RIG_FUNC_SATMODE it is switched on at open, before the first frequency; both bands are
//            read back (rig_get_freq on Sub and Main).
//   automatic: main_sub when the opened backend lists both Main and Sub VFOs, split otherwise (said
//            once in the log).
// A refused (or unanswered) tone, mode or satellite-mode command is reported and dropped; Doppler
// goes on. Only an I/O error reconnects.
#pragma once
#include <memory>
#include <string>

#include "radio/worker.h"

namespace tb::radio {

enum class HamlibVfoScheme { automatic, split, main_sub };

struct HamlibOptions {
  int model = 1;                 // Hamlib rig model number (1 dummy, 2 NET rigctl, 3073 IC-910 ...)
  std::string path;              // serial device, or HOST:PORT for model 2
  int baud = 0;                  // 0: the backend's default
  HamlibVfoScheme scheme = HamlibVfoScheme::automatic;
  // With Main/Sub: the link on Main (the other on Sub). HamlibLink's constructor takes it from the
  // radio registry's entry for `model` when there is one, so both paths put a model's links alike.
  Link main_link = Link::uplink;
};

class HamlibLink final : public RadioLink {
 public:
  explicit HamlibLink(HamlibOptions options);
  ~HamlibLink() override;
  std::string describe() const override;
  void open() override;
  void close() noexcept override;
  void set_frequency(Link link, Hz hz) override;
  void set_mode(Link link, Mode mode) override;
  void send_raw(const std::string& bytes) override;
  // Read back with get_freq (get_split_freq for the split uplink), Hamlib's cache off so the value
  // is the radio's, not the last one trakbox set.
  // Main/Sub and a radio not in split read back truly. One radio in split does not: with the
  // cache off, Hamlib's dummy (4.5) answers get_freq with the transmit VFO and rigctld's VFO A,
  // so dial follow there would mistake trakbox's own uplink for a turn of the downlink dial; its
  // dial is not read (the display says so), as before dial follow. Two radios never use split.
  bool can_read(Link) const override { return scheme_ == HamlibVfoScheme::main_sub || !split_on_; }
  Hz read_frequency(Link link) override;
  void set_ctcss_tone(int tenths_hz) override;   // set_ctcss_tone on the uplink's VFO
  // The port's descriptor hung up (a serial adapter unplugged) or the peer closed the connection
  // (rigctld gone): no traffic, so it may run often.
  void check() override;

  // The scheme in use once open (automatic resolved), and whether satellite mode was switched on.
  HamlibVfoScheme scheme() const { return scheme_; }
  bool satellite_mode() const { return satmode_on_; }

 private:
  void require(int rc, const std::string& what);
  void require_aux(int rc, const std::string& what);
  void ensure_split();
  struct Impl;
  HamlibOptions opt_;
  HamlibVfoScheme scheme_ = HamlibVfoScheme::split;
  bool split_on_ = false;
  bool satmode_on_ = false;
  bool announced_ = false;   // the VFO scheme was logged (first open)
  std::unique_ptr<Impl> impl_;
};

std::unique_ptr<RadioDriver> make_hamlib_radio(const HamlibOptions& options, WorkerTiming timing = {});

// Hamlib's name for a model ("Hamlib Dummy", "NET rigctl", ...); empty when unknown.
std::string hamlib_model_name(int model);

// Shared by the Hamlib and rigctld links: Hamlib's text for an error code (its first line; rigctld's
// RPRT codes are Hamlib's, negated), and SIGPIPE blocked on the calling (worker) thread.
std::string hamlib_error_text(int rc);


}  // namespace tb::radio
