// PstRotator's UDP datagrams (netctl/pst_server.h, --pst-port) on a whole simulated station: the
// input is up to 16 datagrams separated by newlines (a datagram's own "\n" is not needed by the
// protocol), from 127.0.0.1 or, when the first byte is odd, from 192.0.2.9 outside an --allow of
// 127.0.0.0/8. After each, 0.5 s passes and the station ticks.
// Properties: a refused datagram (not allowed, malformed) neither moves the antenna's target nor
// answers; a reply is "AZ:" or "EL:" and a number, printable ASCII; the handler never throws; every
// datagram is counted once (taken or refused).
#include "fuzz_station.h"
#include "netctl/pst_server.h"
#include "rotator/pst/codec.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ProtocolRun run(data, size);
  if (!run) return 0;
  fuzz::ProtocolStation& st = *run.st;
  const bool outsider = size > 0 && (data[0] & 1) != 0;
  netctl::PstHandler handler(*st.station, {"127.0.0.1", {*inet::parse_cidr("127.0.0.0/8")}});
  std::uint64_t seen = 0;
  for (const auto datagram : fuzz::split_lines(run.input, 16)) {
    const auto target = st.station->rotator().status().target;
    const auto before = handler.stats();
    std::vector<std::string> replies;
    try {
      replies = handler.handle(datagram, outsider ? "192.0.2.9" : "127.0.0.1");
    } catch (const std::exception& e) {
      fuzz::violated("the handler threw", e.what());
    }
    ++seen;
    const auto& after = handler.stats();
    TB_FUZZ_CHECK(after.taken + after.refused_bad + after.refused_not_allowed == seen, std::string(datagram));
    const bool refused = after.refused_bad != before.refused_bad || after.refused_not_allowed != before.refused_not_allowed;
    if (refused) {
      TB_FUZZ_CHECK(replies.empty(), std::string(datagram));
      TB_FUZZ_CHECK(st.station->rotator().status().target == target, std::string(datagram));
    }
    TB_FUZZ_CHECK(!outsider || refused, std::string(datagram));
    for (const std::string& r : replies) {
      TB_FUZZ_CHECK(r.size() > 3 && (r.rfind("AZ:", 0) == 0 || r.rfind("EL:", 0) == 0), r);
      TB_FUZZ_CHECK(fuzz::no_control_but(r, ""), r);
      const auto back = rotator::pst::parse_reply(r);
      TB_FUZZ_CHECK(back.az.has_value() || back.el.has_value(), r);
    }
    st.step();
  }
  fuzz::check_model_reads_back(st.model, run.input);
  return 0;
}
