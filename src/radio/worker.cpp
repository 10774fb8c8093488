#include "radio/worker.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace tb::radio {

namespace {

// A Doppler update moves a link by less than its tolerance (2 steps + a second's Doppler); a guarded
// move several times that is the Tuner pairing this link with the other link's turned dial.
bool moves_after_turn(Hz hz, Hz guard, const std::optional<Hz>& accepted) {
  return guard > 0 && accepted && std::llabs(hz - *accepted) > 4 * guard;
}

}  // namespace

WorkerRadio::WorkerRadio(std::unique_ptr<RadioLink> link, WorkerTiming timing)
    : link_(std::move(link)), description_(link_->describe()), timing_(timing) {
  thread_ = std::thread([this] { run(); });
}

WorkerRadio::~WorkerRadio() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void WorkerRadio::enqueue_locked(Job job) {
  // Raw bytes and the recorder's starts and stops each go (a stop then a start are two commands).
  if (job.kind != Job::Kind::raw && job.kind != Job::Kind::record) {
    auto same = std::find_if(queue_.begin(), queue_.end(), [&](const Job& j) {
      return j.kind == job.kind && j.link == job.link;
    });
    if (same != queue_.end()) {  // keep its place in the queue, take the newer value
      *same = std::move(job);
      return;
    }
  }
  queue_.push_back(std::move(job));
}

void WorkerRadio::set_frequency(Link link, Hz hz) {
  {
    std::lock_guard lock(mu_);
    want_hz_[link_index(link)] = hz;
    // Set as told (host mode, a rigctld client, dial follow off): no dial to watch any more.
    guard_[link_index(link)] = 0;
    turned_[link_index(link)].reset();
    enqueue_locked({Job::Kind::frequency, link, hz, Mode::none, {}});
  }
  cv_.notify_all();
}

void WorkerRadio::set_frequency_guarded(Link link, Hz hz, Hz tolerance) {
  {
    std::lock_guard lock(mu_);
    want_hz_[link_index(link)] = hz;
    guard_[link_index(link)] = tolerance;
    Job job{Job::Kind::frequency, link, hz, Mode::none, {}, tolerance};
    if (moves_after_turn(hz, tolerance, link == Link::downlink ? status_.downlink_hz : status_.uplink_hz)) {
      // The other link following a turn of the dial once the knob has rested: ahead of the queue
      // (on a slow line, the FT-847's, a tick's reads and Doppler writes would hold it ~1 s).
      std::erase_if(queue_, [&](const Job& j) { return j.kind == job.kind && j.link == job.link; });
      queue_.push_front(std::move(job));
    } else {
      enqueue_locked(std::move(job));
    }
  }
  cv_.notify_all();
}

std::optional<Hz> WorkerRadio::take_dial_turn(Link link) {
  std::lock_guard lock(mu_);
  return std::exchange(turned_[link_index(link)], std::nullopt);
}

std::chrono::milliseconds WorkerRadio::dial_turn_age(Link link) const {
  std::lock_guard lock(mu_);
  if (!turned_[link_index(link)]) return std::chrono::milliseconds(0);
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() -
                                                               turned_at_[link_index(link)]);
}

void WorkerRadio::carries_for_station(Link link) {
  std::lock_guard lock(mu_);
  station_link_ = link;
}

void WorkerRadio::set_ctcss_tone(int tenths_hz) {
  {
    std::lock_guard lock(mu_);
    enqueue_locked({Job::Kind::tone, Link::uplink, tenths_hz, Mode::none, {}});
  }
  cv_.notify_all();
}

void WorkerRadio::note_readable() {
  status_.reads_downlink = link_->can_read(Link::downlink);
  status_.reads_uplink = link_->can_read(Link::uplink);
}

