// The Yaesu family: menu 6-7's FT-736 form (the FT-847 when STATION.DAT names it), the FT-847, FT-817/818 and FT-736R: the registry's rows of this family (radio/registry.h) and the factories they name.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/yaesu/link.h"

namespace tb::radio {

namespace {

using std::chrono::milliseconds;

MakeRadio make_ft736(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole) {
  YaesuOptions o = YaesuOptions::from(config);
  o.byte_gap = t.yaesu_byte_gap;
  if (m.form != SpecForm::device && spec.baud > 0) o.baud = spec.baud;
  return {make_yaesu_radio(spec.device, o, t.worker), {}};
}

MakeRadio make_ft8xx(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  Ft8xxOptions o;
  o.model = m.protocol == Protocol::ft847 ? Ft8xxOptions::Model::ft847 : Ft8xxOptions::Model::ft817;
  o.label = std::string(m.label.substr(m.label.find(' ') + 1));
  o.byte_gap = o.model == Ft8xxOptions::Model::ft817 ? t.ft817_byte_gap : t.yaesu_byte_gap;
  o.baud = spec.baud > 0 ? spec.baud : (m.form == SpecForm::device ? config.cat_baud : m.baud);
  o.satellite_mode = role == RadioRole::both;   // one of two radios: the main VFO alone
  return {make_ft8xx_radio(spec.device, o, t.worker), {}};
}

// yaesu:DEVICE: the FT-736 unless menu 6-7 (STATION.DAT line 4) names the FT-847.
MakeRadio make_yaesu_family(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  if (config.rig_model == RigModel::yaesu_847) return make_ft8xx(*find_radio_model("ft847"), spec, config, t, role);
  return make_ft736(m, spec, config, t, role);
}

}  // namespace

std::span<const RadioModel> yaesu_rows() {
  static const RadioModel rows[] = {
      {.name = "yaesu", .label = "Yaesu FT-736 (FT-847 in menu 6-7)", .protocol = Protocol::ft736, .baud = 4800,
       .satmode = SatCommand::ft736, .caps = {.links = 2, .satellite_mode = true},
       .note = "the FT-847's own opcodes when STATION.DAT names YAESU_847", .make = make_yaesu_family},
      {.name = "ft847", .label = "Yaesu FT-847", .form = SpecForm::device_baud, .protocol = Protocol::ft847,
       .baud = 4800, .satmode = SatCommand::ft847,
       .caps = {.links = 2, .satellite_mode = true, .reads = true, .ctcss = true}, .hamlib_model = 1001,
       .note = "satellite mode 4E; SAT RX / SAT TX opcodes 11/21, read 13/23", .make = make_ft8xx},
      {.name = "ft817", .label = "Yaesu FT-817", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
       .baud = 4800, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1020,
       .note = "one link: a pair is --radio ft817:A --uplink-radio ft817:B", .make = make_ft8xx},
      {.name = "ft818", .label = "Yaesu FT-818", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
       .baud = 4800, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1041, .note = "as the FT-817",
       .make = make_ft8xx},
      {.name = "ft736", .label = "Yaesu FT-736R", .form = SpecForm::device_baud, .protocol = Protocol::ft736,
       .baud = 4800, .satmode = SatCommand::ft736, .caps = {.links = 2, .satellite_mode = true}, .hamlib_model = 1010,
       .note = "satellite mode 0E; never acknowledged, cannot be read", .make = make_ft736},
  };
  return rows;
}

}  // namespace tb::radio
