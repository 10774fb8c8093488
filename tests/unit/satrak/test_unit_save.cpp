// Issue 14, defect 3: a setting whose save failed (disk full) is not acknowledged. The command is
// answered ERR,12 (internal); the change holds in memory until the next start, and queries still
// answer. Once a save succeeds again, commands are acknowledged again.
#include <doctest/doctest.h>

#include "fixture.h"

using namespace satrak_test;
using tb::satrak::Error;

namespace {
const orbit::UtcTime kT0 = orbit::from_civil(2026, 5, 21, 12, 0, 0);
std::string err(std::string head, Error e) { return tb::satrak::reply_error(head, e); }
}  // namespace

TEST_CASE("A setting that could not be saved is answered ERR,12, not OK") {
  Acu acu(kT0);
  acu.save_error = "cannot write .trakbox-state.json.tmp-1: No space left on device";
  CHECK(acu.cmd("REDUCTION=,4000,4000") == err("REDUCTION=", Error::internal));
  CHECK(acu.cmd("REDUCTION?") == "REDUCTION?,4000,4000");  // in memory, as the log says
  CHECK(acu.cmd("GPS_SETTINGS=,0,41.02N,29.17E") == err("GPS_SETTINGS=", Error::internal));
  CHECK(acu.cmd("VERSION?").rfind("VERSION?,", 0) == 0);  // queries do not save and still answer
  const int failed_saves = acu.saves;
  CHECK(failed_saves >= 2);

  acu.save_error.reset();  // space again
  CHECK(acu.cmd("REDUCTION=,2000,2000") == "REDUCTION=,OK");
  CHECK(acu.saves == failed_saves + 1);
}

TEST_CASE("A refused command stays refused for its own reason when the disk is full too") {
  Acu acu(kT0);
  acu.save_error = "disk full";
  CHECK(acu.cmd("REDUCTION=,62.5,0") == err("REDUCTION=", Error::out_of_range));
}
