// Host mode (menu 7, `trakbox host`, --host-port) on a whole simulated station, line by line.
//
// First byte even: host::Interpreter, as menu 7 and `trakbox host` run it; odd: netctl::HostProtocol,
// as the TCP server runs it. The rest is cut into lines (at most 64); after each, 0.5 s passes and the
// station ticks. Bit 1 of the first byte starts with rotor control off, bit 2 with tracking on.
// Properties: a refused command is one "ERROR ..." line and leaves the antenna's target, the radio
// and tracking alone; a reply never carries a control character onto the TCP client's line; the
// model left behind reads back.
#include "fuzz_station.h"
#include "host/host_mode.h"
#include "netctl/host_server.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ProtocolRun run(data, size);
  if (!run) return 0;
  const std::uint8_t mode = run.mode;
  const std::string_view input = run.input;
  fuzz::ProtocolStation& st = *run.st;
  host::Interpreter interpreter(*st.station);
  netctl::HostProtocol protocol(*st.station);
  if (mode & 1) TB_FUZZ_CHECK(fuzz::clean_host_reply(protocol.greeting()), protocol.greeting());

  for (const auto line : fuzz::split_lines(input, 64)) {
    if (mode & 1) {
      const netctl::Reply r = protocol.handle(line);
      TB_FUZZ_CHECK(fuzz::clean_host_reply(r.text), r.text);
      if (r.close) break;
    } else {
      const auto target = st.station->rotator().status().target;
      const auto sent = st.radio_sim->history().size();
      const auto tracking = st.tracker.mode();
      const host::Reply r = interpreter.execute(line);
      if (!r.ok) {
        TB_FUZZ_CHECK(r.lines.size() == 1 && r.lines[0].rfind("ERROR ", 0) == 0, std::string(line));
        if (r.lines[0].find("radio fault") == std::string::npos) {
          TB_FUZZ_CHECK(st.station->rotator().status().target == target, std::string(line));
          TB_FUZZ_CHECK(st.radio_sim->history().size() == sent, std::string(line));
          TB_FUZZ_CHECK(st.tracker.mode() == tracking, std::string(line));
        }
      }
      if (r.quit) break;
    }
    st.step();
  }
  fuzz::check_model_reads_back(st.model, input);
  return 0;
}
