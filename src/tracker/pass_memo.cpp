#include "tracker/pass_memo.h"

#include "orbit/horizon_mask.h"

namespace tb::tracker {

std::optional<orbit::Pass> PassMemo::get(const orbit::Elements& el, const orbit::Observer& where, orbit::UtcTime now,
                                         const Search& search, std::string_view use, const orbit::PassOptions& po) {
  const Key key{el.catalog_number, std::string(use), po.horizon_deg, po.min_max_elevation_deg};
  auto found = kept_.find(key);
  if (found != kept_.end()) {
    const Entry& k = found->second;
    const orbit::Elements& a = k.elements;
    const bool same_elements = a.epoch_year == el.epoch_year && a.epoch_day == el.epoch_day &&
                               a.mean_motion_rev_per_day == el.mean_motion_rev_per_day &&
                               a.eccentricity == el.eccentricity && a.inclination_deg == el.inclination_deg &&
                               a.raan_deg == el.raan_deg && a.arg_perigee_deg == el.arg_perigee_deg &&
                               a.mean_anomaly_deg == el.mean_anomaly_deg && a.bstar == el.bstar &&
                               a.ndot_over_2 == el.ndot_over_2;
    const bool same_place = k.where.lat_deg == where.lat_deg && k.where.lon_deg == where.lon_deg &&
                            k.where.height_m == where.height_m;
    // Another horizon mask (or none now) is another pass.
    const bool same_mask = k.mask == po.mask || (k.mask && po.mask && *k.mask == *po.mask);
    const bool still_ahead = k.pass ? now <= k.pass->los : now < k.searched_at + kRetry;
    if (same_elements && same_place && same_mask && now >= k.searched_at && still_ahead) return k.pass;
  }
  ++searches_;
  ++by_use_[std::string(use)];
  if (found == kept_.end() && kept_.size() >= kMaxEntries) kept_.clear();  // satellites long gone: start afresh
  Entry e{el, where, po.mask, now, search()};
  kept_[key] = e;
  return e.pass;
}

std::size_t PassMemo::searches(std::string_view use) const {
  const auto it = by_use_.find(use);
  return it == by_use_.end() ? 0 : it->second;
}

}  // namespace tb::tracker
