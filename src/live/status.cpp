#include "live/status.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "live/control_status.h"
#include "live/station_app.h"
#include "gps/monitor.h"
#include "orbit/element_age.h"
#include "radio/two_radios.h"
#include "rotator/parking_mask.h"
#include "station/clock.h"
#include "station/station.h"
#include "store/model.h"
#include "tracker/elements_refresh.h"
#include "tracker/log_json.h"
#include "tracker/pass_memo.h"
#include "tracker/station_loop.h"

namespace tb::app {
namespace {

nlohmann::json pass_json(const std::optional<orbit::Pass>& p, orbit::UtcTime now) {
  if (!p) return nullptr;
  // A satellite still up where the search ended (geostationary) has no LOS to tell: null, and
  // always_up when it was up at the start too. A "pass" of the -2 deg rule whose maximum stays under
  // the horizon never rises: said (rises false) rather than passed off as a pass. In progress: up
  // now, whether the search began inside it or it is the whole pass (whole_pass below).
  return {{"aos", orbit::format_iso8601(p->aos)},
          {"tca", orbit::format_iso8601(p->tca)},
          {"los", p->up_at_end ? nlohmann::json(nullptr) : nlohmann::json(orbit::format_iso8601(p->los))},
          {"max_el_deg", p->max_el_deg},
          {"in_progress", p->up_at_start || (p->aos <= now && now <= p->los)},
          {"always_up", p->up_at_start && p->up_at_end},
          {"rises", p->max_el_deg >= 0.0}};
}

nlohmann::json hz_or_null(const std::optional<radio::Hz>& hz) {
  return hz ? nlohmann::json(*hz) : nlohmann::json(nullptr);
}

const char* mode_name(tracker::Mode m) {
  switch (m) {
    case tracker::Mode::single: return "single";
    case tracker::Mode::multi: return "multiple";
    default: return "off";
  }
}

const char* link_name(rotator::LinkState s) {
  switch (s) {
    case rotator::LinkState::connecting: return "connecting";
    case rotator::LinkState::fault: return "fault";
    default: return "ok";
  }
}

nlohmann::json antenna_json(StationApp& app) {
  tracker::StationLoop& st = app.station();
  const rotator::Status rs = st.rotator().status();
  nlohmann::json a{{"rotor_control", st.rotor_control()},
                   {"link", link_name(rs.link.state)},
                   {"link_message", rs.link.message},
                   {"connects", rs.link.connects},
                   {"message", rs.message},
                   {"on_target", rs.on_target},
                   {"at_limit", rs.limited}};
  // travel_deg: degrees from the rotor stop (which way round, on an overlap rotator).
  if (const auto pos = st.antenna())
    a["position"] = {{"az_deg", pos->az}, {"el_deg", pos->el}, {"travel_deg", rs.az.travel}};
  else a["position"] = nullptr;
  // The one aim (StationLoop::aim): a client's target while it holds, the position an antenna
  // holds at (issue 60, item 9: after a rotctld P 200 30, "hold" with no target and the sky's
  // target drawn at 0/0), never a parking position with parking off.
  const tracker::StationLoop::Aim aim = st.aim();
  a["action"] = aim.action;
  a["target"] = aim.target ? nlohmann::json{{"az_deg", aim.target->az}, {"el_deg", aim.target->el}} : nlohmann::json(nullptr);
  // Which way round the rotator was sent (travel from the stop), when it was sent somewhere.
  if (aim.target && rs.target) a["target"]["travel_deg"] = rs.target->az_travel;
  a["parking_enabled"] = st.rotator().config().parking_enabled;
  a["az_travel_deg"] = st.rotator().config().az_travel_deg;
  const rotator::RotatorConfig& rc = app.model().rotator;  // the sky calibration (trakbox calibrate)
  // A parking position below the horizon mask (issue 57): said, never moved (a problem below).
  const auto into_mask = rotator::parking_mask_warning(rc, app.model().station.mask().get());
  a["parking_into_mask"] = into_mask ? nlohmann::json(*into_mask) : nlohmann::json(nullptr);
  a["sky_calibration"] = {{"az_offset_deg", rc.az_offset_deg},
                          {"el_offset_deg", rc.el_offset_deg},
                          {"source", rc.sky.source},
                          {"time", rc.sky.time}};
  return a;
}

// One link's state: "idle" (nothing sent: no satellite tuned, or no frequency for the link), "not
// sent" (the uplink of a radio that carries none: a receiver such as GQRX), "fault" (the radio
// serving it, with its message), "not connected", "not confirmed" (sent, but the radio has not
// accepted that frequency yet), "confirmed".
nlohmann::json link_json(const radio::RadioStatus& s, radio::Link link, std::optional<radio::Hz> sent) {
  const bool down = link == radio::Link::downlink;
  if (!down && s.no_uplink)  // before the first uplink too (the radio is preset when a satellite is chosen)
    return {{"state", "not sent"}, {"sent_hz", nullptr}, {"read_hz", nullptr},
            {"message", "the radio carries no uplink: give the uplink its own radio with --uplink-radio"}};
  const std::optional<radio::Hz> accepted = down ? s.downlink_hz : s.uplink_hz;
  const char* state = !sent ? "idle"
                      : s.fault ? "fault"
                      : !s.connected ? "not connected"
                      : accepted != sent ? "not confirmed"
                                         : "confirmed";
  return {{"state", state},
          {"sent_hz", hz_or_null(sent)},
          {"read_hz", hz_or_null(down ? s.downlink_read_hz : s.uplink_read_hz)},
          {"message", s.fault ? s.message : std::string()}};
}

// What the radio is tuned to for the satellite it follows: each link's spot (the satellite's
// frame), Doppler and dial, the operator's offsets, the tone and a transponder's passbands; null
// when nothing is tuned.
nlohmann::json tuning_json(StationApp& app) {
  const auto tuned = app.station().tuned();
  if (!tuned || static_cast<std::size_t>(*tuned) >= app.model().db.satellites.size()) return nullptr;
  const radio::Tuner& t = app.station().tuner();
  const radio::Tuning& now = t.last_tuning();
  const auto band = radio::transponder_of(t.satellite());
  const int tone = t.satellite().ctcss_tenths_hz;
  const store::Satellite& sat = app.model().db.satellites[static_cast<std::size_t>(*tuned)];
  nlohmann::json modes = nlohmann::json::array();  // the page's picker: every mode of the satellite
  for (const auto& m : store::modes_of(sat)) modes.push_back(m.name);
  const std::string mode = store::chosen_mode(sat);
  const auto chosen = store::find_mode(sat, mode);
  const int arm = chosen ? chosen->arm_tone_tenths_hz : 0;  // stored and shown; the operator sends it
  return {{"satellite", sat.name()},
          {"mode", mode.empty() ? nlohmann::json(nullptr) : nlohmann::json(mode)},
          {"modes", modes},
          {"arm_tone_hz", arm > 0 ? nlohmann::json(arm / 10.0) : nlohmann::json(nullptr)},
          {"downlink_spot_hz", t.satellite().has_downlink() ? nlohmann::json(t.downlink_spot_hz()) : nlohmann::json(nullptr)},
          {"uplink_spot_hz", t.satellite().has_uplink() ? nlohmann::json(t.uplink_spot_hz()) : nlohmann::json(nullptr)},
          {"downlink_doppler_hz", std::lround(now.downlink_doppler_hz)},
          {"uplink_doppler_hz", std::lround(now.uplink_doppler_hz)},
          {"downlink_dial_hz", hz_or_null(now.downlink_radio_hz)},
          {"uplink_dial_hz", hz_or_null(now.uplink_radio_hz)},
          {"rx_offset_hz", t.rit_hz()},
          {"tx_offset_hz", t.xit_hz()},
          {"tx_key", t.tx_correction_key().empty() ? nlohmann::json(nullptr) : nlohmann::json(t.tx_correction_key())},
          {"tone_hz", tone > 0 ? nlohmann::json(tone / 10.0) : nlohmann::json(nullptr)},
          {"passband", !band ? nlohmann::json(nullptr)
                             : nlohmann::json{{"downlink", {band->downlink_low_hz, band->downlink_high_hz}},
                                              {"uplink", {band->uplink_low_hz, band->uplink_high_hz}},
                                              {"inverting", band->inverting}}}};
}

// The radio's links, each from the radio that serves it (two radios: menu 6-7's U), and the
// dial-follow correction (the RIT) kept for the satellite and mode. Additive to the document.
void add_links(StationApp& app, const radio::RadioStatus& both, nlohmann::json& out) {
  radio::RadioDriver& r = app.station().radio();
  const radio::Tuner& t = app.station().tuner();
  radio::RadioStatus down = both, up = both;
  if (auto* two = dynamic_cast<radio::TwoRadios*>(&r)) {
    down = two->downlink_radio().status();
    up = two->uplink_radio().status();
    if (t.reversed()) std::swap(down, up);
  }
  out["links"] = {{"downlink", link_json(down, radio::Link::downlink, t.last_sent_downlink_hz())},
                  {"uplink", link_json(up, radio::Link::uplink, t.last_sent_uplink_hz())}};
  out["correction"] = {{"key", t.correction_key().empty() ? nlohmann::json(nullptr) : nlohmann::json(t.correction_key())},
                       {"hz", t.rit_hz()},
                       {"remembered", t.correction_remembered()},
                       {"dial_follow", t.dial_follow_active()}};
  out["tuning"] = tuning_json(app);
}

// The receiver's recorder (--record): what it can record, what it records now as it answered, the
// pass being recorded (its start, frequency and the receiver's file name) and a start it refused.
nlohmann::json recording_json(StationApp& app, const radio::RecorderStatus& r) {
  const auto& pass = app.station().recording();
  const auto or_null = [](const std::string& t) { return t.empty() ? nlohmann::json(nullptr) : nlohmann::json(t); };
  return {{"records", or_null(r.can)},
          {"setting", radio::to_string(app.model().radio.record)},
          {"state", radio::to_string(r.now)},
          {"read_back", r.read_back},
          {"refused", or_null(r.refused)},
          {"satellite", pass ? nlohmann::json(pass->satellite) : nlohmann::json(nullptr)},
          {"start", pass ? nlohmann::json(orbit::format_iso8601(pass->start, 0)) : nlohmann::json(nullptr)},
          {"frequency_hz", pass ? nlohmann::json(pass->frequency_hz) : nlohmann::json(nullptr)},
          {"file", pass ? or_null(pass->file) : nlohmann::json(nullptr)}};
}

nlohmann::json radio_json(StationApp& app) {
  radio::RadioDriver& r = app.station().radio();
  const radio::RadioStatus s = r.status();
  nlohmann::json j = {{"radio", r.describe()},
          {"connected", s.connected},
          {"fault", s.fault},
          {"message", s.message},
          {"downlink_hz", hz_or_null(s.downlink_hz)},
          {"uplink_hz", hz_or_null(s.uplink_hz)},
          {"downlink_mode", s.downlink_mode ? nlohmann::json(radio::to_string(*s.downlink_mode)) : nlohmann::json(nullptr)},
          {"uplink_mode", s.uplink_mode ? nlohmann::json(radio::to_string(*s.uplink_mode)) : nlohmann::json(nullptr)},
          {"delivered", s.delivered},
          {"failures", s.failures},
          {"connects", s.connects},
          {"pending", s.pending},
          {"limits", s.limits}};
  add_links(app, s, j);
  j["recording"] = recording_json(app, s.recorder);
  return j;
}

// The tracking list: each satellite now, its element age and its next pass (the tracker's search).
// A pass in progress as a list shows it (issue 47): from when it rose, with the whole pass's
// maximum. The tracker's pass of a satellite already up when it was searched begins at that search
// (aos = then, the maximum what was left of it): the pass around now is searched from before.
std::optional<orbit::Pass> whole_pass(StationApp& app, int db_index, const std::optional<orbit::Pass>& p,
                                      orbit::UtcTime now) {
  if (!p || !p->up_at_start || p->up_at_end) return p;
  const auto whole = app.tracker().pass_at(db_index, now);
  if (whole && !whole->up_at_start && !whole->up_at_end && whole->aos <= now && now <= whole->los) return whole;
  return p;
}

// The Sun or the Moon as a target (issue 58): "body": true; the Moon's range rate and its self-echo
// Doppler at the radio's downlink frequency (EME: -2 f rdot / c), shown, not applied.
void add_body(StationApp& app, orbit::Body body, const tracker::SatNow& c, nlohmann::json& s) {
  s["body"] = true;
  if (body != orbit::Body::moon) return;
  s["range_km"] = c.obs.look.range_km;
  s["range_rate_km_s"] = c.obs.look.range_rate_km_s;
  const auto hz = app.station().radio().status().downlink_hz;
  s["echo_doppler_hz"] =
      hz ? nlohmann::json(orbit::eme_echo_doppler_hz(static_cast<double>(*hz), c.obs.look.range_rate_km_s))
         : nlohmann::json(nullptr);
}

nlohmann::json tracking_list_json(StationApp& app, orbit::UtcTime now) {
  nlohmann::json list = nlohmann::json::array();
  const store::Database& db = app.model().db;
  const orbit::Observer where = app.model().station.observer();
  orbit::PassOptions po;
  po.mask = app.model().station.mask();  // AOS/LOS at the horizon mask, as the events and the tracker
  for (std::size_t k = 0; k < db.selected.size(); ++k) {
    const int i = db.selected[k];
    if (i < 0 || i >= static_cast<int>(db.satellites.size())) continue;
    const auto& sat = db.satellites[static_cast<std::size_t>(i)];
    const orbit::ElementAge age = orbit::element_age(sat.elements, now);
    nlohmann::json e{{"number", k + 1},
                     {"name", sat.name()},
                     {"catalog_number", sat.elements.catalog_number},
                     {"element_age_days", age.days},
                     {"elements_stale", age.stale()}};
    // The tracker's pass when it follows this satellite, else one searched; whole when the search
    // began inside it. Kept (next_passes) until it sets or the station moves: this runs for every
    // push to the page.
    const auto search = [&app, i, now, &where, &po]() -> std::optional<orbit::Pass> {
      std::optional<orbit::Pass> p;
      for (const auto& c : app.tracker().candidates())
        if (c.db_index == i) p = c.pass;
      if (!p) {
        if (const orbit::Sgp4* sgp4 = app.tracker().propagator(i))
          p = orbit::next_pass(*sgp4, where, now, 1.0, po);
      }
      return whole_pass(app, i, p, now);
    };
    const auto pass = app.tracker().passes().get(sat.elements, where, now, search, "status", po);
    if (const auto obs = app.tracker().observe(i, now); obs && obs->obs.ok())
      e["now"] = {{"az_deg", obs->obs.look.az_deg}, {"el_deg", obs->obs.look.el_deg}, {"in_range", obs->in_range}};
    e["next_pass"] = pass_json(pass, now);
    list.push_back(std::move(e));
  }
  return list;
}

const char* link_name(gps::Link l) {
  switch (l) {
    case gps::Link::off: return "off";
    case gps::Link::connecting: return "connecting";
    case gps::Link::no_gpsd: return "no gpsd";
    case gps::Link::no_receiver: return "no receiver";
    case gps::Link::receiving: return "receiving";
    case gps::Link::lost: return "gpsd lost";
  }
  return "?";
}

// The GPS receiver (null when none is configured): the link to gpsd, the fix, the position it last
// confirmed, the clock against GPS time, and whether the station follows it.
nlohmann::json gps_json(StationApp& app) {
  const gps::Monitor* g = app.gps();
  if (!g) return nullptr;
  nlohmann::json j{{"source", g->source()},
                   {"link", link_name(g->link())},
                   {"fix", g->filter().fixed()},
                   {"follow", app.model().gps.follow},
                   {"clock_warned", g->clock_warned()},
                   {"text", g->describe()},
                   {"status_word", g->status_word()}};
  const auto& c = g->filter().confirmed();
  j["position"] = c ? nlohmann::json{{"lat_deg", c->lat_deg},
                                      {"lon_deg", c->lon_deg},
                                      {"alt_m", c->alt_m ? nlohmann::json(*c->alt_m) : nlohmann::json(nullptr)},
                                      {"mode", c->mode},
                                      {"time", orbit::format_iso8601(c->time)}}
                    : nlohmann::json(nullptr);
  j["clock_error_s"] = g->clock_error_s() ? nlohmann::json(*g->clock_error_s()) : nlohmann::json(nullptr);
  return j;
}

}  // namespace

nlohmann::json station_status(StationApp& app, const StatusContext& cx) {
  const orbit::UtcTime now = app.clock().now();
  const station::StationConfig& st = app.model().station;
  nlohmann::json j{{"schema", kStatusSchema},
                   {"running", true},
                   {"pid", ::getpid()},
                   {"version", cx.version},
                   {"service", cx.service},
                   {"state_dir", cx.state_dir},
                   {"time", orbit::format_iso8601(now)},
                   {"clock_rate", app.clock().rate()}};
  j["station"] = {{"callsign", st.callsign},
                  {"lat_deg", st.lat_deg},
                  {"lon_deg", st.lon_deg},
                  {"height_m", st.height_m},
                  {"locator", station::maidenhead_locator(st.lat_deg, st.lon_deg)},
                  {"position_from_gps", app.model().gps.position_from_gps}};
  // The horizon mask (issue 57): its points for the page's sky, the file's kind and what it spans.
  if (const auto mask = st.mask()) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : mask->points()) points.push_back({p.az_deg, p.el_deg});
    j["station"]["horizon_mask"] = {{"kind", mask->kind() == orbit::HorizonMask::Kind::stepped ? "stepped" : "interpolated"},
                                    {"points", points},
                                    {"describe", mask->describe()},
                                    {"text", mask->text()}};
  }
  tracker::Tracker& tr = app.tracker();
  nlohmann::json tracking{{"mode", mode_name(tr.mode())}, {"priority", tr.priority()}};
  nlohmann::json sats = nlohmann::json::array();
  for (const auto& c : tr.candidates()) {
    nlohmann::json s{{"name", c.name}, {"list_number", c.list_number}, {"in_range", c.in_range}};
    if (c.obs.ok()) s["az_deg"] = c.obs.look.az_deg, s["el_deg"] = c.obs.look.el_deg;
    s["pass"] = pass_json(whole_pass(app, c.db_index, c.pass, now), now);
    if (const auto body = tracker::body_target(c.db_index)) add_body(app, *body, c, s);
    sats.push_back(std::move(s));
  }
  tracking["satellites"] = std::move(sats);
  const tracker::SatNow* f = tr.followed();
  tracking["followed"] = f ? nlohmann::json(f->name) : nlohmann::json(nullptr);
  if (const auto& r = app.station().remote_followed()) tracking["remote"] = {{"owner", r->owner}, {"name", r->name}};
  j["tracking"] = std::move(tracking);
  j["antenna"] = antenna_json(app);
  j["radios"] = nlohmann::json::array({radio_json(app)});
  j["tracking_list"] = tracking_list_json(app, now);
  j["gps"] = gps_json(app);
  const tracker::ElementsRefresh& rf = app.refresh();
  j["elements_refresh"] = {{"sources", app.model().refresh.sources.size()},
                           {"last_result", rf.last_result()},
                           {"last_failed", rf.last_failed()},
                           {"running", rf.running()}};
  const auto saved = app.last_saved();
  j["save"] = {{"last_saved", saved ? nlohmann::json(orbit::format_iso8601(
                                          std::chrono::time_point_cast<std::chrono::microseconds>(*saved)))
                                    : nlohmann::json(nullptr)},
               {"failure", app.station().save_failure() ? nlohmann::json(*app.station().save_failure())
                                                        : nlohmann::json(nullptr)}};
  j["servers"] = cx.servers ? cx.servers() : nlohmann::json::array();
  j["attached"] = cx.attached;
  j["keyboard"] = cx.keyboard.empty() ? nlohmann::json(nullptr) : nlohmann::json(cx.keyboard);
  j["status_line"] = app.station().status_line();
  j["log"] = tracker::log_summary(tracker::LogOps(app.station()));
  add_control_status(app.station(), j);
  const auto problems = status_problems(j);
  j["healthy"] = problems.empty();
  j["problems"] = problems;
  j["setup"] = setup_needed(app.model());
  return j;
}