bool WorkerRadio::read_dial(Lock& lock, Link link, Hz guard) {
  const int i = link_index(link);
  lock.unlock();
  std::optional<Hz> read;
  try {
    read = link_->read_frequency(link);
  } catch (const LinkError& e) {
    lock.lock();
    if (e.action == LinkError::Action::drop) return false;
    if (e.action == LinkError::Action::lacks) {
      learn(e);
      return false;
    }
    fail(e.what(), e.action, e.hold_off);
    if (e.action == LinkError::Action::reconnect) {
      link_fault_ = true;
      lose_link(lock);
    }
    return false;
  }
  lock.lock();
  read_at_[i] = std::chrono::steady_clock::now();
  radio_back();
  (link == Link::downlink ? status_.downlink_read_hz : status_.uplink_read_hz) = read;
  std::optional<Hz>& accepted = link == Link::downlink ? status_.downlink_hz : status_.uplink_hz;
  if (guard <= 0 || !accepted || !dial_turned(*read, *accepted, guard)) return false;
  spdlog::info("radio {}: {} dial turned to {} Hz (set {} Hz)", description_, to_string(station_link_.value_or(link)),
               *read, *accepted);
  turned_[i] = *read;
  turned_at_[i] = read_at_[i];
  quiet_[1 - i] = true;
  want_hz_[i] = *read;
  accepted = *read;   // the radio is there now; trakbox's next command starts from it
  return true;
}

void WorkerRadio::set_mode(Link link, Mode mode) {
  if (mode == Mode::none) return;
  {
    std::lock_guard lock(mu_);
    want_mode_[link_index(link)] = mode;
    enqueue_locked({Job::Kind::mode, link, 0, mode, {}});
  }
  cv_.notify_all();
}

void WorkerRadio::send_raw(std::string bytes) {
  {
    std::lock_guard lock(mu_);
    enqueue_locked({Job::Kind::raw, Link::downlink, 0, Mode::none, std::move(bytes)});
  }
  cv_.notify_all();
}

void WorkerRadio::set_recording(Record what) {
  {
    std::lock_guard lock(mu_);
    want_record_ = what;
    Job job{Job::Kind::record, Link::downlink, 0, Mode::none, {}};
    job.record = what;
    enqueue_locked(std::move(job));
  }
  cv_.notify_all();
}

RadioStatus WorkerRadio::status() const {
  std::lock_guard lock(mu_);
  RadioStatus s = status_;
  s.pending = queue_.size() + (busy_ ? 1 : 0);
  return s;
}

bool WorkerRadio::wait_idle(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mu_);
  return idle_cv_.wait_for(lock, timeout, [&] { return queue_.empty() && !busy_; });
}

void WorkerRadio::execute(const Job& job) {
  switch (job.kind) {
    case Job::Kind::frequency: link_->set_frequency(job.link, job.hz); break;
    case Job::Kind::mode: link_->set_mode(job.link, job.mode); break;
    case Job::Kind::raw: link_->send_raw(job.raw); break;
    case Job::Kind::tone: link_->set_ctcss_tone(static_cast<int>(job.hz)); break;
    case Job::Kind::record: record_answer_ = link_->record(job.record); break;
  }
}

void WorkerRadio::recorded(const Job& job) {
  RecorderStatus& r = status_.recorder;
  const bool changed = r.now != record_answer_.now || r.refused != record_answer_.refused;
  r.now = record_answer_.now;
  r.read_back = record_answer_.read_back;
  r.refused = record_answer_.refused;
  ++r.answers;
  // Each start and stop is said (a pass has two); the same answer again after a reconnect is not.
  if (changed || job.record != Record::off) spdlog::info("radio {}: {}", description_, record_answer_.said);
  show_limits();
}

void WorkerRadio::show_limits() {
  std::string limits;
  for (const std::string& l : lacks_) limits += (limits.empty() ? " " : ", ") + l;
  if (!status_.recorder.refused.empty()) limits += (limits.empty() ? " " : ", ") + status_.recorder.refused;
  status_.limits = limits.empty() ? std::string() : link_->name() + ":" + limits;
}

void WorkerRadio::learn(const LinkError& error) {
  retry_at_ = {};
  if (std::find(lacks_.begin(), lacks_.end(), error.capability) != lacks_.end()) return;
  lacks_.push_back(error.capability);
  spdlog::info("radio {}: {}", description_, error.what());
  show_limits();
  if (error.capability == "no uplink") status_.no_uplink = true;
}

