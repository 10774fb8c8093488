// --radio SPEC: which driver, where. The forms come from the radio registry (radio/registry.h,
// `trakbox --radio list`):
//   sim | simulated | (empty)          the simulated radio (default)
//   MODEL:DEVICE[:BAUD][:maindown|:mainup]   a model of the registry (ic9700, ft847, ts2000 ...)
//                                      with its defaults (CI-V address, speed, satellite mode);
//                                      ic905:...[:xvtr] with its 10 GHz transverter
//   icom:DEVICE                        Icom CI-V, 1200 8N2, addresses from menu 6-7
//   kenwood:DEVICE                     Kenwood TS-790/711/811, 4800 8N2
//   yaesu:DEVICE                       Yaesu FT-736, 4800 8N2
//   cat:DEVICE                         the rig chosen in menu 6-7 (Icom/Kenwood/Yaesu)
//   hamlib:MODEL:DEVICE[:BAUD][:split|:mainsub]   any Hamlib backend; MODEL is Hamlib's number or
//                                                 its name (IC-9700, ic9700: rigctl -l)
//   rigctld[:HOST[:PORT]][:split|:mainsub]        a rigctld daemon (Hamlib NET rigctl, model 2);
//                                                 HOST defaults to 127.0.0.1, PORT to 4532
//   flex[:HOST[:PORT]][:duplex]                   a FlexRadio 6000/8000 (SmartSDR TCP API, 4992)
// Parsing is separate from opening so a bad spec is reported before anything starts; opening
// never blocks (the drivers connect on their worker thread).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "radio/config.h"
#include "radio/registry.h"
#include "radio/driver.h"
#include "radio/hamlib/hamlib_radio.h"
#include "radio/worker.h"

namespace tb::radio {

struct RadioSpec {
  std::string name = "sim";        // the registry entry (radio/registry.h): "ic9700", "icom", ...;
                                   // its row says the protocol and everything else
  std::optional<Link> main_link;   // :maindown / :mainup: overrides the model's satellite-mode band
  bool transverter = false;        // :xvtr: the IC-905's 10 GHz transverter is fitted (RadioModel::xvtr_from)
  std::string device;          // icom/kenwood/yaesu/cat/hamlib
  int model = 0;               // hamlib
  int baud = 0;                // hamlib, registry models (0: the default)
  std::string host;            // rigctld
  int port = 0;                // rigctld, gqrx, flex
  bool full_duplex = false;    // flex:...:duplex: SmartSDR's full duplex switched on
  HamlibVfoScheme scheme = HamlibVfoScheme::automatic;
};

struct RadioSpecParse {
  std::optional<RadioSpec> spec;
  std::string error;           // set when spec is empty
};
// option names the option in the messages ("--radio", "--uplink-radio").
RadioSpecParse parse_radio_spec(std::string_view text, std::string_view option = "--radio");

struct DriverTiming {
  WorkerTiming worker;
  // Between the bytes of a 5-byte Yaesu command: Hamlib's write_delay, 50 ms for the FT-736 and
  // FT-847 (ft847.h), 1 ms for the FT-817/818 (ft817.h). A slow line widens the moment in which
  // a turn of the dial is overwritten (docs/radio.md, dial follow).
  std::chrono::milliseconds yaesu_byte_gap{50};
  std::chrono::milliseconds ft817_byte_gap{1};
  // The CI-V waits (tests on a loaded machine lengthen them).
  std::chrono::milliseconds icom_echo_margin{250};
  std::chrono::milliseconds icom_reply_timeout{300};
};

struct MakeRadio {
  std::unique_ptr<RadioDriver> driver;
  std::string error;
};
// Builds the driver for a parsed spec with the station's menu 6-7 configuration.
MakeRadio make_radio(const RadioSpec& spec, const RadioConfig& config, const DriverTiming& timing = {},
                     RadioRole role = RadioRole::both);
MakeRadio make_radio(std::string_view spec, const RadioConfig& config, const DriverTiming& timing = {});
// The downlink radio, and the uplink radio when uplink_spec names one: two radios as one driver
// (radio/two_radios.h). nullopt uplink_spec: the downlink radio carries both links.
MakeRadio make_radios(const RadioSpec& downlink_spec, const std::optional<RadioSpec>& uplink_spec,
                      const RadioConfig& config, const DriverTiming& timing = {});

}  // namespace tb::radio
