// The remote-control servers (servers.h): started from the command line's TrackerConfig.
#include "app/servers.h"

#include <cstdio>

#include <spdlog/spdlog.h>

#include "live/build_info.h"
#include "live/status.h"
#include "tracker/elements_refresh.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"
#include "tracker/web_url.h"
#include "util/cidr.h"

namespace tb::app {

// What SIGHUP re-reads (secret_reload.h): each endpoint with a secret file.
std::vector<SecretEndpoint> secret_endpoints(const TrackerConfig& c, Servers& s) {
  std::vector<SecretEndpoint> e;
  const auto& f = c.secret_files;
  if (s.rotctld) e.push_back({"rotctld", f.rotctld, c.rotctld_secret, [&s](const std::string& v) { s.rotctld->set_secret(v); }});
  if (s.rigctld) e.push_back({"rigctld", f.rigctld, c.rigctld_secret, [&s](const std::string& v) { s.rigctld->set_secret(v); }});
  if (s.host) e.push_back({"host", f.host, c.host_secret, [&s](const std::string& v) { s.host->set_secret(v); }});
  if (s.web_access)
    e.push_back({"web", f.http, c.http_secret, [&s](const std::string& v) {
                   s.web_access->set_secret(v);
                   if (s.web) s.web->close_viewers();
                 }});
  return e;
}

std::optional<std::string> start_netctl(StationApp& app, const TrackerConfig& c, Servers& out) {
  // One guessing budget for every endpoint (netctl/guesses.h): a budget per port multiplied it.
  netctl::GuessPolicy policy;
  policy.exempt = c.guess_exempt;
  out.guesses = std::make_shared<netctl::GuessGuard>(policy);
  auto guard = out.guesses;
  auto opts = [&c, guard](netctl::ServerOptions so, const std::string& secret) {
    so.address = c.listen;
    so.allow = c.allow;
    so.secret = secret;
    so.guard = guard;
    so.auth_deadline = std::chrono::seconds(c.auth_timeout_s);
    return so;
  };
  auto port = [](int p) { return static_cast<std::uint16_t>(p); };
  const char* starting = "";
  try {
    starting = "--rotctld-port";
    if (c.rotctld_port)
      out.rotctld = std::make_unique<netctl::RotctldServer>(app.io(), port(*c.rotctld_port), app.station(),
                                                             opts(netctl::RotctldServer::named("rotctld"), c.rotctld_secret));
    starting = "--rigctld-port";
    if (c.rigctld_port)
      out.rigctld = std::make_unique<netctl::RigctldServer>(app.io(), port(*c.rigctld_port), app.station(),
                                                             opts(netctl::RotctldServer::named("rigctld"), c.rigctld_secret));
    starting = "--host-port";
    if (c.host_port)
      out.host = std::make_unique<netctl::HostServer>(app.io(), port(*c.host_port), app.station(),
                                                       opts(netctl::HostServer::defaults(), c.host_secret));
    starting = "--pst-port";
    if (c.pst_port)
      out.pst = std::make_unique<netctl::PstServer>(app.io(), port(*c.pst_port), app.station(),
                                                     netctl::PstOptions{c.listen, c.allow});
  } catch (const std::exception& e) {
    return std::string(starting) + ": " + e.what();
  }
  return std::nullopt;
}

// Beyond loopback with no allow-list, anyone who can reach a port can swing the antenna: say so
// on standard error and in the log.
void warn_open_endpoints(const TrackerConfig& c, const Servers& s, spdlog::logger& log) {
  const auto open_to_all = [&](const std::string& what, const std::string& address, bool on) {
    if (!on || !c.allow.empty() || inet::is_loopback(address)) return;
    const std::string msg = what + " listens on " + address +
                            " for every address: anyone who can reach it can move the antenna and tune the radio "
                            "(name the stations with --allow CIDR; docs/security.md)";
    log.warn("{}", msg);
    std::fprintf(stderr, "trakbox: WARNING: %s\n", msg.c_str());
  };
  open_to_all("the Satrak server", c.satrak_bind, s.satrak != nullptr);
  open_to_all("the rotctld server", c.listen, s.rotctld != nullptr);
  open_to_all("the rigctld server", c.listen, s.rigctld != nullptr);
  open_to_all("the host-mode server", c.listen, s.host != nullptr);
  open_to_all("the PstRotator UDP server", c.listen, s.pst != nullptr);
  open_to_all("the web server", c.listen, s.web != nullptr);
}

// The servers that run, with what they refused (issue 33's counters) for `trakbox status`.
nlohmann::json servers_json(const Servers& s) {
  nlohmann::json out = nlohmann::json::array();
  const auto line = [&out](const char* name, const netctl::LineServer& srv) {
    const netctl::ServerStats& st = srv.stats();
    out.push_back({{"name", name},
                   {"port", srv.port()},
                   {"clients", srv.client_count()},
                   {"refused_not_allowed", st.refused_not_allowed},
                   {"refused_busy", st.refused_busy},
                   {"refused_per_address", st.refused_per_address},
                   {"refused_locked_out", st.refused_locked_out},
                   {"wrong_secrets", st.wrong_secrets},
                   {"lockouts", st.lockouts}});
  };
  if (s.satrak) {
    const satrak::Server::Stats st = s.satrak->stats();
    out.push_back({{"name", "satrak"},
                   {"port", s.satrak->port()},
                   {"clients", s.satrak->clients()},
                   {"accepted", st.accepted},
                   {"refused", st.refused},
                   {"refused_per_address", st.refused_per_address},
                   {"evicted", st.evicted},
                   {"dropped_slow", st.dropped_slow}});
  }
  if (s.pst) {
    const netctl::PstStats& st = s.pst->stats();
    out.push_back({{"name", "pstrotator"}, {"port", s.pst->port()}, {"taken", st.taken}, {"refused_bad", st.refused_bad},
                   {"refused_not_allowed", st.refused_not_allowed}, {"refused_by_station", st.refused_by_station}});
  }
  if (s.rotctld) line("rotctld", s.rotctld->server());
  if (s.rigctld) line("rigctld", s.rigctld->server());
  if (s.host) line("host", s.host->server());
  if (s.web) {
    const web::Server::Stats st = s.web->stats();
    out.push_back({{"name", "web"},
                   {"port", s.web->port()},
                   {"url", s.web_url},
                   {"clients", st.connections},
                   {"viewers", st.viewers},
                   {"requests", st.requests},
                   {"refused", st.refused},
                   {"dropped_slow", st.dropped}});
  }
  return out;
}

// The web page and API on the station's loop (src/web), when --http-port asks; the URL is said at
// start and in `trakbox status`.
std::optional<std::string> start_web(StationApp& app, const TrackerConfig& c, Servers& out, AttachServer* attach) {
  if (!c.http_port) return std::nullopt;
  web::AccessOptions ao;
  ao.secret = c.http_secret;
  ao.public_view = c.http_public_view;
  ao.hosts = c.http_hosts;
  ao.loopback_only = inet::is_loopback(c.listen);
  out.web_access = std::make_unique<web::Access>(ao, out.guesses);
  web::ApiHooks hooks;
  hooks.status = [&app, &c, &out, attach] {
    StatusContext cx{kVersion, c.state_dir.string(), {}, {}, c.service, [&out] { return servers_json(out); }};
    if (attach) cx.attached = attach->attached(), cx.keyboard = attach->keyboard();
    return station_status(app, cx);
  };
  hooks.save = [&app] { return app.save(); };
  hooks.wall_now_unix = [] { return tracker::ElementsRefresh::wall_now(); };
  hooks.changed = [&out] {
    if (out.web) out.web->push_soon();
  };
  out.web_api = std::make_unique<web::Api>(app.station(), *out.web_access, std::move(hooks));
  web::ServerOptions so;
  so.address = c.listen;
  so.port = static_cast<std::uint16_t>(*c.http_port);
  so.allow = c.allow;
  try {
    out.web = std::make_unique<web::Server>(app.io(), *out.web_api, so);
  } catch (const std::exception& e) {
    return std::string("--http-port: ") + e.what();
  }
  const std::string host = c.listen.find(':') != std::string::npos ? "[" + c.listen + "]" : c.listen;
  out.web_url = "http://" + host + ":" + std::to_string(out.web->port()) + "/";
  tracker::web_page_url() = out.web_url;   // the status line and menu 6-0 show it behind the full-screen menus
  app.log().info("web: the station's page is at {}", out.web_url);
  std::fprintf(stderr, "trakbox: the station's page: %s\n", out.web_url.c_str());
  return std::nullopt;
}

}  // namespace tb::app
