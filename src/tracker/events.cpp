#include "tracker/events.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "store/model.h"
#include "tracker/tracker.h"

namespace tb::tracker {

const std::vector<std::string>& event_kinds() {
  static const std::vector<std::string> kinds{"aos",       "los",       "recording",   "elements",
                                                "link-lost", "link-back", "save-failed", "control"};
  return kinds;
}

nlohmann::json to_json(const Event& e) {
  nlohmann::json j{{"event", e.kind}, {"time", orbit::format_iso8601(e.time, 3)}};
  if (!e.satellite.empty()) {
    j["satellite"] = e.satellite;
    j["catalog_number"] = e.catalog_number;
    j["list_number"] = e.list_number;
    if (e.downlink_hz) j["downlink_hz"] = e.downlink_hz;
    if (e.uplink_hz) j["uplink_hz"] = e.uplink_hz;
  }
  if (e.pass) {
    j["aos"] = orbit::format_iso8601(e.pass->aos, 1);
    j["tca"] = orbit::format_iso8601(e.pass->tca, 1);
    // Still up where the search ended (geostationary): no LOS to tell.
    j["los"] = e.pass->up_at_end ? nlohmann::json(nullptr) : nlohmann::json(orbit::format_iso8601(e.pass->los, 1));
    j["max_el_deg"] = e.pass->max_el_deg;
    j["aos_az_deg"] = e.pass->aos_az_deg;
    j["los_az_deg"] = e.pass->los_az_deg;
  }
  if (!e.detail.empty()) j["detail"] = e.detail;
  if (e.recording) {
    const Event::Recorded& r = *e.recording;
    j["recording"] = {{"state", r.state},
                      {"kind", r.kind},
                      {"start", orbit::format_iso8601(r.start, 0)},
                      {"frequency_hz", r.frequency_hz},
                      {"file", r.file.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.file)},
                      {"read_back", r.read_back},
                      {"why", r.why.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.why)}};
  }
  if (e.control) {
    const auto holder = [](const Holder& h) {
      return nlohmann::json{{"kind", kind_name(h.kind)},
                            {"label", h.label},
                            {"since", orbit::format_iso8601(h.since, 0)},
                            {"until", h.until ? nlohmann::json(orbit::format_iso8601(*h.until, 0)) : nlohmann::json()}};
    };
    j["resource"] = resource_name(e.control->resource);
    j["from"] = holder(e.control->from);
    j["to"] = holder(e.control->to);
    j["why"] = e.control->why;
  }
  return j;
}

