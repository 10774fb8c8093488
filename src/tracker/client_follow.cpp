#include "tracker/client_follow.h"

#include <algorithm>

#include "rotator/pass_plan.h"

namespace tb::tracker {

SkyTarget sky_target(double az_deg, double el_deg) {
  if (el_deg <= 90.0) return {az_deg, el_deg};
  double az = az_deg + 180.0;
  if (az >= 360.0) az -= 360.0;
  return {az, 180.0 - el_deg};
}

std::optional<ClientPassMatcher::Match> ClientPassMatcher::feed(std::string_view client, orbit::UtcTime t,
                                                                SkyTarget target, std::span<const SkyPosition> sky) {
  const SkyPosition* best = nullptr;
  double best_err = kToleranceDeg;
  for (const SkyPosition& s : sky) {
    if (s.el_deg < kLowestElDeg) continue;
    // A client cannot point below the horizon: a satellite just below it is matched at 0.
    const double err = rotator::pointing_error_deg(target.az_deg, target.el_deg, s.az_deg, std::max(s.el_deg, 0.0));
    if (err > kToleranceDeg || (best && best->preferred && !s.preferred)) continue;
    if (err <= best_err || (s.preferred && best && !best->preferred)) {
      best_err = err;
      best = &s;
    }
  }
  if (!best) {
    reset();
    return std::nullopt;
  }
  const double gap = orbit::minutes_between(last_, t) * 60.0;
  const bool same = current_ && client_ == client && current_->db_index == best->db_index && gap >= 0.0 && gap <= kGapS;
  if (!same) {
    client_ = std::string(client);
    current_ = Match{best->db_index, best->name, false, false};
    first_ = t;
    count_ = 0;
  }
  last_ = t;
  ++count_;
  const bool now = count_ >= 2 && orbit::minutes_between(first_, t) * 60.0 >= kRecogniseS;
  current_->newly_recognised = now && !current_->recognised;
  current_->recognised = now;
  return current_;
}

}  // namespace tb::tracker
