// Real rotators through Hamlib: anything Hamlib drives (GS-232, EasyComm, SPID, ...) on a serial
// port, or a rotctld on the network (Hamlib's NET rotctl, model 2).
//
// Hamlib calls block (serial timeouts, TCP), so they all run on a worker thread of this driver; the
// controller talks to it through a small command/status exchange and never waits:
//   set_position / stop   leave a command for the worker (the latest position wins; stop first)
//   read / motion / health  answer from the worker's last report
// A rotator that stops answering: pending and later motion commands are dropped (never replayed),
// the fault is reported (health + message, and spdlog), and the worker reconnects with backoff
// (backoff_min doubling to backoff_max). Hamlib's own debug output goes to spdlog, not the terminal.
#pragma once
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "rotator/driver.h"

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

class HamlibRotator final : public DegreeRotator {
 public:
  explicit HamlibRotator(HamlibOptions options);
  // Stops the worker. Waits at most about two I/O timeouts for it; a worker stuck in a Hamlib call
  // longer than that is left to finish on its own.
  ~HamlibRotator() override;
  HamlibRotator(const HamlibRotator&) = delete;
  HamlibRotator& operator=(const HamlibRotator&) = delete;

  std::string description() const override;
  Health health() override;
  AxisMotion motion() override;
  void stop() override;
  std::optional<AzEl> read() override;
  void set_position(AzEl p) override;
  Range az_range() override;

  struct Shared;  // state shared with the worker (hamlib.cpp)

 private:
  std::shared_ptr<Shared> s_;
  std::thread worker_;
};

// True when Hamlib knows a rotator model of this number.
bool hamlib_rotator_model_exists(int model);

}  // namespace tb::rotator
