// `trakbox calibrate sun --scan` (issue 58, docs/calibration.md): a sun-noise scan driven from the
// command line through the running station's socket. It points the antenna over a cross or grid
// around the computed Sun (rotator/sun_scan.h: span 2 beamwidths, step a quarter), each point through
// the station's goto as the holder "sun scan" (inside the limits; a point the limits move is
// skipped), waits for the rotator to arrive and settle, averages several `l STRENGTH` levels of the
// receiver (GQRX's remote control in dBFS; rigctld's S-meter, coarse), fits the peak (fit_scan) and
// reports the offsets, the Sun's noise over cold sky, the -3 dB beamwidths and the scan's duration in
// station (simulated-clock) seconds; --store stores the offsets as calibrate does. It stops, saying
// why, on standby, on anyone else taking the antenna (a Stop, a move, a client), or the Sun below
// 2 deg.
#pragma once
#include <string>

#include "rotator/sun_scan.h"

namespace tb::app {

struct SunScanRequest {
  std::string socket;            // the running station's
  double beam_deg = 0.0;         // --beam: the antenna's -3 dB beamwidth, degrees
  rotator::ScanShape shape = rotator::ScanShape::cross;
  int readings = 5;              // levels averaged at each point
  double settle_s = 1.0;         // station seconds after the rotator arrives
  std::string receiver = "gqrx:127.0.0.1:7356";  // gqrx:HOST:PORT or rigctld:HOST:PORT
  bool store = false;
};

// The exit status: 0 done (fitted; stored with store), 1 stopped or no fit, 2 bad request.
int run_sun_scan(const SunScanRequest& request);

}  // namespace tb::app
