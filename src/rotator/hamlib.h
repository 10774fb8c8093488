// Real rotators through Hamlib: anything Hamlib drives (GS-232, EasyComm, SPID, ...) on a serial
// port, or a rotctld on the network (Hamlib's NET rotctl, model 2).
//
// Hamlib calls block (serial timeouts, TCP), so they all run on the worker thread of a
// WorkerRotator (worker.h); the controller talks to it through a small command/status exchange and
// never waits. A rotator that stops answering: pending and later motion commands are dropped (never
// replayed), the fault is reported (health + message, and spdlog), and the worker reconnects with
// backoff (backoff_min doubling to backoff_max). Hamlib's own debug output goes to spdlog, not the
// terminal.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

#include "rotator/worker.h"

namespace tb::rotator {

struct HamlibOptions {
  int model = 0;             // Hamlib rotator model number (`rotctl -l`); 2 = NET rotctl
  std::string pathname;      // serial device, or HOST:PORT for model 2
  int baud = 0;              // serial speed; 0 = the backend's default
  std::string label;         // description(); built from the above when empty
  std::chrono::milliseconds poll{250};          // position read interval while connected
  std::chrono::milliseconds io_timeout{1000};   // Hamlib port timeout (one answer)
  std::chrono::milliseconds backoff_min{250};   // first reconnect delay
  std::chrono::milliseconds backoff_max{8000};  // reconnect delay ceiling
};

class HamlibRotator final : public WorkerRotator {
 public:
  explicit HamlibRotator(HamlibOptions options);
};

// True when Hamlib knows a rotator model of this number.
bool hamlib_rotator_model_exists(int model);
// The model number of a Hamlib rotator by its name ("GS-232B", "gs232b", "Yaesu GS-232B": case,
// blanks and dashes ignored; the maker's name may lead), or nothing when Hamlib has no such model
// or more than one of that name.
std::optional<int> hamlib_rotator_model_by_name(std::string_view name);

}  // namespace tb::rotator
