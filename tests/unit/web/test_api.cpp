// The web API's handling, without a socket: the simulated station on the shipped data, requests as
// values. Who may do what (web/access.h), the endpoints of docs/web-api.md, bad input refused with
// a 4xx and a sentence while the station goes on.
#include <doctest/doctest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "support/sim_station.h"
#include "tracker/operations.h"
#include "web/api.h"
#include "web/page.h"

using namespace tb;
using json = nlohmann::json;

namespace {

struct Web : testing::StationFixture {
  explicit Web(web::AccessOptions o = {}, std::shared_ptr<netctl::GuessGuard> guesses = nullptr)
      : access(o, std::move(guesses)) {
    build_station();
    web::ApiHooks hooks;
    hooks.status = [] { return json{{"running", true}}; };
    hooks.save = [this] {
      ++saves;
      return std::optional<std::string>();
    };
    hooks.changed = [this] { ++changes; };
    api = std::make_unique<web::Api>(*station, access, hooks);
  }
  web::Response get(const std::string& target, const std::string& host = "127.0.0.1:8073") {
    web::Request r;
    r.method = "GET";
    r.target = target;
    r.host = host;
    r.peer = "127.0.0.1";
    return api->handle(r, t);
  }
  web::Response post(const std::string& target, const std::string& body, const std::string& origin = "",
                     const std::string& type = "application/json") {
    web::Request r;
    r.method = "POST";
    r.target = target;
    r.host = "127.0.0.1:8073";
    r.origin = origin;
    r.content_type = type;
    r.body = body;
    r.peer = peer;
    r.cookie = cookie;
    r.authorization = authorization;
    return api->handle(r, t);
  }
  static std::string error_of(const web::Response& r) { return json::parse(r.body).at("error").get<std::string>(); }
  web::Access access;
  std::unique_ptr<web::Api> api;
  std::chrono::steady_clock::time_point t{std::chrono::hours(1000)};
  std::string peer = "127.0.0.1", cookie, authorization;
  int saves = 0, changes = 0;
};

}  // namespace

TEST_CASE("web: the page's files are compiled in and the first load is under 150 kB") {
  const web::PageFile* index = web::find_page_file("/index.html");
  REQUIRE(index != nullptr);
  CHECK(index->type == "text/html; charset=utf-8");
  CHECK(index->body.find("<svg id=\"sky\"") != std::string_view::npos);
  REQUIRE(web::find_page_file("/app.js") != nullptr);
  CHECK(web::find_page_file("/app.js")->type == "text/javascript; charset=utf-8");
  CHECK(web::find_page_file("/nothing") == nullptr);
  CHECK(web::first_load_bytes() > 5000);
  CHECK(web::first_load_bytes() <= 150 * 1024);
  MESSAGE("first load: " << web::first_load_bytes() << " bytes");
}

TEST_CASE("web: GET / serves the page; status carries the schema; unknown paths are 404 JSON") {
  Web w;
  const web::Response page = w.get("/");
  CHECK(page.status == 200);
  CHECK(page.content_type == "text/html; charset=utf-8");
  const web::Response st = w.get("/api/v1/status");
  CHECK(st.status == 200);
  CHECK(json::parse(st.body) == json{{"running", true}, {"schema", web::kApiSchema}});
  const web::Response none = w.get("/api/v1/nothing");
  CHECK(none.status == 404);
  CHECK(Web::error_of(none) == "no such endpoint: /api/v1/nothing");
  // A Host that is not a loopback name (DNS rebinding) sees nothing.
  CHECK(w.get("/api/v1/status", "evil.example:8073").status == 403);
}

TEST_CASE("web: security headers on every reply") {
  const auto h = web::security_headers();
  const auto has = [&h](const std::string& k, const std::string& part) {
    for (const auto& [name, value] : h)
      if (name == k && value.find(part) != std::string::npos) return true;
    return false;
  };
  CHECK(has("Content-Security-Policy", "default-src 'self'"));
  CHECK(has("Content-Security-Policy", "frame-ancestors 'none'"));
  CHECK(has("X-Content-Type-Options", "nosniff"));
}

