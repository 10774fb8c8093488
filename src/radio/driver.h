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
// The link as an array index (0 downlink, 1 uplink), for per-link state.
constexpr int link_index(Link l) { return l == Link::downlink ? 0 : 1; }

// A receiver's recorder (--record; docs/radio.md "Recording a pass"), as the receiver answered.
struct RecorderStatus {
  std::string receiver;         // "GQRX", "SDR++": whose recorder (its file names are its own)
  std::string can;              // what it can record: "audio", "audio, iq" ("": no recorder trakbox starts)
  Record now = Record::off;     // what it records now, as it answered
  bool read_back = false;       // `now` was read back (GQRX's u RECORD), not taken from an RPRT 0 (SDR++)
  std::string refused;          // why the last start did not take ("not recording: DSP off"): a limit
  std::uint64_t answers = 0;    // starts and stops answered (the station sees each new one)
  bool operator==(const RecorderStatus&) const = default;
};

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
  // Dial follow: whether the radio's frequency of each link can be read back (Hamlib, the
  // simulated radio; not the native CAT protocols yet), and what it read last.
  bool reads_downlink = false;
  bool reads_uplink = false;
  std::optional<Hz> downlink_read_hz;
  std::optional<Hz> uplink_read_hz;
  // What the radio cannot do, learnt from its answers or known from its registry row, each once:
  // "GQRX: no CTCSS, no uplink" (empty when nothing is lacking). Never a fault.
  std::string limits;
  bool no_uplink = false;        // it carries no uplink: the uplink is not sent (--uplink-radio)
  RecorderStatus recorder;       // a receiver's recorder
};

class RadioDriver {
 public:
  virtual ~RadioDriver() = default;

  // What it is and where: "Icom CI-V on /dev/ttyUSB0 (RX 14h, TX 10h)".
  virtual std::string describe() const = 0;
  virtual void set_frequency(Link link, Hz radio_hz) = 0;
  virtual void set_mode(Link link, Mode mode) = 0;   // Mode::none: ignored
  // Dial follow. A guarded frequency: before it is written the radio's frequency is read, and if it
  // is more than tolerance_hz from what the radio last accepted on that link, the operator turned
  // the dial: the write is dropped and the frequency read is kept for take_dial_turn(). While idle,
  // a driver that can read checks a guarded link the same way. A driver that cannot read (or a
  // tolerance of 0) sets the frequency as set_frequency does.
  virtual void set_frequency_guarded(Link link, Hz radio_hz, Hz tolerance_hz) {
    (void)tolerance_hz;
    set_frequency(link, radio_hz);
  }
  // The radio frequency the operator turned a link to, once (then forgotten); nothing when not.
  virtual std::optional<Hz> take_dial_turn(Link) { return std::nullopt; }
  // How long ago the turn not yet taken was read from the radio (0 when none): the knob's rest is
  // timed from the read, not from the station's next tick.
  virtual std::chrono::milliseconds dial_turn_age(Link) const { return std::chrono::milliseconds(0); }
  // One of two radios (--uplink-radio) carries the station's `link` on its own one link: its
  // messages name that link ("uplink dial turned"), not its own.
  virtual void carries_for_station(Link link) { (void)link; }
  // CTCSS tone on the uplink in tenths of Hz (670: 67.0 Hz), 0: off. Ignored where unsupported.
  virtual void set_ctcss_tone(int tenths_hz) { (void)tenths_hz; }
  // A receiver's recorder: started (audio, iq) or stopped (off) over the radio's own connection;
  // what it answered comes in status().recorder. Ignored by a radio without one (recorder.can "").
  virtual void set_recording(Record what) { (void)what; }
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

// Sends a Tuner's commands: each link's mode before its frequency, downlink first (uplink first when
// the commands say so: the uplink's move after a turn of the downlink dial). A frequency is guarded
// (set_frequency_guarded) when its link's tolerance is above 0.
struct DialGuard {
  Hz downlink_hz = 0;
  Hz uplink_hz = 0;
};
void apply(RadioDriver& radio, const TuneCommands& commands, DialGuard guard = {});

}  // namespace tb::radio
