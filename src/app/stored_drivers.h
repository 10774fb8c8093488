// --rotator, --radio and --uplink-radio are remembered (issue 30): given, they are stored; left
// out, the stored ones are driven (the rotator and radio said to the operator).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cli/tracker_config.h"
#include "store/owner.h"

namespace tb::app {

// Stores the drivers c names, or puts the stored ones into c. The lines to tell the operator go to
// `said`; a stored spec this trakbox cannot use is the error returned.
std::optional<std::string> apply_stored_drivers(TrackerConfig& c, store::ModelOwner& owner,
                                                std::vector<std::string>& said);

}  // namespace tb::app
