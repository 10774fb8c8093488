// How fast one address may guess an endpoint's secret (issue 33). Every wrong secret from an
// address makes its next answer wait longer, whichever connection it comes on: an attempt is answered
// only when the address is free again (free_at), and each answer, taken on the spot, sets when that
// is, so the answers to one address's guesses come one after another, each `delay` after the one
// before, and opening more connections buys an attacker nothing. After `lockout_after` wrong secrets the address is locked
// out for `lockout_for`: its connections are refused at accept. A right secret forgets the address;
// so does `forget_after` without a wrong one. Pure: the caller passes the time.
//
// With the defaults the first ten guesses take 0.5+1+2+4+8+16+30+30+30 s (about 2 minutes), then
// the address is locked out for 10 minutes: at most 10 guesses in 12 minutes, about 0.014 a second.
#pragma once
#include <chrono>
#include <cstddef>
#include <string>
#include <unordered_map>

namespace tb::netctl {

struct GuessPolicy {
  std::chrono::milliseconds first_delay{500};      // after the first wrong secret
  std::chrono::milliseconds max_delay{30000};      // the delay doubles up to this
  int lockout_after = 10;                          // wrong secrets in a row from one address
  std::chrono::milliseconds lockout_for{600000};
  std::chrono::milliseconds forget_after{900000};  // no wrong secret for this long: a clean slate
  std::size_t max_addresses = 4096;                // remembered at once (the oldest forgotten first)
};

class GuessGuard {
 public:
  using Clock = std::chrono::steady_clock;
  explicit GuessGuard(GuessPolicy p = {}) : p_(p) {}

  // When an attempt from `address` may be answered: `now`, or later while its earlier wrong secrets
  // are being paid for. A caller that must wait asks again when the time comes (another connection
  // of the address may have been answered meanwhile).
  Clock::time_point free_at(const std::string& address, Clock::time_point now);
  // An attempt answered at `now` (only when free_at(address, now) <= now) was wrong: the address is
  // busy for the delay its failures have earned. True when this locked the address out.
  bool wrong(const std::string& address, Clock::time_point now);
  // The right secret: the address is forgotten.
  void right(const std::string& address) { table_.erase(address); }
  // Until when `address` is locked out (a time <= now when it is not).
  Clock::time_point locked_until(const std::string& address, Clock::time_point now);
  int failures(const std::string& address) const;
  const GuessPolicy& policy() const { return p_; }

 private:
  struct Entry {
    int failures = 0;
    Clock::time_point next_answer{};   // the earliest time the next attempt is answered
    Clock::time_point last_wrong{};
    Clock::time_point locked_until{};
  };
  Entry& entry(const std::string& address, Clock::time_point now);
  std::chrono::milliseconds delay_after(int failures) const;

  GuessPolicy p_;
  std::unordered_map<std::string, Entry> table_;
};

}  // namespace tb::netctl
