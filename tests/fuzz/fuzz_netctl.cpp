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

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ProtocolRun run(data, size);
  if (!run) return 0;
  fuzz::ProtocolStation& st = *run.st;
  const std::string_view input = run.input;
#ifdef FUZZ_RIGCTL
  const auto protocol = std::make_unique<netctl::RigctlProtocol>(*st.station);
#else
  const auto protocol = std::make_unique<netctl::RotctlProtocol>(*st.station);
#endif

  for (const auto line : fuzz::split_lines(input, 64)) {
    const auto target = st.station->rotator().status().target;
    const auto sent = st.radio_sim->history().size();
    const netctl::Reply r = protocol->handle(line);
    TB_FUZZ_CHECK(fuzz::clean_hamlib_reply(r.text), r.text);
    if (r.text.find("RPRT -") != std::string::npos) {
      TB_FUZZ_CHECK(st.station->rotator().status().target == target, std::string(line) + " -> " + r.text);
      TB_FUZZ_CHECK(st.radio_sim->history().size() == sent, std::string(line) + " -> " + r.text);
    }
    if (r.close) break;
    st.step();
  }
  // The overlong-line answer, as the server sends it.
  TB_FUZZ_CHECK(fuzz::clean_hamlib_reply(protocol->overlong().text), protocol->overlong().text);
  fuzz::check_model_reads_back(st.model, input);
  return 0;
}