TEST_CASE("web: POST track, rotor and radio act through StationOps; bad input is a 4xx and changes nothing") {
  Web w;
  web::Response r = w.post("/api/v1/track", R"({"satellite":"ISS"})");
  CHECK(r.status == 200);
  CHECK(w.tracker.mode() == tracker::Mode::single);
  CHECK(w.changes == 1);
  r = w.post("/api/v1/rotor", R"({"control":true})");
  CHECK(r.status == 200);
  CHECK(w.model.rotor_control);
  CHECK(w.saves >= 1);

  CHECK(Web::error_of(w.post("/api/v1/track", R"({"satellite":"ISSS"})")) == "unknown satellite 'ISSS'; did you mean ISS?");
  CHECK(w.post("/api/v1/track", R"({"satellite":"ISSS"})").status == 409);
  CHECK(w.post("/api/v1/track", R"({"satellite":42})").status == 400);
  CHECK(w.post("/api/v1/rotor", R"({"control":"yes"})").status == 400);
  CHECK(w.post("/api/v1/rotor", R"({"goto":{"az":"north","el":10}})").status == 400);
  CHECK(Web::error_of(w.post("/api/v1/rotor", R"({"goto":{"az":400,"el":10}})")) ==
        "azimuth 400 out of range: expected 0 to 360");
  CHECK(w.post("/api/v1/radio", R"({"doppler":1})").status == 400);
  CHECK(w.post("/api/v1/track", "not json").status == 400);
  CHECK(w.post("/api/v1/track", "[1,2]").status == 400);
  CHECK(w.post("/api/v1/track", std::string(1 << 20, '[')).status == 413);
  CHECK(w.post("/api/v1/track", std::string(200, '[') + std::string(200, ']')).status == 400);
  CHECK(w.post("/api/v1/track", R"({"satellite":"ISS"})", "", "text/plain").status == 415);
  // A page of another site may not change anything, even on loopback.
  CHECK(w.post("/api/v1/rotor", R"({"control":false})", "http://evil.example").status == 403);
  CHECK(w.model.rotor_control);
  // The station still tracks ISS.
  w.run(2.0);
  REQUIRE(w.tracker.followed() != nullptr);
  CHECK(w.tracker.followed()->name == "ISS");

  CHECK(w.post("/api/v1/radio", R"({"doppler":false})").status == 200);
  CHECK_FALSE(w.station->doppler());
  CHECK(w.post("/api/v1/rotor", R"({"action":"stop"})").status == 200);
  // Stop stops the rotator only (issue 44): the page holds the antenna, the choice stays.
  CHECK(w.tracker.mode() == tracker::Mode::single);
  CHECK(w.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::web);
}

TEST_CASE("web: passes of a satellite, checked against the pass search; bad hours and names refused") {
  Web w;
  w.run(0.2);
  const web::Response r = w.get("/api/v1/passes?sat=ISS&hours=12");
  REQUIRE(r.status == 200);
  const json j = json::parse(r.body);
  CHECK(j["satellite"] == "ISS");
  const auto i = w.model.db.find("ISS");
  orbit::PassOptions rising;   // only passes that rise: a maximum of -0.4 deg is none to plan for
  rising.min_max_elevation_deg = 1e-9;
  const auto found = orbit::find_passes(*w.tracker.propagator(*i), w.model.station.observer(), w.station->now(),
                                        orbit::add_minutes(w.station->now(), 720.0), rising);
  REQUIRE(j["passes"].size() == found.size());
  REQUIRE_FALSE(found.empty());
  CHECK(j["passes"][0]["aos"] == orbit::format_iso8601(found[0].aos));
  CHECK(w.get("/api/v1/passes?sat=ISS&hours=abc").status == 400);
  CHECK(w.get("/api/v1/passes?sat=ISS&hours=1000").status == 400);
  CHECK(Web::error_of(w.get("/api/v1/passes?sat=NOPE")) == "unknown satellite 'NOPE'");
  CHECK(w.get("/api/v1/passes?sat=%zz").status == 400);
  CHECK(w.get("/api/v1/satellites").status == 200);
}

