// The web front end's request handling, free of any transport (Boost.Beast stays in server.cpp):
// a request goes in as values, a response comes out. It serves the page's files (compiled in,
// page.h), the login, and the JSON API /api/v1/... (docs/web-api.md), deciding who may do what
// (access.h) before anything is read or changed. Every station change goes through
// tracker::StationOps, as the menus', host mode's and rotctld's do.
//
// Promises (checked by the fuzz target tests/fuzz/fuzz_web.cpp): no exception leaves handle(); an
// error is a JSON object {"error": "a sentence"} with a 4xx status; every reply carries the
// security headers (CSP default-src 'self', nosniff, frame-ancestors 'none'); the secret never
// appears in a reply.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "orbit/passes.h"
#include "web/access.h"

namespace tb::tracker {
class StationLoop;
}

namespace tb::web {

inline constexpr int kApiSchema = 1;              // the "schema" field of /api/v1/status
inline constexpr std::size_t kMaxBody = 16 * 1024; // bytes a request body may have

struct Request {
  std::string method;         // "GET", "POST", ...
  std::string target;         // "/api/v1/passes?sat=ISS&hours=12"
  std::string host;           // the Host header
  std::string origin;         // the Origin header ("" when none)
  std::string cookie;         // the Cookie header
  std::string authorization;  // the Authorization header
  std::string content_type;
  std::string body;
  std::string peer;           // the client's address ("127.0.0.1", "::1", ...)
  std::string forwarded_proto;  // X-Forwarded-Proto: believed only from a loopback peer (a proxy)
};

struct Response {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // beyond the security headers
  std::string why;  // an error's sentence (the body's "error"), for the log's line of refusals
  // A reply too big to hold whole (the ADIF export of the log): the body is made in pieces as the
  // client takes them, each bounded, each dropped once written (server.cpp sends it chunked). Each
  // call gives the next piece, "" at the end; it runs on the loop. `trailers` is asked at the end.
  std::function<std::string()> stream;
  std::function<std::vector<std::pair<std::string, std::string>>()> trailers;
};

// The methods a path takes ("GET, HEAD", "POST", ...: the Allow header of a 405); nullopt for a
// path that is no endpoint and no page file (404).
std::optional<std::string> allowed_methods(const std::string& path);

// The headers every response carries.
std::vector<std::pair<std::string, std::string>> security_headers();

// What the API needs of the running station besides the StationLoop: the document of
// `trakbox status --json` (live/status.h, built by the caller), saving the state, the wall clock of
// the element refresh, and a word to the live viewers that something changed.
struct ApiHooks {
  std::function<nlohmann::json()> status;
  std::function<std::optional<std::string>()> save;
  std::function<std::int64_t()> wall_now_unix;
  std::function<void()> changed;
};

class Api {
 public:
  Api(tracker::StationLoop& station, Access& access, ApiHooks hooks);

  // Never throws.
  Response handle(const Request& r, std::chrono::steady_clock::time_point now);
  // Whether a WebSocket upgrade to /api/v1/live may go ahead (the viewing rules and the Origin);
  // the refusal response when not.
  std::optional<Response> refuse_live(const Request& r, std::chrono::steady_clock::time_point now);

  // The live state the WebSocket sends at each tick: {"type":"state","status":{...},"sky":{...}}.
  std::string live_state();
  // The same document as JSON, for the live feed's patches (web/live_feed.h); it may throw.
  nlohmann::json live_document();
  // The sky plot's facts for the followed satellite: now, its pass (AOS/TCA/LOS and the track),
  // the antenna's reading and target, the planned path and the part it cannot follow.
  nlohmann::json sky();

 private:
  Response route(const Request& r, const Grant& g);
  Response post(const std::string& path, const nlohmann::json& body, const std::string& peer);
  Response satellites();
  Response passes(const std::string& query);       // api_passes.cpp: the planner's passes
  Response passes_ics(const std::string& query);   // the same as an iCalendar
  Response login(const Request& r, std::chrono::steady_clock::time_point now);

  tracker::StationLoop& station_;
  Access& access_;
  ApiHooks hooks_;
  std::optional<std::pair<int, orbit::Pass>> real_pass_;  // sky(): the followed pass from its AOS
};

// Pieces of a target, exposed for the tests: the path and a query parameter ("" when absent),
// percent-decoded; nullopt for a malformed escape.
std::string target_path(const std::string& target);
std::optional<std::string> query_param(const std::string& target, const std::string& name);

}  // namespace tb::web
