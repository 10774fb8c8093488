// The next pass of each satellite, searched once and kept: a status document (the web page's, pushed
// every second to every viewer, and `trakbox status`) shows every tracking-list satellite's next pass,
// and a search is thousands of SGP4 steps. A kept pass is searched again when the satellite's
// elements change (a refresh, an edit), when the station moves (menu 4, the page, a GPS fix
// followed), when it has set, or when the clock goes back (menu 5); a search that found nothing
// is tried again after kRetry.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <optional>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "orbit/passes.h"
#include "orbit/time.h"

namespace tb::tracker {

class PassMemo {
 public:
  static constexpr std::chrono::minutes kRetry{10};
  using Search = std::function<std::optional<orbit::Pass>()>;

  // The pass kept for this satellite seen from `where` at `now`, or what search() gives (then kept).
  std::optional<orbit::Pass> get(const orbit::Elements& el, const orbit::Observer& where, orbit::UtcTime now,
                                 const Search& search);
  std::size_t searches() const { return searches_; }  // how many times get() searched

 private:
  struct Entry {
    int epoch_year = 0;
    double epoch_day = 0;
    orbit::Observer where;
    orbit::UtcTime searched_at{};
    std::optional<orbit::Pass> pass;
  };
  std::map<int, Entry> kept_;  // by catalog number; bounded by the database
  std::size_t searches_ = 0;
};

}  // namespace tb::tracker
