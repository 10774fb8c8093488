// Menus change the stored model through its owner (store/owner.h), as every front end does.
#include "menus/menus.h"
#include "tracker/station_loop.h"

namespace tb::menus {

bool commit(term::Terminal& t, Services& s, store::Areas areas, std::string what,
            const std::function<void(store::Model&)>& change) {
  const store::EditResult r = s.station.owner().edit(areas, std::move(what), store::Origin::menus, change);
  if (r.ok()) return true;
  t.bell();
  t.line("Not kept: " + *r.refusal);
  return false;
}

}  // namespace tb::menus