std::vector<std::string> setup_needed(const store::Model& m) {
  // A first start runs as the factory's station (NOCALL at 27.4 N 128.7 E): said until the operator
  // sets both, so that passes, Doppler and the log's STATION_CALLSIGN are the operator's own.
  std::vector<std::string> out;
  const store::Model factory = store::factory_defaults();
  if (m.station.callsign.empty() || m.station.callsign == factory.station.callsign)
    out.push_back("callsign not set (" + (m.station.callsign.empty() ? std::string("none") : m.station.callsign) +
                  "): QSOs are logged without STATION_CALLSIGN; set it in menu 4, the page's Station card or "
                  "with trakbox settings set station.callsign CALL");
  if (m.station.lat_deg == factory.station.lat_deg && m.station.lon_deg == factory.station.lon_deg &&
      !m.gps.position_from_gps)
    out.push_back(fmt::format("station position not set: the factory's {:.3f}, {:.3f} ({}) is used; set it in menu 4, "
                              "the page's Station card or with trakbox --station LAT,LON[,HEIGHT]",
                              m.station.lat_deg, m.station.lon_deg,
                              station::maidenhead_locator(m.station.lat_deg, m.station.lon_deg)));
  return out;
}

std::vector<std::string> status_problems(const nlohmann::json& s) {
  std::vector<std::string> out;
  const auto& a = s.at("antenna");
  if (a.at("link") != "ok") out.push_back("rotator link " + a.at("link").get<std::string>() + ": " + a.value("link_message", ""));
  if (const auto w = a.value("parking_into_mask", nlohmann::json()); w.is_string()) out.push_back(w.get<std::string>());
  for (const auto& r : s.at("radios"))
    if (r.value("fault", false)) out.push_back("radio fault: " + r.value("message", ""));
  if (!s.at("save").at("failure").is_null()) out.push_back("state not saved: " + s["save"]["failure"].get<std::string>());
  if (const auto sn = s.value("satnogs", nlohmann::json()); sn.is_object() && sn.value("error", nlohmann::json()).is_string())
    out.push_back(sn["error"].get<std::string>());
  // GPS: a receiver that cannot be heard, or a clock off GPS time, is a problem; a lost fix is
  // shown, not counted (the station keeps its position).
  if (const auto g = s.value("gps", nlohmann::json()); g.is_object()) {
    if (g.value("link", "") != "receiving") out.push_back("GPS: " + g.value("status_word", g.value("link", "")));
    else if (g.value("clock_warned", false)) out.push_back("GPS: " + g.value("status_word", std::string("clock off GPS time")));
  }
  // The satellites tracked now on element sets past the age their orbits allow: the antenna is
  // pointed by unreliable positions (issue 39). A stale set elsewhere in the list is shown (STALE),
  // not counted: it moves nothing.
  std::vector<std::string> tracked;
  for (const auto& c : s.at("tracking").value("satellites", nlohmann::json::array())) tracked.push_back(c.value("name", ""));
  int stale = 0;
  double oldest = 0.0;
  for (const auto& e : s.value("tracking_list", nlohmann::json::array()))
    if (e.value("elements_stale", false) &&
        std::find(tracked.begin(), tracked.end(), e.value("name", "")) != tracked.end()) {
      ++stale;
      oldest = std::max(oldest, e.value("element_age_days", 0.0));
    }
  if (stale > 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "elements of %d tracked satellite(s) too old (up to %.1f days): refresh them "
                                   "(menu 3-5, --elements-url)", stale, oldest);
    out.push_back(buf);
  }
  if (s.at("elements_refresh").value("last_failed", false))
    out.push_back("element refresh failed: " + s["elements_refresh"].value("last_result", ""));
  if (const auto l = s.value("log", nlohmann::json()); l.is_object()) {
    if (l.contains("problem")) out.push_back("logbook: " + l.value("problem", std::string()));
    if (l.contains("upload_problem")) out.push_back("logger: " + l.value("upload_problem", std::string()));
  }
  return out;
}