TEST_CASE("web: a pass in progress is planned whole, from its real AOS with its whole maximum (issue 47)") {
  Web w;
  w.run(0.2);
  const auto i = w.model.db.find("ISS");
  REQUIRE(i);
  const orbit::UtcTime t0 = w.station->now();
  orbit::PassOptions rising;
  rising.min_max_elevation_deg = 1e-9;
  const auto found = orbit::find_passes(*w.tracker.propagator(*i), w.model.station.observer(), t0,
                                        orbit::add_minutes(t0, 720.0), rising);
  REQUIRE_FALSE(found.empty());
  const orbit::Pass first = found.front();
  REQUIRE_FALSE(first.up_at_start);
  // A minute after its culmination: planned from its AOS, its maximum the whole pass's.
  w.now = orbit::add_minutes(first.tca, 1.0);
  w.run(0.2);
  const json j = json::parse(w.get("/api/v1/passes?sat=ISS&hours=2").body);
  REQUIRE_FALSE(j["passes"].empty());
  const json& p = j["passes"][0];
  CHECK(p["in_progress"] == true);
  CHECK(p["aos"] == orbit::format_iso8601(first.aos));
  CHECK(p["los"] == orbit::format_iso8601(first.los));
  CHECK(p["max_el_deg"].get<double>() == doctest::Approx(first.max_el_deg).epsilon(1e-6));
  // Above its remaining maximum but below the whole pass's: still planned.
  char q[80];
  std::snprintf(q, sizeof q, "/api/v1/passes?sat=ISS&hours=2&min_el=%.1f", first.max_el_deg - 0.05);
  const json high = json::parse(w.get(q).body);
  REQUIRE_FALSE(high["passes"].empty());
  CHECK(high["passes"][0]["aos"] == orbit::format_iso8601(first.aos));
}

TEST_CASE("web: with a secret, changes need the bearer or a session with the page's Origin") {
  web::AccessOptions o;
  o.secret = "correct horse battery staple";
  o.loopback_only = false;
  Web w(o);
  w.peer = "192.0.2.7";
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 401);
  CHECK(w.get("/api/v1/status").status == 401);  // no public view
  w.authorization = "Bearer wrong";
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 401);
  // The guessing throttle: the next attempt at once is refused.
  w.authorization = "Bearer correct horse battery staple";
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 429);
  w.t += std::chrono::seconds(2);
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 200);
  CHECK(w.model.rotor_control);
  w.authorization.clear();

  // The login page's form: a session cookie, HttpOnly and SameSite=Strict; the secret never echoed.
  const web::Response bad = w.post("/login", "secret=nope", "http://127.0.0.1:8073", "application/x-www-form-urlencoded");
  CHECK(bad.status == 303);
  w.t += std::chrono::seconds(5);
  const web::Response in = w.post("/login", "secret=correct+horse+battery+staple", "http://127.0.0.1:8073",
                                  "application/x-www-form-urlencoded");
  CHECK(in.status == 303);
  std::string set_cookie;
  for (const auto& [k, v] : in.headers)
    if (k == "Set-Cookie") set_cookie = v;
  CHECK(set_cookie.find("HttpOnly") != std::string::npos);
  CHECK(set_cookie.find("SameSite=Strict") != std::string::npos);
  CHECK(set_cookie.find("correct") == std::string::npos);
  CHECK(set_cookie.find("Secure") == std::string::npos);  // plain HTTP: a Secure cookie would be dropped
  w.cookie = set_cookie.substr(0, set_cookie.find(';'));
  // The session from another site (no Origin, or another one) changes nothing.
  CHECK(w.post("/api/v1/rotor", R"({"control":false})").status == 403);
  CHECK(w.post("/api/v1/rotor", R"({"control":false})", "http://evil.example").status == 403);
  CHECK(w.model.rotor_control);
  CHECK(w.post("/api/v1/rotor", R"({"control":false})", "http://127.0.0.1:8073").status == 200);
  CHECK_FALSE(w.model.rotor_control);
}

