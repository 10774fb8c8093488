// The ADC-count model of the TrakBox rotator interface. Pure: values in, values out, no I/O, no clock.
//
// Coordinates
//   counts      raw 10-bit readings of the rotator potentiometers (0..1023). The *corrected* reading
//               is raw + skew (menu 6-3: "skew is added to the ADC reading"); every decision below
//               works on corrected counts.
//   travel      azimuth as degrees of rotation from the rotor stop, 0 .. az_travel_deg (360 for the
//               TrakBox). It is what the potentiometer measures, and it is unambiguous where compass
//               azimuth is not (0 and 360 are both north for a North-start rotator).
//   compass az  degrees from north through east, [0, 360): travel + 180 for a South start.
//   el          degrees above the horizon; 0..90 over the span, or 0..180 for rotators allowed to
//               flip over the top (the later firmware's flip mode calibrates 0 and 180 degrees).
//
//   travel(c) = (c - az_span.min) * az_travel_deg / (az_span.max - az_span.min)
//   compass   = (travel + start) mod 360,   start = 0 (rotor start North) or 180 (South)
//   el(c)     = (c - el_span.min) * top / (el_span.max - el_span.min),  top = 90, or 180 with flip
// with c the corrected count. See docs/rotator.md.
#pragma once
#include <limits>
#include <optional>
#include <vector>

#include "rotator/config.h"
#include "station/station.h"

namespace tb::rotator {

enum class Axis { az, el };

// What an axis motor is told to do. Azimuth: increase = clockwise (CW), decrease = counter-clockwise
// (CCW). Elevation: increase = UP, decrease = DOWN.
enum class Drive : int { decrease = -1, stop = 0, increase = 1 };

// "CW", "CCW", "UP", "DOWN" or "STOP".
const char* drive_name(Axis axis, Drive d);
inline int sign(Drive d) { return static_cast<int>(d); }

// A closed interval.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool empty() const { return hi < lo; }
  bool contains(double x) const { return x >= lo && x <= hi; }
  double clamp(double x) const { return x < lo ? lo : (x > hi ? hi : x); }
  double width() const { return hi - lo; }
};

// A position in the rotator's own coordinates: azimuth travel from the stop and elevation (which
// exceeds 90 when the antenna is flipped over the top).
struct RotatorPosition {
  double az_travel = 0.0;
  double el = 0.0;
  friend bool operator==(const RotatorPosition&, const RotatorPosition&) = default;
};

// [0, 360)
double wrap360(double deg);
// The compass azimuth of the rotor stop: 0 for North, 180 for South.
double rotor_start_deg(station::RotorStart start);
// Smallest angle between two compass azimuths, [0, 180].
double azimuth_distance(double a_deg, double b_deg);

class AdcModel {
 public:
  AdcModel() : AdcModel(RotatorConfig{}, station::RotorStart::north) {}
  AdcModel(const RotatorConfig& config, station::RotorStart start);

  const RotatorConfig& config() const { return c_; }
  station::RotorStart rotor_start() const { return start_; }
  double start_deg() const { return rotor_start_deg(start_); }

  // Skew.
  // Skew and the sky calibration's offsets (RotatorConfig::az_offset_deg, el_offset_deg) together.
  double shift(Axis a) const;                   // skew + offset, counts
  double corrected(Axis a, double raw) const;   // raw + shift
  double raw(Axis a, double corrected) const;   // corrected - shift
  int dead_band(Axis a) const { return a == Axis::az ? c_.az_dead_band : c_.el_dead_band; }

  // Scale: degrees of travel per count of this span (the resolution), and its inverse.
  double deg_per_count(Axis a) const;
  double counts_per_deg(Axis a) const { return 1.0 / deg_per_count(a); }

  // Corrected counts <-> degrees (linear, extrapolated outside the span).
  double az_travel_from_counts(double counts) const;
  double counts_from_az_travel(double travel) const;
  double el_from_counts(double counts) const;
  double counts_from_el(double el) const;
  double compass_from_travel(double travel) const;

  // A raw reading as the displays show it: skew added, azimuth as a compass bearing.
  double az_deg_from_raw(double raw) const { return compass_from_travel(az_travel_from_counts(corrected(Axis::az, raw))); }
  double el_deg_from_raw(double raw) const { return el_from_counts(corrected(Axis::el, raw)); }

  // Where the axis may be commanded: the rotation limits (menu 6-4, when enabled), the elevation
  // flip (0..90, or 0..180 when allowed), the calibrated span (the pot's ends are the mechanical
  // stops, 6-1) seen through the skew, and the ADC range. Azimuth in travel degrees, elevation in
  // degrees. Empty when the configuration leaves nowhere to go (validate() reports it).
  Range az_travel_range() const;
  Range el_range() const;
  // The same in corrected counts.
  Range counts_range(Axis a) const;

