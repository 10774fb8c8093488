// Refusals said in the log once per address per minute (issue 46): every endpoint's refusals (a
// wrong secret, a lockout, --allow, the caps, a bad Host or Origin, a bad request) name the address
// and the reason, and a client refused a thousand times a second writes one line a minute of each
// kind (the HTTP status: a wrong secret is never hidden behind a bad request), which says how many
// refusals of that kind went unsaid since the line before. "An address" as the guessing budget
// counts it (netctl::key_of: an IPv4 address, an IPv6 /64). Pure: the caller passes the time.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>

namespace tb::web {

class RefusalLog {
 public:
  using Clock = std::chrono::steady_clock;
  explicit RefusalLog(std::chrono::seconds every = std::chrono::seconds(60), std::size_t max_addresses = 4096)
      : every_(every), max_(max_addresses) {}
  // A refusal of `address` at `now`. When it is to be logged: how many of the address's refusals
  // went unsaid since its last line; nullopt when its last line was less than `every` ago. When the
  // table is full of addresses said within the minute, new ones share one entry, "(others)".
  std::optional<std::uint64_t> note(const std::string& address, int kind, Clock::time_point now);
  std::size_t size() const { return table_.size(); }

 private:
  struct Entry {
    Clock::time_point said;
    std::uint64_t unsaid = 0;
  };
  std::chrono::seconds every_;
  std::size_t max_;
  std::unordered_map<std::string, Entry> table_;
};

}  // namespace tb::web