void WorkerRadio::fail(const std::string& message, LinkError::Action action, std::chrono::milliseconds hold_off) {
  ++status_.failures;
  if (message != logged_) spdlog::warn("radio {}: {}", description_, message);  // once, until it works
  logged_ = message;
  status_.fault = true;
  status_.message = message;
  const bool retry = action == LinkError::Action::retry;
  retry_at_ = std::chrono::steady_clock::now() +
              std::max(hold_off, retry ? std::min(backoff_, timing_.retry_max) : backoff_);
  backoff_ = std::min(backoff_ * 2, timing_.backoff_max);
}

void WorkerRadio::radio_back() {
  if (!link_->answered_again()) return;
  for (Link l : {Link::downlink, Link::uplink}) {
    const int i = link_index(l);
    if (want_mode_[i]) enqueue_locked({Job::Kind::mode, l, 0, *want_mode_[i], {}});
    if (want_hz_[i] && !turned_[i]) enqueue_locked({Job::Kind::frequency, l, *want_hz_[i], Mode::none, {}, guard_[i]});
  }
}

void WorkerRadio::run() {
  backoff_ = timing_.backoff_first;
  Lock lock(mu_);
  while (true) {
    if (queue_.empty() && !busy_) idle_cv_.notify_all();
    wait_for_work(lock);
    if (stop_) break;
    if (std::chrono::steady_clock::now() < retry_at_) {
      cv_.wait_until(lock, retry_at_, [&] { return stop_; });
      if (stop_) break;
    }
    if (!open_ && !connect(lock)) continue;
    if (queue_.empty()) {
      check_link(lock);
      continue;
    }
    deliver_next(lock);
  }
  finish(lock);
}

void WorkerRadio::wait_for_work(Lock& lock) {
  // The link is opened at start (a wrong or missing port is reported at once, not at the first
  // pass) and reopened after a loss, whether or not anything waits to be sent; an open one is
  // checked every check_every while idle (wait_until returns at the check time, queue empty).
  auto ready = [&] { return stop_ || !queue_.empty() || (!open_ && want_open_); };
  if (open_)
    cv_.wait_until(lock, next_check_, ready);
  else
    cv_.wait(lock, ready);
}

void WorkerRadio::check_link(Lock& lock) {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_check_) return;
  next_check_ = now + timing_.check_every;
  lock.unlock();
  std::optional<LinkError> error;
  try {
    link_->check();
  } catch (const LinkError& e) {
    error = e;
  }
  lock.lock();
  if (error) {
    fail(error->what(), LinkError::Action::reconnect, error->hold_off);
    link_fault_ = true;
    return lose_link(lock);
  }
  // Reopened and still there with nothing to send: the port works again (the fault shown was
  // cleared at the reopen; a refused command's fault stays until the next delivery).
  // Dial follow: the guarded links that can be read, while nothing waits to be sent to them.
  for (Link l : {Link::downlink, Link::uplink}) {
    if (guard_[link_index(l)] <= 0 || turned_[link_index(l)] || quiet_[link_index(l)] || !link_->can_read(l)) continue;
    if (now - read_at_[link_index(l)] < timing_.check_every) continue;   // read lately (before a write)
    if (std::any_of(queue_.begin(), queue_.end(), [&](const Job& j) { return j.kind == Job::Kind::frequency && j.link == l; }))
      continue;
    read_dial(lock, l, guard_[link_index(l)]);
    if (!open_) return;
  }
  if (link_fault_) {
    spdlog::info("radio {}: working again", description_);
    link_fault_ = false;
    logged_.clear();
    backoff_ = timing_.backoff_first;
  }
}

void WorkerRadio::lose_link(Lock& lock) {
  lock.unlock();
  link_->close();
  lock.lock();
  open_ = false;
  want_open_ = true;
  status_.connected = false;
}

