#include "web/api.h"
#include "web/control_api.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "orbit/element_age.h"
#include "orbit/passes.h"
#include "station/station.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "util/cidr.h"
#include "util/json_limits.h"
#include "util/text.h"
#include "web/api_log.h"
#include "web/live_feed.h"
#include "web/api_radio.h"
#include "web/page.h"

namespace tb::web {

namespace {

using json = nlohmann::json;

// Text a client sent, fit to quote in a reply: printable ASCII (others as '?'), at most `max`.
std::string printable(std::string_view s, std::size_t max) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < max; ++i) out.push_back(s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?');
  if (s.size() > max) out += "...";
  return out;
}

Response error(int status, std::string sentence) {
  Response r;
  r.status = status;
  r.body = json{{"error", sentence}}.dump();
  r.why = std::move(sentence);
  return r;
}

Response ok(const json& j) {
  Response r;
  r.body = j.dump(-1, ' ', false, json::error_handler_t::replace);
  return r;
}

// A request the grant does not allow: its status and sentence; 429 says when to try again.
Response refused(const Grant& g) {
  Response r = error(g.status_not_change, g.why_not_change.value_or("log in first"));
  if (g.status_not_change == 429 && g.retry_after_s > 0) r.headers.emplace_back("Retry-After", std::to_string(g.retry_after_s));
  return r;
}

Response redirect(const std::string& to) {
  Response r;
  r.status = 303;
  r.content_type = "text/plain";
  r.headers.emplace_back("Location", to);
  return r;
}

int hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = text::to_lower(c);
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::optional<std::string> percent_decode(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '+') out.push_back(' ');
    else if (s[i] != '%') out.push_back(s[i]);
    else {
      if (i + 2 >= s.size() || hex(s[i + 1]) < 0 || hex(s[i + 2]) < 0) return std::nullopt;
      out.push_back(static_cast<char>(hex(s[i + 1]) * 16 + hex(s[i + 2])));
      i += 2;
    }
  }
  return out;
}

// A form or query field of `fields` ("a=1&b=2"); "" when absent, nullopt for a bad escape. A field
// given more than once is every value, joined by commas ("sat=A&sat=B" is "A,B", as "sat=A,B"; a
// number given twice is then no number, and refused as such): never the first one alone.
std::optional<std::string> field(std::string_view fields, const std::string& name) {
  std::optional<std::string> out;
  for (std::string_view part : text::split(fields, '&')) {
    const auto eq = part.find('=');
    const auto key = percent_decode(part.substr(0, eq));
    if (!key || *key != name) continue;
    const auto value = eq == std::string_view::npos ? std::optional<std::string>("") : percent_decode(part.substr(eq + 1));
    if (!value) return std::nullopt;
    out = out ? *out + "," + *value : *value;
  }
  return out ? *out : std::string();
}

json pass_json(const orbit::Pass& p) {
  return {{"aos", orbit::format_iso8601(p.aos)}, {"tca", orbit::format_iso8601(p.tca)},
          {"los", orbit::format_iso8601(p.los)}, {"max_el_deg", p.max_el_deg},
          {"aos_az_deg", p.aos_az_deg},          {"tca_az_deg", p.tca_az_deg},
          {"los_az_deg", p.los_az_deg}};
}

json az_el(double az, double el) { return json::array({std::round(az * 100) / 100, std::round(el * 100) / 100}); }

}  // namespace

std::vector<std::pair<std::string, std::string>> security_headers() {
  return {{"Content-Security-Policy", "default-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'self'"},
          {"X-Content-Type-Options", "nosniff"},
          {"X-Frame-Options", "DENY"},
          {"Referrer-Policy", "no-referrer"},
          {"Cache-Control", "no-store"}};
}

std::string target_path(const std::string& target) {
  const auto q = target.find('?');
  return target.substr(0, q);
}

std::optional<std::string> query_param(const std::string& target, const std::string& name) {
  const auto q = target.find('?');
  if (q == std::string::npos) return std::string();
  return field(std::string_view(target).substr(q + 1), name);
}

