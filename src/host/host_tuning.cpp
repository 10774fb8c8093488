// Host mode's tuning commands, trakbox's own (the manual's set tunes only by FU/FD): the passband
// position of a linear transponder, the operator's RX and TX offsets and the uplink's CTCSS tone,
// through the same StationOps operations as the page's POST /api/v1/radio.
//   PB435640000   the downlink spot in Hz (the uplink follows by the transponder's rule)
//   OR+120 OT-300 the RX / TX offset in Hz (OR0 OT0: reset), kept per satellite and mode
//   CT67.0 CT0    the tone in Hz, 0 for none
//   ?T            TUNE SPOT <down> <up> RX <+hz> TX <+hz> TONE <hz>
#include <string>

#include "host/host_mode.h"
#include "radio/doppler.h"
#include "station/station.h"
#include "store/model.h"
#include "store/settings.h"
#include "tracker/station_loop.h"
#include "util/text.h"

namespace tb::host {

namespace {

std::string signed_text(long long v) { return (v >= 0 ? "+" : "") + std::to_string(v); }

constexpr auto tuning_error = &Reply::error;  // "ERROR ..."

}  // namespace

std::optional<Reply> Interpreter::tuning(std::string_view u, std::string_view line) {
  const bool pb = u.rfind("PB", 0) == 0, orx = u.rfind("OR", 0) == 0, otx = u.rfind("OT", 0) == 0;
  const bool ct = u.rfind("CT", 0) == 0;
  if (u == "?T") {
    const radio::Tuner& t = station_.tuner();
    if (!station_.tuned()) return tuning_error("?T: no satellite is tuned: track one first");
    const int tone = t.satellite().ctcss_tenths_hz;
    return Reply{{"TUNE SPOT " + std::to_string(t.downlink_spot_hz()) + " " + std::to_string(t.uplink_spot_hz()) +
                  " RX " + signed_text(t.rit_hz()) + " TX " + signed_text(t.xit_hz()) + " TONE " +
                  std::to_string(tone / 10) + "." + std::to_string(tone % 10)},
                 true, false};
  }
  if (u.rfind("QTH", 0) == 0) return station(line.substr(3));
  if (!pb && !orx && !otx && !ct) return std::nullopt;
  const std::string cmd(u.substr(0, 2));
  const std::string arg = text::trimmed(line.substr(2));
  tracker::OpResult done;
  if (ct) {
    const auto hz = text::parse_double(arg);
    if (!hz) return tuning_error("CT: '" + arg.substr(0, 20) + "' is not a tone: expected Hz such as CT67.0, or CT0 for none");
    done = ops().tune_tone(*hz);
  } else {
    const auto hz = text::parse_integer<long long>(arg);
    if (!hz)
      return tuning_error(cmd + ": '" + arg.substr(0, 20) + "' is not a whole number of Hz, e.g. " +
                   (pb ? "PB435640000" : cmd + "+120"));
    if (pb) done = ops().tune_spot(*hz);
    else done = ops().tune_offsets(orx ? std::optional<long long>(*hz) : std::nullopt,
                                   otx ? std::optional<long long>(*hz) : std::nullopt);
  }
  if (!done.ok()) return tuning_error(cmd + ": " + *done.refusal);
  if (done.model_changed) station_.save_settings();   // on disk before the prompt returns
  return Reply{};
}

// QTH JN58td | QTH LAT,LON[,HEIGHT_M]: the station's position, as menu 4 sets it, read as --station
// reads it (store::parse_position: one reading); without a height the stored one stays.
Reply Interpreter::station(std::string_view arg) {
  const store::ParsedPosition p = store::parse_position(text::trimmed(arg));
  if (!p.ok()) return tuning_error("QTH: " + p.error);
  const tracker::OpResult done = ops().set_station(p.lat_deg, p.lon_deg, p.height_m.value_or(station_.model().station.height_m));
  if (!done.ok()) return tuning_error("QTH: " + *done.refusal);
  return Reply{{"QTH " + done.note.substr(done.note.find(' ') + 1)}, true, false};
}

// MODE alone: "MODES RS-44 SSB* CW FT4" (the chosen one starred); MODE NAME chooses one and the
// radio goes to it: "MODE RS-44 FT4 435611000 145993610" (the mode's downlink and uplink, Hz).
Reply Interpreter::sat_mode(std::string_view arg) {
  const std::string name = text::trimmed(arg);
  const auto tuned = station_.tuned();
  if (!tuned) return tuning_error("MODE: no satellite is tuned: track one first");
  const store::Satellite& sat = station_.model().db.satellites[static_cast<std::size_t>(*tuned)];
  if (name.empty()) {
    std::string line = "MODES " + sat.name();
    const std::string chosen = store::chosen_mode(sat);
    for (const auto& m : store::modes_of(sat)) line += " " + m.name + (m.name == chosen ? "*" : "");
    return Reply{{line}, true, false};
  }
  if (auto no = ask_radio("MODE")) return *no;
  const tracker::OpResult done = ops().choose_mode("", name);
  if (!done.ok()) return tuning_error("MODE: " + *done.refusal);
  if (done.model_changed) station_.save_settings();  // on disk before the prompt returns
  const store::Satellite& now = station_.model().db.satellites[static_cast<std::size_t>(*tuned)];
  return Reply{{"MODE " + now.name() + " " + now.mode + " " + std::to_string(now.radio.downlink_hz) + " " +
                std::to_string(now.radio.uplink_hz)},
               true, false};
}

}  // namespace tb::host
