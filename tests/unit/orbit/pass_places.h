// The stations and the day the pass tests search (test_passes.cpp's Skyfield references were
// computed for them; test_pass_tools.cpp plans over the same day), written once; a test file takes
// them all with `using namespace tb::testing::pass_places`.
#pragma once
#include "orbit/observe.h"
#include "orbit/time.h"

namespace tb::testing::pass_places {

inline const orbit::Observer kDarmstadt{49.8706, 8.6494, 140.0};
inline const orbit::Observer kSydney{-33.8688, 151.2093, 50.0};
inline const orbit::UtcTime kDay0 = orbit::from_civil(2018, 1, 21);   // 2018-01-21T00:00Z
inline const orbit::UtcTime kDay1 = orbit::from_civil(2018, 1, 22);

}  // namespace tb::testing::pass_places
