// How old an element set is at the time something is computed from it, and whether that is too
// old (or too far before its epoch) to trust. SGP4's error grows with the distance from the epoch:
// a low orbit's drag makes a two-week-old set miss by tens of kilometres along track, while a
// high orbit's set stays usable for weeks. Every view that uses a set says its age, and warns past
// the limit of its orbit (issue 12, "Honest answers"; docs/orbit.md).
#pragma once
#include <string>

#include "orbit/elements.h"
#include "orbit/time.h"

namespace tb::orbit {

// Low orbits (period under 225 minutes, SGP4's near-earth case) and the others.
inline constexpr double kLowOrbitAgeLimitDays = 14.0;
inline constexpr double kHighOrbitAgeLimitDays = 30.0;

struct ElementAge {
  double days = 0.0;        // at - epoch; negative before the epoch
  double limit_days = 0.0;  // what the orbit allows either side of its epoch
  bool low_orbit = true;
  bool stale() const { return days > limit_days || -days > limit_days; }
  // "0.3 days", "5.0 days before epoch"
  std::string text() const;
  // When stale: "elements 1826.3 days old (more than 14 for a low orbit): positions are unreliable";
  // "" otherwise.
  std::string warning() const;
};

ElementAge element_age(const Elements& e, UtcTime at);

}  // namespace tb::orbit
