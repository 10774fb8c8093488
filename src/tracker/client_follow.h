// Which pass an outside client follows (issue 57). Gpredict, rotctl scripts, satnogs-client,
// PstRotator and Satrak GOTO streams send az/el targets without naming the satellite; trakbox
// compares each target with where the database's satellites are at that moment. A target within
// kToleranceDeg of a satellite above the horizon matches it; the station then maps the target
// through that pass's PassPlan (which way round on an overlap rotator, the flip), the same plan its
// own tracking uses. The plan changes only the way round, never the direction the antenna points,
// so it is used from the first matching target; the pass counts as recognised (status, the log,
// the page say so) once its targets have matched for kRecogniseS seconds. A target matching no
// satellite ends it: that target goes the way nearest the antenna, as before.
// Pure: values in, values out; docs/sharing.md "Passes followed for outside clients".
#pragma once
#include <optional>
#include <span>
#include <string>

#include "orbit/time.h"

namespace tb::tracker {

// Where a database satellite is at the target's time (compass az, elevation).
struct SkyPosition {
  int db_index = -1;
  std::string name;
  double az_deg = 0.0;
  double el_deg = 0.0;
  // Matched first when within the tolerance (a SatNOGS job's own elements while its window holds).
  bool preferred = false;
};

// A target as the sky sees it: a client's over-the-top target (elevation above 90, from a client
// that flips itself) is the direction az + 180, 180 - el.
struct SkyTarget {
  double az_deg = 0.0;
  double el_deg = 0.0;
};
SkyTarget sky_target(double az_deg, double el_deg);

class ClientPassMatcher {
 public:
  static constexpr double kToleranceDeg = 3.0;   // target to satellite, great-circle degrees
  static constexpr double kRecogniseS = 5.0;     // matched this long (2 targets or more): recognised
  static constexpr double kGapS = 120.0;         // longer without a target: the match starts again
  static constexpr double kLowestElDeg = -2.0;   // satellites below this are not matched

  struct Match {
    int db_index = -1;
    std::string name;
    bool recognised = false;      // matched kRecogniseS and more
    bool newly_recognised = false;  // by this target: say so once
  };
  // A target from `client` at t and where the satellites are then. The satellite it matches (a
  // preferred one within the tolerance, else the nearest; near the zenith any azimuth matches), or
  // nothing.
  std::optional<Match> feed(std::string_view client, orbit::UtcTime t, SkyTarget target,
                            std::span<const SkyPosition> sky);
  // The client's hold ended.
  void reset() { *this = ClientPassMatcher{}; }
  // What holds now, if anything.
  const std::optional<Match>& current() const { return current_; }
  const std::string& client() const { return client_; }

 private:
  std::string client_;
  std::optional<Match> current_;
  orbit::UtcTime first_{}, last_{};
  int count_ = 0;
};

}  // namespace tb::tracker
