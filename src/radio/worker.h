// A radio behind a worker thread: the caller's calls queue and return at once; the worker talks to
// the hardware (which may block: serial timeouts, Icom echo waits, Yaesu byte spacing, Hamlib),
// reports faults, retries with backoff and reconnects.
//
// The device-specific part is a RadioLink, used only on the worker thread.
#pragma once
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "radio/driver.h"

namespace tb::radio {

// What a link throws when something went wrong.
struct LinkError : std::runtime_error {
  enum class Action {
    reconnect,  // the port or connection is broken: close, reopen with backoff, retry
    retry,      // the link is up but this attempt failed (no echo, collision, timeout): retry
    drop,       // the radio refused this command (NG, a value out of range): don't retry it
    // The radio has no such feature (no CTCSS encoder, no uplink, a mode it lacks): a capability
    // learnt once, said once in the log and in the status's `limits`, never a fault or a failure.
    lacks,
  };
  Action action;
  std::string capability;                 // lacks: "no CTCSS", "no uplink", "no mode CW"
  std::chrono::milliseconds hold_off{0};  // reconnect: wait at least this long (a peer held elsewhere)
  LinkError(Action a, const std::string& what) : std::runtime_error(what), action(a) {}
  LinkError(std::string lacking, const std::string& what)
      : std::runtime_error(what), action(Action::lacks), capability(std::move(lacking)) {}
};

class RadioLink {
 public:
  virtual ~RadioLink() = default;
  virtual std::string describe() const = 0;
  // The radio's short name for the status's limits ("GQRX: no CTCSS, no uplink").
  virtual std::string name() const { return describe(); }
  virtual void open() = 0;                 // throws LinkError
  virtual void close() noexcept = 0;       // leave the radio tidy (Yaesu: CAT off), close the port
  virtual void set_frequency(Link link, Hz hz) = 0;
  virtual void set_mode(Link link, Mode mode) = 0;
  virtual void send_raw(const std::string& bytes) = 0;
  // Dial follow: whether read_frequency works for a link once open, and the radio's frequency of
  // that link now (throws LinkError). Links that cannot read keep the defaults.
  virtual bool can_read(Link) const { return false; }
  virtual Hz read_frequency(Link link) {
    throw LinkError(LinkError::Action::drop, std::string("cannot read the ") + to_string(link) + " frequency");
  }
  virtual void set_ctcss_tone(int tenths_hz) { (void)tenths_hz; }
  // Called every WorkerTiming::check_every while the link is open and idle: throws
  // LinkError(reconnect) when the port or connection is gone (a serial adapter unplugged, the pty's
  // other end closed), so a loss is seen and reported without waiting for the next command.
  virtual void check() {}
  // True once when the radio answered again after a silence (switched off and on behind a port
  // that stayed): the worker then sends everything again, as after a reconnect.
  virtual bool answered_again() { return false; }
  // The receiver's recorder (--record), once open: what it can record ("audio", "audio, iq"; ""
  // none), and a start (audio, iq) or a stop (off), answered with what it records now. A start the
  // receiver refuses (GQRX with its DSP off) is an answer (`refused`), not an error.
  struct Recording {
    Record now = Record::off;
    bool read_back = false;   // read back from the receiver, not assumed
    std::string refused;      // "not recording: DSP off"
    std::string said;         // one line for the log: what was sent and what it answered
  };
  virtual std::string records() const { return {}; }
  virtual Recording record(Record what) {
    throw LinkError("no recorder", describe() + ": no recorder trakbox can start (" + to_string(what) + " not sent)");
  }
};

struct WorkerTiming {
  std::chrono::milliseconds backoff_first{200};    // wait after the first failure
  std::chrono::milliseconds backoff_max{5000};     // doubling up to this
  std::chrono::milliseconds check_every{500};      // RadioLink::check() while open and idle
  // A radio that stopped answering on a port that works (switched off behind its interface):
  // asked again at least this often, so it is tuned within a second or two of answering again.
  std::chrono::milliseconds retry_max{1000};
  // Connected means answering: a link that can read is asked its downlink's frequency at each
  // connect, and only an answer makes it connected. Off only for the unit tests that compare a
  // radio's exact command sequence from the first byte (the integration tests run it on).
  bool ask_at_connect = true;
};

class WorkerRadio final : public RadioDriver {
 public:
  explicit WorkerRadio(std::unique_ptr<RadioLink> link, WorkerTiming timing = {});
  ~WorkerRadio() override;   // delivers what is queued (one attempt), closes the link, joins
  WorkerRadio(const WorkerRadio&) = delete;
  WorkerRadio& operator=(const WorkerRadio&) = delete;

