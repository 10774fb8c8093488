// A horizon mask (issue 57): the lowest elevation the station sees a satellite at, by azimuth, for
// a station behind a roof, trees or a hill. Apart from the rotator's floor (its elevation limit):
// passes, AOS/LOS and the planner use max(mask(az), floor). Read from the common file forms:
//   * pairs per line, "AZ EL" separated by blanks (N.I.N.A's .hrz), or "AZ,EL" (a CSV; a first
//     line "az,el" is a header): interpolated linearly in azimuth between the points, round the
//     circle (after the last point back to the first);
//   * the VLBI Field System's step list "AZ EL AZ EL ... AZ" (on one line or more; an odd count of
//     numbers, more than two on a line): stepped, EL from its AZ up to the next AZ.
// '#' starts a comment; blank lines are skipped. Azimuths 0..360 increasing, elevations -90..90.
// Pure. docs/rotator.md "Horizon mask".
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::orbit {

struct MaskPoint {
  double az_deg = 0.0;
  double el_deg = 0.0;
  bool operator==(const MaskPoint&) const = default;
};

class HorizonMask {
 public:
  enum class Kind { interpolated, stepped };
  // points: azimuths increasing in 0..360; stepped: one more azimuth than elevations is given as
  // the last point's azimuth (its elevation unused).
  HorizonMask(Kind kind, std::vector<MaskPoint> points);
  Kind kind() const { return kind_; }
  const std::vector<MaskPoint>& points() const { return points_; }
  // The mask's elevation at a compass azimuth.
  double at(double az_deg) const;
  // The lowest elevation it has anywhere (the pass search's fast bound).
  double min_el() const;
  double max_el() const;
  // "interpolated, 5 points, 0.0..25.0 deg" / "stepped, 4 steps, ...".
  std::string describe() const;
  // The mask as one line the reader takes back, as the state document keeps it (the setting
  // station.horizon_mask): "0 5; 214 25; 262 25; 263 5" (interpolated, pairs joined by ';') or the
  // step list "0 5 214 25 262 5 360" (stepped).
  std::string text() const;
  bool operator==(const HorizonMask&) const = default;

 private:
  Kind kind_;
  std::vector<MaskPoint> points_;
};

struct MaskReading {
  std::optional<HorizonMask> mask;
  std::string error;  // "line 3: azimuth 400 is outside 0..360"; empty when read
};
// The text of a mask file; `name` starts the error ("mask.hrz line 3: ..."). One line without a
// line break may join its pairs with ';' (the form text() writes; "pair N" then names the place).
MaskReading read_horizon_mask(std::string_view text, std::string_view name = "horizon mask");

// The mask of a stored text (HorizonMask::text()'s form), shared: the station asks for it at every
// pass search, and the last text read is kept. Nothing for "" or a text that is no mask.
std::shared_ptr<const HorizonMask> shared_horizon_mask(const std::string& text);

}  // namespace tb::orbit
