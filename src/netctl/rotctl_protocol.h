// The rotctld protocol (Hamlib's TCP rotator daemon, port 4533 by convention) answered by trakbox's
// station, so that Gpredict and every Hamlib client (rotctl -m 2) can drive the antenna.
//
//   P az el / \set_pos   point there (through trakbox's model: limits, dead band); tracking stops
//   p / \get_pos         where the antenna points: two lines, azimuth and elevation
//   S / \stop            motors off, tracking stops (always works)
//   K / \park            to the parking position
//   M dir speed / \move  2 up, 4 down, 8 CCW, 16 CW: drive at the rotator's rate until S
//   _ / \get_info        one line naming the rotator
//   \dump_state          what Hamlib's NET client reads when it opens (protocol 1)
//   1 / \dump_caps       capabilities, for people
//   q / Q                close
//
// Positions are compass bearings. Rules (docs/hamlib-endpoints.md):
//  * azimuth -180..540 and elevation 0..90 (0..180 where the elevation may flip) are the protocol's
//    range: outside it the request is refused (RPRT -1) and nothing changes. Inside it the azimuth
//    is taken modulo 360, and a position outside trakbox's rotation limits or span is clamped to the
//    nearest limit (as trakbox's own tracking does), RPRT 0; p then says where the antenna went.
//  * p answers the azimuth in the frame the client uses, as its own P shows it: after a P with a
//    negative azimuth (Gpredict set to -180..180) in (-180, 180], after one above 180 (a 0..360
//    client) and before any P in [0, 360). A client that compares p with what it sent (Gpredict
//    re-sends P whenever they differ by more than its threshold) then sees the antenna arrive.
//  * each client is a holder of the antenna (tracker/control.h, docs/sharing.md): its P, S, K or M
//    suspends trakbox's own tracking until it disconnects or is silent --handback seconds; standby
//    or another client holding under --exclusive refuses them, RPRT -9, and nothing changes;
//  * with rotor control off (the E key) P, K and M are refused (RPRT -9) and nothing changes;
//    S always works. K with parking disabled: RPRT -9. A rotator link in fault: P, K, M and p
//    answer RPRT -6.
// Transport-free: the server hands it lines; it acts on the StationLoop at once.
#pragma once
#include <string>
#include <vector>

#include "netctl/protocol.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::netctl {

class RotctlProtocol final : public LineProtocol {
 public:
  explicit RotctlProtocol(tracker::StationLoop& station,
                          tracker::HolderKind kind = tracker::HolderKind::rotctld);
  void client_line(const std::string& peer) override;
  void client_left(const std::string& peer) override;

  // The protocol's coordinate range (what \dump_state advertises and P accepts).
  static constexpr double kMinAz = -180.0;
  static constexpr double kMaxAz = 540.0;
  double max_el() const;  // 90, or 180 where the elevation may flip over the top

  // The azimuth frame p answers in: the lowest azimuth it reports, 0 (0..360) or -180 (-180..180).
  double az_frame_lo() const { return az_frame_lo_; }
  // A compass azimuth [0, 360) in a frame starting at frame_lo (0 or -180).
  static double in_frame(double compass_az, double frame_lo);

 protected:
  const std::vector<Command>& commands() const override;
  Outcome execute(int id, const std::vector<std::string>& args) override;

 private:
  Outcome set_pos(const std::vector<std::string>& args);
  Outcome get_pos();
  Outcome stop();
  Outcome park();
  Outcome move(const std::vector<std::string>& args);
  Outcome info();
  Outcome dump_state();
  Outcome dump_caps();
  // Why the antenna cannot be moved now, if it cannot.
  // A command that moves the antenna takes rotor control (the E key), as it does through host mode
  // and Satrak; then io when the rotator link is in fault.
  Error cannot_move();

  tracker::StationOps ops();  // as the client sending the current line
  std::string label(const std::string& peer) const;

  tracker::StationLoop& station_;
  tracker::HolderKind kind_;
  std::string peer_;          // the client whose line is being handled
  double az_frame_lo_ = 0.0;  // set by the azimuths P receives
};

}  // namespace tb::netctl
