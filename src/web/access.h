// Who may do what on the web endpoint (docs/security.md, "The web page and API"). Pure: the
// caller passes the request's facts and the time.
//
//  - Every request, with or without a secret, names this station in its Host (no DNS rebinding,
//    issue 46): an IP literal (a browser that typed the address: rebinding needs a name), localhost,
//    or a name given with --http-host, each with an optional port; nothing else (127.evil.example,
//    127.0.0.1.nip.io and localhost.evil are names of other sites).
//  - Loopback only, no secret (the default): every client on the machine may view and change, but
//    a browser request must come from the page itself: a state change needs an Origin that names
//    the Host it was sent to.
//  - Another address: --allow ranges and a secret are required (the configuration refuses
//    otherwise). A change needs a session (cookie from the login page, HttpOnly, SameSite=Strict)
//    with a matching Origin, or `Authorization: Bearer SECRET`. Viewing needs the same unless
//    --http-public-view.
//  - Wrong secrets are slowed and locked out per address (an IPv6 /64 as one) by netctl::GuessGuard:
//    the process's one budget, shared with the other ports (issue 38), when the caller passes it.
#pragma once
#include <chrono>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "netctl/guesses.h"

namespace tb::web {

struct AccessOptions {
  std::string secret;          // empty: none (loopback only)
  bool public_view = false;    // viewing without the secret
  bool loopback_only = true;   // the server listens on a loopback address
  std::chrono::hours session_life{12};
  std::size_t max_sessions = 64;
  std::vector<std::string> hosts;  // --http-host: the names the station answers to beyond localhost
};

// What a request may do.
struct Grant {
  bool view = false;
  bool change = false;
  std::optional<std::string> why_not_change;  // a sentence, when change is false
  int status_not_change = 403;
  int retry_after_s = 0;  // with 429: when the address may try again
};

class Access {
 public:
  using Clock = std::chrono::steady_clock;
  // `guesses`: the budget of wrong secrets shared by every endpoint of the process; one of its own
  // when none is given (the unit tests, the fuzz target).
  explicit Access(AccessOptions o, std::shared_ptr<netctl::GuessGuard> guesses = nullptr)
      : o_(std::move(o)), guesses_(guesses ? std::move(guesses) : std::make_shared<netctl::GuessGuard>()) {}

  // Host, Origin, Cookie and Authorization headers as sent; `state_changing`: a POST.
  Grant grant(const std::string& peer, const std::string& host, const std::string& origin, const std::string& cookie,
              const std::string& authorization, bool state_changing, Clock::time_point now);
  // The login: the secret given in the login form. A new session token when right; nullopt when
  // wrong (counted) or while the address must wait (retry_after says how long, in seconds).
  std::optional<std::string> login(const std::string& peer, const std::string& given, Clock::time_point now,
                                   int& retry_after_s);
  void logout(const std::string& cookie);
  bool needs_secret() const { return !o_.secret.empty(); }
  bool public_view() const { return o_.public_view; }
  // Whether Origin names the Host (scheme http or https, the same host and port).
  static bool origin_matches(const std::string& origin, const std::string& host);
  // The session token of a Cookie header ("" when none).
  static std::string session_of(const std::string& cookie);
  // Whether a Host header names this station: an IPv4 or [IPv6] literal, localhost, or one of
  // `names` (ASCII case ignored), each with an optional port 0-65535; an exact parse.
  static bool host_allowed(const std::string& host, const std::vector<std::string>& names);
  bool host_allowed(const std::string& host) const { return host_allowed(host, o_.hosts); }
  // The secret changed (SIGHUP re-read the file): the sessions of the old one end.
  void set_secret(std::string secret);
  std::size_t sessions() const { return sessions_.size(); }

 private:
  bool valid_session(const std::string& token, Clock::time_point now);
  AccessOptions o_;
  std::shared_ptr<netctl::GuessGuard> guesses_;
  std::map<std::string, Clock::time_point> sessions_;  // token -> expiry
};

inline constexpr const char* kSessionCookie = "trakbox_session";

}  // namespace tb::web
