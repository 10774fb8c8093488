#include "menus/take_back.h"

#include "menus/common.h"

namespace tb::menus {

tracker::OpResult with_confirmation(term::Terminal& t, tracker::StationLoop& station,
                                    const std::function<tracker::OpResult(tracker::StationOps&)>& op,
                                    bool show_refusal) {
  tracker::StationOps ops(station);
  tracker::OpResult r = op(ops);
  if (r.confirm) {
    t.line("");
    const bool yes = ask_yes_no(t, r.confirm->label + " holds it now. Take it back [Y/N] ? ");
    t.line("");
    if (!yes) return r;
    tracker::StationOps confirmed(station, tracker::Requester::menus(), true);
    r = op(confirmed);
  }
  if (!r.ok() && show_refusal) t.line(*r.refusal);
  return r;
}

}  // namespace tb::menus