namespace {

// "pass AOS - LOS max 41.2"; "always up, max 32.4" (no AOS or LOS); "... (never rises)".
template <class Num>
std::string pass_text(const nlohmann::json& p, const std::string& what, const Num& num) {
  if (p.value("always_up", false)) return "always up (no AOS or LOS), el " + num(p["max_el_deg"], 1);
  const std::string los = p.contains("los") && p["los"].is_string() ? p["los"].get<std::string>() : "still up";
  std::string l = what + " " + p.value("aos", "") + " - " + los + " max " + num(p["max_el_deg"], 1);
  if (!p.value("rises", true)) l += " (never rises)";
  return l;
}

// ", REC audio SO-50 since 2026-05-21T14:10:02Z, gqrx_20260521_141002_436795000.wav" while the
// receiver records (read back or not); nothing otherwise (a refusal is among the limits).
std::string recording_text(const nlohmann::json& radio) {
  const auto r = radio.value("recording", nlohmann::json());
  if (!r.is_object() || r.value("state", "off") == "off") return {};
  const auto str = [&r](const char* k) {
    const nlohmann::json v = r.value(k, nlohmann::json());
    return v.is_string() ? v.get<std::string>() : std::string();
  };
  std::string t = ", REC " + str("state");
  if (!str("satellite").empty()) t += " " + str("satellite") + " since " + str("start");
  if (!str("file").empty()) t += ", " + str("file");
  if (!r.value("read_back", false)) t += " (not read back)";
  return t;
}

}  // namespace

