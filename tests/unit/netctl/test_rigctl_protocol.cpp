// The rigctld protocol against a whole simulated station: every command short and long, the VFO
// mapping (A / Main = downlink, B / Sub = uplink), the Extended Response Protocol, malformed input,
// and the rules (10 Hz step, no fighting trakbox's own Doppler, a radio in fault).
#include <doctest/doctest.h>

#include "fixture.h"
#include "netctl/rigctl_protocol.h"
#include "tracker/operations.h"

using namespace tb;
using namespace nettest;
using netctl::RigctlProtocol;
using Rig = ProtocolOn<RigctlProtocol>;  // a fresh station and the protocol on it
using radio::Link;

TEST_CASE_FIXTURE(Rig, "rigctl: F / f and \\set_freq / \\get_freq tune the current VFO's link") {
  CHECK(ask(p, "f") == "0\n");  // nothing tuned yet
  CHECK(ask(p, "F 145950000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::downlink) == 145950000);
  CHECK(!st.radio_sim->frequency(Link::uplink));
  CHECK(ask(p, "f") == "145950000\n");
  CHECK(ask(p, "\\get_freq") == "145950000\n");
  // Hamlib's NET client sends "%f"; trakbox's radios take 10 Hz steps.
  CHECK(ask(p, "\\set_freq 145800003.000000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::downlink) == 145800000);
  CHECK(ask(p, "F 145800005.6") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::downlink) == 145800010);
  CHECK(ask(p, "F1.4595e8") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::downlink) == 145950000);
  const auto h = st.radio_sim->history();
  REQUIRE(h.size() == 4);
  CHECK(h.back() == radio::RadioEvent{radio::RadioEvent::Kind::frequency, Link::downlink, 145950000, radio::Mode::none, {}});
}

TEST_CASE_FIXTURE(Rig, "rigctl: V / v select the link: VFO A / Main / RX = downlink, VFO B / Sub / TX = uplink") {
  CHECK(ask(p, "v") == "VFOA\n");
  CHECK(ask(p, "V VFOB") == "RPRT 0\n");
  CHECK(p.current_link() == Link::uplink);
  CHECK(ask(p, "v") == "VFOB\n");
  CHECK(ask(p, "F 435100000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::uplink) == 435100000);
  CHECK(ask(p, "f") == "435100000\n");
  CHECK(ask(p, "\\set_vfo Main") == "RPRT 0\n");
  CHECK(ask(p, "\\get_vfo") == "Main\n");
  CHECK(ask(p, "F 145900000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::downlink) == 145900000);
  CHECK(ask(p, "V Sub") == "RPRT 0\n");
  CHECK(ask(p, "v") == "Sub\n");
  CHECK(ask(p, "V currVFO") == "RPRT 0\n");  // stays
  CHECK(ask(p, "v") == "Sub\n");
  CHECK(ask(p, "V RX") == "RPRT 0\n");
  CHECK(ask(p, "v") == "VFOA\n");
  CHECK(ask(p, "V TX") == "RPRT 0\n");
  CHECK(ask(p, "v") == "VFOB\n");
  CHECK(ask(p, "+v") == "get_vfo:\nVFO: VFOB\nRPRT 0\n");
  // VFOs trakbox has no link for.
  CHECK(ask(p, "V VFOC") == "RPRT -16\n");
  CHECK(ask(p, "V MEM") == "RPRT -16\n");
  CHECK(ask(p, "V SubB") == "RPRT -16\n");
  CHECK(ask(p, "V xyz") == "RPRT -16\n");
  CHECK(ask(p, "V") == "RPRT -1\n");
  CHECK(ask(p, "V VFOA VFOB") == "RPRT -1\n");
  CHECK(ask(p, "v") == "VFOB\n");
  CHECK(ask(p, "V ?") == "VFOA VFOB Main Sub currVFO\nRPRT 0\n");
}

TEST_CASE_FIXTURE(Rig, "rigctl: I / i and X / x set the uplink (the split TX VFO) whatever VFO is current") {
  CHECK(ask(p, "i") == "0\n");
  CHECK(ask(p, "I 435100000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::uplink) == 435100000);
  CHECK(!st.radio_sim->frequency(Link::downlink));
  CHECK(ask(p, "i") == "435100000\n");
  CHECK(ask(p, "\\set_split_freq 435100020") == "RPRT 0\n");
  CHECK(ask(p, "\\get_split_freq") == "435100020\n");
  CHECK(ask(p, "+i") == "get_split_freq:\nTX Frequency: 435100020\nRPRT 0\n");
  CHECK(ask(p, "+I 435100000") == "set_split_freq: 435100000\nRPRT 0\n");

  CHECK(ask(p, "x") == "RPRT -6\n");
  CHECK(ask(p, "X LSB 2400") == "RPRT 0\n");
  CHECK(st.radio_sim->mode(Link::uplink) == radio::Mode::lsb);
  CHECK(ask(p, "x") == "LSB\n0\n");
  CHECK(ask(p, "\\set_split_mode FM 0") == "RPRT 0\n");
  CHECK(ask(p, "\\get_split_mode") == "FM\n0\n");
  CHECK(ask(p, "+x") == "get_split_mode:\nTX Mode: FM\nTX Passband: 0\nRPRT 0\n");
  CHECK(!st.radio_sim->mode(Link::downlink));
}

TEST_CASE_FIXTURE(Rig, "rigctl: M / m set and read the current VFO's mode") {
  CHECK(ask(p, "m") == "RPRT -6\n");
  CHECK(ask(p, "M USB 2400") == "RPRT 0\n");
  CHECK(st.radio_sim->mode(Link::downlink) == radio::Mode::usb);
  CHECK(ask(p, "m") == "USB\n0\n");
  CHECK(ask(p, "\\set_mode CW -1") == "RPRT 0\n");
  CHECK(ask(p, "\\get_mode") == "CW\n0\n");
  CHECK(ask(p, "+m") == "get_mode:\nMode: CW\nPassband: 0\nRPRT 0\n");
  CHECK(ask(p, "+M FM 15000") == "set_mode: FM 15000\nRPRT 0\n");
  CHECK(ask(p, ";\\get_mode") == "get_mode:;Mode: FM;Passband: 0;RPRT 0\n");
  CHECK(ask(p, "|M LSB 0") == "set_mode: LSB 0|RPRT 0\n");
  CHECK(ask(p, "V VFOB") == "RPRT 0\n");
  CHECK(ask(p, "M USB 0") == "RPRT 0\n");
  CHECK(st.radio_sim->mode(Link::uplink) == radio::Mode::usb);
  CHECK(st.radio_sim->mode(Link::downlink) == radio::Mode::lsb);
  CHECK(ask(p, "M ?") == "USB LSB CW FM\nRPRT 0\n");
  CHECK(ask(p, "X ?") == "USB LSB CW FM\nRPRT 0\n");
}

TEST_CASE_FIXTURE(Rig, "rigctl: S / s split; T / t PTT") {
  CHECK(ask(p, "s") == "0\nVFOB\n");
  CHECK(ask(p, "S 1 VFOB") == "RPRT 0\n");
  CHECK(p.split());
  CHECK(ask(p, "s") == "1\nVFOB\n");
  CHECK(ask(p, "\\set_split_vfo 1 Sub") == "RPRT 0\n");
  CHECK(ask(p, "\\get_split_vfo") == "1\nSub\n");
  CHECK(ask(p, "+s") == "get_split_vfo:\nSplit: 1\nTX VFO: Sub\nRPRT 0\n");
  CHECK(ask(p, "S 1 VFOA") == "RPRT -16\n");  // trakbox transmits on the uplink, VFO B
  CHECK(ask(p, "S 2 VFOB") == "RPRT -1\n");
  CHECK(ask(p, "S 1") == "RPRT -1\n");
  CHECK(ask(p, "S 1 VFOC") == "RPRT -16\n");
  CHECK(ask(p, "s") == "1\nSub\n");
  CHECK(ask(p, "S 0 VFOA") == "RPRT 0\n");
  CHECK(ask(p, "s") == "0\nSub\n");

  CHECK(ask(p, "t") == "0\n");
  CHECK(ask(p, "\\get_ptt") == "0\n");
  CHECK(ask(p, "+t") == "get_ptt:\nPTT: 0\nRPRT 0\n");
  CHECK(ask(p, "T 0") == "RPRT 0\n");
  CHECK(ask(p, "\\set_ptt 0") == "RPRT 0\n");
  CHECK(ask(p, "T 1") == "RPRT -11\n");  // trakbox has no PTT line
  CHECK(ask(p, "T 3") == "RPRT -11\n");
  CHECK(ask(p, "T 4") == "RPRT -1\n");
  CHECK(ask(p, "T") == "RPRT -1\n");
  CHECK(ask(p, "t") == "0\n");
  CHECK(st.radio_sim->history().empty());
}

TEST_CASE_FIXTURE(Rig, "rigctl: what Hamlib's NET client asks when it opens") {
  CHECK(ask(p, "\\chk_vfo") == "0\n");
  CHECK(ask(p, "+\\chk_vfo") == "chk_vfo:\nChkVFO: 0\nRPRT 0\n");
  CHECK(ask(p, "\\get_powerstat") == "1\n");
  CHECK(ask(p, "\\get_lock_mode") == "0\n");
  const auto l = lines(ask(p, "\\dump_state"));
  REQUIRE(l.size() > 20);
  CHECK(l[0] == "1");  // protocol 1
  CHECK(l[3] == "10000.000000 100000000000.000000 0x2e -1 -1 0x3 0x0");
  CHECK(l[4] == "0 0 0 0 0 0 0");
  CHECK(l[6] == "0 0 0 0 0 0 0");
  CHECK(l.back() == "done");
  CHECK(std::find(l.begin(), l.end(), "RPRT 0") == l.end());
  CHECK(ask(p, "_") == "trakbox radio (simulated radio)\n");
  CHECK(ask(p, "+\\get_info") == "get_info:\nInfo: trakbox radio (simulated radio)\nRPRT 0\n");
  const std::string caps = ask(p, "\\dump_caps");
  CHECK(caps.find("VFO list:\tVFOA (downlink) VFOB (uplink)\n") != std::string::npos);
  CHECK(ask(p, "1") == caps);
  const auto q = p.handle("q");
  CHECK(q.close);
  CHECK(q.text == "RPRT 0\n");  // netrigctl_close reads it
}

TEST_CASE_FIXTURE(Rig, "rigctl: malformed requests are answered RPRT -1 / -8 / -11 and change nothing") {
  REQUIRE(ask(p, "F 145950000") == "RPRT 0\n");
  REQUIRE(ask(p, "I 435100000") == "RPRT 0\n");
  REQUIRE(ask(p, "M USB 2400") == "RPRT 0\n");
  const auto before = st.radio_sim->history();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"F abc", "RPRT -1\n"},
      {"F", "RPRT -1\n"},
      {"F 145950000 145950000", "RPRT -1\n"},
      {"F -145950000", "RPRT -1\n"},
      {"F 0", "RPRT -1\n"},
      {"F 9999", "RPRT -1\n"},           // below 10 kHz
      {"F 100000000001", "RPRT -1\n"},   // above 100 GHz
      {"F 1e300", "RPRT -1\n"},
      {"F nan", "RPRT -1\n"},
      {"F 145.95MHz", "RPRT -1\n"},
      {"\\set_freq", "RPRT -1\n"},
      {"I", "RPRT -1\n"},
      {"I 1x", "RPRT -1\n"},
      {"M", "RPRT -1\n"},
      {"M USB", "RPRT -1\n"},
      {"M AM 0", "RPRT -1\n"},           // not a mode trakbox's radios take
      {"M None 0", "RPRT -1\n"},
      {"M USB wide", "RPRT -1\n"},
      {"M USB -2", "RPRT -1\n"},
      {"X WFM 0", "RPRT -1\n"},
      {"f VFOA", "RPRT -1\n"},           // no VFO arguments (chk_vfo says 0)
      {"W", "RPRT -11\n"},               // unknown
      {"J 100", "RPRT -11\n"},           // Hamlib's RIT: not offered
      {"\\set_level AF 0.5", "RPRT -11\n"},
      {"\\set_powerstat 0", "RPRT -11\n"},
      {std::string(netctl::kMaxLineLength + 10, 'F'), "RPRT -8\n"},
  };
  for (const auto& [line, want] : cases) {
    CAPTURE(line);
    CHECK(ask(p, line) == want);
  }
  CHECK(st.radio_sim->history() == before);
  CHECK(ask(p, "f") == "145950000\n");
  CHECK(ask(p, "+F abc") == "set_freq: abc\nRPRT -1\n");
  CHECK(ask(p, "+W 1") == "W: 1\nRPRT -11\n");
  // Found by fuzzing: the Extended Response echo carried the request's control bytes back as they
  // were (a NUL, an ESC). They are blanks, like control bytes in every value.
  CHECK(ask(p, std::string("+F 4\0\x1b[2J", 9)) == "set_freq: 4  [2J\nRPRT -1\n");
  CHECK(ask(p, "+\x01 x") == " : x\nRPRT -11\n");
  CHECK(st.radio_sim->history() == before);
}

TEST_CASE("rigctl: a set takes the radio from trakbox's Doppler (issue 44); standby refuses it (RPRT -9)") {
  store::Model m = shipped_model();
  m.radio.uplink_correction = false;  // trakbox corrects the downlink only
  SimStation st(m);
  RigctlProtocol p(*st.station);
  const auto ao7 = st.model.db.find("AO-07");
  REQUIRE(ao7);
  st.tracker.track_single(*ao7);
  st.step();
  REQUIRE(st.station->tuner().satellite().has_downlink());
  CHECK(ask(p, "F 145950000") == "RPRT 0\n");
  CHECK(st.station->control().holder(tracker::Resource::radio).kind == tracker::HolderKind::rigctld);
  CHECK(st.station->control().tracking_drives(tracker::Resource::antenna));  // held separately
  st.step();
  st.step();
  CHECK(st.radio_sim->frequency(Link::downlink) == 145950000);  // Doppler paused: the client's stays
  CHECK(ask(p, "I 432150000") == "RPRT 0\n");
  CHECK(st.radio_sim->frequency(Link::uplink) == 432150000);
  // It goes: trakbox's tracking holds the radio again.
  p.client_left("");
  st.step();
  CHECK(st.station->control().tracking_drives(tracker::Resource::radio));
  // Standby: refused, nothing sent.
  REQUIRE(tracker::StationOps(*st.station).standby(true).ok());
  const auto before = st.radio_sim->history();
  CHECK(ask(p, "F 145950000") == "RPRT -9\n");
  CHECK(ask(p, "M USB 0") == "RPRT -9\n");
  CHECK(st.radio_sim->history() == before);
}

TEST_CASE_FIXTURE(Rig, "rigctl: a radio in fault refuses sets (RPRT -6) and reads back what it last took") {
  REQUIRE(ask(p, "F 145950000") == "RPRT 0\n");
  st.radio_sim->simulate_fault("interface not echoing");
  CHECK(ask(p, "F 145800000") == "RPRT -6\n");
  CHECK(ask(p, "I 435000000") == "RPRT -6\n");
  CHECK(ask(p, "M FM 0") == "RPRT -6\n");
  CHECK(ask(p, "f") == "145950000\n");
  CHECK(ask(p, "i") == "0\n");
  st.radio_sim->clear_fault();
  CHECK(ask(p, "F 145800000") == "RPRT 0\n");
  CHECK(ask(p, "f") == "145800000\n");
}
