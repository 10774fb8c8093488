// How fast one address may guess an endpoint's secret (issues 33, 38). Every wrong secret from an
// address makes its next answer wait longer, whichever connection and whichever endpoint it comes on:
// an attempt is answered only when the address is free again (free_at), and each answer, taken on
// the spot, sets when that is, so the answers to one address's guesses come one after another, each
// `delay` after the one before, and opening more connections buys an attacker nothing. After
// `lockout_after` wrong secrets the address is locked out for `lockout_for`: its connections are
// refused at accept. A right secret forgets the address; so does `forget_after` without a wrong one.
// Pure: the caller passes the time.
//
// "An address" is an IPv4 address, and an IPv6 /64 (key_of): one host holds a whole /64, so a
// budget per /128 was 2^64 budgets. The process has ONE GuessGuard, shared by every endpoint
// (rotctld, rigctld, host mode): a budget per port multiplied it by the ports (issue 38).
//
// A shared address (NAT, a /64 of many hosts) shares the budget and the lockout: a lockout refuses
// everyone behind it for lockout_for, renewed by each wrong secret after it until forget_after passes
// without one. A station the operator trusts may be exempted from the lockout (policy.exempt,
// --guess-exempt RANGE): its wrong secrets are still slowed, never locked out. The log says whose
// wrong secrets locked the address out (lockout_cause) when it refuses a client.
//
// With the defaults the first ten guesses take 0.5+1+2+4+8+16+30+30+30 s (about 2 minutes), then
// the address is locked out for 10 minutes: at most 10 guesses in 12 minutes, about 0.014 a second.
// The table holds max_addresses; when it is full the entry wrong longest ago that is not locked out
// is forgotten (found at once: entries are kept in order); when every one is locked out, new
// addresses share one entry, "(everyone else)", rather than the table growing or being scanned.
#pragma once
#include <chrono>
#include <cstddef>
#include <list>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "util/cidr.h"

namespace tb::netctl {

struct GuessPolicy {
  std::chrono::milliseconds first_delay{500};      // after the first wrong secret
  std::chrono::milliseconds max_delay{30000};      // the delay doubles up to this
  int lockout_after = 10;                          // wrong secrets in a row from one address
  std::chrono::milliseconds lockout_for{600000};
  std::chrono::milliseconds forget_after{900000};  // no wrong secret for this long: a clean slate
  std::size_t max_addresses = 4096;                // remembered at once (see above)
  std::vector<inet::Cidr> exempt;                  // never locked out (still slowed)
};

// The key an address is counted under: an IPv4 address as it is (also when seen as ::ffff:a.b.c.d),
// an IPv6 address as its /64 ("2001:db8:1::/64"); text that is no address, as it is.
std::string key_of(const std::string& address);

class GuessGuard {
 public:
  using Clock = std::chrono::steady_clock;
  explicit GuessGuard(GuessPolicy p = {}) : p_(std::move(p)) {}
  GuessGuard(const GuessGuard&) = delete;  // entries point into the order lists
  GuessGuard& operator=(const GuessGuard&) = delete;

  // When an attempt from `address` may be answered: `now`, or later while its earlier wrong secrets
  // are being paid for. A caller that must wait asks again when the time comes (another connection
  // of the address may have been answered meanwhile).
  Clock::time_point free_at(const std::string& address, Clock::time_point now);
  // An attempt answered at `now` (only when free_at(address, now) <= now) was wrong: the address is
  // busy for the delay its failures have earned. True when this locked the address out. `endpoint`
  // ("rotctld") is kept for the log's lockout_cause.
  bool wrong(const std::string& address, Clock::time_point now, const std::string& endpoint = "");
  // The right secret: the address is forgotten.
  void right(const std::string& address);
  // Until when `address` is locked out (a time <= now when it is not).
  Clock::time_point locked_until(const std::string& address, Clock::time_point now);
  // For the log: "2001:db8:1::/64 (wrong secrets from 2001:db8:1::1 on rotctld)".
  std::string lockout_cause(const std::string& address);
  int failures(const std::string& address) const;
  std::size_t size() const { return table_.size(); }
  const GuessPolicy& policy() const { return p_; }

 private:
  struct Entry {
    int failures = 0;
    Clock::time_point next_answer{};   // the earliest time the next attempt is answered
    Clock::time_point last_wrong{};
    Clock::time_point locked_until{};
    std::string last_address, last_endpoint;
    bool locked = false;               // in locked_ (else in unlocked_)
    std::list<std::string>::iterator in_unlocked;
    std::multimap<Clock::time_point, std::string>::iterator in_locked;
  };
  std::string key(const std::string& address) const;
  Entry& entry(const std::string& key, Clock::time_point now);
  void erase(const std::string& key);
  bool make_room(Clock::time_point now);
  std::chrono::milliseconds delay_after(int failures) const;

  GuessPolicy p_;
  std::unordered_map<std::string, Entry> table_;
  std::list<std::string> unlocked_;                          // oldest wrong secret first
  std::multimap<Clock::time_point, std::string> locked_;     // by locked_until
  Clock::time_point last_now_{};                             // the latest time a caller passed
};

}  // namespace tb::netctl
