// The station's recording of a pass on the receiver it drives (--record): started when the
// satellite the receiver is tuned to rises above the rotor start elevation, stopped when it sets;
// each answer of the receiver and each stop is a `recording` event (docs/radio.md "Recording a pass").
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "tracker/recording.h"
#include "tracker/station_loop.h"

namespace tb::tracker {

StationLoop::~StationLoop() {
  // Leaving during a pass: the recorder is stopped (the radio's worker sends what is queued once).
  if (recording_ && radio_) radio_->set_recording(radio::Record::off);
}

int StationLoop::to_record(bool drive_radio) const {
  if (model_.radio.record == radio::Record::off || !tuned_ || !doppler_) return -1;
  const auto i = static_cast<std::size_t>(*tuned_);
  if (i >= model_.db.satellites.size()) return -1;
  // The satellite the receiver is tuned to, as the one who tunes it sees it now.
  const orbit::Observation* obs = nullptr;
  if (const SatNow* f = tracker_.followed(); f && tracker_.mode() != Mode::off && f->db_index == *tuned_ && drive_radio)
    obs = &f->obs;
  else if (remote_ && remote_db_ == tuned_)
    obs = &remote_->obs;
  if (!obs || !obs->ok() || obs->look.el_deg < model_.pass_events.rotor_start_el_deg) return -1;
  if (!records_satellite(model_.radio, model_.db.satellites[i].name())) return -1;
  return *tuned_;
}

void StationLoop::record_pass(orbit::UtcTime now, bool drive_radio) {
  const radio::RecorderStatus rs = radio_->status().recorder;
  if (rs.answers != recorder_answers_) {
    recorder_answers_ = rs.answers;
    if (recording_ && !recording_->answered) {
      recording_->answered = true;
      recording_told(rs.now != radio::Record::off ? "started" : "not started", rs, now);
    }
  }
  const int want = rs.can.empty() ? -1 : to_record(drive_radio);
  if (recording_ && (want != recording_->db_index || model_.radio.record != recording_->kind)) {
    radio_->set_recording(radio::Record::off);
    recording_told("stopped", rs, now);
    recording_.reset();
  }
  if (want < 0 || recording_) return;
  PassRecording r;
  r.db_index = want;
  r.satellite = model_.db.satellites[static_cast<std::size_t>(want)].name();
  r.kind = model_.radio.record;
  r.start = now;
  // The receiver's frequency now: the downlink it was last sent (the Doppler of this tick).
  r.frequency_hz = tuner_.last_sent_downlink_hz().value_or(radio_->status().downlink_hz.value_or(0));
  r.file = recording_file_name(rs.receiver, r.kind, now, r.frequency_hz);
  recording_ = r;
  spdlog::info("recording: {} is up: starting {}'s {} recorder ({} Hz{})", r.satellite, rs.receiver,
               radio::to_string(r.kind), r.frequency_hz, r.file.empty() ? "" : ", file " + r.file);
  radio_->set_recording(r.kind);
}

void StationLoop::recording_told(const char* state, const radio::RecorderStatus& rs, orbit::UtcTime now) {
  const PassRecording& r = *recording_;
  const std::string_view st = state;
  Event e;
  e.kind = "recording";
  e.time = now;
  e.satellite = r.satellite;
  if (r.db_index >= 0 && static_cast<std::size_t>(r.db_index) < model_.db.satellites.size()) {
    e.catalog_number = model_.db.satellites[static_cast<std::size_t>(r.db_index)].elements.catalog_number;
    e.list_number = model_.db.list_number(r.db_index);
  }
  e.downlink_hz = r.frequency_hz;
  e.recording = Event::Recorded{std::string(state), radio::to_string(r.kind), r.start, r.frequency_hz, r.file,
                                st == "started" && rs.read_back, st == "not started" ? rs.refused : std::string()};
  e.detail = st == "started"       ? fmt::format("{} records {}{}{}", rs.receiver, radio::to_string(r.kind),
                                                 r.file.empty() ? "" : " into " + r.file,
                                                 rs.read_back ? " (read back)" : " (not read back)")
             : st == "not started" ? fmt::format("{}: {}", rs.receiver, rs.refused)
                                   : fmt::format("{}'s recorder stopped", rs.receiver);
  spdlog::info("recording: {} {}: {}", r.satellite, state, e.detail);
  if (recording_event_) recording_event_(e);
}

}  // namespace tb::tracker
