#pragma once
// How every accept loop waits after a failed accept (issue 38): out of descriptors (EMFILE, ENFILE),
// out of memory, the accept is tried again after 100 ms, then 200, 400, 800 ms and 1 s at most,
// never at once (re-arming at once spun a core at 15,000 failed accepts a second). The first failure
// of a run is logged, the rest are counted and the count logged when an accept succeeds again:
//
//   if (ec) { if (b.failed()) log("accept failed: ..."); timer.expires_after(b.delay()); ... }
//   else if (const auto n = b.succeeded()) log("accepting again after {} failures", n);
//
// Pure: no clock, no I/O.
#include <algorithm>
#include <chrono>
#include <cstdint>

namespace tb::util {

class AcceptBackoff {
 public:
  static constexpr std::chrono::milliseconds kFirst{100};
  static constexpr std::chrono::milliseconds kMax{1000};

  // An accept failed: true when it is the first of a run (the one to log).
  bool failed() {
    ++failures_;
    delay_ = failures_ == 1 ? kFirst : std::min(delay_ * 2, kMax);
    return failures_ == 1;
  }
  // How long to wait before the next accept, after failed().
  std::chrono::milliseconds delay() const { return delay_; }
  // An accept succeeded: the failures of the run that ended (0 when there was none).
  std::uint64_t succeeded() {
    const std::uint64_t n = failures_;
    failures_ = 0;
    delay_ = kFirst;
    return n;
  }
  std::uint64_t failures() const { return failures_; }

 private:
  std::uint64_t failures_ = 0;
  std::chrono::milliseconds delay_ = kFirst;
};

}  // namespace tb::util
