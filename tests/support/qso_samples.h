// The logbook's sample QSOs, shared by the logbook's, the ADIF's and the logger's tests: an RS-44
// SSB QSO from the page and an ISS FM QSO from host mode, with every field set (the values of
// docs/logbook.md's example record).
#pragma once
#include "logbook/qso.h"

namespace tb::testing {

inline logbook::Qso rs44_qso() {
  return logbook::Qso{
      .id = 1,
      .call = "W1AW",
      .grid = "FN31",
      .rst_sent = "59",
      .rst_rcvd = "57",
      .time_on = 1796161460,  // 2026-12-01 21:44:20 UTC (Python calendar.timegm)
      .sat_name = "RS-44",
      .lotw_name = "RS-44",
      .norad = 44909,
      .mode = "SSB",
      .uplink_hz = 145'965'000,
      .downlink_hz = 435'640'000,
      .uplink_tuned_hz = 145'962'310,
      .downlink_tuned_hz = 435'648'070,
      .band = "2m",
      .band_rx = "70cm",
      .my_grid = "DM42",
      .station_call = "WA7GXD",
      .power_w = 2.5,
      .note = "first <RS-44> QSO",
      .source = logbook::Source::web,
  };
}

inline logbook::Qso iss_qso() {
  return logbook::Qso{
      .id = 2,
      .call = "K1JT",
      .grid = "FN20xr",
      .time_on = 1796161800,
      .sat_name = "ISS",
      .lotw_name = "ARISS",
      .norad = 25544,
      .mode = "FM",
      .uplink_hz = 145'990'000,
      .downlink_hz = 437'800'000,
      .band = "2m",
      .band_rx = "70cm",
      .my_grid = "DM42",
      .source = logbook::Source::host,
  };
}

}  // namespace tb::testing
