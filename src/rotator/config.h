// Rotator configuration: what menus 6-1 to 6-4 and 6-6-3 of the manual set, plus the few numbers the
// control loop needs that the 8052 firmware kept to itself (motor rate and coast).
//
// Units: ADC counts (raw 10-bit readings, 0..1023) for the span, the dead band and the skew, as the
// manual has them; degrees for parking, limits and presets (what menu 6-4 and 6-6-3 prompt for).
//
// Factory defaults (menu 6-9) are chosen so that trakbox works with the simulated rotator out of the
// box and so that the manual's resolution figures hold:
//   azimuth   span 0..1023 counts = 360 deg of travel from the stop  -> 0.352 deg a count
//   elevation span 0..511 counts  = 0..90 deg (a 0..180 deg elevation rotator whose pot fills the
//             whole ADC range, as the manual's "0 V at one extreme, 5 V at the other")
//                                                                       -> 0.176 deg a count
//   dead band 3 counts azimuth, 1 count elevation (the manual's defaults), skew 0
//   parking off (0/0), limits off (az 0..360, el 0..90), presets 0/0, elevation flip not allowed.
// See docs/rotator.md.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace tb::rotator {

inline constexpr int kAdcMaxCount = 1023;  // 10-bit ADC

// The allowed range of each configured number, in one place: validate(), menus 6-2 to 6-4, the
// station file (menu 6-9) and the state document's reader all take them from here.
namespace limits {
struct Counts {
  int lo, hi;
  constexpr bool contains(int v) const { return v >= lo && v <= hi; }
};
inline constexpr Counts kSpan{0, kAdcMaxCount};  // ADC span ends
inline constexpr int kMinSpanWidth = 10;         // max - min, counts
inline constexpr Counts kDeadBand{0, 100};
inline constexpr Counts kSkew{-512, 512};
inline constexpr double kTravelMinDeg = 360.0, kTravelMaxDeg = 720.0;  // azimuth travel from the stop
inline constexpr double kCoastMaxS = 5.0;
inline constexpr double kSkyOffsetMaxDeg = 45.0;  // the sky calibration's offsets, either way (trakbox calibrate)
}  // namespace limits

// The record of the sky calibration's offsets: what measured them ("sun", "moon", "sun scan"; ""
// none), when (ISO 8601 UTC of the measurement), and the offsets and record before it, which
// `trakbox calibrate undo` restores (an undo swaps the two, so a second undo redoes).
struct SkyCalibration {
  std::string source;
  std::string time;
  double previous_az_offset_deg = 0.0;
  double previous_el_offset_deg = 0.0;
  std::string previous_source;
  std::string previous_time;
  friend bool operator==(const SkyCalibration&, const SkyCalibration&) = default;
};

// An azimuth/elevation pair in degrees. Azimuth is from north through east.
struct AzEl {
  double az = 0.0;
  double el = 0.0;
  friend bool operator==(const AzEl&, const AzEl&) = default;
};

// Raw ADC counts at the two calibration points of one axis (menus 6-1 and 6-2).
// Azimuth: min = fully counter-clockwise (the rotor stop), max = fully clockwise.
// Elevation: min = horizon (0 deg), max = straight up (90 deg).
struct AxisSpan {
  int min = 0;
  int max = kAdcMaxCount;
  int width() const { return max - min; }
  friend bool operator==(const AxisSpan&, const AxisSpan&) = default;
};

struct RotatorConfig {
  // 6-1 / 6-2: ADC span value.
  AxisSpan az_span{0, 1023};
  AxisSpan el_span{0, 511};
  // Azimuth degrees the span covers, from the stop. 360 for the TrakBox; 450 or 540 for overlap
  // rotators (the span then covers 0..450 from the stop, and azimuths near the stop can be reached
  // two ways).
  double az_travel_deg = 360.0;

  // 6-3: dead band (counts ignored when pointing) and skew (counts added to the reading).
  int az_dead_band = 3;
  int el_dead_band = 1;
  int az_skew = 0;
  int el_skew = 0;

  // 6-4: parking position and rotation limits, in degrees.
  bool parking_enabled = false;
  AzEl parking{0.0, 0.0};
  bool limits_enabled = false;
  // Azimuth limits are compass azimuths: the allowed sector runs clockwise from az_limit_min to
  // az_limit_max (so 270 -> 90 is the northern half). max - min >= 360 means no azimuth limit.
  double az_limit_min = 0.0;
  double az_limit_max = 360.0;
  double el_limit_min = 0.0;
  double el_limit_max = 90.0;

  // When the limits split the travel into two pieces (the rotor stop inside the allowed sector:
  // a South start with limits 10..350), whether the excluded sector between them may be crossed.
  // false (the default): the limits are barriers, and the antenna keeps to the piece it is in
  // (driving across the excluded sector would take the rotator outside its limits). true: they are
  // pointing limits only, and the pass planner may move the antenna to the other piece between
  // passes, never during one (menu 6-4 asks; docs/rotator.md "Limits that split the travel").
  bool cross_limit_sector = false;

  // 6-6-3: five preset positions.
  std::array<AzEl, 5> presets{};

  // Elevation over the top (rotators whose elevation goes to 180 deg): the later firmware's flip
  // mode (v3.30a: "you must calibrate the EL rotor at 0 and 180 degree point"). The elevation span
  // then covers 0..180 degrees, not 0..90, and the pass planner may use el' = 180 - el,
  // az' = az + 180.
  bool el_flip_allowed = false;
  // The degrees the elevation span covers and the elevation may reach: 180 in flip mode, else 90.
  double el_top_deg() const { return el_flip_allowed ? 180.0 : 90.0; }

  // The motors as the control loop models them: full-speed rate and the time constant with which a
  // motor spins up and coasts down (first-order). They time the drive pulses so that an axis stops
  // inside the dead band even when the loop ticks only once a second. Defaults are the simulated
  // rotator's; tune them for real hardware (docs/rotator.md).
  double az_rate_deg_s = 6.0;
  double el_rate_deg_s = 3.0;
  double coast_s = 0.15;
  // An axis driven this long without its reading changing is stopped and reported stalled (a rotator
  // that cannot reach the calibrated end must not be driven forever: the manual's "smoke" warning).
  double stall_s = 3.0;

  // The sky calibration (`trakbox calibrate sun|moon`, its --scan; docs/calibration.md): degrees
  // added to the reading on top of the skew, so that the antenna peaked on the Sun or the Moon reads
  // the body's computed position. The targets are seen through them too (AdcModel::corrected).
  double az_offset_deg = 0.0;
  double el_offset_deg = 0.0;
  SkyCalibration sky;  // what set them, when, and what they replaced

  friend bool operator==(const RotatorConfig&, const RotatorConfig&) = default;
};

// Every problem with a configuration, one sentence each naming the field and what is expected.
// Empty when the configuration is usable.
std::vector<std::string> validate(const RotatorConfig& c);

}  // namespace tb::rotator
