#include "station/station.h"

namespace tb::station {
const char* to_string(RotorStart r) { return r == RotorStart::north ? "North" : "South"; }
}  // namespace tb::station
