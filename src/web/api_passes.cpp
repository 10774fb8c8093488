// GET /api/v1/passes and /api/v1/passes.ics: the planner's passes (docs/web-api.md). The query:
//   sat=A,B   the satellites by name (none: the tracking list), at most kMaxPlanSatellites
//   min_el=D  only passes whose maximum reaches D degrees, 0 to 90 (default 0: passes that rise)
//   hours=H   the window from the station's time, 1 to 72 (default 24)
//   with=LOC  only the times a second station (a Maidenhead locator or LAT,LON) sees it too
// Each pass carries the passes of the others it overlaps and a small sky track.
#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "orbit/pass_tools.h"
#include "orbit/time.h"
#include "station/station.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "util/text.h"
#include "web/api.h"

namespace tb::web {

namespace {

using json = nlohmann::json;

constexpr std::size_t kMaxPlanSatellites = 15;   // the tracking list's length
constexpr double kMaxPlanHours = 72.0;
constexpr int kTrackPoints = 16;

std::string passes_shown(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < 40; ++i) out.push_back(s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?');
  return out;
}

Response passes_refuse(int status, std::string sentence) {
  Response r;
  r.status = status;
  r.body = json{{"error", std::move(sentence)}}.dump();
  return r;
}

struct Planned {
  std::vector<orbit::NamedPass> passes;
  std::vector<int> db_index;   // of each pass
  orbit::UtcTime from{};
  double hours = 24.0, min_el = 0.0;
  std::optional<orbit::Observer> with;
  std::string with_text;
};

// "JN58td" or "48.1,11.6": the second station.
std::optional<orbit::Observer> second_station(const std::string& text) {
  if (auto loc = station::maidenhead_centre(text)) return loc;
  const auto parts = text::split(text, ',');
  if (parts.size() != 2) return std::nullopt;
  const auto lat = text::parse_double(text::trim(parts[0], text::kWhitespace));
  const auto lon = text::parse_double(text::trim(parts[1], text::kWhitespace));
  if (!lat || !lon || std::abs(*lat) > 90.0 || std::abs(*lon) > 180.0) return std::nullopt;
  orbit::Observer o;
  o.lat_deg = *lat;
  o.lon_deg = *lon;
  return o;
}

std::optional<Response> plan(tracker::StationLoop& station, const std::string& target, Planned& out) {
  const auto sat = query_param(target, "sat"), hours = query_param(target, "hours"),
             min_el = query_param(target, "min_el"), with = query_param(target, "with");
  if (!sat || !hours || !min_el || !with) return passes_refuse(400, "passes: a bad %-escape in the query");
  if (!hours->empty()) {
    const auto h = text::parse_double(*hours);
    if (!h || !(*h >= 1.0 && *h <= kMaxPlanHours))
      return passes_refuse(400, "passes: hours '" + passes_shown(*hours) + "': expected 1 to 72");
    out.hours = *h;
  }
  if (!min_el->empty()) {
    const auto e = text::parse_double(*min_el);
    if (!e || !(*e >= 0.0 && *e <= 90.0)) return passes_refuse(400, "passes: min_el '" + passes_shown(*min_el) + "': expected 0 to 90 degrees");
    out.min_el = *e;
  }
  if (!with->empty()) {
    out.with = second_station(*with);
    if (!out.with)
      return passes_refuse(400, "passes: with '" + passes_shown(*with) + "': expected a Maidenhead locator (JN58td) or LAT,LON");
    out.with_text = *with;
  }
  const store::Model& m = station.model();
  std::vector<int> chosen;
  if (sat->empty()) chosen = m.db.selected;
  else {
    tracker::StationOps ops(station);
    for (const std::string_view name : text::split(*sat, ',')) {
      const auto i = ops.find_satellite(name);
      if (!i) return passes_refuse(404, ops.unknown_satellite(passes_shown(name)));
      if (std::find(chosen.begin(), chosen.end(), *i) == chosen.end()) chosen.push_back(*i);
    }
  }
  if (chosen.size() > kMaxPlanSatellites)
    return passes_refuse(400, "passes: at most 15 satellites at once; " + std::to_string(chosen.size()) + " given");
  out.from = station.now();   // the station clock: with tracking off the tracker has not ticked
  const orbit::UtcTime stop = orbit::add_minutes(out.from, out.hours * 60.0);
  orbit::PassOptions options;
  options.min_max_elevation_deg = std::max(out.min_el, 1e-9);   // passes that rise, at least
  // AOS and LOS at the station's horizon mask (issue 57); a mutual pass (`with`) is both places'
  // plain horizons: the other place's mask is not known.
  if (!out.with) options.mask = m.station.mask();
  const orbit::Observer here = m.station.observer();
  for (const int i : chosen) {
    const orbit::Sgp4* sgp4 = station.tracker().propagator(i);
    if (!sgp4) continue;   // no usable orbit: nothing to plan
    const std::string& name = m.db.satellites[static_cast<std::size_t>(i)].name();
    const auto search = [&](orbit::UtcTime start) {
      std::vector<orbit::Pass> f = out.with ? orbit::mutual_passes(*sgp4, here, *out.with, start, stop, options)
                                            : orbit::find_passes(*sgp4, here, start, stop, options);
      std::erase_if(f, [&](const orbit::Pass& p) { return p.los < out.from; });
      return f;
    };
    // A pass in progress is planned whole (issue 47): its real AOS and the whole pass's maximum
    // (also against min_el), searched from half an hour before, or 6 hours or a day for a long one.
    // One up even then (geostationary) is planned from now, as before.
    std::vector<orbit::Pass> found;
    for (const double back : {30.0, 360.0, 1440.0}) {
      found = search(orbit::add_minutes(out.from, -back));
      if (found.empty() || !found.front().up_at_start) break;
    }
    if (!found.empty() && found.front().up_at_start) found = search(out.from);
    for (const orbit::Pass& p : found) {
      out.passes.push_back({name, p});
      out.db_index.push_back(i);
    }
  }
  std::vector<std::size_t> order(out.passes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return out.passes[a].pass.aos < out.passes[b].pass.aos; });
  Planned sorted = out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted.passes[k] = out.passes[order[k]];
    sorted.db_index[k] = out.db_index[order[k]];
  }
  out = std::move(sorted);
  return std::nullopt;
}