TEST_CASE("web: wrong secrets share the process's one budget with the other ports, an IPv6 /64 as one") {
  // Issue 38: one GuessGuard for every endpoint. Wrong secrets given to rotctld from 2001:db8:1::1
  // make a bearer from 2001:db8:1::2 (the same /64) wait on the web endpoint, and the web's own
  // wrong secret is counted in the same budget, under its name.
  auto guard = std::make_shared<netctl::GuessGuard>();
  web::AccessOptions o;
  o.secret = "correct horse battery staple";
  o.loopback_only = false;
  Web w(o, guard);
  const auto now = w.t;
  CHECK_FALSE(guard->wrong("2001:db8:1::1", now, "rotctld"));
  w.peer = "2001:db8:1::2";
  w.authorization = "Bearer correct horse battery staple";
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 429);
  CHECK_FALSE(w.model.rotor_control);
  w.t += std::chrono::seconds(1);  // the 0.5 s the first wrong secret earned has passed
  w.authorization = "Bearer wrong";
  CHECK(w.post("/api/v1/rotor", R"({"control":true})").status == 401);
  CHECK(guard->failures("2001:db8:1::99") == 2);
  CHECK(guard->failures("2001:db8:2::1") == 0);
}

TEST_CASE("web: the sky of a followed pass: the satellite now, the track from AOS to LOS, the plan") {
  Web w;
  const int iss = *w.model.db.find("ISS");
  const auto pass = orbit::next_pass(*w.tracker.propagator(iss), w.model.station.observer(), w.now, 2.0);
  REQUIRE(pass.has_value());
  w.now = pass->tca;  // the middle of the next ISS pass
  REQUIRE(w.post("/api/v1/rotor", R"({"control":true})").status == 200);
  REQUIRE(w.post("/api/v1/track", R"({"satellite":"ISS"})").status == 200);
  w.run(0.3);
  const json sky = w.api->sky();
  REQUIRE(sky["satellite"].is_object());
  const tracker::SatNow* f = w.tracker.followed();
  REQUIRE(f != nullptr);
  CHECK(sky["satellite"]["az_el"][0].get<double>() == doctest::Approx(f->obs.look.az_deg).epsilon(0.001));
  CHECK(sky["satellite"]["az_el"][1].get<double>() == doctest::Approx(f->obs.look.el_deg).epsilon(0.001));
  REQUIRE(sky["pass"].is_object());
  // Tracking began mid-pass: the pass is drawn from its real AOS, not from when tracking began.
  REQUIRE(f->pass->up_at_start);
  const auto aos = orbit::parse_iso8601(sky["pass"]["aos"].get<std::string>());
  REQUIRE(aos.has_value());
  CHECK(std::abs(std::chrono::duration<double>(*aos - pass->aos).count()) < 1.0);
  CHECK(sky["pass"]["track"].size() == 61);
  CHECK(sky["pass"]["planned"].size() == sky["pass"]["track"].size());
  CHECK(sky["pass"]["lost"].size() == sky["pass"]["track"].size());
  CHECK(sky["antenna"].is_array());
  // Slewing from where it was to the pass: the word says so.
  CHECK(sky["antenna_state"] == "moving");
}

TEST_CASE("the session cookie is Secure behind a TLS proxy on loopback, and only there") {
  web::AccessOptions o;
  o.secret = "correct horse battery staple";
  o.loopback_only = false;
  Web w(o);
  auto login = [&](const std::string& peer, const std::string& proto) {
    w.t += std::chrono::seconds(5);  // past the guessing throttle
    web::Request r;
    r.method = "POST";
    r.target = "/login";
    r.host = "127.0.0.1:8073";
    r.origin = "https://127.0.0.1:8073";
    r.content_type = "application/x-www-form-urlencoded";
    r.body = "secret=correct+horse+battery+staple";
    r.peer = peer;
    r.forwarded_proto = proto;
    const web::Response res = w.api->handle(r, w.t);
    for (const auto& [k, v] : res.headers)
      if (k == "Set-Cookie") return v;
    return std::string();
  };
  const std::string proxied = login("127.0.0.1", "https");
  CHECK(proxied.find("; HttpOnly; SameSite=Strict; Secure") != std::string::npos);
  CHECK(login("::1", "https").find("; Secure") != std::string::npos);
  CHECK(login("127.0.0.1", "http").find("Secure") == std::string::npos);
  CHECK(login("127.0.0.1", "").find("Secure") == std::string::npos);
  // From elsewhere the header is the client's own word: not believed.
  const std::string direct = login("192.0.2.7", "https");
  CHECK(direct.find("HttpOnly") != std::string::npos);
  CHECK(direct.find("Secure") == std::string::npos);
}

