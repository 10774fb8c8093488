// The station file of menu 6-9 against the Model: a parsed file (station_file.h) applied to the
// model as a whole or not at all, and the model written out as a file of either firmware, which
// parse_station_file reads back.
#pragma once
#include <string>
#include <vector>

#include "store/model.h"
#include "store/station_file.h"

namespace tb::store {

// Applies the file to the model (station, rotator span/dead band/skew/parking/limits, radio rig,
// F/A and Icom addresses; from a later-firmware file also what its extra items set, above) when
// the resulting rotator configuration passes rotator::validate; returns its complaints otherwise,
// and then the model is unchanged. What the file does not carry (presets, Doppler corrections,
// the mic-click ADC values, the database; the bauds when not given) is left as it is.
std::vector<std::string> apply_station_file(const StationFile& f, Model& m);

// The model's values as a station file (five lines, each ending in "\n"): what parse reads back.
std::string write_station_file(const Model& m);
// The same in the later firmware's seven-line form (a `;` comment first), with every item it has.
std::string write_station_file_later(const Model& m);

}  // namespace tb::store
