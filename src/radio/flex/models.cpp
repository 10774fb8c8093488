// FlexRadio 6000/8000 over the SmartSDR TCP/IP API: the registry's row of this family
// (radio/registry.h) and the factory it names.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/flex/link.h"

namespace tb::radio {

namespace {

MakeRadio make_flex(const RadioModel&, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole role) {
  FlexOptions o;
  o.host = spec.host;
  o.port = spec.port;
  o.role = role;
  o.full_duplex = spec.full_duplex;
  return {make_flex_radio(o, t.worker), {}};
}

}  // namespace

std::span<const RadioModel> flex_rows() {
  static const RadioModel rows[] = {
      {.name = "flex", .label = "FlexRadio 6000/8000 (SmartSDR)", .form = SpecForm::flex, .protocol = Protocol::flex,
       .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 2036, .port = 4992,
       .note = "SmartSDR TCP API, slices as links (down: a receive slice, up: the tx=1 slice); "
               "HOST 127.0.0.1, PORT 4992 by default; :duplex switches full duplex on (two SCUs: "
               "FLEX-6600/6700/8600); Hamlib's 2036 is its CAT port",
       .make = make_flex},
  };
  return rows;
}

}  // namespace tb::radio
