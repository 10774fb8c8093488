// The sun-noise scan's mathematics: the pattern of pointings around the computed Sun (or Moon), and
// the fit of the averaged receiver levels that finds the peak: the pointing correction, the Sun's
// noise over cold sky, and the -3 dB beamwidth. Pure: numbers in, numbers out; the front end that
// moves the antenna and reads the receiver drives it (docs/calibration.md).
//
// Coordinates of the scan: offsets from the body's computed position ON THE SKY, degrees:
//   x = cross-elevation = (az - body az) * cos(body el),   y = el - body el.
// A pointing for offset (x, y) is az = body az + x / cos(body el), el = body el + y (scan_target),
// recomputed for each point at the time it is taken: the Sun moves 0.25 deg a minute.
//
// Use:
//   auto plan = scan_pattern(ScanShape::grid, 2 * beam, beam / 4);     // offsets, or plan.error
//   for each point: move to scan_target(body_look(...), p); read the level several times;
//                   samples.push_back({reading, body_look(...) at that time, average_level_db(levels)});
//   auto fit = fit_scan(samples);          // fit.correction, fit.peak_over_cold_db, fit.beamwidth_*
#pragma once
#include <span>
#include <string>
#include <vector>

#include "rotator/config.h"
#include "rotator/sky_calibration.h"

namespace tb::rotator {

enum class ScanShape {
  cross,  // one line through the body in cross-elevation, one in elevation: 4 * span / step + 1 points
  grid,   // every (x, y) of the square, rows swept back and forth: (2 * span / step + 1)^2 points
};

struct ScanPoint {
  double x_deg = 0.0;  // cross-elevation offset on the sky
  double y_deg = 0.0;  // elevation offset
};

struct ScanPattern {
  std::vector<ScanPoint> points;
  std::string error;   // when not empty, no points: why
  bool ok() const { return error.empty(); }
};

// The most points one line of a pattern may have each side of the centre (span / step).
inline constexpr int kMaxScanStepsEachSide = 20;

// The offsets of a scan reaching span_deg each side of the body in steps of step_deg (a span that is
// not a whole number of steps ends at the last whole step). Refused when either is not positive, or
// span / step exceeds kMaxScanStepsEachSide. Suggested: span = 2 beamwidths, step = beamwidth / 4.
ScanPattern scan_pattern(ScanShape shape, double span_deg, double step_deg);

// Where to point for an offset from the body's position (azimuth wrapped to [0, 360)).
AzEl scan_target(AzEl body, ScanPoint p);

// Several levels in dB (dBFS, or any dB scale) averaged as power, in dB.
double average_level_db(std::span<const double> levels_db);

// One pointing of a scan: where the antenna read (skew applied), where the body was computed at
// that moment, and the averaged level there.
struct ScanSample {
  AzEl reading;
  AzEl body;
  double level_db = 0.0;
};

struct ScanFit {
  PointingCorrection correction;   // true - reading, as BodyFix's: apply with skew_for
  double peak_x_deg = 0.0;         // where the peak was found, offsets on the sky from the body
  double peak_y_deg = 0.0;
  double peak_over_cold_db = 0.0;  // the fitted peak's power over the cold-sky level, dB (Y factor)
  double cold_sky_db = 0.0;        // the cold-sky level the fit used, in the readings' scale
  double beamwidth_x_deg = 0.0;    // -3 dB full width in cross-elevation
  double beamwidth_y_deg = 0.0;    // and in elevation
  double rms_db = 0.0;             // the fit's residual over the points it used, dB
  int points_used = 0;
  std::string error;               // when not empty, nothing above is valid: why
  bool ok() const { return error.empty(); }
};

// Fits a Gaussian beam over a flat cold sky to the samples: the cold-sky level is the mean power of
// the lowest fifth of the samples (at least two); the points at least 10 % of the peak's excess over
// it are fitted, their natural log of the excess power as a quadratic in x and y (weighted by the
// excess squared), which is a Gaussian in each axis. Refused, saying why, with fewer than six
// samples, with no excess over the noise, when the levels do not fall off on both sides of the peak
// in each axis, or when the peak lies outside the scanned square.
ScanFit fit_scan(std::span<const ScanSample> samples);

}  // namespace tb::rotator
