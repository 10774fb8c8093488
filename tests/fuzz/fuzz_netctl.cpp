// The rotctld and rigctld protocols (what Gpredict and Hamlib clients send) on a whole simulated
// station, line by line. One source, two targets: fuzz_rotctl (netctl::RotctlProtocol) and
// fuzz_rigctl (netctl::RigctlProtocol, built with FUZZ_RIGCTL), each with its corpus and dictionary.
// Bit 1 of the first byte starts with rotor control off, bit 2 with the tracker following a
// satellite (so the rigctl refusals while the tracker tunes are reached). At most 64 lines; after
// each, 0.5 s passes and the station ticks.
// Properties: a reply is text on its lines (no control character but line ends and tabs); a refused
// command (RPRT n < 0) leaves the antenna's target and the radio alone; the model reads back.
#include "fuzz_station.h"
#include "netctl/rigctl_protocol.h"
#include "netctl/rotctl_protocol.h"

using namespace tb;

namespace {
bool clean(std::string_view s) { return fuzz::no_control_but(s, "\n\t"); }  // dump_caps has "Key:\tvalue"
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t mode = data[0];
  const std::string_view input = fuzz::as_text(data + 1, size - 1);

  fuzz::ProtocolStation st(mode);
#ifdef FUZZ_RIGCTL
  const auto protocol = std::make_unique<netctl::RigctlProtocol>(*st.station);
#else
  const auto protocol = std::make_unique<netctl::RotctlProtocol>(*st.station);
#endif

  for (const auto line : fuzz::split_lines(input, 64)) {
    const auto target = st.station->rotator().status().target;
    const auto sent = st.radio_sim->history().size();
    const netctl::Reply r = protocol->handle(line);
    TB_FUZZ_CHECK(clean(r.text), r.text);
    if (r.text.find("RPRT -") != std::string::npos) {
      TB_FUZZ_CHECK(st.station->rotator().status().target == target, std::string(line) + " -> " + r.text);
      TB_FUZZ_CHECK(st.radio_sim->history().size() == sent, std::string(line) + " -> " + r.text);
    }
    if (r.close) break;
    st.step();
  }
  // The overlong-line answer, as the server sends it.
  TB_FUZZ_CHECK(clean(protocol->overlong().text), protocol->overlong().text);
  fuzz::check_model_reads_back(st.model, input);
  return 0;
}