// Connected means answering: a link whose dial can be read is asked its downlink's frequency right
// after the port opens, and only an answer makes it connected. A radio that is silent (a wrong
// speed, the radio off, a cable) stays one fault with one message while its port is reopened with
// backoff. A link that cannot read (the FT-736's CAT only listens) is connected once it is open.
void WorkerRadio::answers() {
  if (!timing_.ask_at_connect || !link_->can_read(Link::downlink)) return;
  try {
    (void)link_->read_frequency(Link::downlink);
  } catch (const LinkError& e) {
    if (e.action == LinkError::Action::drop || e.action == LinkError::Action::lacks) return;
    link_->close();
    if (e.hold_off.count() > 0) throw;   // the peer is held by another program: its own words
    LinkError silent(LinkError::Action::reconnect,
                     "no answer: check the speed, the cable, the power (" + std::string(e.what()) + ")");
    silent.hold_off = e.hold_off;
    throw silent;
  }
}

bool WorkerRadio::connect(Lock& lock) {
  busy_ = true;
  lock.unlock();
  std::optional<LinkError> error;
  bool opened = false;
  try {
    link_->open();
    opened = true;
    answers();
  } catch (const LinkError& e) {
    error = e;
  }
  lock.lock();
  busy_ = false;
  if (error) {
    // A port that opens on a silent radio is asked again as a silent radio is (at most retry_max
    // apart: it is tuned within a second or two of answering), one fault all the while.
    fail(error->what(), opened ? LinkError::Action::retry : LinkError::Action::reconnect, error->hold_off);
    link_fault_ = true;
    return false;
  }
  open_ = true;
  want_open_ = false;
  link_->answered_again();   // everything is sent again below
  next_check_ = std::chrono::steady_clock::now() + timing_.check_every;
  status_.connected = true;
  status_.recorder.can = link_->records();   // probed at open (GQRX: u ?)
  status_.recorder.receiver = link_->name();
  note_readable();
  if (!status_.reads_downlink && !status_.reads_uplink && status_.connects == 0)   // said once
    spdlog::info("radio {}: its dial cannot be read back: dial follow will not see a turn of it", description_);
  ++status_.connects;
  spdlog::info("radio {}: {}", description_, status_.connects > 1 ? "reconnected" : "connected");
  // The port is open: no fault to show (the endpoints take commands again). The backoff and the
  // log's memory of the failure stay until a command is delivered or a check passes, so a port
  // that opens but fails every write neither retries fast nor logs every round.
  status_.fault = false;
  status_.message.clear();
  // Whatever the radio was told before, tell it again.
  for (Link l : {Link::downlink, Link::uplink}) {
    if (want_mode_[link_index(l)]) enqueue_locked({Job::Kind::mode, l, 0, *want_mode_[link_index(l)], {}});
    if (want_hz_[link_index(l)]) enqueue_locked({Job::Kind::frequency, l, *want_hz_[link_index(l)], Mode::none, {}});
  }
  // A recording asked for goes again (the receiver reads first: one already recording is left so).
  const bool record_queued =
      std::any_of(queue_.begin(), queue_.end(), [](const Job& j) { return j.kind == Job::Kind::record; });
  if (want_record_ && *want_record_ != Record::off && !record_queued) {
    Job job{Job::Kind::record, Link::downlink, 0, Mode::none, {}};
    job.record = *want_record_;
    enqueue_locked(std::move(job));
  }
  return true;
}