std::string format_status(const nlohmann::json& s) {
  std::string out;
  auto line = [&out](const std::string& l) { out += l + "\n"; };
  auto num = [](const nlohmann::json& v, int decimals) {
    if (!v.is_number()) return std::string("-");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v.get<double>());
    return std::string(buf);
  };
  line(std::string("trakbox ") + s.value("version", "") + (s.value("service", false) ? " (service)" : "") + ", pid " +
       std::to_string(s.value("pid", 0)) + ", state " + s.value("state_dir", "") + ": " +
       (s.value("healthy", false) ? "running" : "running, with problems"));
  if (const auto st = s.value("station", nlohmann::json()); st.is_object())
    line("  station   " + st.value("callsign", "") + " " + num(st["lat_deg"], 4) + ", " + num(st["lon_deg"], 4) + ", " +
         num(st["height_m"], 0) + " m, " + st.value("locator", "") +
         (st.contains("horizon_mask") ? ", horizon mask " + st["horizon_mask"].value("describe", "") : ""));
  for (const auto& n : s.value("setup", nlohmann::json::array())) line("  SETUP     " + n.get<std::string>());
  line("  time      " + s.value("time", "") + (s.value("clock_rate", 1.0) != 1.0 ? " (clock x" + num(s["clock_rate"], 1) + ")" : ""));
  const auto& t = s.at("tracking");
  std::string tracking = "  tracking  " + t.value("mode", "off");
  if (!t.at("followed").is_null()) tracking += ", following " + t["followed"].get<std::string>();
  line(tracking);
  for (const auto& c : t.at("satellites")) {
    std::string l = "            #" + std::to_string(c.value("list_number", 0)) + " " + c.value("name", "") + " az " +
                    num(c.value("az_deg", nlohmann::json()), 1) + " el " + num(c.value("el_deg", nlohmann::json()), 1);
    if (c.contains("pass") && !c["pass"].is_null()) l += "  " + pass_text(c["pass"], "pass", num);
    line(l);
  }
  const auto& a = s.at("antenna");
  std::string ant = "  antenna   ";
  ant += a.at("position").is_null() ? "position unknown"
                                     : "az " + num(a["position"]["az_deg"], 1) + " el " + num(a["position"]["el_deg"], 1);
  ant += ", " + a.value("action", "hold");
  if (!a.at("target").is_null()) ant += " to az " + num(a["target"]["az_deg"], 1) + " el " + num(a["target"]["el_deg"], 1);
  ant += ", rotor control " + std::string(a.value("rotor_control", false) ? "on" : "off") + ", link " + a.value("link", "");
  // An outside client's targets recognised as a pass (issue 57): "following rotctld's targets ...".
  if (const auto f = a.find("follows"); f != a.end() && f->is_string()) ant += ", " + f->get<std::string>();
  line(ant);
  if (const auto c = s.value("control", nlohmann::json()); c.is_object())
    line("  control   antenna " + c["antenna"].value("label", "") + ", radio " + c["radio"].value("label", "") +
         (s.value("standby", false) ? " (STANDBY)" : ""));
  // The windows trakbox yields in (`trakbox reserve`, SatNOGS jobs), as --json lists them.
  for (const auto& w : s.value("reservations", nlohmann::json::array()))
    line("  reserved  " + w.value("start", "") + " - " + w.value("end", "") + " " + w.value("kind", "") +
         (w.value("satellite", "").empty() ? std::string() : " " + w.value("satellite", "")) +
         (w.value("note", "").empty() ? std::string() : " (" + w.value("note", "") + ")"));
  for (const auto& r : s.at("radios"))
    line("  radio     " + r.value("radio", "") + ": downlink " + num(r.value("downlink_hz", nlohmann::json()), 0) +
         " Hz, uplink " + num(r.value("uplink_hz", nlohmann::json()), 0) + " Hz, " +
         (r.value("fault", false) ? "fault: " + r.value("message", "") : std::string("ok")) +
         (r.value("limits", "").empty() ? std::string() : " (" + r.value("limits", "") + ")") + recording_text(r));
  for (const auto& e : s.at("tracking_list")) {
    std::string l = "  list #" + std::to_string(e.value("number", 0)) + "  " + e.value("name", "") + ", elements " +
                    num(e["element_age_days"], 1) + " days old" + (e.value("elements_stale", false) ? " (STALE)" : "");
    if (!e.at("next_pass").is_null()) l += ", " + pass_text(e["next_pass"], "next pass", num);
    line(l);
  }
  if (const auto g = s.value("gps", nlohmann::json()); g.is_object())
    line("  gps       " + g.value("source", "") + ": " + g.value("text", "") +
         (g.value("follow", false) ? ", followed" : ", not followed"));
  const auto& rf = s.at("elements_refresh");
  line("  elements  " + std::to_string(rf.value("sources", 0)) + " refresh source(s)" +
       (rf.value("last_result", "").empty() ? std::string() : ": " + rf.value("last_result", "")));
  for (const auto& srv : s.value("servers", nlohmann::json::array())) {
    std::string l = "  server    " + srv.value("name", "") + " port " + std::to_string(srv.value("port", 0)) + ", " +
                    std::to_string(srv.value("clients", 0)) + " client(s)";
    if (srv.contains("url")) l += ", " + srv.value("url", "");
    for (const auto& [key, value] : srv.items())
      if (key.rfind("refused", 0) == 0 || key == "wrong_secrets" || key == "lockouts" || key == "evicted" ||
          key == "dropped_slow")
        if (value.is_number() && value.get<long long>() > 0) l += ", " + key + " " + std::to_string(value.get<long long>());
    line(l);
  }
  if (const auto l = s.value("log", nlohmann::json()); l.is_object() && l.value("open", false)) {
    std::string t = "  log       " + std::to_string(l.value("count", 0)) + " QSO(s)";
    if (l.contains("last") && l["last"].is_object())
      t += ", last " + l["last"].value("call", "") + " " + l["last"].value("sat_name", "") + " " + l["last"].value("time_on", "");
    t += ", " + std::to_string(l.value("queue", 0)) + " to upload";
    line(t);
    if (const auto g = l.value("logger", nlohmann::json()); g.is_object()) {
      const auto when = [&](const char* k) { return g[k].is_string() ? g[k].get<std::string>() : std::string("never"); };
      line("  logger    " + g.value("kind", "") + " " + g.value("url", "") + ", last upload " + when("last_upload") +
           ", radio posted " + when("last_radio_post"));
    }
  }
  const auto& sv = s.at("save");
  line("  saved     " + (sv.at("last_saved").is_null() ? std::string("not yet") : sv["last_saved"].get<std::string>()));
  if (const auto& who = s.at("attached"); !who.empty()) {
    std::string l = "  attached ";
    for (const auto& w : who) l += " " + w.get<std::string>() + ";";
    if (!s.at("keyboard").is_null()) l += " keyboard: " + s["keyboard"].get<std::string>();
    line(l);
  }
  for (const auto& p : s.at("problems")) line("  PROBLEM   " + p.get<std::string>());
  return out;
}

}  // namespace tb::app