  // Azimuth limit sector converted to travel (before span and skew are applied): the sector
  // az_limit_min -> az_limit_max clockwise, as the piece of travel in force. A sector that contains
  // the rotor stop falls in two pieces (South start, limits 10..350: travel 0..170 = compass
  // 180..350 and travel 190..360 = compass 10..180, the excluded 350..10 between them); the
  // antenna is in one of them at a time: az_piece().
  Range az_limit_travel() const;
  // Every piece of travel the limit sector covers, in travel order (one, or two when the limits
  // split the travel), each seen through the span and skew as az_travel_range() is (a piece the
  // span leaves nothing of is empty, keeping the indices).
  std::vector<Range> az_pieces() const;
  // The limits leave two pieces of travel the antenna cannot pass between within them.
  bool travel_split() const;
  // The piece in force (an index into az_pieces()): by default the longest (the first of equal
  // ones); the controller sets it to the piece the antenna is in (limits as barriers) or the one a
  // pass plan chose (crossing between passes, RotatorConfig::cross_limit_sector).
  int az_piece() const;
  void set_az_piece(int index) { piece_ = index; }
  // The piece containing a travel position, else the nearest one.
  int az_piece_of(double travel) const;
  // The piece of az_pieces() containing a compass azimuth, if any.
  std::optional<int> az_piece_for_compass(double compass_az) const;

  // The travel that points at a compass azimuth, inside az_travel_range(). Where the azimuth can be
  // reached more than one way (0/360 at the stop, or the overlap of a 450-degree rotator), the way
  // nearest current_travel. Outside the limits: the limit angularly nearest the azimuth.
  double travel_for(double compass_az, double current_travel) const;
  // Wound (issue 57): an azimuth more than one turn from the stop (the overlap of a 450- or
  // 540-degree rotator) that the travel also reaches one turn back: that travel; nothing otherwise.
  std::optional<double> unwound_travel(double travel) const;
  // A compass az/el target clamped into the limits, in rotator coordinates.
  RotatorPosition target_for(AzEl compass, double current_travel) const;
  // A rotator-coordinate target clamped into the limits.
  RotatorPosition clamp(RotatorPosition p) const;
  // Target counts (corrected) for a rotator position, rounded to whole counts.
  int target_counts(Axis a, const RotatorPosition& p) const;

 private:
  RotatorConfig c_;
  station::RotorStart start_ = station::RotorStart::north;
  int piece_ = -1;  // -1: the default piece
  std::vector<Range> limit_pieces() const;  // az_pieces() before span and skew
  Range mech_travel() const;                // the calibrated span seen through the skew, as travel
};

// ---------------------------------------------------------------------------------------------
// The motor as the control loop models it: full speed `rate` (counts/s) once spun up, first-order
// spin-up and coast with time constant tau. Driving for T seconds from velocity v0 and then
// switching off moves the axis rate*T + v0*tau in all (the spin-up lag and the coast cancel), which
// is what lets a loop that ticks slowly still stop inside a one-count dead band.
struct MotorState {
  double x = 0.0;  // position, counts
  double v = 0.0;  // velocity, counts/s (signed)
};
// Advances by dt seconds with the motor commanded to velocity v_cmd.
MotorState motor_advance(MotorState s, double v_cmd, double tau_s, double dt_s);
// A coasting motor whose speed has fallen below this share of its full rate is at rest: friction
// holds it (the simulated rotator stops it there; the controller reports the axis still from
// then). At 6 deg/s and coast 0.15 s the last 0.018 deg of the coast, 0.05 of a count.
inline constexpr double kMotorStopFraction = 0.02;

// One axis of the per-tick control decision.
struct AxisLoopInput {
  double reading = 0.0;   // corrected counts
  double target = 0.0;    // corrected counts
  int dead_band = 0;      // counts
  Range range{};          // corrected counts the axis may be driven in
  Drive driving = Drive::stop;  // the drive in force now
  double velocity = 0.0;  // modelled velocity now, counts/s (signed)
  double rate = 1.0;      // full-speed rate, counts/s (> 0)
  double coast_s = 0.0;   // motor time constant
};

struct AxisCommand {
  Drive drive = Drive::stop;
  double run_for_s = 0.0;  // how long to drive before switching off by itself (the caller caps it)
  bool at_limit = false;   // stopped because the axis is at a limit with the target beyond it
  friend bool operator==(const AxisCommand&, const AxisCommand&) = default;
};

// The drive decision for one axis.
//  * e = target - reading - velocity*coast_s (the error left once the axis has coasted to rest).
//  * A stopped axis stays stopped while the error now or e is within the dead band (an error
//    exactly at the dead band is inside it); otherwise it is driven towards where e says.
//  * A driven axis keeps going towards the centre of the dead band (hysteresis: no stop at the
//    band's near edge, so a new small error does not restart it at once), for run_for_s =
//    e / rate seconds, after which it switches off and coasts onto the target.
//  * An axis at or beyond a limit of `range` is never driven further out, whatever the target.
AxisCommand decide(const AxisLoopInput& in);

}  // namespace tb::rotator
