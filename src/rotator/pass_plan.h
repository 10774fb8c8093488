// Pass planning against the rotor stop. Before AOS the tracker hands over the whole pass as sampled
// az/el; the planner chooses how the rotator follows it so the antenna never swings through the
// stop mid-pass:
//   * which way round: the azimuth travel (0..360 from the stop, or 0..450 on an overlap rotator)
//     the whole pass is followed in;
//   * the elevation flip (el' = 180 - el, az' = az + 180, over the top) when the pass would
//     otherwise cross the stop and the rotator may flip;
//   * failing both, the antenna waits at the end of travel for the part of the pass beyond it
//     (held_at_stop) rather than swinging round through 360 degrees while the satellite is up.
// Pure: values in, values out.
//
//   PassPlan plan = plan_pass(track, PassGeometry::from(rot.model()), rot.status().az.travel);
//   rot.set_target(plan.aos);                       // ahead of AOS
//   rot.set_target(plan.map(look.az_deg, look.el_deg));  // every target during the pass
#pragma once
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "orbit/time.h"
#include "rotator/adc_model.h"

namespace tb::rotator {

struct TrackPoint {
  orbit::UtcTime time{};
  double az_deg = 0.0;  // compass
  double el_deg = 0.0;
};

// What the planner needs to know of the rotator.
struct PassGeometry {
  station::RotorStart start = station::RotorStart::north;
  Range az_travel{0.0, 360.0};  // where the azimuth may go, degrees of travel from the stop
  Range el{0.0, 90.0};          // where the elevation may go (to 180 on a flip rotator)
  bool flip_allowed = false;
  // Limits that split the travel (AdcModel::az_pieces): az_travel is piece `piece`; the planner
  // may choose among `choices` (indices into pieces: the piece in force alone when the limits are
  // barriers or the pass has begun, both when they may be crossed between passes).
  std::vector<Range> pieces;
  int piece = 0;
  std::vector<int> choices;
  // Coverage counts the samples at or above the rotor start elevation (STATION.DAT line 5).
  double start_el = -2.0;
  // The azimuth motor's full-speed rate (RotatorConfig::az_rate_deg_s; 0: unknown): a pass whose
  // azimuth turns faster near its culmination is followed over the top when the rotator can flip.
  double az_rate_deg_s = 0.0;
  // The rotator as the controller's model sees it: limits, span, skew, flip, the piece in force;
  // may_cross: the planner may choose the other piece of a split travel.
  static PassGeometry from(const AdcModel& m, bool may_cross = false, double start_el = -2.0);
};

// How much of a pass the antenna follows: the samples at or above the rotor start elevation whose
// azimuth the plan reaches (not held at a limit or the stop).
struct PassCoverage {
  double fraction = 1.0;  // 0..1 (1 for an empty track)
  std::optional<orbit::UtcTime> from, to;  // the first and last sample followed
  int samples = 0;        // samples counted
  int followed = 0;       // of which followed
  bool full() const { return followed == samples; }
};

struct PassPlan {
  PassGeometry geometry;
  bool flip = false;            // follow the pass over the top
  // Over the top through the zenith (issue 57): a pass so high that its azimuth turns faster than
  // the motor near culmination, on a rotator that can flip, is followed in the vertical plane of
  // azimuth plane_az (perpendicular to the azimuth at culmination, on the AOS side): the azimuth
  // stays there and the elevation runs 0 -> 180 through the zenith. The pointing error is at most
  // 90 - the pass's maximum elevation (1.2 deg for an 88.8 deg pass), where following the azimuth
  // would leave the antenna behind by tens of degrees for half a minute.
  bool over_top = false;
  double plane_az = 0.0;
  // What the plan says about how fast the pass turns: its fastest azimuth rate between samples.
  double peak_az_rate_deg_s = 0.0;
  double window_center = 0.0;   // travel: each azimuth is taken within +-180 of this
  RotatorPosition aos;          // where to be at AOS
  bool held_at_stop = false;    // part of the pass lies beyond the travel: the antenna waits there
  double max_error_deg = 0.0;   // largest pointing error over the samples (0 when it all fits)
  double mean_error_deg = 0.0;
  PassCoverage coverage;
  // The keyhole (issue 57): a pass whose azimuth turns faster near its culmination than the motor,
  // on a rotator that does not follow it over the top. Chasing the satellite, the antenna falls
  // behind after the culmination by up to following_error_deg (20 degrees and more for an 88-degree
  // pass on a 6 deg/s motor). Instead the turn begins before the culmination and runs at the motor's
  // rate on the schedule `lead` (the azimuth in travel degrees by time), chosen so that the largest
  // pointing error over the pass, max_error_deg, is the smallest any schedule within the motor's
  // rate can give. Empty when the motor keeps up (or over the top).
  struct LeadPoint {
    orbit::UtcTime time{};
    double az_travel = 0.0;
  };
  std::vector<LeadPoint> lead;
  double following_error_deg = 0.0;  // the worst error chasing the satellite instead (with a lead)
  double lead_rate_deg_s = 0.0;      // the rate the schedule assumes: 90 % of the motor's