  std::string describe() const override { return description_; }
  void set_frequency(Link link, Hz radio_hz) override;
  void set_mode(Link link, Mode mode) override;
  void set_frequency_guarded(Link link, Hz radio_hz, Hz tolerance_hz) override;
  std::optional<Hz> take_dial_turn(Link link) override;
  void carries_for_station(Link link) override;
  std::chrono::milliseconds dial_turn_age(Link link) const override;
  void set_ctcss_tone(int tenths_hz) override;
  void send_raw(std::string bytes) override;
  void set_recording(Record what) override;
  RadioStatus status() const override;
  bool wait_idle(std::chrono::milliseconds timeout) override;

 private:
  struct Job {
    enum class Kind { frequency, mode, raw, tone, record } kind;
    Link link = Link::downlink;
    Hz hz = 0;                       // frequency; tone: tenths of Hz
    Mode mode = Mode::none;
    std::string raw;
    Hz guard = 0;                    // frequency: dial-follow tolerance, 0 unguarded
    Record record = Record::off;     // record: the recorder started (audio, iq) or stopped (off)
  };
  using Lock = std::unique_lock<std::mutex>;
  void enqueue_locked(Job job);
  void run();
  void execute(const Job& job);
  // The worker thread's steps, each called with mu_ held (lock) and unlocking it around radio I/O.
  bool connect(Lock& lock);          // opens the link; false (fault recorded) when it did not
  void answers();                    // after open, mu_ unlocked: throws LinkError when it is silent
  void deliver_next(Lock& lock);     // runs the job at the head of the queue
  void job_failed(Lock& lock, Job job, const LinkError& error);
  // Records a fault and the back-off before the next try (a retry on a working port: at most
  // retry_max; a lost port: doubling to backoff_max).
  void fail(const std::string& message, LinkError::Action action = LinkError::Action::reconnect,
            std::chrono::milliseconds hold_off = {});
  // A feature the radio lacks (LinkError::Action::lacks): kept in the status, said once.
  void learn(const LinkError& error);
  // The status's limits: the capabilities learnt missing, then a refused recording.
  void show_limits();
  // A recording job's answer (record_answer_, from execute) into the status, said once.
  void recorded(const Job& job);
  // The radio answered again after a silence (RadioLink::answered_again): whatever it was told is
  // sent again, as after a connect (its link asks for satellite mode again itself).
  void radio_back();
  void finish(Lock& lock);           // stopping: one attempt at what is queued, then close
  void wait_for_work(Lock& lock);    // until stop, a job, a reconnect due, or a check due
  void check_link(Lock& lock);       // the idle check; a lost link is closed for reconnecting
  void lose_link(Lock& lock);        // closes a broken link; the worker reopens it with backoff
  // Dial follow: reads a link's frequency (mu_ unlocked around the read) and records a turn when it
  // is more than guard from the accepted frequency. True when the operator turned the dial.
  // The status's reads_downlink/uplink from the link as it is now (under mu_).
  void note_readable();
  bool read_dial(Lock& lock, Link link, Hz guard);

  std::unique_ptr<RadioLink> link_;
  std::optional<Link> station_link_;   // one of two radios: the station's link its one link carries
  const std::string description_;
  const WorkerTiming timing_;

  mutable std::mutex mu_;
  std::condition_variable cv_;       // work arrived / stop
  std::condition_variable idle_cv_;  // queue drained
  std::deque<Job> queue_;
  bool busy_ = false;
  bool stop_ = false;
  std::optional<Hz> want_hz_[2];     // last requested per link (re-sent after a reconnect)
  std::optional<Mode> want_mode_[2];
  std::optional<Record> want_record_;  // the recorder asked for (asked again after a reconnect)
  RadioLink::Recording record_answer_; // worker thread: the last recording job's answer
  RadioStatus status_;
  Hz guard_[2] = {0, 0};             // the tolerance of the last guarded frequency per link
  std::optional<Hz> turned_[2];      // a turn of the dial not yet taken
  std::chrono::steady_clock::time_point turned_at_[2]{};   // ... and when it was read
  // Not read while idle: the other link after a turn of one dial, until trakbox writes it again
  // (it moves it to the new pair once the knob rests). Only what can have turned is read then, and
  // on a slow line (the FT-847's) the move does not wait behind a read of the link it moves.
  bool quiet_[2] = {false, false};
  // When each link was last read: an idle read comes only when none was made for check_every
  // (a guarded write reads first, so a link written each second is not read twice as often).
  std::chrono::steady_clock::time_point read_at_[2]{};
  // Worker-thread state.
  bool open_ = false;
  bool want_open_ = true;            // opened at start, reopened after a loss, with or without jobs
  bool link_fault_ = false;          // the port failed (open, lost) and has not worked since
  std::string logged_;               // the failure last logged (not again until something works)
  std::set<std::string> refusals_said_;  // refused commands already reported (each once)
  std::vector<std::string> lacks_;       // capabilities learnt missing, in the order learnt
  std::chrono::steady_clock::time_point next_check_{};
  std::chrono::milliseconds backoff_{};
  std::chrono::steady_clock::time_point retry_at_{};
  std::thread thread_;
};

}  // namespace tb::radio