TEST_CASE("web: an outside client holds the antenna: 409 naming it, then confirm; standby and reserve (issue 44)") {
  Web w;
  REQUIRE(w.post("/api/v1/track", R"({"satellite":"ISS"})").status == 200);
  const tracker::Requester gpredict{tracker::HolderKind::rotctld, "rotctld 127.0.0.1:51234"};
  REQUIRE(tracker::StationOps(*w.station, gpredict).go_to(200.0, 30.0).ok());
  web::Response r = w.post("/api/v1/rotor", R"({"goto":{"az":90,"el":10}})");
  CHECK(r.status == 409);
  const json j = json::parse(r.body);
  CHECK(j["confirm_needed"] == true);
  CHECK(j["holder"]["kind"] == "rotctld");
  CHECK(j["holder"]["label"] == "rotctld 127.0.0.1:51234");
  CHECK(j["error"] == "rotctld 127.0.0.1:51234 holds the antenna: confirm to take it back");
  CHECK(w.station->control().holder(tracker::Resource::antenna).kind == tracker::HolderKind::rotctld);
  r = w.post("/api/v1/control", R"({"take_back":true,"confirm":true})");
  CHECK(r.status == 200);
  CHECK(w.station->control().tracking_drives(tracker::Resource::antenna));
  CHECK(w.tracker.mode() == tracker::Mode::single);  // the suspended tracking resumes what was chosen

  CHECK(w.post("/api/v1/standby", R"({"on":"yes"})").status == 400);
  CHECK(w.post("/api/v1/standby", R"({"on":true})").status == 200);
  CHECK(w.model.sharing.standby);
  CHECK(w.post("/api/v1/rotor", R"({"goto":{"az":90,"el":10}})").status == 409);
  CHECK(w.post("/api/v1/standby", R"({"on":false})").status == 200);
  CHECK_FALSE(w.station->control().standby());

  r = w.post("/api/v1/reserve", R"({"start":"2030-01-01T10:00:00Z","end":"2030-01-01T09:00:00Z"})");
  CHECK(r.status == 409);
  CHECK(json::parse(r.body)["error"] == "a reservation ends after it starts");
  CHECK(w.post("/api/v1/reserve", R"({"start":"soon","end":"later"})").status == 409);
  CHECK(w.model.sharing.reservations.empty());
  CHECK(w.post("/api/v1/reserve", R"({"start":"2030-01-01T10:00:00Z","end":"2030-01-01T11:00:00Z","note":"EME"})").status ==
        200);
  REQUIRE(w.model.sharing.reservations.size() == 1);
  CHECK(w.model.sharing.reservations[0].note == "EME");
  CHECK(w.model.sharing.reservations[0].start_unix == 1893492000);
}