void WorkerRadio::deliver_next(Lock& lock) {
  Job job = std::move(queue_.front());
  queue_.pop_front();
  if (job.kind == Job::Kind::frequency && job.guard > 0 && link_->can_read(job.link)) {
    const int i = link_index(job.link);
    // A turn seen earlier that the station has not taken yet is kept, not overwritten.
    if (turned_[i]) return;
    // Read before writing: a turn of the dial since the last command is kept too. Not for the
    // other link's move after a turn when that link was read within the last second (its dial
    // unturned then) or left unread since the turn (quiet_): the move goes out at once.
    const bool fresh = quiet_[i] || std::chrono::steady_clock::now() - read_at_[i] < 2 * timing_.check_every;
    const bool follow = moves_after_turn(job.hz, job.guard, job.link == Link::downlink ? status_.downlink_hz : status_.uplink_hz);
    if (!(follow && fresh)) {
      busy_ = true;
      const auto failures = status_.failures;
      const bool turned = read_dial(lock, job.link, job.guard);
      busy_ = false;
      if (!open_) queue_.push_front(std::move(job));   // the link broke while reading: later
      if (turned || !open_) return;
      // The radio did not answer the read (switched off; its writes, never acknowledged, would go
      // nowhere unseen): the write waits for it, tried again as a failed command is.
      if (status_.failures != failures) {
        if (!std::any_of(queue_.begin(), queue_.end(), [&](const Job& j) { return j.kind == job.kind && j.link == job.link; }))
          queue_.push_back(std::move(job));
        return;
      }
    }
  }
  busy_ = true;
  lock.unlock();
  std::optional<LinkError> error;
  std::string other;
  try {
    execute(job);
  } catch (const LinkError& e) {
    error = e;
  } catch (const std::exception& e) {  // an encoder refused the value
    other = e.what();
  }
  lock.lock();
  busy_ = false;
  if (error) return job_failed(lock, std::move(job), *error);
  if (!other.empty()) {  // not retried: the same value would fail again
    fail(other);
    retry_at_ = {};
    return;
  }
  ++status_.delivered;
  radio_back();
  note_readable();  // a command may have changed it (a Hamlib radio that just went into split)
  if (status_.fault || link_fault_) spdlog::info("radio {}: working again", description_);
  link_fault_ = false;
  logged_.clear();
  status_.fault = false;
  status_.message.clear();
  backoff_ = timing_.backoff_first;
  if (job.kind == Job::Kind::frequency) {
    quiet_[link_index(job.link)] = false;
    (job.link == Link::downlink ? status_.downlink_hz : status_.uplink_hz) = job.hz;
    (job.link == Link::downlink ? status_.downlink_read_hz : status_.uplink_read_hz).reset();
  }
  if (job.kind == Job::Kind::mode) (job.link == Link::downlink ? status_.downlink_mode : status_.uplink_mode) = job.mode;
  if (job.kind == Job::Kind::record) recorded(job);
}

void WorkerRadio::job_failed(Lock& lock, Job job, const LinkError& error) {
  if (error.action == LinkError::Action::lacks) return learn(error);   // not a failure: nothing to retry
  if (error.action == LinkError::Action::drop) {
    // Refused (a tone, a mode, an uplink the radio cannot carry): reported the first time, then
    // only counted, so a refusal repeated every Doppler update neither fills the log nor makes the
    // fault come and go each second. Nothing is retried; the rest of the tuning goes on.
    ++status_.failures;
    retry_at_ = {};
    if (!refusals_said_.insert(error.what()).second) return;
    spdlog::warn("radio {}: {}", description_, error.what());
    status_.fault = true;
    status_.message = error.what();
    return;
  }
  fail(error.what(), error.action, error.hold_off);
  if (error.action == LinkError::Action::reconnect) {
    link_fault_ = true;
    lose_link(lock);
  }
  // Retry it, unless a newer value for the same thing arrived meanwhile. A command that failed
  // on a working link goes to the back, so one silent radio (an Icom pair: RX radio switched
  // off) does not hold up the commands for the other.
  const bool superseded = job.kind != Job::Kind::raw && job.kind != Job::Kind::record &&
      std::any_of(queue_.begin(), queue_.end(), [&](const Job& j) { return j.kind == job.kind && j.link == job.link; });
  if (superseded) return;
  if (error.action == LinkError::Action::retry) queue_.push_back(std::move(job));
  else queue_.push_front(std::move(job));
}

void WorkerRadio::finish(Lock& lock) {
  if (open_) {
    while (!queue_.empty()) {
      Job job = std::move(queue_.front());
      queue_.pop_front();
      lock.unlock();
      try {
        execute(job);
      } catch (const std::exception&) {
      }
      lock.lock();
    }
    lock.unlock();
    link_->close();
    lock.lock();
  }
  queue_.clear();
  status_.connected = false;
  idle_cv_.notify_all();
}

}  // namespace tb::radio
