// A degree rotator behind a worker thread, for drivers whose I/O blocks (Hamlib on a serial port or
// rotctld, another Satrak ACU on the network). The loop's calls never wait:
//   set_position / stop      leave a command for the worker (the latest position wins; stop first)
//   read / motion / limits / health / az_range   answer from the worker's last report
// The worker connects, then serves: the pending stop, the pending position, and a poll every
// `poll`. A link that fails is reported (health + message, and spdlog); motion commands pending or
// given while it is down are dropped (never replayed), and the worker reconnects with backoff
// (backoff_min doubling to backoff_max). A position the rotator refuses is a fault (health) until
// one is accepted; the link stays up.
//
// Connected means answering: after open() the link is polled once, and only a valid reply makes it
// connected (health ok, "connected" in the log). A peer that never answers is one problem ("no
// answer from the GS-232B at 9600 baud: check the speed, the cable, the power"), logged once, its
// port reopened with the same backoff, and one fault however long it lasts: at most one link-lost /
// link-back pair per episode for the events.
//
// The device-specific part is a RotatorLink, used only on the worker thread.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "rotator/driver.h"

namespace tb::rotator {

// What one poll found; what it leaves empty stays as it was.
struct LinkReport {
  std::optional<AzEl> position;
  std::optional<AxisMotion> motion;
  std::optional<LimitFlags> limits;
  // A fault the controller reported of its own (Easycomm's "AL..." line): the link stays up; the
  // health shows it (a fault, said once in the log) until the controller has been quiet 10 s.
  std::optional<std::string> alarm;
};

// Every call but close() returns false when the link is lost (or could not be opened), with
// `error` saying why.
class RotatorLink {
 public:
  virtual ~RotatorLink() = default;
  virtual bool open(std::string& error) = 0;  // tidies up after itself when it fails
  virtual void close() = 0;                   // after open() succeeded, also when the link was lost
  // The azimuths the connected rotator accepts (asked after each open()).
  virtual Range az_range() { return {0.0, 360.0}; }
  virtual bool stop(std::string& error) = 0;
  // `refusal` set (the link staying up) when the rotator answered but refused the position.
  virtual bool go_to(AzEl p, std::optional<std::string>& refusal, std::string& error) = 0;
  virtual bool poll(LinkReport& report, std::string& error) = 0;
  // Who answers (or does not), for the one message of a silent peer: "the GS-232B at 9600 baud"
  // and what to look at ("check the speed, the cable, the power"). Asked after open().
  virtual std::string peer() const { return {}; }
  virtual std::string silent_hint() const { return "check the speed, the cable, the power"; }
};

struct LinkTiming {
  std::chrono::milliseconds poll{250};          // poll interval while connected
  std::chrono::milliseconds io_timeout{1000};   // one answer
  std::chrono::milliseconds backoff_min{250};   // first reconnect delay
  std::chrono::milliseconds backoff_max{8000};  // reconnect delay ceiling
};

class WorkerRotator : public DegreeRotator {
 public:
  // `label` names the rotator in description(), health messages and the log.
  WorkerRotator(std::string label, std::unique_ptr<RotatorLink> link, LinkTiming timing);
  // Stops the worker. Waits at most about two I/O timeouts for it; a worker stuck in a blocking
  // call longer than that is left to finish on its own (it owns the link and the shared state).
  ~WorkerRotator() override;
  WorkerRotator(const WorkerRotator&) = delete;
  WorkerRotator& operator=(const WorkerRotator&) = delete;

  std::string description() const override;
  Health health() override;
  AxisMotion motion() override;
  LimitFlags limits() override;
  void stop() override;
  std::optional<AzEl> read() override;
  void set_position(AzEl p) override;
  Range az_range() override;

  struct Shared;  // state shared with the worker (worker.cpp)

 private:
  std::shared_ptr<Shared> s_;
  std::thread worker_;
};

}  // namespace tb::rotator
