#include "tracker/station_loop.h"
#include "tracker/web_url.h"

#include "store/drivers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "radio/two_radios.h"
#include "store/settings.h"

namespace tb::tracker {

StationLoop::StationLoop(store::ModelOwner& owner, const station::Clock& clock, Tracker& tracker,
                         std::unique_ptr<rotator::Controller> rotator, std::unique_ptr<radio::RadioDriver> radio)
    : owner_(owner),
      model_(owner.model()),
      clock_(clock),
      tracker_(tracker),
      rotator_(std::move(rotator)),
      radio_(std::move(radio)),
      tuner_(owner.model().radio) {
  owner_.listen([this, alive = std::weak_ptr<int>(alive_)](const store::Notice& n) {
    if (!alive.expired()) on_model_changed(n);
  });
  rotator_->set_control_enabled(model_.rotor_control);
  rotator_->set_error_detection(model_.rotator_error_detection);
  sharing_changed();
  if (model_.sharing.standby) control_.set_standby(true, clock_.now());  // stored: it survives a restart
  // The Tracker may outlive this station (a test rebuilds it around the same Tracker): the hook
  // does nothing once this one is gone, and a newer station's hook replaces it.
  tracker_.on_choice([this, alive = std::weak_ptr<int>(alive_)] {
    if (alive.expired()) return;
    // A choice of what to track (any front end; StationOps asked the operator to confirm first
    // when an outside client held): trakbox's tracking drives both again.
    for (const Resource r : {Resource::antenna, Resource::radio})
      if (!control_.standby()) apply(control_.request(r, Requester::menus(), clock_.now(), true, true).changes);
    record_choice();
  });
}

void StationLoop::set_rotor_control(bool on) {
  // Announced when it changes: on_model_changed applies it, saves and wakes the loop.
  const bool changed = owner_.set("rotor_control", on, store::Origin::station).changed;
  rotator_->set_control_enabled(on);
  if (!changed) wake();
}

// What the owner announced, applied to what depends on it: the rotator's and the radio's
// configuration, the pass plan and the position's generation (whoever caches a pass compares it),
// the sharing rules; then the state is saved and the loop ticks at once.
void StationLoop::on_model_changed(const store::Notice& n) {
  using store::Area;
  if (n.changes(Area::position)) {
    planned_.reset();
    ++position_generation_;
  }
  if (n.changes(Area::rotator) || n.changes(Area::control) || n.changes(Area::station)) {
    planned_.reset();
    rotator_->set_config(model_.rotator, model_.station.rotor_start);
    rotator_->set_control_enabled(model_.rotor_control);
    rotator_->set_error_detection(model_.rotator_error_detection);
  }
  // The tuner keeps the corrections it learnt itself; anything else of the radio is sent afresh.
  if (n.changes(Area::radio) && n.what != kCorrectionsEdit && n.what != kDialFollowEdit) {
    tuner_.set_config(model_.radio);
    tuned_.reset();
  }
  if (n.changes(Area::elements) || (n.changes(Area::radio_entries) && n.what != kToneEdit)) {
    find_remote_in_database();
    tuned_.reset();  // frequencies may have changed: select the satellite again
  }
  if (n.changes(Area::sharing)) sharing_changed();
  if (settings_changed_) settings_changed_();
  wake();
}

void StationLoop::record_choice() {
  store::TrackingChoice c;
  if (tracker_.mode() == Mode::multi) {
    c.mode = store::TrackingChoice::Mode::multi;
  } else if (tracker_.mode() == Mode::single) {
    const int i = tracker_.single_index();
    if (const auto body = body_target(i)) {
      // A body by its name, catalog number 0 (no satellite has it): start_stored_tracking reads it back.
      c.mode = store::TrackingChoice::Mode::single;
      c.name = std::string(orbit::body_name(*body));
    } else if (i < 0 || i >= static_cast<int>(model_.db.satellites.size())) {
      return;
    } else {
      c.mode = store::TrackingChoice::Mode::single;
      c.catalog_number = model_.db.satellites[static_cast<std::size_t>(i)].elements.catalog_number;
      c.name = model_.db.satellites[static_cast<std::size_t>(i)].name();
    }
  } else {
    return;
  }
  const bool priority = tracker_.mode() == Mode::multi ? tracker_.priority() : model_.priority_mode;
  if (c == model_.tracking && priority == model_.priority_mode) return;
  (void)owner_.edit(store::bit(store::Area::control), "tracking choice", store::Origin::station,
                    [&](store::Model& m) {
                      m.tracking = c;
                      m.priority_mode = priority;
                    });
}

void StationLoop::reconfigure() {
  planned_.reset();  // the geometry may have changed
  ++position_generation_;
  find_remote_in_database();  // the database may have changed too
  rotator_->set_config(model_.rotator, model_.station.rotor_start);
  rotator_->set_control_enabled(model_.rotor_control);
  rotator_->set_error_detection(model_.rotator_error_detection);
  tuner_.set_config(model_.radio);
  tuned_.reset();  // frequencies may have changed: select the satellite again
  sharing_changed();
}

void StationLoop::sharing_changed() {
  ControlSettings cs;
  cs.handback_s = model_.sharing.handback_s;
  cs.exclusive = kind_named(model_.sharing.exclusive);
  control_.set_settings(cs);
  std::vector<Window> w = satnogs_windows_;
  for (const store::Reservation& r : model_.sharing.reservations)
    w.push_back({"operator", r.id, orbit::UtcTime{std::chrono::seconds(r.start_unix)},
                 orbit::UtcTime{std::chrono::seconds(r.end_unix)}, "", r.note, "", ""});
  control_.set_windows(std::move(w));
}

bool StationLoop::apply_gps_position() {
  if (!gps_ || !model_.gps.follow) return false;
  const auto& fix = gps_->filter().confirmed();
  if (!fix || !gps_->filter().fixed()) return false;
  const station::StationConfig& st = model_.station;
  const double moved = gps::distance_m(st.lat_deg, st.lon_deg, fix->lat_deg, fix->lon_deg);
  const double climbed = fix->alt_m ? std::abs(*fix->alt_m - st.height_m) : 0.0;
  if (model_.gps.position_from_gps && moved <= model_.gps.threshold_m && climbed <= model_.gps.threshold_m) return false;
  // A receiver's height beyond what the station takes is clamped to its range (a fix is not typed).
  const store::Bounds h = store::bounds("station.height_m");
  const double height = fix->alt_m ? std::clamp(*fix->alt_m, h.lo, h.hi) : st.height_m;
  const store::EditResult r = owner_.set_position(fix->lat_deg, fix->lon_deg, height, store::Origin::gps, fix->time);
  if (!r.ok()) spdlog::warn("gps: the fix {:.5f}, {:.5f} not taken: {}", fix->lat_deg, fix->lon_deg, *r.refusal);
  return r.changed;
}

void StationLoop::remote_follow(std::optional<RemoteFollow> f) {
  const bool same = f && remote_ && remote_->catalog_number == f->catalog_number;
  remote_ = std::move(f);
  if (!same) find_remote_in_database();
}

void StationLoop::find_remote_in_database() {
  remote_db_.reset();
  if (!remote_) return;
  const auto& sats = model_.db.satellites;
  for (std::size_t i = 0; i < sats.size(); ++i)
    if (sats[i].elements.catalog_number == remote_->catalog_number) {
      remote_db_ = static_cast<int>(i);
      return;
    }
}

void StationLoop::follow_radio(int db_index, const orbit::Observation& obs) {
  if (!tuned_ || *tuned_ != db_index) {
    const store::Satellite& chosen = model_.db.satellites[static_cast<std::size_t>(db_index)];
    const radio::SatelliteRadio& sat = chosen.radio;
    tuner_.select(sat, chosen.name(), store::chosen_mode(chosen));
    tuned_ = db_index;
    if (sat.ctcss_tenths_hz > 0 || tone_sent_) radio_->set_ctcss_tone(sat.ctcss_tenths_hz);
    tone_sent_ = sat.ctcss_tenths_hz > 0;
    // CAT only at AOS: the radio is preset now to the chosen satellite's frequencies and modes (with
    // the Doppler of the moment), so that it does not stay on the last satellite's until AOS. The
    // AOS edge sends them afresh.
    const radio::RadioConfig& rc = tuner_.config();
    if (obs.ok() && !radio::at_aos(obs.look.el_deg) && rc.cat_policy == radio::CatPolicy::aos_only &&
        sat.doppler == radio::DopplerControl::cat && !rc.parking.enabled) {
      const radio::Tuning t = radio::compute_tuning(tuner_.satellite(), radio::Corrections::from(rc),
                                                    obs.look.range_rate_km_s, tuner_.rit_hz(), tuner_.xit_hz());
      radio::TuneCommands preset;
      // A link whose correction is off is the operator's: left alone, as the Tuner leaves it.
      if (rc.downlink_correction != radio::DownlinkCorrection::off) {
        preset.downlink_hz = t.downlink_radio_hz;
        if (sat.downlink_mode != radio::Mode::none && t.downlink_radio_hz) preset.downlink_mode = sat.downlink_mode;
      }
      if (rc.uplink_correction) {
        preset.uplink_hz = t.uplink_radio_hz;
        if (sat.uplink_mode != radio::Mode::none && t.uplink_radio_hz) preset.uplink_mode = sat.uplink_mode;
      }
      if (tuner_.reversed()) {
        std::swap(preset.downlink_hz, preset.uplink_hz);
        std::swap(preset.downlink_mode, preset.uplink_mode);
      }
      radio::apply(*radio_, preset);
    }
  }
  if (!obs.ok()) return;
  const double rr = obs.look.range_rate_km_s;
  // The radio link that carries each of the tuner's links (FREQ.DAT ir/kr swap them).
  const bool swap = tuner_.reversed();
  const radio::Link down = swap ? radio::Link::uplink : radio::Link::downlink;
  const radio::Link up = swap ? radio::Link::downlink : radio::Link::uplink;
  const bool follow = tuner_.dial_follow_active();
  // Dial follow: a turn of either dial the radio reported since the last tick moves that link's
  // spot at once; the other link follows once the knob has rested (Tuner::settle).
  // The knob's rest is timed on the station's clock (real time, or --clock-rate's), from when the
  // radio's dial was read, not from this tick.
  const auto age_down = radio_->dial_turn_age(down), age_up = radio_->dial_turn_age(up);
  const std::optional<radio::Hz> turned_down = radio_->take_dial_turn(down);
  const std::optional<radio::Hz> turned_up = radio_->take_dial_turn(up);
  const double read_ago_s = std::chrono::duration<double>(turned_down && turned_up ? std::min(age_down, age_up)
                                                                                   : std::max(age_down, age_up)).count();
  const double now_s = std::chrono::duration<double>(clock_.now().time_since_epoch()).count();
  if (follow && (turned_down || turned_up)) {
    using Turn = radio::Tuner::Turn;
    switch (tuner_.dial_turn(turned_down, turned_up, rr, now_s - read_ago_s)) {
      case Turn::downlink:
      case Turn::uplink: {
        const bool d = turned_down.has_value();
        spdlog::info("radio: {} dial turned to {} Hz: spot {} Hz down, {} Hz up; the {} follows once the knob "
                     "has rested {} ms", d ? "downlink" : "uplink", d ? *turned_down : *turned_up,
                     tuner_.downlink_spot_hz(), tuner_.uplink_spot_hz(), d ? "uplink" : "downlink",
                     tuner_.config().dial_rest_ms);
        break;
      }
      case Turn::rit_xit:
        if (!rit_said_)
          spdlog::info("radio: both links moved together ({} / {} Hz): RIT/XIT, not a turn of the dial",
                       *turned_down, *turned_up);
        rit_said_ = true;
        break;
      case Turn::outside:
        spdlog::warn("radio: {} reads {} Hz, far outside the transponder: not taken as a turn of the dial",
                     turned_down ? "downlink" : "uplink", turned_down ? *turned_down : *turned_up);
        break;
      case Turn::none: break;
    }
  }
  if (tuner_.settle(now_s))
    spdlog::info("radio: the knob rested: spot {} Hz down, {} Hz up", tuner_.downlink_spot_hz(), tuner_.uplink_spot_hz());
  const radio::TuneCommands cmd = tuner_.update(obs.look.el_deg, rr);
  radio::DialGuard guard;
  // Not at the AOS edge: what the dial shows then is left from before the pass, not a new spot.
  if (follow && !tuner_.parked() && !cmd.aos) {
    (swap ? guard.uplink_hz : guard.downlink_hz) = tuner_.dial_tolerance_downlink_hz();
    (swap ? guard.downlink_hz : guard.uplink_hz) = tuner_.dial_tolerance_uplink_hz();
  }
  radio::apply(*radio_, cmd, guard);
}

void StationLoop::set_uplink_radio(std::unique_ptr<radio::RadioDriver> uplink) {
  std::unique_ptr<radio::RadioDriver> downlink;
  if (auto* two = dynamic_cast<radio::TwoRadios*>(radio_.get())) downlink = two->release_downlink();
  else downlink = std::move(radio_);
  radio_.reset();  // the old uplink radio closes here
  if (uplink) radio_ = std::make_unique<radio::TwoRadios>(std::move(downlink), std::move(uplink));
  else radio_ = std::move(downlink);
  resend_radio();
}

void StationLoop::resend_radio() {
  tuner_.resend();   // the spot stays; frequencies and modes go out again, and the tone
  const int tone = tuned_ ? tuner_.satellite().ctcss_tenths_hz : 0;
  if (tone > 0) radio_->set_ctcss_tone(tone);
  tone_sent_ = tone > 0;
}

void StationLoop::set_tone(int tenths_hz) {
  tuner_.set_tone(tenths_hz);
  if (tenths_hz > 0 || tone_sent_) radio_->set_ctcss_tone(tenths_hz);
  tone_sent_ = tenths_hz > 0;
}

std::optional<std::chrono::milliseconds> StationLoop::radio_due_in() const {
  const auto due = tuner_.settle_due_s();
  if (!due) return std::nullopt;
  const double now_s = std::chrono::duration<double>(clock_.now().time_since_epoch()).count();
  return std::chrono::milliseconds(std::max<long long>(0, static_cast<long long>((*due - now_s) * 1000.0) + 1));
}

std::optional<radio::Hz> StationLoop::next_uplink() {
  if (!tuned_) return std::nullopt;
  const auto i = static_cast<std::size_t>(*tuned_);
  radio::SatelliteRadio r = model_.db.satellites[i].radio;
  if (!r.next_uplink()) return std::nullopt;
  // Not announced as the radio entries' change: the tuner moves to the new uplink here, keeping
  // everything else it has sent.
  const bool kept = owner_.edit(store::bit(store::Area::other), "alternate uplink", store::Origin::station,
                                [&](store::Model& m) { m.db.satellites[i].radio = r; }).ok();
  if (!kept) return std::nullopt;
  tuner_.set_uplink(r.uplink_hz);
  return r.uplink_hz;
}

rotator::AzEl StationLoop::point(rotator::AzEl compass) {
  tracker_.stop();
  const rotator::RotatorPosition p = rotator_->set_target(compass, rotator::Controller::Piece::containing);
  wake();
  return rotator::AzEl{rotator_->model().compass_from_travel(p.az_travel), p.el};
}

void StationLoop::apply(const std::vector<Change>& changes) {
  for (const Change& c : changes) {
    spdlog::info("control: the {} is held by {} ({}), was {}", resource_name(c.resource), c.to.label, c.why,
                 c.from.label);
    if (c.resource == Resource::antenna) {
      end_client_follow("the hold ended");
      client_match_.reset();
      client_lead_.reset();
    }
    if (c.to.kind == HolderKind::tracking) {
      // The radio back from a client: the operator's spot, offsets and tone stay (the satellite is
      // not selected again); frequencies, modes and the tone go out afresh.
      if (c.resource == Resource::radio) resend_radio();
      else planned_.reset();
      wake();
    }
    if (control_changed_) control_changed_(c);
  }
}

void StationLoop::stop_antenna() {
  tracker_.stop();
  rotator_->stop();
  wake();
}

void StationLoop::tick() {
  const orbit::UtcTime now = clock_.now();
  apply(control_.tick(now));
  const bool drive_antenna = control_.tracking_drives(Resource::antenna);
  const bool drive_radio = control_.tracking_drives(Resource::radio);
  // A SatNOGS job due within the pre-position time: the antenna goes to its pass's start, whether
  // trakbox tracks or not, unless trakbox's own satellite is up and followed now (the job takes the
  // antenna at its window's start all the same).
  const bool job_first = drive_antenna && (tracker_.mode() == Mode::off || tracker_.last_decision().antenna != Decision::Antenna::point) &&
                         preposition_for_job(now);
  if (tracker_.mode() != Mode::off) remote_follow(std::nullopt);
  if (doppler_ && remote_ && remote_db_ && static_cast<std::size_t>(*remote_db_) < model_.db.satellites.size())
    follow_radio(*remote_db_, remote_->obs);
  if (tracker_.mode() != Mode::off) {
    const Decision d = tracker_.tick();
    const SatNow* followed = tracker_.followed();
    const rotator::PassPlan* plan = nullptr;
    // A satellite's pass of minutes is planned against the rotor stop whole; the Sun's or the Moon's
    // arc of hours is not: it is followed from where it is, and the controller unwinds once where
    // it crosses the stop (a minute lost in a day), inside the limits as any target.
    if (drive_antenna && followed && !body_target(followed->db_index) &&
        (d.antenna == Decision::Antenna::point || d.antenna == Decision::Antenna::preposition))
      plan = plan_for(*followed);
    // While someone else holds the antenna the decision is kept, not applied (the hold suspends).
    switch (drive_antenna && !job_first ? d.antenna : Decision::Antenna::hold) {
      case Decision::Antenna::point:
        if (plan) rotator_->set_target(plan->map_at(now, d.az_deg, std::max(0.0, d.el_deg)));
        else rotator_->set_target(rotator::AzEl{d.az_deg, std::max(0.0, d.el_deg)});
        break;
      case Decision::Antenna::preposition:
        if (plan) rotator_->set_target(plan->aos);
        else rotator_->set_target(rotator::AzEl{d.az_deg, d.el_deg});
        break;
      case Decision::Antenna::park:
        rotator_->park();  // does nothing when parking is off: the antenna stays where it is
        break;
      case Decision::Antenna::hold:
        break;
    }
    // The radio follows the satellite being followed; a body has no radio entry (the Sun's noise
    // needs no tuning; the Moon's echo Doppler is shown by status, the operator tunes for it).
    if (const SatNow* f = tracker_.followed(); f && doppler_ && drive_radio && !body_target(f->db_index))
      follow_radio(f->db_index, f->obs);
  }
  client_keyhole(now);
  unwind_after_pass(now);
  record_pass(now, drive_radio);
  rotator_->tick(now);
}

std::chrono::milliseconds StationLoop::next_tick_in() const {
  auto in = std::min(rotator_->next_tick_in(), std::chrono::milliseconds(1000));
  if (const auto radio = radio_due_in()) in = std::min(in, *radio);   // the other link's move when the knob rests
  return in;
}

std::optional<std::string> StationLoop::coverage_note(int db_index) const {
  if (!planned_ || planned_->db_index != db_index || planned_->plan.coverage.full()) return std::nullopt;
  return planned_->plan.coverage_text();
}

std::optional<rotator::AzEl> StationLoop::antenna() const {
  const auto& s = rotator_->status();
  if (!s.has_position) return std::nullopt;
  return rotator::AzEl{s.az.deg, s.el.deg};
}

StationLoop::Aim StationLoop::aim() const {
  const rotator::Status& rs = rotator_->status();
  std::optional<rotator::AzEl> here;
  if (rs.has_position) here = rotator::AzEl{rs.az.deg, rs.el.deg};
  std::optional<rotator::AzEl> commanded = here;
  if (rs.target) commanded = rotator::AzEl{rotator_->model().compass_from_travel(rs.target->az_travel), rs.target->el};
  if (!control_.tracking_drives(Resource::antenna)) return {commanded, "held"};
  if (tracker_.mode() == Mode::off) return {commanded, rs.target ? "point" : "hold"};
  const Decision& d = tracker_.last_decision();
  switch (d.antenna) {
    case Decision::Antenna::point: return {rotator::AzEl{d.az_deg, d.el_deg}, "point"};
    case Decision::Antenna::preposition: return {rotator::AzEl{d.az_deg, d.el_deg}, "preposition"};
    case Decision::Antenna::park:
      // The parking position itself (the decision's az/el are not where it parks).
      if (rotator_->config().parking_enabled) return {rotator_->config().parking, "park"};
      return {here, "hold"};   // parking off: Controller::park moves nothing
    default: return {here, "hold"};
  }
}

std::string StationLoop::status_line() const {
  const orbit::UtcTime now = clock_.now();
  const auto c = orbit::to_civil(now);
  char buf[256];
  std::string sat = "-";
  if (const SatNow* f = tracker_.followed(); f && tracker_.mode() != Mode::off) {
    char s[64];
    std::snprintf(s, sizeof s, "%s%s", f->name.c_str(), f->in_range ? " AOS" : "");
    sat = s;
  } else if (remote_) {
    char s[96];
    std::snprintf(s, sizeof s, "%s: %s%s", remote_->owner.c_str(), remote_->name.c_str(),
                  remote_->obs.ok() && remote_->obs.look.el_deg >= -2.0 ? " AOS" : "");
    sat = s;
  }
  const auto& rs = rotator_->status();
  std::string rot;
  if (!rs.link.ok()) {
    rot = std::string("FAULT ") + rs.link.message;
  } else if (rs.has_position) {
    char r[64];
    std::snprintf(r, sizeof r, "%5.1f/%4.1f%s", rs.az.deg, rs.el.deg,
                  (rs.az.moving != rotator::Drive::stop || rs.el.moving != rotator::Drive::stop) ? " moving" : "");
    rot = r;
  }
  const radio::RadioStatus radio = radio_->status();
  std::string rig = radio.fault ? "FAULT " + radio.message : "";
  if (!radio.fault) {
    auto mhz = [](std::optional<radio::Hz> hz) {
      char b[24] = "---";
      if (hz) std::snprintf(b, sizeof b, "%.5f", static_cast<double>(*hz) / 1e6);
      return std::string(b);
    };
    rig = "D " + mhz(radio.downlink_hz) + " U " + mhz(radio.uplink_hz);
  }
  std::snprintf(buf, sizeof buf, " %04d/%02d/%02d %02d:%02d:%02d UTC | %s", c.year, c.month, c.day, c.hour, c.minute,
                static_cast<int>(c.second), sat.c_str());
  std::string line = buf;
  // What needs the operator comes before the antenna and radio readings, which are on other
  // screens too: a terminal narrower than the line cuts its end (issue 30). Faults first, in a
  // word each so that they stay within 80 columns; their detail ends the line, and 6-0 and
  // `trakbox status` have it whole (issue 39).
  if (!rs.link.ok()) line += " | ROTOR FAULT";
  if (radio.fault) line += " | RADIO FAULT";
  if (save_failure_) line += " | STATE NOT SAVED";
  if (!notice_.empty()) line += " | " + notice_;
  if (radio.recorder.now != radio::Record::off) line += " | REC";   // the receiver records the pass
  // The drivers by name (issue 30): "Rotor SIM ON ...", "Radio hamlib 3081 D ...", before the longer
  // notes (who holds what, the pass an outside client follows, the GPS, the pass's coverage), so
  // that 100 to 120 columns keep the antenna and the radio (issue 60: they were cut off there).
  std::snprintf(buf, sizeof buf, " | Rotor %s %s %s | Radio %s %s", store::driver_label(model_.rotator_driver).c_str(),
                model_.rotor_control ? "ON " : "OFF", rot.c_str(), store::driver_label(model_.radio_driver).c_str(),
                rig.c_str());
  line += buf;
  if (const std::string held = held_text(control_); !held.empty()) line += " | " + held;
  if (const std::string follows = client_follow_text(); !follows.empty()) line += " | " + follows;
  if (gps_)
    if (const std::string w = gps_->status_word(); !w.empty()) line += " | " + w;
  if (const SatNow* f = tracker_.followed(); f && tracker_.mode() != Mode::off)
    if (const auto note = coverage_note(f->db_index)) line += " | " + *note;
  if (!web_page_url().empty()) line += " | " + web_page_url();
  return line;
}

}  // namespace tb::tracker