TEST_CASE("web: each endpoint its methods: 405 with that endpoint's Allow, 404 for no endpoint (issue 56, item 14)") {
  Web w;
  const auto ask = [&w](const std::string& method, const std::string& target) {
    web::Request r;
    r.method = method;
    r.target = target;
    r.host = "127.0.0.1:8073";
    r.peer = "127.0.0.1";
    r.content_type = "application/json";
    r.body = "{}";
    return w.api->handle(r, w.t);
  };
  const auto allow_of = [](const web::Response& r) {
    for (const auto& [k, v] : r.headers)
      if (k == "Allow") return v;
    return std::string("(none)");
  };
  struct Case {
    const char* method;
    const char* target;
    const char* allow;
  };
  for (const Case& c : {Case{"POST", "/api/v1/log.adi", "GET, HEAD"}, Case{"DELETE", "/api/v1/status", "GET, HEAD"},
                        Case{"PUT", "/api/v1/log", "GET, HEAD, POST"}, Case{"GET", "/api/v1/track", "POST"},
                        Case{"GET", "/api/v1/log/edit", "POST"}, Case{"POST", "/api/v1/sky", "GET, HEAD"},
                        Case{"POST", "/app.js", "GET, HEAD"}, Case{"GET", "/logout", "POST"},
                        Case{"OPTIONS", "/api/v1/passes?sat=ISS", "GET, HEAD"}, Case{"POST", "/api/v1/live", "GET"}}) {
    CAPTURE(c.method);
    CAPTURE(c.target);
    const web::Response r = ask(c.method, c.target);
    CHECK(r.status == 405);
    CHECK(allow_of(r) == c.allow);
    CHECK(Web::error_of(r).find(std::string("not allowed on ") + web::target_path(c.target)) != std::string::npos);
  }
  CHECK(ask("DELETE", "/api/v1/nothing").status == 404);
  CHECK(ask("POST", "/nothing.html").status == 404);
  CHECK(ask("GET", "/api/v1/live").status == 426);  // the WebSocket, asked without the upgrade
  CHECK(web::allowed_methods("/api/v1/log") == std::optional<std::string>("GET, HEAD, POST"));
  CHECK(!web::allowed_methods("/api/v1/logs"));
}

TEST_CASE("web: the Station card's horizon mask: read as the menus read it, a bad one a 400 changing nothing (issue 57)") {
  Web w;
  web::Response r = w.post("/api/v1/station", R"({"horizon_mask":"0 0\n190 25\n230 0"})");  // pairs one a line
  CHECK(r.status == 200);
  CHECK(w.model.station.horizon_mask == "0 0; 190 25; 230 0");
  CHECK(json::parse(r.body)["note"] == "horizon mask interpolated, 3 points, 0.0..25.0 deg");
  // Malformed: the reader's sentence, nothing changed (the place neither, asked with it).
  r = w.post("/api/v1/station", R"({"horizon_mask":"0 0; 190 25; 400 0","locator":"JN58td"})");
  CHECK(r.status == 400);
  CHECK(Web::error_of(r) == "station: horizon mask pair 3: azimuth 400 is outside 0..360");
  CHECK(w.model.station.horizon_mask == "0 0; 190 25; 230 0");
  CHECK(w.model.station.lat_deg == doctest::Approx(27.391));
  CHECK(w.post("/api/v1/station", R"({"horizon_mask":5})").status == 400);
  // With the place: both kept; the step list as typed on one line.
  r = w.post("/api/v1/station", R"({"horizon_mask":"0 0 190 25 230 0 360","locator":"JN58td"})");
  CHECK(r.status == 200);
  CHECK(w.model.station.horizon_mask == "0 0 190 25 230 0 360");
  CHECK(w.model.station.lat_deg == doctest::Approx(48.1458).epsilon(1e-3));
  // Parking into the roof: stored as asked, said loudly in the answer (the position is the operator's).
  REQUIRE(w.station->owner()
              .edit(store::bit(store::Area::rotator), "test", store::Origin::menus,
                    [](store::Model& m) {
                      m.rotator.parking_enabled = true;
                      m.rotator.parking = {210.0, 0.0};
                    })
              .ok());
  r = w.post("/api/v1/station", R"({"horizon_mask":"0 0; 190 25; 230 0"})");
  CHECK(r.status == 200);
  CHECK(json::parse(r.body)["note"] ==
        "horizon mask interpolated, 3 points, 0.0..25.0 deg; WARNING: parking at azimuth 210.0, elevation 0.0 points "
        "into the horizon mask (12.5 there)");
  CHECK(w.model.rotator.parking.az == 210.0);
  r = w.post("/api/v1/rotor", R"({"action":"park"})");
  CHECK(json::parse(r.body)["note"].get<std::string>().find("WARNING: parking at azimuth 210.0") != std::string::npos);
  // none clears it.
  CHECK(w.post("/api/v1/station", R"({"horizon_mask":"none"})").status == 200);
  CHECK(w.model.station.horizon_mask.empty());
}
