// The station's one cache of "the next pass" (issue 55): the tracker's candidates, the AOS/LOS
// events, the status document (the page, `trakbox status`) and the Satrak unit all ask here, so they
// agree, and a search (thousands of SGP4 steps) is made once. A kept pass is searched again when
// the satellite's elements change (a refresh, an edit, another element set), when the station moves
// (menu 4, the page, host QTH, a GPS fix followed) or its horizon mask changes, when it has set, or
// when the clock goes back
// (menu 5, a Satrak TIME=); a search that found nothing is tried again after kRetry.
//
// Each user keeps its own entry per satellite (`use`): the events search from the rotor-start
// elevation with --event-min-el, Satrak from its threshold, status wants a pass in progress whole.
#pragma once
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "orbit/passes.h"
#include "orbit/time.h"

namespace tb::tracker {

class PassMemo {
 public:
  static constexpr std::chrono::minutes kRetry{10};
  static constexpr std::size_t kMaxEntries = 512;  // every use of every database satellite, with room
  using Search = std::function<std::optional<orbit::Pass>()>;

  // The pass kept for this satellite and use, seen from `where` at `now`, or what search() gives
  // (then kept). `use` names the user ("tracker", "events", "status", "satrak"); `po` is part of
  // the key (a horizon or a minimum elevation changed is another pass).
  std::optional<orbit::Pass> get(const orbit::Elements& el, const orbit::Observer& where, orbit::UtcTime now,
                                 const Search& search, std::string_view use = "status",
                                 const orbit::PassOptions& po = {});
  std::size_t searches() const { return searches_; }  // how many times get() searched
  std::size_t searches(std::string_view use) const;   // of them, for one use

 private:
  struct Entry {
    orbit::Elements elements;  // as searched: an edit of any orbital field is another orbit
    orbit::Observer where;
    std::shared_ptr<const orbit::HorizonMask> mask;  // as searched with (PassOptions::mask)
    orbit::UtcTime searched_at{};
    std::optional<orbit::Pass> pass;
  };
  using Key = std::tuple<int, std::string, double, double>;  // catalog, use, horizon, min max elevation
  std::map<Key, Entry> kept_;
  std::map<std::string, std::size_t, std::less<>> by_use_;
  std::size_t searches_ = 0;
};

}  // namespace tb::tracker
