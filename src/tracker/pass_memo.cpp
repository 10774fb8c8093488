#include "tracker/pass_memo.h"

namespace tb::tracker {

std::optional<orbit::Pass> PassMemo::get(const orbit::Elements& el, const orbit::Observer& where, orbit::UtcTime now,
                                         const Search& search) {
  auto found = kept_.find(el.catalog_number);
  if (found != kept_.end()) {
    const Entry& k = found->second;
    const bool same_elements = k.epoch_year == el.epoch_year && k.epoch_day == el.epoch_day;
    const bool same_place = k.where.lat_deg == where.lat_deg && k.where.lon_deg == where.lon_deg &&
                            k.where.height_m == where.height_m;
    const bool still_ahead = k.pass ? now <= k.pass->los : now < k.searched_at + kRetry;
    if (same_elements && same_place && now >= k.searched_at && still_ahead) return k.pass;
  }
  ++searches_;
  Entry e{el.epoch_year, el.epoch_day, where, now, search()};
  kept_[el.catalog_number] = e;
  return e.pass;
}

}  // namespace tb::tracker
