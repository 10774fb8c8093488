// Standalone mode: no menus. The front-panel selector picks satellite N (1-15) of the tracking list;
// the two-line LCD shows time, satellite, azimuth and elevation (or A/E/P with the MA display), and
// the AOS LED blinks when the satellite is in range with tracking off, steady when tracking.
#pragma once
#include <string>
#include <vector>

#include "menus/menus.h"

namespace tb::menus {

void standalone(term::Terminal& t, Services& s, int selector);

}  // namespace tb::menus
