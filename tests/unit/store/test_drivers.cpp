// The drivers' short names and their place in the state (issue 30: --rotator and --radio are
// remembered like --uplink-radio).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "store/drivers.h"
#include "store/model.h"

using tb::store::driver_label;

TEST_CASE("driver labels: SIM, Hamlib's model number, the network peer, else the kind") {
  CHECK(driver_label("") == "SIM");
  CHECK(driver_label("simulated") == "SIM");
  CHECK(driver_label("hamlib:603:/dev/ttyUSB0") == "hamlib 603");
  CHECK(driver_label("hamlib:3081:/dev/ttyUSB1:19200") == "hamlib 3081");
  CHECK(driver_label("rotctld:localhost:4533") == "rotctld localhost");
  CHECK(driver_label("rigctld") == "rigctld");
  CHECK(driver_label("satrak:acu.example:4001") == "satrak acu.example");
  CHECK(driver_label("icom:/dev/ttyUSB1") == "icom");
}

TEST_CASE("the drivers go through the state document, and an older document has none") {
  tb::store::Model m = tb::store::factory_defaults();
  m.rotator_driver = "hamlib:603:/dev/ttyUSB0";
  m.radio_driver = "icom:/dev/ttyUSB1";
  auto j = tb::store::to_json(m);
  const tb::store::Model back = tb::store::model_from_json(j);
  CHECK(back.rotator_driver == m.rotator_driver);
  CHECK(back.radio_driver == m.radio_driver);
  j.erase("drivers");
  CHECK(tb::store::model_from_json(j).rotator_driver.empty());
}
