// The logbook's sample QSOs, shared by the logbook's, the ADIF's and the logger's tests: an RS-44
// SSB QSO from the page and an ISS FM QSO from host mode, with every field set (the values of
// docs/logbook.md's example record).
#pragma once
#include <cstdint>

#include "logbook/qso.h"

namespace tb::testing {

// The other station, the satellite and the link; both samples are 2 m up and 70 cm down, from
// DM42. (A pair of fields that go together is set on one line.)
inline logbook::Qso on_satellite(int id, const char* call, const char* grid, std::int64_t time_on, const char* sat,
                                 const char* lotw, int norad, const char* mode, std::int64_t uplink_hz,
                                 std::int64_t downlink_hz) {
  logbook::Qso q;
  q.id = id;
  q.call = call, q.grid = grid;
  q.time_on = time_on;
  q.sat_name = sat, q.lotw_name = lotw;
  q.norad = norad;
  q.mode = mode;
  q.uplink_hz = uplink_hz, q.downlink_hz = downlink_hz;
  q.band = "2m", q.band_rx = "70cm";
  q.my_grid = "DM42";
  return q;
}

// 2026-12-01 21:44:20 UTC (Python calendar.timegm), every field set.
inline logbook::Qso rs44_qso() {
  logbook::Qso q =
      on_satellite(1, "W1AW", "FN31", 1796161460, "RS-44", "RS-44", 44909, "SSB", 145'965'000, 435'640'000);
  q.rst_sent = "59", q.rst_rcvd = "57";
  q.uplink_tuned_hz = 145'962'310, q.downlink_tuned_hz = 435'648'070;
  q.station_call = "WA7GXD";
  q.power_w = 2.5;
  q.note = "first <RS-44> QSO";
  q.source = logbook::Source::web;
  return q;
}

// Six minutes later, from host mode: no reports, no tuned frequencies, no note.
inline logbook::Qso iss_qso() {
  logbook::Qso q =
      on_satellite(2, "K1JT", "FN20xr", 1796161800, "ISS", "ARISS", 25544, "FM", 145'990'000, 437'800'000);
  q.source = logbook::Source::host;
  return q;
}

}  // namespace tb::testing
