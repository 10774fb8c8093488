#include "netctl/guesses.h"

#include <arpa/inet.h>

#include <algorithm>
#include <array>

namespace tb::netctl {

namespace {
constexpr const char* kOverflow = "(everyone else)";
}

std::string key_of(const std::string& address) {
  const auto a = inet::detail::parse_address(address);
  if (!a) return address;
  char buf[64] = {};
  if (!a->first) {
    ::inet_ntop(AF_INET, a->second.data(), buf, sizeof buf);
    return buf;
  }
  std::array<std::uint8_t, 16> net{};
  std::copy(a->second.begin(), a->second.begin() + 8, net.begin());
  ::inet_ntop(AF_INET6, net.data(), buf, sizeof buf);
  return std::string(buf) + "/64";
}

// key_of(address), or the shared entry when the address is new, the table full and every entry in it
// locked out (make_room could free none).
std::string GuessGuard::key(const std::string& address) const {
  std::string k = key_of(address);
  if (table_.size() < p_.max_addresses || table_.find(k) != table_.end()) return k;
  const bool room = !unlocked_.empty() || (!locked_.empty() && locked_.begin()->first <= last_now_);
  return room ? k : std::string(kOverflow);
}

void GuessGuard::erase(const std::string& k) {
  const auto it = table_.find(k);
  if (it == table_.end()) return;
  if (it->second.locked) locked_.erase(it->second.in_locked);
  else if (k != kOverflow) unlocked_.erase(it->second.in_unlocked);
  table_.erase(it);
}

// The table is full: forgets the entry whose lockout ended first, else the one wrong longest ago
// that is not locked out. False when every entry is locked out now.
bool GuessGuard::make_room(Clock::time_point now) {
  if (!locked_.empty() && locked_.begin()->first <= now) {
    erase(std::string(locked_.begin()->second));
    return true;
  }
  if (!unlocked_.empty()) {
    erase(std::string(unlocked_.front()));
    return true;
  }
  return false;
}

GuessGuard::Entry& GuessGuard::entry(const std::string& k, Clock::time_point now) {
  auto it = table_.find(k);
  if (it != table_.end()) {
    Entry& e = it->second;
    if (e.failures > 0 && now - e.last_wrong >= p_.forget_after && now >= e.locked_until) {
      if (k == kOverflow) {
        e = Entry{};
        return e;
      }
      if (e.locked) {
        locked_.erase(e.in_locked);
        e.in_unlocked = unlocked_.insert(unlocked_.begin(), k);  // wrong longest ago
      }
      const auto at = e.in_unlocked;
      e = Entry{};
      e.in_unlocked = at;
    }
    return e;
  }
  if (k != kOverflow && table_.size() >= p_.max_addresses) make_room(now);
  auto [pos, added] = table_.try_emplace(k);
  // The shared entry is in neither order: it is never forgotten to make room.
  if (added && k != kOverflow) pos->second.in_unlocked = unlocked_.insert(unlocked_.end(), k);
  return pos->second;
}

std::chrono::milliseconds GuessGuard::delay_after(int failures) const {
  if (failures <= 0) return std::chrono::milliseconds(0);
  std::chrono::milliseconds d = p_.first_delay;
  for (int i = 1; i < failures && d < p_.max_delay; ++i) d *= 2;
  return std::min(d, p_.max_delay);
}

GuessGuard::Clock::time_point GuessGuard::free_at(const std::string& address, Clock::time_point now) {
  last_now_ = now;
  const std::string k = key(address);
  if (table_.find(k) == table_.end()) return now;  // never wrong: answered at once
  return std::max(now, entry(k, now).next_answer);
}

bool GuessGuard::wrong(const std::string& address, Clock::time_point now, const std::string& endpoint) {
  last_now_ = now;
  const std::string k = key(address);
  Entry& e = entry(k, now);
  ++e.failures;
  e.last_wrong = now;
  e.last_address = address;
  e.last_endpoint = endpoint;
  e.next_answer = now + delay_after(e.failures);
  // Kept in order: wrong just now, so last among the unlocked.
  if (!e.locked && k != kOverflow) unlocked_.splice(unlocked_.end(), unlocked_, e.in_unlocked);
  // The shared entry of new addresses when the table is all locked out is slowed, never locked out: a
  // lockout there would refuse every newcomer.
  const bool exempt = k == kOverflow || std::any_of(p_.exempt.begin(), p_.exempt.end(),
                                                    [&](const inet::Cidr& c) { return inet::contains(c, address); });
  if (e.failures >= p_.lockout_after && e.locked_until <= now && !exempt) {
    // Each wrong secret after the lockout locks the address out again, until forget_after has passed
    // without one.
    e.locked_until = now + p_.lockout_for;
    e.next_answer = e.locked_until;
    if (e.locked) locked_.erase(e.in_locked);
    else unlocked_.erase(e.in_unlocked);
    e.locked = true;
    e.in_locked = locked_.emplace(e.locked_until, k);
    return true;
  }
  return false;
}

// (The shared entry stays: one right secret among many addresses does not clear the others' guesses.)
void GuessGuard::right(const std::string& address) {
  if (const std::string k = key(address); k != kOverflow) erase(k);
}

GuessGuard::Clock::time_point GuessGuard::locked_until(const std::string& address, Clock::time_point now) {
  last_now_ = now;
  auto it = table_.find(key(address));
  if (it == table_.end()) return Clock::time_point{};
  return it->second.locked_until;
}

std::string GuessGuard::lockout_cause(const std::string& address) {
  const std::string k = key(address);
  auto it = table_.find(k);
  if (it == table_.end()) return k;
  const Entry& e = it->second;
  std::string s = k + " (wrong secrets";
  if (!e.last_address.empty()) s += ", the last from " + e.last_address;
  if (!e.last_endpoint.empty()) s += " on " + e.last_endpoint;
  return s + ")";
}

int GuessGuard::failures(const std::string& address) const {
  auto it = table_.find(key(address));
  return it == table_.end() ? 0 : it->second.failures;
}

}  // namespace tb::netctl