  // A target during the pass, in rotator coordinates for Controller::set_target.
  RotatorPosition map(double az_deg, double el_deg) const;
  // The same at time t: inside the keyhole the azimuth comes from the lead schedule, not the target.
  RotatorPosition map_at(orbit::UtcTime t, double az_deg, double el_deg) const;
  // The keyhole in words, for the log, the page and status; "" without one:
  //   "keyhole 13:51:18-13:51:49: the azimuth turns ahead of the satellite at 5.4 deg/s: at most 6.2
  //    deg off (23.1 chasing it)"
  std::string keyhole_text() const;
  // Where the antenna points (compass az/el) while the satellite is at az/el: map() seen from the
  // sky, the flip undone (for the pass plots).
  AzEl pointing_at(double az_deg, double el_deg) const;
  // What the antenna does of the pass, for the displays and status:
  //   "antenna on target 10:00:00-10:02:30 (13% of the pass): it reaches azimuth 180.0-350.0", or
  //   "PASS OUT OF ANTENNA REACH (it reaches azimuth 180.0-350.0)" when it follows none of it.
  std::string coverage_text() const;
  // Whether the antenna, on this plan, does not point at a satellite at az/el (the pass plots'
  // red: the plan holds it elsewhere; the zenith's azimuth does not count).
  bool lost_at(double az_deg, double el_deg) const;
};

// Plans a pass sampled at even steps (AOS first). current_travel, when given, breaks ties between
// equally good ways round (the one with the shorter slew to AOS wins); otherwise the way that keeps
// furthest from the ends of travel does. An empty track gives the plain mapping.
// With a split travel and more than one choice: the piece that covers the most of the pass above
// the start elevation, then the one covering its highest sample, then the piece in force.
PassPlan plan_pass(std::span<const TrackPoint> track, const PassGeometry& g,
                   std::optional<double> current_travel = std::nullopt);

// When to sample a pass for its plan: every coarse_s seconds from AOS to LOS, and every second within
// fine_s of the culmination, where a high pass's azimuth turns fastest (the keyhole's schedule and
// the over-the-top plane are found from those); sorted, AOS and LOS included.
std::vector<orbit::UtcTime> pass_sample_times(orbit::UtcTime aos, orbit::UtcTime tca, orbit::UtcTime los,
                                              double coarse_s = 10.0, double fine_s = 120.0);

// Seconds to slew between two rotator positions at the configured motor rates (axes move together).
double slew_seconds(const RotatorPosition& from, const RotatorPosition& to, const RotatorConfig& c);

// Angle between two pointing directions (compass az, el), degrees.
double pointing_error_deg(double az1, double el1, double az2, double el2);

}  // namespace tb::rotator