std::vector<std::pair<std::string, std::string>> event_environment(const Event& e) {
  std::vector<std::pair<std::string, std::string>> env{{"TRAKBOX_EVENT", e.kind},
                                                       {"TRAKBOX_TIME", orbit::format_iso8601(e.time, 3)}};
  if (!e.satellite.empty()) {
    env.emplace_back("TRAKBOX_SATELLITE", e.satellite);
    env.emplace_back("TRAKBOX_CATALOG_NUMBER", std::to_string(e.catalog_number));
    env.emplace_back("TRAKBOX_LIST_NUMBER", std::to_string(e.list_number));
    env.emplace_back("TRAKBOX_DOWNLINK_HZ", std::to_string(e.downlink_hz));
    env.emplace_back("TRAKBOX_UPLINK_HZ", std::to_string(e.uplink_hz));
  }
  if (e.pass) {
    env.emplace_back("TRAKBOX_AOS", orbit::format_iso8601(e.pass->aos, 1));
    env.emplace_back("TRAKBOX_TCA", orbit::format_iso8601(e.pass->tca, 1));
    env.emplace_back("TRAKBOX_LOS", e.pass->up_at_end ? std::string() : orbit::format_iso8601(e.pass->los, 1));
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", e.pass->max_el_deg);
    env.emplace_back("TRAKBOX_MAX_EL_DEG", buf);
  }
  if (!e.detail.empty()) env.emplace_back("TRAKBOX_DETAIL", e.detail);
  if (e.recording) {
    env.emplace_back("TRAKBOX_RECORDING", e.recording->state);
    env.emplace_back("TRAKBOX_RECORDING_KIND", e.recording->kind);
    env.emplace_back("TRAKBOX_RECORDING_START", orbit::format_iso8601(e.recording->start, 0));
    env.emplace_back("TRAKBOX_RECORDING_HZ", std::to_string(e.recording->frequency_hz));
    env.emplace_back("TRAKBOX_RECORDING_FILE", e.recording->file);
  }
  if (e.control) {
    env.emplace_back("TRAKBOX_RESOURCE", std::string(resource_name(e.control->resource)));
    env.emplace_back("TRAKBOX_HOLDER", std::string(kind_name(e.control->to.kind)));
    env.emplace_back("TRAKBOX_HOLDER_LABEL", e.control->to.label);
    env.emplace_back("TRAKBOX_PREVIOUS_HOLDER", std::string(kind_name(e.control->from.kind)));
  }
  env.emplace_back("TRAKBOX_EVENT_JSON", to_json(e).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  return env;
}

Event PassEventSource::pass_event(const char* kind, int db_index, const Watch& w, orbit::UtcTime now) const {
  const auto& sat = model_.db.satellites[static_cast<std::size_t>(db_index)];
  Event e;
  e.kind = kind;
  e.time = now;
  e.satellite = sat.name();
  e.catalog_number = sat.elements.catalog_number;
  e.list_number = model_.db.list_number(db_index);
  e.pass = w.pass;
  e.downlink_hz = static_cast<long long>(sat.radio.downlink_hz);
  e.uplink_hz = static_cast<long long>(sat.radio.uplink_hz);
  return e;
}

std::vector<Event> PassEventSource::step(orbit::UtcTime now) {
  std::vector<Event> out;
  std::map<int, Watch> kept;
  orbit::PassOptions po;
  po.horizon_deg = model_.pass_events.rotor_start_el_deg;
  po.mask = model_.station.mask();  // AOS and LOS at the horizon mask, where it is higher
  // --event-min-el: a pass that never rises that high (one that only grazes the -2 deg rule) is
  // no pass to announce: no AOS, so no LOS and no hook (issue 39).
  po.min_max_elevation_deg = model_.event_min_el_deg;
  last_step_ = now;
  for (const int i : model_.db.selected) {
    if (i < 0 || i >= static_cast<int>(model_.db.satellites.size())) continue;
    const orbit::Elements& el = model_.db.satellites[static_cast<std::size_t>(i)].elements;
    Watch w;
    if (const auto found = watches_.find(el.catalog_number); found != watches_.end()) w = found->second;
    // New elements (a refresh, an edit): search again; an AOS already told stays told.
    if (w.catalog_number != el.catalog_number || w.epoch_year != el.epoch_year || w.epoch_day != el.epoch_day) {
      w.catalog_number = el.catalog_number;
      w.epoch_year = el.epoch_year;
      w.epoch_day = el.epoch_day;
      if (!w.aos_fired) w.pass.reset();
    }
    // Until its AOS is told, the pass watched is the station's pass cache's (pass_memo.h): another
    // when the station moves, the elements change or the clock goes back. Once told, it stays to
    // its LOS (a satellite still up where the search ended gets its next stretch, untold).
    if (!w.aos_fired || !w.pass) {
      if (const orbit::Sgp4* sgp4 = tracker_.propagator(i)) {
        const orbit::Observer where = model_.station.observer();
        w.pass = tracker_.passes().get(
            el, where, now,
            [&] {
              ++searches_;
              return orbit::next_pass(*sgp4, where, now, 2.0, po);
            },
            "events", po);
        if (w.pass && now > w.pass->los) w.pass.reset();  // told below at its LOS already
      }
    }
    if (w.pass && !w.aos_fired && now >= w.pass->aos - lead_ && now < w.pass->los) {
      w.aos_fired = true;
      out.push_back(pass_event("aos", i, w, now));
    }
    if (w.pass && now >= w.pass->los) {
      if (w.pass->up_at_end) {
        // Still up where the search stopped (a geostationary satellite): no LOS; search on.
        w.pass.reset();
      } else {
        if (w.aos_fired) out.push_back(pass_event("los", i, w, now));
        w.aos_fired = false;
        w.pass.reset();  // the next one is searched at the next step (after this LOS)
      }
    }
    kept[el.catalog_number] = w;
  }
  watches_ = std::move(kept);  // satellites taken off the list are forgotten
  return out;
}

}  // namespace tb::tracker
