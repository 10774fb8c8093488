// The --rotator option: which rotator trakbox drives.
//   simulated[:mount=AZ,EL]          the simulated rotator (the default); mount: a mounting error, the
//                                    rotator reading AZ and EL degrees more than where the antenna points
//   hamlib:MODEL:DEVICE[:BAUD]       any rotator Hamlib drives, e.g. hamlib:603:/dev/ttyUSB0:9600
//                                    (MODEL is Hamlib's number, `rotctl -l`; the last field is BAUD
//                                    when it is all digits)
//   rotctld:HOST[:PORT]              a rotctld on the network (Hamlib NET rotctl, model 2); PORT
//                                    defaults to 4533; an IPv6 HOST goes in brackets: [::1]:4533
//   easycomm3:DEVICE[:BAUD]          an Easycomm III controller natively (SatNOGS; 19200 baud)
//   easycomm2:DEVICE[:BAUD]          an Easycomm II controller natively (9600 baud)
//   pstrotator:HOST[:PORT]           a box speaking PstRotator's UDP (PORT 12000; replies to PORT+1)
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "rotator/hamlib.h"
#include "rotator/simulated.h"

namespace tb::rotator {

struct RotatorSpec {
  enum class Kind { simulated, hamlib, rotctld, easycomm2, easycomm3, pstrotator };
  Kind kind = Kind::simulated;
  int model = 0;        // hamlib: Hamlib model number (rotctld: 2)
  std::string device;   // hamlib: the serial device; rotctld: HOST:PORT (Hamlib's pathname)
  int baud = 0;         // hamlib, easycomm: serial speed, 0 = the backend's (the protocol's) default
  std::string host;     // rotctld
  int port = 0;         // rotctld
  double mount_az_deg = 0.0;  // simulated: the mounting error (SimulatedRotatorParams::mount_*)
  double mount_el_deg = 0.0;
  friend bool operator==(const RotatorSpec&, const RotatorSpec&) = default;
};

struct SpecResult {
  std::optional<RotatorSpec> spec;
  std::string error;  // what is wrong and what is expected, when there is no spec
};

// Each kind's parser, given the whole --rotator value ("hamlib:603:/dev/ttyUSB0:9600"); the rotator
// registry (rotator/registry.h) picks one by the name before the first ':'. The Hamlib model
// must exist.
SpecResult parse_simulated_spec(std::string_view text);
SpecResult parse_hamlib_spec(std::string_view text);
SpecResult parse_rotctld_spec(std::string_view text);
SpecResult parse_easycomm_spec(std::string_view text);   // easycomm2:... and easycomm3:...
SpecResult parse_pstrotator_spec(std::string_view text);
// The spec written back ("simulated", "hamlib:603:/dev/ttyUSB0:9600", "rotctld:localhost:4533").
std::string to_string(const RotatorSpec& spec);

// The drivers, one factory per kind: the simulated rotator runs on `clock` with `sim`; a Hamlib
// rotator (hamlib: or rotctld:) takes its timings from `hamlib`, and model, pathname and baud from
// the spec.
std::unique_ptr<RotatorDriver> make_simulated_rotator(const station::Clock& clock, const SimulatedRotatorParams& sim = {});
std::unique_ptr<RotatorDriver> make_hamlib_rotator(const RotatorSpec& spec, HamlibOptions hamlib = {});
std::unique_ptr<RotatorDriver> make_easycomm_rotator(const RotatorSpec& spec);
std::unique_ptr<RotatorDriver> make_pst_rotator(const RotatorSpec& spec);

}  // namespace tb::rotator
