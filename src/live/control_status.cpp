#include "live/control_status.h"

#include <nlohmann/json.hpp>

#include "tracker/station_loop.h"

namespace tb::app {

namespace {

nlohmann::json holder_json(const tracker::Holder& h) {
  return {{"kind", tracker::kind_name(h.kind)},
          {"label", h.label},
          {"since", orbit::format_iso8601(h.since, 0)},
          {"until", h.until ? nlohmann::json(orbit::format_iso8601(*h.until, 0)) : nlohmann::json(nullptr)}};
}

// Whether trakbox tunes the radio now, in a few words.
std::string doppler_text(const tracker::StationLoop& st) {
  const tracker::Holder& h = st.control().holder(tracker::Resource::radio);
  if (h.kind == tracker::HolderKind::standby) return "paused (standby)";
  if (h.kind != tracker::HolderKind::tracking) return "held by " + h.label;
  if (!st.doppler()) return "off";
  if (st.tracker().mode() == tracker::Mode::off && !st.remote_followed()) return "paused (nothing tracked)";
  return "on";
}

}  // namespace

void add_control_status(const tracker::StationLoop& station, nlohmann::json& j) {
  const tracker::Control& c = station.control();
  j["control"] = {{"antenna", holder_json(c.holder(tracker::Resource::antenna))},
                  {"radio", holder_json(c.holder(tracker::Resource::radio))}};
  j["standby"] = c.standby();
  nlohmann::json res = nlohmann::json::array();
  for (const tracker::Window& w : c.windows())
    res.push_back({{"kind", w.kind},
                   {"id", w.id},
                   {"start", orbit::format_iso8601(w.start, 0)},
                   {"end", orbit::format_iso8601(w.end, 0)},
                   {"satellite", w.satellite},
                   {"note", w.note}});
  j["reservations"] = std::move(res);
  if (const auto& sn = station.satnogs_state())
    j["satnogs"] = {{"station", sn->station},
                    {"url", sn->url},
                    {"jobs", sn->jobs},
                    {"last_poll", sn->last_poll.empty() ? nlohmann::json(nullptr) : nlohmann::json(sn->last_poll)},
                    {"error", sn->error ? nlohmann::json(*sn->error) : nlohmann::json(nullptr)}};
  // The pass an outside client's targets are recognised to follow (issue 57).
  if (j.contains("antenna")) {
    const std::string follows = station.client_follow_text();
    j["antenna"]["follows"] = follows.empty() ? nlohmann::json(nullptr) : nlohmann::json(follows);
  }
  // A link trakbox does not tune now says why, not "confirmed" (the Radio panel shows the state).
  const std::string doppler = doppler_text(station);
  if (j.contains("radios"))
    for (auto& r : j["radios"]) {
      r["doppler"] = doppler;
      if (doppler == "on" || !r.contains("links")) continue;
      for (auto& [name, link] : r["links"].items())
        if (link.value("state", "") != "fault" && link.value("state", "") != "not connected")
          link["state"] = "Doppler " + doppler;
    }
}

}  // namespace tb::app
