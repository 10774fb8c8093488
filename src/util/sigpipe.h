#pragma once
// SIGPIPE on a thread that writes to sockets through a library (Hamlib's rigctld and rotctld
// links): a peer that went away must make the write fail with EPIPE, not end the program. SIGPIPE
// goes to the thread that wrote, so the worker threads block it for themselves; one whose link
// broke may drain the signal left pending.
#include <signal.h>

#include <ctime>

namespace tb::sigpipe {

inline void block_on_this_thread() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

// Takes every SIGPIPE pending for this thread (blocked, so never delivered), without waiting.
inline void drain_pending() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGPIPE);
  timespec zero{0, 0};
  while (sigtimedwait(&set, nullptr, &zero) > 0) {
  }
}

}  // namespace tb::sigpipe
