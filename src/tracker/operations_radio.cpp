// StationOps' radio operations: the passband position, the operator's offsets and the tone
// (operations.h). Each checks everything before it changes the tuner or the model.
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "radio/doppler.h"
#include "rotator/parking_mask.h"
#include "station/station.h"
#include "store/model.h"
#include "store/owner.h"
#include "tracker/operations.h"
#include "util/text.h"
#include "tracker/station_loop.h"

namespace tb::tracker {

namespace {

std::string hz_text(std::int64_t hz) { return std::to_string(hz) + " Hz"; }

std::string signed_hz(std::int64_t hz) { return (hz > 0 ? "+" : "") + hz_text(hz); }

// The satellite the radio is tuned for, or the refusal.
std::optional<std::string> untuned(StationLoop& station) {
  if (!station.tuned()) return "no satellite is tuned: track one first";
  if (!station.doppler()) return "Doppler is off: the radio is left alone (turn Doppler on first)";
  return std::nullopt;
}

}  // namespace

OpResult StationOps::tune_spot(std::int64_t downlink_hz) {
  if (const auto why = untuned(station_)) return OpResult::refuse(*why);
  if (auto no = ask(Resource::radio, true)) return *no;  // the operator tunes trakbox's own tracking (control.h)
  radio::Tuner& t = station_.tuner();
  const std::string& name = model_.db.satellites[static_cast<std::size_t>(*station_.tuned())].name();
  const auto band = radio::transponder_of(t.satellite());
  if (!band)
    return OpResult::refuse(name + " has no transponder passband (its freq/mode record gives no down=LOW-HIGH): "
                            "its frequencies are fixed");
  if (!band->downlink_inside(downlink_hz))
    return OpResult::refuse("spot " + hz_text(downlink_hz) + " is outside " + name + "'s downlink passband " +
                            std::to_string(band->downlink_low_hz) + "-" + hz_text(band->downlink_high_hz));
  t.set_spot(downlink_hz);
  station_.antenna_changed();   // a tick now: the radio hears of it at once
  OpResult r;
  r.note = "spot " + hz_text(t.downlink_spot_hz()) + " down, " + hz_text(t.uplink_spot_hz()) + " up";
  return r;
}

OpResult StationOps::tune_offsets(std::optional<std::int64_t> rx_hz, std::optional<std::int64_t> tx_hz) {
  if (!rx_hz && !tx_hz) return OpResult::refuse("no offset given: expected an RX or a TX offset in Hz");
  for (const auto& [what, v] : {std::pair{"RX", rx_hz}, std::pair{"TX", tx_hz}})
    if (v && (*v > radio::kMaxOffsetHz || *v < -radio::kMaxOffsetHz))
      return OpResult::refuse(std::string(what) + " offset " + hz_text(*v) + " out of range: expected -" +
                              std::to_string(radio::kMaxOffsetHz) + " to " + std::to_string(radio::kMaxOffsetHz));
  if (const auto why = untuned(station_)) return OpResult::refuse(*why);
  if (auto no = ask(Resource::radio, true)) return *no;  // the operator tunes trakbox's own tracking (control.h)
  radio::Tuner& t = station_.tuner();
  t.set_offsets(rx_hz, tx_hz);
  OpResult r;
  r.model_changed = station_.owner()
                        .edit(store::bit(store::Area::radio), std::string(kCorrectionsEdit), origin(),
                              [&](store::Model& m) {
                                m.radio.corrections = t.config().corrections;
                                m.radio.tx_corrections = t.config().tx_corrections;
                              })
                        .changed;
  station_.antenna_changed();
  r.note = "RX offset " + signed_hz(t.rit_hz()) + ", TX offset " + signed_hz(t.xit_hz()) + " (" +
           (t.correction_key().empty() ? std::string("this pass") : t.correction_key()) + ")";
  return r;
}

OpResult StationOps::tune_tone(double hz) {
  const double tenths = std::round(hz * 10.0);
  if (!std::isfinite(hz) || std::abs(hz * 10.0 - tenths) > 1e-6 || (hz != 0.0 && (hz < 60.0 || hz > 300.0))) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", hz);
    return OpResult::refuse(std::string("tone ") + buf + " Hz: expected a CTCSS tone from 60.0 to 300.0 Hz "
                            "(tenths, e.g. 67.0) or 0 for none");
  }
  if (const auto why = untuned(station_)) return OpResult::refuse(*why);
  if (auto no = ask(Resource::radio, true)) return *no;  // the operator tunes trakbox's own tracking (control.h)
  const auto i = static_cast<std::size_t>(*station_.tuned());
  const std::string name = model_.db.satellites[i].name();  // (a copy: the edit replaces the record)
  const int t = static_cast<int>(tenths);
  OpResult r;
  r.model_changed = station_.owner()
                        .edit(store::bit(store::Area::radio_entries), std::string(kToneEdit), origin(),
                              [&](store::Model& m) { m.db.satellites[i].radio.ctcss_tenths_hz = t; })
                        .changed;
  station_.set_tone(t);
  r.note = name + (t > 0 ? " tone " + std::to_string(t / 10) + "." + std::to_string(t % 10) + " Hz" : " no tone");
  return r;
}

