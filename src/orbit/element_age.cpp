#include "orbit/element_age.h"

#include <cmath>
#include <cstdio>

namespace tb::orbit {

namespace {
constexpr double kLowOrbitMaxPeriodMin = 225.0;  // SGP4's boundary between near-earth and deep space
}

ElementAge element_age(const Elements& e, UtcTime at) {
  ElementAge a;
  a.days = minutes_between(e.epoch(), at) / kMinutesPerDay;
  const double period_min = e.mean_motion_rev_per_day > 0 ? kMinutesPerDay / e.mean_motion_rev_per_day : 0.0;
  a.low_orbit = period_min < kLowOrbitMaxPeriodMin;
  a.limit_days = a.low_orbit ? kLowOrbitAgeLimitDays : kHighOrbitAgeLimitDays;
  return a;
}

std::string ElementAge::text() const {
  char buf[64];
  if (days < 0) std::snprintf(buf, sizeof buf, "%.1f days before epoch", -days);
  else std::snprintf(buf, sizeof buf, "%.1f days", days);
  return buf;
}

std::string ElementAge::warning() const {
  if (!stale()) return "";
  char buf[160];
  std::snprintf(buf, sizeof buf, "elements %.1f days %s (more than %.0f for a %s orbit): positions are unreliable",
                std::abs(days), days < 0 ? "before their epoch" : "old", limit_days, low_orbit ? "low" : "high");
  return buf;
}

}  // namespace tb::orbit
