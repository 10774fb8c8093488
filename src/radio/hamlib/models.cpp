// Hamlib: any backend through libhamlib, and a rigctld daemon: the registry's rows of this family (radio/registry.h) and the factories they name.
#include "radio/factory.h"
#include "radio/registry.h"
#include "radio/registry_rows.h"

#include "radio/hamlib/hamlib_models.h"
#include "radio/hamlib/hamlib_radio.h"
#include "radio/hamlib/rigctld_link.h"

namespace tb::radio {

namespace {

using std::chrono::milliseconds;

MakeRadio make_hamlib(const RadioModel&, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole) {
  if (hamlib_model_name(spec.model).empty())
    return {nullptr, "--radio hamlib:" + std::to_string(spec.model) + ": Hamlib has no rig model " +
                         std::to_string(spec.model) + " (see rigctl -l)"};
  return {make_hamlib_radio({spec.model, spec.device, spec.baud, spec.scheme}, t.worker), {}};
}

MakeRadio make_rigctld(const RadioModel&, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole) {
  return {make_hamlib_radio({2, spec.host + ":" + std::to_string(spec.port), 0, spec.scheme}, t.worker), {}};
}

// A receiver's remote control (GQRX, SDR++): rigctld's protocol, the downlink only.
MakeRadio make_receiver(const RadioModel& m, const RadioSpec& spec, const RadioConfig&, const DriverTiming& t, RadioRole) {
  RigctldPeer peer{std::string(m.label.substr(0, m.label.find(' '))), true, m.one_client, m.caps.records_audio,
                   m.caps.records_iq, m.caps.reads_recorder};
  auto link = std::make_unique<RigctldLink>(spec.host + ":" + std::to_string(spec.port), HamlibVfoScheme::split, peer);
  return {std::make_unique<WorkerRadio>(std::move(link), t.worker), {}};
}

}  // namespace

std::span<const RadioModel> hamlib_rows() {
  static const RadioModel rows[] = {
      {.name = "hamlib", .label = "any Hamlib backend", .form = SpecForm::hamlib, .protocol = Protocol::hamlib,
       .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1},
       .note = "MODEL: Hamlib's number or name (rigctl -l)", .make = make_hamlib},
      {.name = "rigctld", .label = "a rigctld daemon (NET rigctl)", .form = SpecForm::rigctld,
       .protocol = Protocol::rigctld, .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1},
       .hamlib_model = 2, .note = "HOST 127.0.0.1, PORT 4532 by default", .make = make_rigctld},
      {.name = "gqrx", .label = "GQRX remote control (receiver)", .form = SpecForm::receiver,
       .protocol = Protocol::receiver,
       .caps = {.links = 1, .reads = true, .step_hz = 1, .records_audio = true, .records_iq = true, .reads_recorder = true},
       .port = 7356, .one_client = true,
       .note = "downlink only: no uplink, no tone; records audio (IQ where it has U IQRECORD); HOST 127.0.0.1, "
               "PORT 7356 by default; one client at a time (Tools > Remote control in GQRX)",
       .make = make_receiver},
      {.name = "sdrpp", .label = "SDR++ rigctl server (receiver)", .form = SpecForm::receiver,
       .protocol = Protocol::receiver, .caps = {.links = 1, .reads = true, .step_hz = 1, .records_audio = true},
       .port = 4532, .one_client = true,
       .note = "downlink only: no uplink, no tone; records audio (Recording ticked in its rigctl module); HOST "
               "127.0.0.1, PORT 4532 by default (trakbox's own rigctld server's too: give one of them another); one "
               "client at a time",
       .make = make_receiver},
  };
  return rows;
}

}  // namespace tb::radio
