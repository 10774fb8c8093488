#include "tracker/log_ops.h"

#include <chrono>
#include <tuple>

#include <fmt/format.h>

#include "logbook/qso.h"
#include "orbit/observe.h"
#include "orbit/sgp4.h"
#include "station/station.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::tracker {

LogOps::LogOps(StationLoop& station) : station_(station), logging_(station.logging()) {}

logbook::Logbook* LogOps::book(std::string& why) const {
  if (!logging_) {
    why = "the logbook is not open in this program";
    return nullptr;
  }
  if (!logging_->book) {
    why = "the logbook could not be opened: " + logging_->open_error;
    return nullptr;
  }
  return logging_->book.get();
}

namespace {

// A QSO through a satellite that was below the horizon here at its time: stored (the operator may
// log afterwards, or a partner's grid), but said (issue 60).
std::optional<std::string> below_horizon(const store::Satellite& sat, const orbit::Observer& here, std::int64_t time_on) {
  const orbit::Sgp4 prop(sat.elements);
  const orbit::UtcTime t{std::chrono::seconds(time_on)};
  const orbit::Observation o = orbit::observe(prop, here, t);
  if (!o.ok() || o.look.el_deg >= 0.0) return std::nullopt;
  return fmt::format("{} was below the horizon here ({:.1f} deg) at {} UTC", sat.name(), o.look.el_deg,
                     logbook::utc_text(time_on).substr(11));
}

}  // namespace

LogResult LogOps::fill(const LogRequest& r) const {
  LogResult out;
  logbook::Qso& q = out.qso;
  const store::Model& model = station_.model();
  q.call = r.call;
  q.grid = r.grid;
  q.rst_sent = r.rst_sent;
  q.rst_rcvd = r.rst_rcvd;
  q.note = r.note;
  q.source = r.source;
  q.power_w = r.power_w;
  // The station's callsign as menu 4 has it; the factory's NOCALL (or anything else that is no
  // callsign) is left out rather than refusing the operator's QSO.
  if (!logbook::check_callsign("station_call", model.station.callsign)) q.station_call = model.station.callsign;
  q.my_grid = station::maidenhead_locator(model.station.lat_deg, model.station.lon_deg).substr(0, 6);
  const auto now = std::chrono::floor<std::chrono::seconds>(station_.clock().now());
  q.time_on = r.time_on ? *r.time_on : now.time_since_epoch().count();

  // The satellite: the one named, else the one the radio follows (tracked, or a remote's).
  std::optional<int> db;
  const SatNow* followed = station_.tracker().followed();
  if (!r.sat.empty()) {
    db = StationOps(station_).find_satellite(r.sat);
    if (!db) return {"sat: " + StationOps(station_).unknown_satellite(r.sat), q, std::nullopt};
  } else if (followed) {
    db = followed->db_index;
  } else if (station_.remote_db_index()) {
    db = station_.remote_db_index();
  }
  if (!db || *db < 0 || *db >= static_cast<int>(model.db.satellites.size()))
    return {std::string("sat: no satellite is tracked; name one"), q, std::nullopt};
  const store::Satellite& sat = model.db.satellites[static_cast<std::size_t>(*db)];
  q.sat_name = sat.name();
  q.norad = sat.elements.catalog_number;
  if (logging_) q.lotw_name = logging_->names.name(q.norad);

  // The radio: the Tuner's spot and what it last sent when it follows this satellite; else the
  // satellite's freq/mode record.
  const bool tuned = followed && followed->db_index == *db;
  const radio::Tuner& t = station_.tuner();
  const radio::SatelliteRadio& rec = tuned ? t.satellite() : sat.radio;
  q.downlink_hz = tuned ? t.downlink_spot_hz() : rec.downlink_hz;
  q.uplink_hz = tuned ? t.uplink_spot_hz() : rec.uplink_hz;
  if (tuned) {
    q.downlink_tuned_hz = t.last_sent_downlink_hz().value_or(0);
    q.uplink_tuned_hz = t.last_sent_uplink_hz().value_or(0);
  }
  // The emission: the one given, else the satellite's chosen mode as ADIF names it (FT4: MFSK with
  // SUBMODE FT4), else the link's radio mode (USB: SSB).
  const radio::Mode m = rec.uplink_mode != radio::Mode::none ? rec.uplink_mode : rec.downlink_mode;
  const auto named = logbook::adif_of_mode_name(store::chosen_mode(sat));
  if (!r.mode.empty()) q.mode = r.mode;
  else if (named) std::tie(q.mode, q.submode) = *named;
  else q.mode = m == radio::Mode::none ? std::string() : logbook::adif_mode(radio::to_string(m));
  q = logbook::normalized(std::move(q));
  if (auto e = logbook::check_qso(q)) out.refusal = *e;
  out.warning = below_horizon(sat, model.station.observer(), q.time_on);
  return out;
}

LogResult LogOps::log(const LogRequest& r) {
  LogResult out = fill(r);
  if (!out.ok()) return out;
  std::string why;
  logbook::Logbook* b = book(why);
  if (!b) return {why, out.qso, std::nullopt};
  const logbook::Added a = b->add(out.qso, logging_->upload);
  if (!a.ok()) return {a.error, out.qso, std::nullopt};
  if (auto stored = b->get(a.id)) out.qso = *stored;
  if (logging_->on_logged) logging_->on_logged();
  return out;
}

}  // namespace tb::tracker