json rounded(double v) { return std::round(v * 10.0) / 10.0; }

}  // namespace

Response Api::passes(const std::string& target) {
  Planned p;
  if (auto bad = plan(station_, target, p)) return *bad;
  const auto overlap = orbit::overlaps(p.passes);
  const orbit::Observer here = station_.model().station.observer();
  json list = json::array();
  for (std::size_t k = 0; k < p.passes.size(); ++k) {
    const orbit::Pass& pass = p.passes[k].pass;
    json track = json::array();
    if (const orbit::Sgp4* s = station_.tracker().propagator(p.db_index[k])) {
      const double minutes = orbit::minutes_between(pass.aos, pass.los);
      for (int n = 0; n <= kTrackPoints; ++n) {
        const orbit::Observation o = orbit::observe(*s, here, orbit::add_minutes(pass.aos, minutes * n / kTrackPoints));
        if (o.ok()) track.push_back(json::array({rounded(o.look.az_deg), rounded(std::max(o.look.el_deg, 0.0))}));
      }
    }
    json overlaps = json::array();
    for (const int j : overlap[k]) overlaps.push_back(j);
    list.push_back({{"satellite", p.passes[k].satellite},
                    {"aos", orbit::format_iso8601(pass.aos)},
                    {"tca", orbit::format_iso8601(pass.tca)},
                    {"los", orbit::format_iso8601(pass.los)},
                    {"max_el_deg", pass.max_el_deg},
                    {"aos_az_deg", pass.aos_az_deg},
                    {"tca_az_deg", pass.tca_az_deg},
                    {"los_az_deg", pass.los_az_deg},
                    {"in_progress", pass.up_at_start || (pass.aos <= p.from && p.from <= pass.los)},
                    {"overlaps", std::move(overlaps)},
                    {"track", std::move(track)}});
  }
  json j{{"from", orbit::format_iso8601(p.from)},
         {"hours", p.hours},
         {"min_el_deg", p.min_el},
         {"with", p.with ? json(p.with_text) : json(nullptr)},
         {"passes", std::move(list)}};
  const auto sat = query_param(target, "sat");
  if (sat && !sat->empty() && sat->find(',') == std::string::npos && !p.passes.empty())
    j["satellite"] = p.passes.front().satellite;
  else if (sat && !sat->empty() && sat->find(',') == std::string::npos) {
    const auto i = tracker::StationOps(station_).find_satellite(*sat);
    j["satellite"] = station_.model().db.satellites[static_cast<std::size_t>(*i)].name();
  }
  Response r;
  r.body = j.dump(-1, ' ', false, json::error_handler_t::replace);
  return r;
}

Response Api::passes_ics(const std::string& target) {
  Planned p;
  if (auto bad = plan(station_, target, p)) return *bad;
  const auto& st = station_.model().station;
  std::string where = station::maidenhead_locator(st.lat_deg, st.lon_deg);
  if (p.with) where += " and " + p.with_text;
  Response r;
  r.content_type = "text/calendar; charset=utf-8";
  r.body = orbit::ical_passes(p.passes, p.from, where);
  r.headers.emplace_back("Content-Disposition", "attachment; filename=\"trakbox-passes.ics\"");
  return r;
}

}  // namespace tb::web