std::optional<std::string> allowed_methods(const std::string& path) {
  static const std::vector<std::pair<std::string_view, std::string_view>> kEndpoints = {
      {"/", "GET, HEAD"},
      {"/login", "GET, HEAD, POST"},
      {"/logout", "POST"},
      {"/api/v1/status", "GET, HEAD"},
      {"/api/v1/satellites", "GET, HEAD"},
      {"/api/v1/passes", "GET, HEAD"},
      {"/api/v1/passes.ics", "GET, HEAD"},
      {"/api/v1/sky", "GET, HEAD"},
      {"/api/v1/live", "GET"},
      {"/api/v1/log", "GET, HEAD, POST"},
      {"/api/v1/log.adi", "GET, HEAD"},
      {"/api/v1/log/edit", "POST"},
      {"/api/v1/log/delete", "POST"},
      {"/api/v1/track", "POST"},
      {"/api/v1/rotor", "POST"},
      {"/api/v1/calibrate", "POST"},
      {"/api/v1/radio", "POST"},
      {"/api/v1/station", "POST"},
      {"/api/v1/standby", "POST"},
      {"/api/v1/control", "POST"},
      {"/api/v1/reserve", "POST"},
      {"/api/v1/elements/refresh", "POST"}};
  for (const auto& [p, methods] : kEndpoints)
    if (p == path) return std::string(methods);
  if (find_page_file(path)) return std::string("GET, HEAD");
  return std::nullopt;
}

static bool method_in(const std::string& method, const std::string& allow) {
  for (std::string_view m : text::split(allow, ','))
    if (text::trim(m, " ") == method) return true;
  return false;
}

// The reply's sentence for the log's line of refusals, when the handler left `why` empty (issue 56:
// a refused QSO was logged with an empty reason): the body's "error".
static void fill_why(Response& r) {
  if (r.status < 400 || !r.why.empty() || r.stream) return;
  std::string unused;
  const json j = json_limits::parse_bounded<json>(r.body, unused);
  if (j.is_object() && j.contains("error") && j["error"].is_string()) r.why = j["error"].get<std::string>();
}

Api::Api(tracker::StationLoop& station, Access& access, ApiHooks hooks)
    : station_(station), access_(access), hooks_(std::move(hooks)) {}

Response Api::handle(const Request& r, std::chrono::steady_clock::time_point now) {
  try {
    const std::string path = target_path(r.target);
    // Each endpoint its methods (RFC 9110 15.5.6: a 405 names them in Allow); a path that is none, 404.
    const auto allow = allowed_methods(path);
    if (!allow)
      return error(404, (path.rfind("/api/", 0) == 0 ? "no such endpoint: " : "no such page: ") + printable(path, 60));
    if (!method_in(r.method, *allow)) {
      Response res = error(405, "method " + printable(r.method, 10) + " not allowed on " + printable(path, 60) + ": " + *allow);
      res.headers.emplace_back("Allow", *allow);
      return res;
    }
    if (path == "/login" && r.method == "POST") return login(r, now);
    const bool changing = r.method == "POST";
    const Grant g = access_.grant(r.peer, r.host, r.origin, r.cookie, r.authorization, changing, now);
    Response res = route(r, g);
    fill_why(res);
    return res;
  } catch (const std::exception& e) {
    spdlog::warn("web: {} {}: {}", r.method, target_path(r.target).substr(0, 80), e.what());
    return error(400, "the request could not be handled");
  } catch (...) {
    return error(400, "the request could not be handled");
  }
}

// The session cookie's attributes. Secure when the browser reached the page over HTTPS: trakbox
// speaks plain HTTP, so that is only known from a TLS proxy in front (docs/security.md), and its
// X-Forwarded-Proto is believed only from a loopback peer; a client elsewhere could send the header
// itself, and a cookie marked Secure over plain HTTP would just be dropped by the browser.
static std::string cookie_attributes(const Request& r) {
  const bool https = inet::is_loopback(r.peer) && text::trim(r.forwarded_proto, text::kWhitespace) == "https";
  return std::string("; Path=/; HttpOnly; SameSite=Strict") + (https ? "; Secure" : "");
}

