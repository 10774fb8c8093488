// Two element sets of Debian gpredict's satellites.dat, written out field by field (no parser
// involved), for the SGP4 tests and benchmarks. Header-only; needs tb_orbit.
#pragma once
#include "orbit/elements.h"

namespace tb::testing {

// ISS (ZARYA): near earth, drag terms active.
// 1 25544U 98067A   18020.89808844  .00002078  00000-0  38550-4 0  9992
// 2 25544  51.6424  32.9776 0003646  28.7227  39.5332 15.54190080 95614
inline orbit::Elements iss_2018() {
  orbit::Elements e;
  e.name = "ISS (ZARYA)";
  e.catalog_number = 25544;
  e.epoch_year = 2018;
  e.epoch_day = 20.89808844;
  e.ndot_over_2 = 0.00002078;
  e.bstar = 0.38550e-4;
  e.inclination_deg = 51.6424;
  e.raan_deg = 32.9776;
  e.eccentricity = 0.0003646;
  e.arg_perigee_deg = 28.7227;
  e.mean_anomaly_deg = 39.5332;
  e.mean_motion_rev_per_day = 15.54190080;
  return e;
}

// MOLNIYA 1-53: deep space, half-day resonance (SGP4's most expensive case), negative BSTAR.
// 1 13070U 82015A   18019.33649993  .00000405  00000-0 -24669-3 0  9992
// 2 13070  62.4528 108.1401 7349782 265.0722  44.8738  2.00563378262951
inline orbit::Elements molniya_2018() {
  orbit::Elements e;
  e.name = "MOLNIYA 1-53";
  e.catalog_number = 13070;
  e.epoch_year = 2018;
  e.epoch_day = 19.33649993;
  e.ndot_over_2 = 0.00000405;
  e.bstar = -0.24669e-3;
  e.inclination_deg = 62.4528;
  e.raan_deg = 108.1401;
  e.eccentricity = 0.7349782;
  e.arg_perigee_deg = 265.0722;
  e.mean_anomaly_deg = 44.8738;
  e.mean_motion_rev_per_day = 2.00563378;
  return e;
}

}  // namespace tb::testing
