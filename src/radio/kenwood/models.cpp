// The Kenwood family: menu 6-7's TS-790/711/811 form, the TS-2000 and TS-790: the registry's rows of this family (radio/registry.h) and the factories they name.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/kenwood/link.h"

namespace tb::radio {

namespace {

using std::chrono::milliseconds;

MakeRadio make_kenwood(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  KenwoodOptions o = KenwoodOptions::from(config);
  if (m.form != SpecForm::device) {
    o.baud = spec.baud > 0 ? spec.baud : m.baud;
    o.reads = m.caps.reads;
    o.ctcss = m.caps.ctcss;
    o.model = std::string(m.label);
    o.label = o.model;   // a model's row names it; the family's (menu 6-7's rig) says "Kenwood"
    o.one_link = role != RadioRole::both;
    if (m.satmode == SatCommand::kenwood_sa) {   // (:mainup is refused by parse_radio_spec)
      o.vfo_select = 'R';
      o.satellite_mode = role == RadioRole::both;
    }
  }
  return {make_kenwood_radio(spec.device, o, t.worker), {}};
}

}  // namespace

std::span<const RadioModel> kenwood_rows() {
  static const RadioModel rows[] = {
      {.name = "kenwood", .label = "Kenwood TS-790/711/811", .protocol = Protocol::kenwood, .baud = 4800,
       .caps = {.links = 2}, .note = "downlink VFO A, uplink VFO B", .make = make_kenwood},
      {.name = "ts2000", .label = "Kenwood TS-2000", .form = SpecForm::device_baud, .protocol = Protocol::kenwood,
       .baud = 9600, .main_link = Link::downlink, .satmode = SatCommand::kenwood_sa,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 2014,
       .note = "satellite mode SA: Main down (FA), Sub up (FB); TN/TO tone; read with FA;/FB;", .make = make_kenwood},
      {.name = "ts790", .label = "Kenwood TS-790", .form = SpecForm::device_baud, .protocol = Protocol::kenwood,
       .baud = 4800, .caps = {.links = 2}, .hamlib_model = 2007, .note = "VFO A down, B up", .make = make_kenwood},
  };
  return rows;
}

}  // namespace tb::radio