Response Api::login(const Request& r, std::chrono::steady_clock::time_point now) {
  if (!access_.host_allowed(r.host))
    return error(403, "Host '" + printable(r.host, 60) + "' is not this station's name");
  if (!r.origin.empty() && !Access::origin_matches(r.origin, r.host))
    return error(403, "a login must come from the login page itself (Origin)");
  if (!access_.needs_secret()) return redirect("/");
  if (r.body.size() > kMaxBody) return error(413, "the request body is over 16 kB");
  const auto given = field(r.body, "secret");
  int wait = 0;
  const auto token = given ? access_.login(r.peer, *given, now, wait) : std::nullopt;
  if (!token) return redirect(wait > 0 ? "/login#wait" : "/login#wrong");
  Response res = redirect("/");
  res.headers.emplace_back("Set-Cookie",
                           std::string(kSessionCookie) + "=" + *token + cookie_attributes(r));
  return res;
}

std::optional<Response> Api::refuse_live(const Request& r, std::chrono::steady_clock::time_point now) {
  try {
    const Grant g = access_.grant(r.peer, r.host, r.origin, r.cookie, r.authorization, false, now);
    if (!r.origin.empty() && !Access::origin_matches(r.origin, r.host))
      return error(403, "the live feed is for the page itself (Origin does not match)");
    if (!g.view) {
      Grant why = g;
      if (!why.why_not_change) why.status_not_change = 401;
      return refused(why);
    }
    return std::nullopt;
  } catch (...) {
    return error(400, "the request could not be handled");
  }
}

Response Api::route(const Request& r, const Grant& g) {
  const std::string path = target_path(r.target);
  if (r.method == "GET" || r.method == "HEAD") {
    // The page's files are public (they hold no station data); the page asks for the rest.
    const std::string file = path == "/" ? "/index.html" : path == "/login" ? "/login.html" : path;
    if (const PageFile* f = find_page_file(file)) {
      Response res;
      res.content_type = std::string(f->type);
      res.body = std::string(f->body);
      return res;
    }
    if (path.rfind("/api/v1/", 0) != 0) return error(404, "no such page: " + printable(path, 60));
    if (!g.view) return refused(g);
    if (path == "/api/v1/status") {
      json j = hooks_.status ? hooks_.status() : json::object();
      j["schema"] = kApiSchema;
      return ok(j);
    }
    if (path == "/api/v1/satellites") return satellites();
    if (path == "/api/v1/passes") return passes(r.target);
    if (path == "/api/v1/passes.ics") return passes_ics(r.target);
    if (path == "/api/v1/sky") return ok(sky());
    if (path == "/api/v1/live") return error(426, "/api/v1/live is a WebSocket (Upgrade: websocket)");
    if (is_log_path(path))
      return log_get(station_, path, r.target, hooks_.wall_now_unix ? hooks_.wall_now_unix() : 0,
                     hooks_.status ? hooks_.status().value("version", std::string()) : std::string());
    return error(404, "no such endpoint: " + printable(path, 60));
  }
  if (path == "/logout") {
    access_.logout(r.cookie);
    Response res = redirect("/login");
    res.headers.emplace_back("Set-Cookie", std::string(kSessionCookie) + "=" + cookie_attributes(r) + "; Max-Age=0");
    return res;
  }
  if (path.rfind("/api/v1/", 0) != 0) return error(404, "no such endpoint: " + printable(path, 60));
  if (!g.change) return refused(g);
  if (r.body.size() > kMaxBody) return error(413, "the request body is over 16 kB");
  const std::string type = text::lower(text::trim(r.content_type.substr(0, r.content_type.find(';')), text::kWhitespace));
  if (type != "application/json") return error(415, "the body must be JSON (Content-Type: application/json)");
  std::string why;
  const json body = r.body.empty() ? json::object() : json_limits::parse_bounded<json>(r.body, why);
  if (why.starts_with("nested")) return error(400, "the JSON body is nested too deep");
  if (body.is_discarded()) return error(400, "the body is not valid JSON");
  if (!body.is_object()) return error(400, "the body must be a JSON object");
  if (is_log_path(path)) {
    Response res = log_post(station_, path, body, "web " + printable(r.peer, 60));
    if (res.status == 200 && hooks_.changed) hooks_.changed();
    return res;
  }
  Response res = post(path, body, r.peer);
  // Every change asked from the page, logged with who asked and what came of it.
  const json reply = json_limits::parse_bounded<json>(res.body, why);
  const std::string said = reply.is_object() ? reply.value("note", reply.value("error", std::string())) : std::string();
  spdlog::info("web: {} {} from {}: {} {}", path, printable(body.dump(-1, ' ', true, json::error_handler_t::replace), 120),
               printable(r.peer, 60), res.status, printable(said, 160));
  return res;
}

