// One interface for every radio: the simulated radio, the serial CAT radios (Icom CI-V, Kenwood,
// Yaesu FT-736) and Hamlib. The tracker, host mode and menus talk only to this.
//
// Every call returns at once: drivers that talk to hardware queue the request for their own worker
// thread, keep only the newest frequency and mode per link (an unsent older value is replaced),
// and report how it went through status(). A frequency or mode that could not be delivered is
// retried with backoff until it is, or until a newer one replaces it; after a reconnect the last
// requested frequencies and modes are sent again.
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "radio/config.h"
#include "radio/doppler.h"

namespace tb::radio {

enum class Link { downlink, uplink };
const char* to_string(Link l);   // "downlink" / "uplink"

struct RadioStatus {
  bool connected = false;        // port / socket open
  bool fault = false;            // the last attempt failed; message says why
  std::string message;           // the fault, e.g. "interface not echoing"; empty when fine
  std::optional<Hz> downlink_hz; // last frequency the radio accepted
  std::optional<Hz> uplink_hz;
  std::optional<Mode> downlink_mode;
  std::optional<Mode> uplink_mode;
  std::uint64_t delivered = 0;   // commands delivered
  std::uint64_t failures = 0;    // failed attempts
  std::uint64_t connects = 0;    // successful opens (more than 1: it reconnected)
  std::size_t pending = 0;       // requests not yet delivered
};

class RadioDriver {
 public:
  virtual ~RadioDriver() = default;

  // What it is and where: "Icom CI-V on /dev/ttyUSB0 (RX 14h, TX 10h)".
  virtual std::string describe() const = 0;
  virtual void set_frequency(Link link, Hz radio_hz) = 0;
  virtual void set_mode(Link link, Mode mode) = 0;   // Mode::none: ignored
  // Host mode "S": bytes to the radio as they are (Icom: the caller supplies the whole frame).
  virtual void send_raw(std::string bytes) = 0;
  virtual RadioStatus status() const = 0;
  // Waits until nothing is queued or in flight (true), or the timeout (false). For tests and
  // orderly shutdown; never call it from the event loop in normal operation.
  virtual bool wait_idle(std::chrono::milliseconds timeout) = 0;

  void set_downlink_frequency(Hz hz) { set_frequency(Link::downlink, hz); }
  void set_uplink_frequency(Hz hz) { set_frequency(Link::uplink, hz); }
  void set_downlink_mode(Mode m) { set_mode(Link::downlink, m); }
  void set_uplink_mode(Mode m) { set_mode(Link::uplink, m); }
};

// Sends a Tuner's commands: each link's mode before its frequency, downlink first.
void apply(RadioDriver& radio, const TuneCommands& commands);

}  // namespace tb::radio