OpResult StationOps::choose_mode(std::string_view satellite, std::string_view mode) {
  std::optional<int> db = satellite.empty() ? station_.tuned() : find_satellite(satellite);
  if (!db) return OpResult::refuse(satellite.empty() ? std::string("no satellite is tuned: name one")
                                                     : fmt::format("unknown satellite '{}'", satellite));
  const auto i = static_cast<std::size_t>(*db);
  const store::Satellite& sat = model_.db.satellites[i];
  const auto found = store::find_mode(sat, mode);
  if (!found) {
    std::string names;
    for (const auto& m : store::modes_of(sat)) names += (names.empty() ? "" : ", ") + m.name;
    return OpResult::refuse(names.empty() ? fmt::format("{} has no modes: its freq/mode record is empty", sat.name())
                                          : fmt::format("{} has no mode '{}': its modes are {}", sat.name(), mode, names));
  }
  const bool tuned = station_.tuned() == db;
  if (tuned)
    if (auto no = ask(Resource::radio, true)) return *no;  // the radio is retuned: the operator's rule (control.h)
  const std::string name = sat.name();  // (a copy: the edit replaces the record)
  const store::EditResult done = station_.owner().edit(
      store::bit(store::Area::radio_entries), std::string(kModeEdit), origin(),
      [&](store::Model& m) { store::choose_mode(m.db.satellites[i], found->name); });
  if (!done.ok()) return OpResult::refuse(*done.refusal);
  OpResult r;
  r.model_changed = done.changed;
  if (tuned) station_.antenna_changed();  // a tick now: the radio goes to the mode at once
  const radio::SatelliteRadio& rec = found->radio;
  r.note = fmt::format("{} {}: {} Hz down, {} Hz up", name, found->name, rec.downlink_hz, rec.uplink_hz);
  return r;
}

}  // namespace tb::tracker

namespace tb::tracker {

OpResult StationOps::set_station(double lat_deg, double lon_deg, double height_m) {
  // Each number by the settings table's rule and sentence (store/settings.h), through the one door.
  const store::EditResult done = station_.owner().set_position(lat_deg, lon_deg, height_m, origin());
  if (!done.ok()) return OpResult::refuse(*done.refusal);
  OpResult r;
  r.model_changed = done.changed;
  r.note = fmt::format("station {:.4f}, {:.4f}, {:.0f} m", lat_deg, lon_deg, height_m);
  return r;
}

OpResult StationOps::set_callsign(const std::string& callsign) {
  const store::EditResult done = station_.owner().set("station.callsign", text::upper(callsign), origin());
  if (!done.ok()) return OpResult::refuse(*done.refusal);
  OpResult r;
  r.model_changed = done.changed;
  r.note = "callsign " + station_.model().station.callsign;
  return r;
}

OpResult StationOps::set_horizon_mask(const std::string& text) {
  const store::EditResult done = station_.owner().set("station.horizon_mask", text, origin());
  if (!done.ok()) return OpResult::refuse(*done.refusal);
  OpResult r;
  r.model_changed = done.changed;
  const store::Model& m = station_.model();
  r.note = "horizon mask " + station::describe_mask(m.station);
  if (const auto w = rotator::parking_mask_warning(m.rotator, m.station.mask().get())) r.note += "; WARNING: " + *w;
  return r;
}

}  // namespace tb::tracker
