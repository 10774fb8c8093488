#include "web/refusals.h"

#include "netctl/guesses.h"

namespace tb::web {

std::optional<std::uint64_t> RefusalLog::note(const std::string& address, int kind, Clock::time_point now) {
  std::string key = netctl::key_of(address) + " " + std::to_string(kind);
  if (table_.size() >= max_ && table_.find(key) == table_.end()) {
    std::erase_if(table_, [&](const auto& kv) { return now - kv.second.said >= every_; });
    if (table_.size() >= max_) key = "(others)";
  }
  const auto [it, added] = table_.try_emplace(key);
  Entry& e = it->second;
  if (added || now - e.said >= every_) {
    const std::uint64_t unsaid = added ? 0 : e.unsaid;
    e.said = now;
    e.unsaid = 0;
    return unsaid;
  }
  ++e.unsaid;
  return std::nullopt;
}

}  // namespace tb::web