Response Api::post(const std::string& path, const json& b, const std::string& peer) {
  // The page acts as the operator "web ADDRESS" (tracker/control.h); "confirm":true takes the antenna
  // from an outside client or a reservation, which is otherwise a 409 naming the holder.
  const bool confirmed = b.contains("confirm") && b["confirm"].is_boolean() && b["confirm"].get<bool>();
  tracker::StationOps ops(station_, {tracker::HolderKind::web, "web " + printable(peer, 60)}, confirmed);
  tracker::OpResult done;
  auto boolean = [&b](const char* key) -> std::optional<bool> {
    const auto it = b.find(key);
    if (it == b.end() || !it->is_boolean()) return std::nullopt;
    return it->get<bool>();
  };
  if (path == "/api/v1/track") {
    const bool priority = boolean("priority").value_or(station_.model().priority_mode);
    if (b.contains("satellite")) {
      if (!b["satellite"].is_string()) return error(400, "track: \"satellite\" must be a string, e.g. \"ISS\"");
      done = ops.track(b["satellite"].get<std::string>());
    } else if (b.contains("list")) {
      if (!b["list"].is_array()) return error(400, "track: \"list\" must be an array of names");
      std::vector<std::string> names;
      for (const auto& n : b["list"]) {
        if (!n.is_string()) return error(400, "track: \"list\" must hold names (strings)");
        names.push_back(n.get<std::string>());
      }
      done = ops.track_list(names, priority);
    } else if (b.contains("multi")) {
      if (!b["multi"].is_boolean() || !b["multi"].get<bool>()) return error(400, "track: \"multi\" must be true");
      done = ops.track_multi(priority);
    } else if (b.contains("stop")) {
      done = ops.stop();
    } else {
      return error(400, "track: expected {\"satellite\":NAME}, {\"list\":[NAMES]} or {\"multi\":true}");
    }
  } else if (path == "/api/v1/rotor") {
    if (b.contains("control")) {
      const auto on = boolean("control");
      if (!on) return error(400, "rotor: \"control\" must be true or false");
      done = ops.rotor_control(*on);
    } else if (b.contains("action")) {
      const std::string a = b["action"].is_string() ? b["action"].get<std::string>() : "";
      if (a == "stop") done = ops.stop();
      else if (a == "park") done = ops.park();
      else return error(400, "rotor: \"action\" must be \"stop\" or \"park\"");
    } else if (b.contains("goto")) {
      const json& g = b["goto"];
      if (!g.is_object() || !g.contains("az") || !g.contains("el") || !g["az"].is_number() || !g["el"].is_number())
        return error(400, "rotor: \"goto\" must be {\"az\":DEGREES,\"el\":DEGREES}");
      done = ops.go_to(g["az"].get<double>(), g["el"].get<double>());
    } else {
      return error(400, "rotor: expected {\"control\":true|false}, {\"action\":\"stop\"|\"park\"} or {\"goto\":{...}}");
    }
  } else if (path == "/api/v1/calibrate") {
    // "This is the Sun/Moon" and its undo (issue 58, docs/calibration.md).
    const std::string body = b.contains("body") && b["body"].is_string() ? b["body"].get<std::string>() : "";
    if (const auto which = orbit::parse_body(body)) done = ops.calibrate(*which);
    else if (boolean("undo").value_or(false)) done = ops.calibrate_undo();
    else return error(400, "calibrate: expected {\"body\":\"sun\"|\"moon\"} or {\"undo\":true}");
  } else if (path == "/api/v1/radio") {
    if (const auto bad = radio_request(ops, b, done)) return error(400, *bad);
  } else if (path == "/api/v1/station") {
    if (const auto bad = station_request(ops, station_.model().station.height_m, b, done)) return error(400, *bad);
  } else if (path == "/api/v1/standby" || path == "/api/v1/control" || path == "/api/v1/reserve") {
    if (const auto r = control_post(ops, path, b)) done = *r;
    else return error(400, path == "/api/v1/standby"   ? "standby: expected {\"on\":true|false}"
                           : path == "/api/v1/reserve" ? "reserve: expected {\"start\":ISO,\"end\":ISO,\"note\":TEXT}"
                                                       : "control: expected {\"take_back\":true}");
  } else if (path == "/api/v1/elements/refresh") {
    done = ops.refresh_elements(hooks_.wall_now_unix ? hooks_.wall_now_unix() : 0);
  } else {
    return error(404, "no such endpoint: " + printable(path, 60));
  }
  if (!done.ok()) return refused(done);
  json reply{{"ok", true}, {"note", done.note}};
  if (done.model_changed && hooks_.save)
    if (const auto why = hooks_.save()) reply["saved"] = false, reply["save_failure"] = *why;
  if (hooks_.changed) hooks_.changed();
  return ok(reply);
}

