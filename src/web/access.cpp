#include "web/access.h"

#include <arpa/inet.h>

#include <algorithm>
#include <array>
#include <random>

#include "util/safe_text.h"
#include "util/secret.h"
#include "util/text.h"

namespace tb::web {

namespace {

// 32 random bytes from the system's source, in hex.
std::string new_token() {
  std::random_device rd;  // /dev/urandom on Linux
  static constexpr char kHex[] = "0123456789abcdef";
  std::string t;
  for (int i = 0; i < 16; ++i) {
    const unsigned v = rd();
    t.push_back(kHex[v & 15]);
    t.push_back(kHex[(v >> 4) & 15]);
    t.push_back(kHex[(v >> 8) & 15]);
    t.push_back(kHex[(v >> 12) & 15]);
  }
  return t;
}

std::string lower_trimmed(std::string_view s) { return text::lower(text::trim(s, text::kWhitespace)); }

bool port_ok(std::string_view p) {
  if (p.empty() || p.size() > 5) return false;
  unsigned v = 0;
  for (const char c : p) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<unsigned>(c - '0');
  }
  return v <= 65535;
}

}  // namespace

bool Access::host_allowed(const std::string& host, const std::vector<std::string>& names) {
  const std::string_view h = text::trim(host, " \t");
  std::string_view name, port;
  bool has_port = false;
  if (!h.empty() && h.front() == '[') {
    const auto end = h.find(']');
    if (end == std::string_view::npos) return false;
    const std::string inside(h.substr(1, end - 1));
    in6_addr a6{};
    if (::inet_pton(AF_INET6, inside.c_str(), &a6) != 1) return false;
    const std::string_view rest = h.substr(end + 1);
    if (rest.empty()) return true;
    return rest.front() == ':' && port_ok(rest.substr(1));
  }
  const auto colon = h.find(':');
  name = h.substr(0, colon);
  if (colon != std::string_view::npos) {
    has_port = true;
    port = h.substr(colon + 1);
  }
  if (name.empty() || (has_port && !port_ok(port))) return false;
  const std::string n(name);
  in_addr a4{};
  if (::inet_pton(AF_INET, n.c_str(), &a4) == 1) return true;
  if (text::iequals(n, "localhost")) return true;
  return std::any_of(names.begin(), names.end(), [&](const std::string& want) { return text::iequals(n, want); });
}

bool Access::origin_matches(const std::string& origin, const std::string& host) {
  const std::string o = lower_trimmed(origin);
  const std::string h = lower_trimmed(host);
  if (h.empty()) return false;
  return o == "http://" + h || o == "https://" + h;
}

std::string Access::session_of(const std::string& cookie) {
  const std::string key = std::string(kSessionCookie) + "=";
  for (std::string_view part : text::split(cookie, ';')) {
    part = text::trim(part, text::kWhitespace);
    if (part.substr(0, key.size()) == key) return std::string(part.substr(key.size()));
  }
  return {};
}

bool Access::valid_session(const std::string& token, Clock::time_point now) {
  if (token.empty()) return false;
  for (auto it = sessions_.begin(); it != sessions_.end();) it = it->second <= now ? sessions_.erase(it) : std::next(it);
  // Compared in constant time against every live session: the token is a secret too.
  bool found = false;
  for (const auto& [t, expiry] : sessions_) found = secret::equal(token, t) || found;
  return found;
}

Grant Access::grant(const std::string& peer, const std::string& host, const std::string& origin,
                    const std::string& cookie, const std::string& authorization, bool state_changing,
                    Clock::time_point now) {
  Grant g;
  const bool origin_ok = origin.empty() || origin_matches(origin, host);
  if (!host_allowed(host)) {
    g.why_not_change = "Host '" + text::visible_bytes(host.substr(0, 60)) +
                       "' is not this station's name (an IP address, localhost, or a name given with --http-host)";
    return g;
  }
  if (!needs_secret()) {
    // Loopback only: the machine's own users; a browser only from the page itself.
    g.view = true;
    g.change = origin_ok;
    if (!origin_ok) g.why_not_change = "a request from another site (Origin " + std::string("does not match the page") + ")";
    return g;
  }
  bool bearer = false;
  const std::string auth(text::trim(authorization, text::kWhitespace));
  if (!auth.empty()) {
    if (auth.size() < 7 || text::lower(auth.substr(0, 7)) != "bearer ") {
      g.why_not_change = "Authorization: expected Bearer and the secret";
      g.status_not_change = 401;
      return g;
    }
    if (const auto free = std::max(guesses_->free_at(peer, now), guesses_->locked_until(peer, now)); free > now) {
      g.why_not_change = "too many wrong secrets from this address: wait and try again";
      g.status_not_change = 429;
      g.retry_after_s = static_cast<int>(std::chrono::ceil<std::chrono::seconds>(free - now).count());
      return g;
    }
    bearer = secret::equal(text::trim(std::string_view(auth).substr(7), text::kWhitespace), o_.secret);
    if (!bearer) {
      guesses_->wrong(peer, now, "web");
      g.why_not_change = "wrong secret";
      g.status_not_change = 401;
      return g;
    }
    guesses_->right(peer);
  }
  const bool session = !bearer && valid_session(session_of(cookie), now);
  g.view = bearer || session || o_.public_view;
  if (bearer) {
    g.change = true;
  } else if (session) {
    // A session rides on the browser's cookie: only the page itself may use it.
    g.change = !origin.empty() && origin_matches(origin, host);
    if (!g.change) g.why_not_change = "a change with a session must come from the page itself (Origin)";
  } else {
    g.why_not_change = "log in first (the login page, or Authorization: Bearer SECRET)";
    g.status_not_change = 401;
  }
  (void)state_changing;
  return g;
}

std::optional<std::string> Access::login(const std::string& peer, const std::string& given, Clock::time_point now,
                                         int& retry_after_s) {
  retry_after_s = 0;
  const auto free = std::max(guesses_->free_at(peer, now), guesses_->locked_until(peer, now));
  if (free > now) {
    retry_after_s = static_cast<int>(std::chrono::ceil<std::chrono::seconds>(free - now).count());
    return std::nullopt;
  }
  if (o_.secret.empty() || !secret::equal(given, o_.secret)) {
    guesses_->wrong(peer, now, "web");
    return std::nullopt;
  }
  guesses_->right(peer);
  if (sessions_.size() >= o_.max_sessions) {
    auto oldest = sessions_.begin();
    for (auto it = sessions_.begin(); it != sessions_.end(); ++it)
      if (it->second < oldest->second) oldest = it;
    sessions_.erase(oldest);
  }
  std::string token = new_token();
  sessions_[token] = now + o_.session_life;
  return token;
}

void Access::logout(const std::string& cookie) { sessions_.erase(session_of(cookie)); }

void Access::set_secret(std::string secret) {
  if (secret == o_.secret) return;
  o_.secret = std::move(secret);
  sessions_.clear();
}

}  // namespace tb::web
