#include "netctl/guesses.h"

#include <algorithm>

namespace tb::netctl {

GuessGuard::Entry& GuessGuard::entry(const std::string& address, Clock::time_point now) {
  auto it = table_.find(address);
  if (it != table_.end()) {
    Entry& e = it->second;
    if (e.failures > 0 && now - e.last_wrong >= p_.forget_after && now >= e.locked_until) e = Entry{};
    return e;
  }
  if (table_.size() >= p_.max_addresses) {
    // Forget the address whose last wrong secret is oldest (never one that is locked out now).
    auto oldest = table_.end();
    for (auto i = table_.begin(); i != table_.end(); ++i)
      if (i->second.locked_until <= now && (oldest == table_.end() || i->second.last_wrong < oldest->second.last_wrong))
        oldest = i;
    if (oldest != table_.end()) table_.erase(oldest);
  }
  return table_[address];
}

std::chrono::milliseconds GuessGuard::delay_after(int failures) const {
  if (failures <= 0) return std::chrono::milliseconds(0);
  std::chrono::milliseconds d = p_.first_delay;
  for (int i = 1; i < failures && d < p_.max_delay; ++i) d *= 2;
  return std::min(d, p_.max_delay);
}

GuessGuard::Clock::time_point GuessGuard::free_at(const std::string& address, Clock::time_point now) {
  if (table_.find(address) == table_.end()) return now;  // never wrong: answered at once
  return std::max(now, entry(address, now).next_answer);
}

bool GuessGuard::wrong(const std::string& address, Clock::time_point now) {
  Entry& e = entry(address, now);
  ++e.failures;
  e.last_wrong = now;
  e.next_answer = now + delay_after(e.failures);
  if (e.failures >= p_.lockout_after && e.locked_until <= now) {
    // Each wrong secret after the lockout locks the address out again, until forget_after has passed
    // without one.
    e.locked_until = now + p_.lockout_for;
    e.next_answer = e.locked_until;
    return true;
  }
  return false;
}

GuessGuard::Clock::time_point GuessGuard::locked_until(const std::string& address, Clock::time_point now) {
  auto it = table_.find(address);
  if (it == table_.end()) return Clock::time_point{};
  (void)now;
  return it->second.locked_until;
}

int GuessGuard::failures(const std::string& address) const {
  auto it = table_.find(address);
  return it == table_.end() ? 0 : it->second.failures;
}

}  // namespace tb::netctl