Response Api::satellites() {
  const store::Model& m = station_.model();
  const orbit::UtcTime now = station_.tracker().last_tick_time();
  json list = json::array();
  for (std::size_t i = 0; i < m.db.satellites.size(); ++i) {
    const auto& s = m.db.satellites[i];
    const orbit::ElementAge age = orbit::element_age(s.elements, now);
    json e{{"name", s.name()},
           {"catalog_number", s.elements.catalog_number},
           {"list_number", m.db.list_number(static_cast<int>(i))},
           {"element_age_days", age.days},
           {"elements_stale", age.stale()},
           {"downlink_hz", s.radio.downlink_hz},
           {"uplink_hz", s.radio.uplink_hz}};
    // Its modes (issue 59): each name with its downlink and uplink, and the chosen one's name.
    json modes = json::array();
    for (const auto& mo : store::modes_of(s))
      modes.push_back({{"name", mo.name}, {"downlink_hz", mo.radio.downlink_hz}, {"uplink_hz", mo.radio.uplink_hz}});
    const std::string chosen = store::chosen_mode(s);
    e["modes"] = std::move(modes);
    e["mode"] = chosen.empty() ? json(nullptr) : json(chosen);
    list.push_back(std::move(e));
  }
  return ok(json{{"satellites", std::move(list)}});
}

