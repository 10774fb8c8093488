// The rigctld protocol (Hamlib's TCP radio daemon, port 4532 by convention) answered by trakbox's
// radio, so that Gpredict and every Hamlib client (rigctl -m 2) can tune it.
//
// VFO mapping: VFO A / Main / RX is trakbox's downlink; VFO B / Sub / TX (the split TX VFO) is the
// uplink.
//
//   F hz / \set_freq            the current VFO's link        f / \get_freq
//   M mode passband / \set_mode the current VFO's link        m / \get_mode
//   V vfo / \set_vfo            VFOA, VFOB, Main, Sub, ...    v / \get_vfo
//   S split txvfo / \set_split_vfo                            s / \get_split_vfo
//   I hz / \set_split_freq      the uplink                    i / \get_split_freq
//   X mode passband / \set_split_mode  the uplink             x / \get_split_mode
//   T ptt / \set_ptt            0 only: trakbox has no PTT    t / \get_ptt (always 0)
//   _ / \get_info, \chk_vfo, \dump_state, 1 / \dump_caps, \get_powerstat, \get_lock_mode, q / Q
//
// Rules (docs/hamlib-endpoints.md):
//  * frequencies 10 kHz .. 100 GHz (integer or decimal Hz), else RPRT -1; rounded to trakbox's
//    10 Hz tuning step. Modes FM, USB, LSB, CW ("M ?" lists them); others RPRT -1. The passband
//    is accepted and not applied: trakbox does not set filters; m reads passband 0.
//  * a set takes the radio (tracker/control.h, docs/sharing.md): trakbox's Doppler pauses while the
//    client holds it, until it disconnects or is silent --handback seconds; then tracking tunes
//    again. Standby, or another client holding under --exclusive, refuses sets, RPRT -9.
//  * gets answer what the radio last accepted; a frequency never tuned reads 0 (Hamlib's client
//    gives a command up when its frequency read fails), a mode never set RPRT -6.
//  * a radio in fault: sets RPRT -6 and nothing is queued.
// The current VFO and the split flag are the server's (shared by its clients, as one rig is).
#pragma once
#include <string>
#include <vector>

#include "netctl/protocol.h"
#include "radio/driver.h"
#include "tracker/station_loop.h"

namespace tb::netctl {

class RigctlProtocol final : public LineProtocol {
 public:
  explicit RigctlProtocol(tracker::StationLoop& station,
                          tracker::HolderKind kind = tracker::HolderKind::rigctld);
  void client_line(const std::string& peer) override;
  void client_left(const std::string& peer) override;

  static constexpr radio::Hz kMinHz = 10'000;
  static constexpr radio::Hz kMaxHz = 100'000'000'000;

  radio::Link current_link() const { return current_; }
  bool split() const { return split_; }

 protected:
  const std::vector<Command>& commands() const override;
  Outcome execute(int id, const std::vector<std::string>& args) override;

 private:
  Outcome set_freq(radio::Link link, const std::vector<std::string>& args);
  Outcome get_freq(radio::Link link, const char* key);
  Outcome set_mode(radio::Link link, const std::vector<std::string>& args);
  Outcome get_mode(radio::Link link, const char* mode_key, const char* passband_key);
  Outcome set_vfo(const std::vector<std::string>& args);
  Outcome set_split(const std::vector<std::string>& args);
  Outcome set_ptt(const std::vector<std::string>& args);
  Outcome dump_state();
  Outcome dump_caps();
  // Why a link cannot be set now, if it cannot.
  Error cannot_set();
  std::string label(const std::string& peer) const;

  tracker::StationLoop& station_;
  tracker::HolderKind kind_;
  std::string peer_;  // the client whose line is being handled
  radio::Link current_ = radio::Link::downlink;
  std::string current_name_ = "VFOA";
  bool split_ = false;
  std::string tx_name_ = "VFOB";
};

}  // namespace tb::netctl
