// Debian gpredict's satellites.dat for the SGP4 and pass tests and the benchmarks: the whole
// catalogue as parsed from the file, and two of its sets written out value by value (no parser
// involved). Header-only; needs tb_orbit.
#pragma once
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "orbit/elements.h"
#include "test_paths.h"  // TRAKBOX_GPREDICT_SATDATA

namespace tb::testing {

// Every element set of the file (979; epochs 2017 Dec 23 to 2018 Jan 22). A missing file throws.
inline std::vector<orbit::Elements> gpredict_catalogue_sets() {
  std::ifstream in(TRAKBOX_GPREDICT_SATDATA, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " TRAKBOX_GPREDICT_SATDATA);
  std::ostringstream text;
  text << in.rdbuf();
  return orbit::parse_gpredict_satdata(text.str(), TRAKBOX_GPREDICT_SATDATA).sets;
}

// An element set from the values SGP4 reads, in the order of the two lines; the other fields keep
// their defaults.
inline orbit::Elements make_elements(std::string name, int catalog_number, int epoch_year, double epoch_day,
                                     double ndot_over_2, double bstar, double inclination_deg, double raan_deg,
                                     double eccentricity, double arg_perigee_deg, double mean_anomaly_deg,
                                     double mean_motion_rev_per_day) {
  return orbit::Elements{.name = std::move(name),
                         .catalog_number = catalog_number,
                         .international_designator = {},
                         .epoch_year = epoch_year,
                         .epoch_day = epoch_day,
                         .ndot_over_2 = ndot_over_2,
                         .bstar = bstar,
                         .inclination_deg = inclination_deg,
                         .raan_deg = raan_deg,
                         .eccentricity = eccentricity,
                         .arg_perigee_deg = arg_perigee_deg,
                         .mean_anomaly_deg = mean_anomaly_deg,
                         .mean_motion_rev_per_day = mean_motion_rev_per_day};
}

// ISS (ZARYA): near earth, drag terms active.
// 1 25544U 98067A   18020.89808844  .00002078  00000-0  38550-4 0  9992
// 2 25544  51.6424  32.9776 0003646  28.7227  39.5332 15.54190080 95614
inline orbit::Elements iss_2018() {
  return make_elements("ISS (ZARYA)", 25544, 2018, 20.89808844, 0.00002078, 0.38550e-4, 51.6424, 32.9776,
                       0.0003646, 28.7227, 39.5332, 15.54190080);
}

// MOLNIYA 1-53: deep space, half-day resonance (SGP4's most expensive case), negative BSTAR.
// 1 13070U 82015A   18019.33649993  .00000405  00000-0 -24669-3 0  9992
// 2 13070  62.4528 108.1401 7349782 265.0722  44.8738  2.00563378262951
inline orbit::Elements molniya_2018() {
  return make_elements("MOLNIYA 1-53", 13070, 2018, 19.33649993, 0.00000405, -0.24669e-3, 62.4528, 108.1401,
                       0.7349782, 265.0722, 44.8738, 2.00563378);
}

}  // namespace tb::testing
