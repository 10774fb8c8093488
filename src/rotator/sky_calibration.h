// "This is the Sun" / "this is the Moon": the operator has peaked the antenna on the body by hand
// (or a sun-noise scan found the peak, rotator/sun_scan.h); the difference between the rotator's
// reading and the body's computed position becomes the pointing correction. Pure: readings and
// positions in, a correction (or the reason there is none) and its undo out. docs/calibration.md.
//
// Conventions, one for every front end:
//   correction = true - reading, in degrees: what must be added to the reading for the display to
//   show where the antenna really points. Azimuth wrapped to (-180, 180].
//   On the ADC model (and on degree rotators, whose degrees the driver maps into the same span) the
//   correction is stored as skew, counts added to the reading (menu 6-3): skew += round(correction
//   x counts per degree). The part a whole count cannot hold is reported as the residual.
//
// Use:
//   auto fix = body_fix(Body::sun, t, reading, body_look(Body::sun, station, t));
//   if (!fix.ok()) show(fix.error);
//   auto skew = skew_for(config, fix.correction);       // refusal if the skew would leave its range
//   if (skew.ok()) config = skew.apply(config);          // ... and skew.undo(config) puts it back
#pragma once
#include <string>

#include "orbit/observe.h"
#include "orbit/sky.h"
#include "rotator/config.h"

namespace tb::rotator {

// Degrees to add to a reading (true - reading). az in (-180, 180].
struct PointingCorrection {
  double az_deg = 0.0;
  double el_deg = 0.0;
};

// The lowest the body may be for a calibration on it: near the horizon refraction, ground
// reflections and the mask make the peak unreliable.
inline constexpr double kMinCalibrationElevationDeg = 2.0;

// One "this is the body": when, the reading, the body's computed position and the correction.
struct BodyFix {
  orbit::Body body = orbit::Body::sun;
  orbit::UtcTime time{};
  AzEl reading;        // compass azimuth and elevation as the rotator reported them (skew applied)
  AzEl computed;       // the body's topocentric az/el at `time` (orbit::body_look)
  PointingCorrection correction;
  std::string error;   // when not empty, no correction: why (the body too low, a flipped reading)
  bool ok() const { return error.empty(); }
};

// The correction that makes `reading` equal the body's `computed` look angles. Refused when the
// body is below kMinCalibrationElevationDeg, when the reading's elevation is outside 0..90 (flipped
// over the top: flip back first), or when a value is not finite.
BodyFix body_fix(orbit::Body body, orbit::UtcTime t, AzEl reading, const orbit::LookAngles& computed);

// A correction turned into skew, with what it replaces: apply() and undo() are each other's inverse.
struct SkewChange {
  int az_skew_before = 0, el_skew_before = 0;
  int az_skew_after = 0, el_skew_after = 0;
  double az_residual_deg = 0.0;  // correction minus what the whole counts hold
  double el_residual_deg = 0.0;
  std::string error;             // when not empty, no change: why (the skew would leave its range)
  bool ok() const { return error.empty(); }
  RotatorConfig apply(RotatorConfig c) const;
  RotatorConfig undo(RotatorConfig c) const;
};

// The skew that adds `correction` to the readings of a rotator configured as `c` (its spans give
// the counts per degree). Refused, naming the axis, when the new skew leaves limits::kSkew.
SkewChange skew_for(const RotatorConfig& c, const PointingCorrection& correction);

// The sky calibration as degree offsets (RotatorConfig::az_offset_deg, el_offset_deg and its record
// `sky`; `trakbox calibrate`): exact, where a skew holds whole counts only. The reading had the old
// offsets in it, so the new ones are the old plus the correction; the record names the source ("sun",
// "moon", "sun scan") and the time of the measurement (ISO 8601 UTC), and keeps what it replaced.
struct OffsetChange {
  RotatorConfig after;  // the whole configuration with the new offsets and record
  std::string error;    // when not empty, no change: why (an offset would leave its range, nothing to undo)
  bool ok() const { return error.empty(); }
};
OffsetChange offsets_for(const RotatorConfig& c, const PointingCorrection& correction, const std::string& source,
                         const std::string& time_iso);
// `calibrate undo`: the previous offsets and record back; the current become the previous, so a
// second undo redoes. Refused when no calibration was ever stored.
OffsetChange undo_offsets(const RotatorConfig& c);

}  // namespace tb::rotator
