// The remote-control servers of a running trakbox (run_tracker's step "servers", tracker_app.cpp):
// rotctld, rigctld, host mode and PstRotator's UDP (netctl), the web page and API, the Satrak unit
// started by tracker_app.cpp; what SIGHUP re-reads of their secrets; what `trakbox status` says of them.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/secret_reload.h"
#include "cli/tracker_config.h"
#include "live/attach_server.h"
#include "live/station_app.h"
#include "netctl/guesses.h"
#include "netctl/host_server.h"
#include "netctl/pst_server.h"
#include "netctl/server.h"
#include "satrak/server.h"
#include "satrak/unit.h"
#include "util/loop_fwd.h"
#include "web/access.h"
#include "web/api.h"
#include "web/server.h"

namespace tb::app {

// Remote control on the same event loop: the Satrak ACU protocol, rotctld/rigctld compatibles,
// host mode.
struct Servers {
  std::unique_ptr<satrak::Unit> satrak_unit;
  std::unique_ptr<satrak::Server> satrak;
  std::unique_ptr<netctl::RotctldServer> rotctld;
  std::unique_ptr<netctl::RigctldServer> rigctld;
  std::unique_ptr<netctl::HostServer> host;
  std::unique_ptr<netctl::PstServer> pst;   // --pst-port: PstRotator's UDP commands
  // The web page and API (--http-port): who may do what, the requests' handler, the server.
  std::unique_ptr<web::Access> web_access;
  std::unique_ptr<web::Api> web_api;
  std::unique_ptr<web::Server> web;
  std::string web_url;
  // The one budget of wrong secrets for every endpoint (netctl/guesses.h): a budget per port
  // multiplied it. Made by start_netctl, shared by the web endpoint.
  std::shared_ptr<netctl::GuessGuard> guesses;

  // Closed before the last save; the Satrak unit after it (its settings are saved with the model).
  void close_listeners() {
    web.reset();
    rotctld.reset();
    rigctld.reset();
    host.reset();
    pst.reset();
    satrak.reset();
  }
};

std::vector<SecretEndpoint> secret_endpoints(const TrackerConfig& c, Servers& s);
// rotctld, rigctld, host mode, PstRotator's UDP as the command line asks; the option and the error
// of the first that cannot start.
std::optional<std::string> start_netctl(StationApp& app, const TrackerConfig& c, Servers& out);
void warn_open_endpoints(const TrackerConfig& c, const Servers& s, spdlog::logger& log);
nlohmann::json servers_json(const Servers& s);
std::optional<std::string> start_web(StationApp& app, const TrackerConfig& c, Servers& out, AttachServer* attach);

}  // namespace tb::app
