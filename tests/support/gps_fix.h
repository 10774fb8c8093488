// A GPS receiver's reports for the tests of what reads a gps::Monitor (Satrak, host mode, menus):
// the Satrak document's GPS_DATA? example position, 41.01N 29.17E, 120 m above the ellipsoid.
#pragma once
#include "gps/monitor.h"
#include "orbit/time.h"

namespace tb::testing {

// One report there: mode 3 (with the height), 2 (without) or 1 (no fix, no position).
inline gps::Report gps_report(orbit::UtcTime gps_time, int mode = 3) {
  gps::Report r;
  r.mode = mode;
  if (mode >= 2) {
    r.lat_deg = 41.01;
    r.lon_deg = 29.17;
  }
  if (mode >= 3) r.alt_m = 120.0;
  r.time = gps_time;
  return r;
}

// The link up and `count` reports a second apart from gps_time, received at clock_time on: with 3
// (gps::kConfirmReports), the position is confirmed at gps_time + 2 s.
inline void feed_gps_fix(gps::Monitor& m, orbit::UtcTime gps_time, orbit::UtcTime clock_time, int mode = 3,
                         int count = gps::kConfirmReports) {
  m.on_link(gps::Link::receiving);
  for (int i = 0; i < count; ++i) m.on_report(gps_report(orbit::add_seconds(gps_time, i), mode), orbit::add_seconds(clock_time, i));
}

}  // namespace tb::testing
