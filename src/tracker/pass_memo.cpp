#include "tracker/pass_memo.h"

namespace tb::tracker {

std::optional<orbit::Pass> PassMemo::get(const orbit::Elements& el, orbit::UtcTime now, const Search& search) {
  auto found = kept_.find(el.catalog_number);
  if (found != kept_.end()) {
    const Entry& k = found->second;
    const bool same_elements = k.epoch_year == el.epoch_year && k.epoch_day == el.epoch_day;
    const bool still_ahead = k.pass ? now <= k.pass->los : now < k.searched_at + kRetry;
    if (same_elements && now >= k.searched_at && still_ahead) return k.pass;
  }
  ++searches_;
  Entry e{el.epoch_year, el.epoch_day, now, search()};
  kept_[el.catalog_number] = e;
  return e.pass;
}

}  // namespace tb::tracker