json Api::sky() {
  tracker::Tracker& tr = station_.tracker();
  json j{{"time", orbit::format_iso8601(tr.last_tick_time())}};
  const auto antenna = station_.antenna();
  j["antenna"] = antenna ? az_el(antenna->az, antenna->el) : json(nullptr);
  const tracker::Decision& d = tr.last_decision();
  // One word for the antenna panel: fault, moving, parked, on target (at its limit when the target
  // was clamped to the limits) or idle.
  const rotator::Status& rs = station_.rotator().status();
  const bool moving = rs.az.moving != rotator::Drive::stop || rs.el.moving != rotator::Drive::stop;
  const bool parked = rs.on_target && station_.rotator().config().parking_enabled && rs.target &&
                      (tr.mode() == tracker::Mode::off || d.antenna == tracker::Decision::Antenna::park) &&
                      antenna && rotator::azimuth_distance(antenna->az, station_.rotator().config().parking.az) < 2.0 &&
                      std::abs(antenna->el - station_.rotator().config().parking.el) < 2.0;
  j["antenna_state"] = !rs.link.ok() ? "fault"
                       : moving       ? "moving"
                       : parked       ? "parked"
                       : rs.on_target ? (rs.limited ? "at its limit" : "on target")
                                      : "idle";
  // Where the antenna was last sent by whoever holds it (issue 44): the tracker's decision only while
  // trakbox's tracking drives it, else the rotator's commanded target (a goto, rotctld, Satrak).
  const tracker::StationLoop::Aim aim = station_.aim();
  j["target"] = aim.target ? az_el(aim.target->az, aim.target->el) : json(nullptr);
  const tracker::SatNow* f = tr.mode() == tracker::Mode::off ? nullptr : tr.followed();
  if (!f || !f->obs.ok()) {
    j["satellite"] = nullptr;
    j["pass"] = nullptr;
    return j;
  }
  j["satellite"] = {{"name", f->name}, {"az_el", az_el(f->obs.look.az_deg, f->obs.look.el_deg)}, {"in_range", f->in_range}};
  if (!f->pass) {
    j["pass"] = nullptr;
    return j;
  }
  // A pass already up when tracking began: drawn from its real AOS (searched once per pass).
  // The same pass when its LOS agrees to the searches' precision (each found to about a second from
  // a different start: equal to the nanosecond, they never were, and the sky began where tracking did).
  const auto same_los = [](const orbit::Pass& a, const orbit::Pass& b) {
    return std::abs(orbit::minutes_between(a.los, b.los)) * 60.0 < 5.0;
  };
  if (f->pass->up_at_start &&
      !(real_pass_ && real_pass_->first == f->db_index && same_los(real_pass_->second, *f->pass))) {
    const auto real = tr.pass_at(f->db_index, tr.last_tick_time());
    real_pass_ = std::make_pair(f->db_index, real && same_los(*real, *f->pass) ? *real : *f->pass);
  }
  const orbit::Pass& pass = f->pass->up_at_start ? real_pass_->second : *f->pass;
  json p = pass_json(pass);
  // The plan in force is this pass's only when what it follows lies inside the pass (before the
  // next pass is planned, at its pre-positioning, it is still the last one's).
  const rotator::PassPlan* plan = station_.current_plan();
  if (plan && plan->coverage.from &&
      (*plan->coverage.from < orbit::add_minutes(pass.aos, -1.0) || orbit::add_minutes(pass.los, 1.0) < *plan->coverage.to))
    plan = nullptr;
  json track = json::array(), planned = json::array(), lost = json::array();
  for (const orbit::Observation& o : tr.pass_track(f->db_index, pass, 60)) {
    if (!o.ok()) continue;
    const double az = o.look.az_deg, el = std::max(o.look.el_deg, 0.0);
    track.push_back(az_el(az, el));
    if (!plan) continue;
    const rotator::AzEl a = plan->pointing_at(az, el);
    planned.push_back(az_el(a.az, std::max(a.el, 0.0)));
    lost.push_back(plan->lost_at(az, el));
  }
  p["track"] = std::move(track);
  p["planned"] = std::move(planned);
  p["lost"] = std::move(lost);
  if (plan) p["coverage"] = plan->coverage_text();
  if (plan) p["coverage_full"] = plan->coverage.full();
  if (plan && !plan->lead.empty()) p["keyhole"] = plan->keyhole_text();
  // Before the antenna pre-positions (kPrepositionMinutes before AOS): when and where it will move.
  const orbit::UtcTime moves = orbit::add_minutes(pass.aos, -tracker::Tracker::kPrepositionMinutes);
  if (tr.last_tick_time() < moves && d.antenna != tracker::Decision::Antenna::preposition) {
    const double az = plan ? station_.rotator().model().compass_from_travel(plan->aos.az_travel) : pass.aos_az_deg;
    j["moves"] = {{"at", orbit::format_iso8601(moves)}, {"az_deg", std::round(az * 10) / 10},
                  {"lead_min", tracker::Tracker::kPrepositionMinutes}};
  }
  j["pass"] = std::move(p);
  return j;
}

json Api::live_document() {
  json status = hooks_.status ? hooks_.status() : json::object();
  status["schema"] = kApiSchema;
  status["doppler"] = station_.doppler();
  const auto& st = station_.model().station;
  // The station as the status gives it (the callsign, the locator), its position always from the model.
  json& where = status["station"];
  if (!where.is_object()) where = json::object();
  where["callsign"] = st.callsign;
  where["locator"] = station::maidenhead_locator(st.lat_deg, st.lon_deg);
  where["lat_deg"] = st.lat_deg;
  where["lon_deg"] = st.lon_deg;
  where["height_m"] = st.height_m;
  shape_for_live(status);
  return json{{"type", "state"}, {"status", std::move(status)}, {"sky", sky()}};
}

std::string Api::live_state() {
  try {
    return live_document().dump(-1, ' ', false, json::error_handler_t::replace);
  } catch (const std::exception& e) {
    return json{{"type", "error"}, {"error", e.what()}}.dump(-1, ' ', false, json::error_handler_t::replace);
  }
}

}  // namespace tb::web
