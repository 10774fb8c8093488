// The Yaesu family: menu 6-7's FT-736 form (the FT-847 when STATION.DAT names it), the FT-847,
// FT-817/818, FT-857, FT-897 and FT-736R: the registry's rows of this family (radio/registry.h) and the factories they name.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/yaesu/link.h"
#include "radio/yaesu/newcat_link.h"

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
  o.bands.assign(m.bands.begin(), m.bands.end());
  return {make_ft8xx_radio(spec.device, o, t.worker), {}};
}

// yaesu:DEVICE: the FT-736 unless menu 6-7 (STATION.DAT line 4) names the FT-847.
MakeRadio make_yaesu_family(const RadioModel& m, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  if (config.rig_model == RigModel::yaesu_847) return make_ft8xx(*find_radio_model("ft847"), spec, config, t, role);
  return make_ft736(m, spec, config, t, role);
}

// FT-857/857D and FT-897/897D: 0.1-56, 76-108 (receive), 118-164 and 420-470 MHz (the manuals'
// specifications): no 23 cm.
constexpr Hz kKHz = 1000, kMHz = 1000 * kKHz;
constexpr HzRange kFt857Bands[] = {
    {100 * kKHz, 56 * kMHz}, {76 * kMHz, 108 * kMHz}, {118 * kMHz, 164 * kMHz}, {420 * kMHz, 470 * kMHz}};

// The ASCII family: FT-991/991A 0.03-56, 118-164 (receive) and 420-470 MHz; FTX-1 the same bands;
// FT-710 and FTdx10 0.03-75 MHz (HF, 6 m, 4 m).
constexpr HzRange kFt991Bands[] = {{30 * kKHz, 56 * kMHz}, {118 * kMHz, 164 * kMHz}, {420 * kMHz, 470 * kMHz}};
constexpr HzRange kHf6Bands[] = {{30 * kKHz, 75 * kMHz}};

MakeRadio make_newcat(const RadioModel& m, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole role) {
  NewcatOptions o;
  o.label = std::string(m.label.substr(m.label.find(' ') + 1));
  o.vfo_b = role == RadioRole::uplink;
  o.baud = spec.baud > 0 ? spec.baud : m.baud;
  o.bands.assign(m.bands.begin(), m.bands.end());
  o.ctcss = m.caps.ctcss;
  if (m.name == "ft991") o.ids = {"0670", "0570"}, o.fm_dial_lock = true;
  else if (m.name == "ftx1") o.ids = {"0840"}, o.mode_md1 = true;
  else if (m.name == "ft710") o.ids = {"0800"};
  else if (m.name == "ftdx10") o.ids = {"0761"};
  return {make_newcat_radio(spec.device, o, t.worker), {}};
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
      {.name = "ft857", .label = "Yaesu FT-857", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
       .baud = 4800, .bands = kFt857Bands, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1022,
       .note = "FT-857/857D: the FT-817's commands, one link (CAT speed menu 020)", .make = make_ft8xx},
      {.name = "ft897", .label = "Yaesu FT-897", .form = SpecForm::device_baud, .protocol = Protocol::ft817,
       .baud = 4800, .bands = kFt857Bands, .caps = {.reads = true, .ctcss = true}, .hamlib_model = 1023,
       .note = "FT-897/897D: the FT-817's commands, one link", .make = make_ft8xx},
      {.name = "ft991", .label = "Yaesu FT-991A", .form = SpecForm::device_baud, .protocol = Protocol::newcat,
       .baud = 4800, .bands = kFt991Bands, .caps = {.reads = true, .ctcss = true, .step_hz = 1}, .hamlib_model = 1035,
       .note = "FT-991/991A (ID0670;): one link; as the uplink on VFO-B; FM locks the dial (LK)", .make = make_newcat},
      {.name = "ftx1", .label = "Yaesu FTX-1", .form = SpecForm::device_baud, .protocol = Protocol::newcat,
       .baud = 38400, .bands = kFt991Bands, .caps = {.reads = true, .step_hz = 1},
       .note = "ID0840;: one link; as the uplink FB and MD1 (Sub); never ST", .make = make_newcat},
      {.name = "ft710", .label = "Yaesu FT-710", .form = SpecForm::device_baud, .protocol = Protocol::newcat,
       .baud = 38400, .bands = kHf6Bands, .caps = {.reads = true, .step_hz = 1}, .hamlib_model = 1049,
       .note = "ID0800;: HF/6 m, one link; as the uplink on VFO-B", .make = make_newcat},
      {.name = "ftdx10", .label = "Yaesu FTdx10", .form = SpecForm::device_baud, .protocol = Protocol::newcat,
       .baud = 38400, .bands = kHf6Bands, .caps = {.reads = true, .step_hz = 1}, .hamlib_model = 1042,
       .note = "ID0761;: HF/6 m, one link; as the uplink on VFO-B", .make = make_newcat},
      {.name = "ft736", .label = "Yaesu FT-736R", .form = SpecForm::device_baud, .protocol = Protocol::ft736,
       .baud = 4800, .satmode = SatCommand::ft736, .caps = {.links = 2, .satellite_mode = true}, .hamlib_model = 1010,
       .note = "satellite mode 0E; never acknowledged, cannot be read", .make = make_ft736},
  };
  return rows;
}

}  // namespace tb::radio
