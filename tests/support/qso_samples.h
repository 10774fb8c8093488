// The logbook's sample QSOs, shared by the logbook's, the ADIF's and the logger's tests: an RS-44
// SSB QSO from the page and an ISS FM QSO from host mode, with every field set (the values of
// docs/logbook.md's example record).
#pragma once
#include "logbook/qso.h"

namespace tb::testing {

inline logbook::Qso rs44_qso() {
  logbook::Qso q;
  q.id = 1;
  q.call = "W1AW";
  q.grid = "FN31";
  q.rst_sent = "59";
  q.rst_rcvd = "57";
  q.time_on = 1796161460;  // 2026-12-01 21:44:20 UTC (Python calendar.timegm)
  q.sat_name = "RS-44";
  q.lotw_name = "RS-44";
  q.norad = 44909;
  q.mode = "SSB";
  q.uplink_hz = 145'965'000;
  q.downlink_hz = 435'640'000;
  q.uplink_tuned_hz = 145'962'310;
  q.downlink_tuned_hz = 435'648'070;
  q.band = "2m";
  q.band_rx = "70cm";
  q.my_grid = "DM42";
  q.station_call = "WA7GXD";
  q.power_w = 2.5;
  q.note = "first <RS-44> QSO";
  q.source = logbook::Source::web;
  return q;
}

inline logbook::Qso iss_qso() {
  logbook::Qso q;
  q.id = 2;
  q.call = "K1JT";
  q.grid = "FN20xr";
  q.time_on = 1796161800;
  q.sat_name = "ISS";
  q.lotw_name = "ARISS";
  q.norad = 25544;
  q.mode = "FM";
  q.uplink_hz = 145'990'000;
  q.downlink_hz = 437'800'000;
  q.band = "2m";
  q.band_rx = "70cm";
  q.my_grid = "DM42";
  q.source = logbook::Source::host;
  return q;
}

}  // namespace tb::testing
