// The Satrak unit's tracking: the auto-tracking window, pre-positioning, following the satellite
// with the offsets applied, the SSPA, and the periodic check that drives them all.
#include <algorithm>

#include <spdlog/spdlog.h>

#include "satrak/unit.h"
#include "satrak/unit_internal.h"

namespace tb::satrak {
using namespace detail;
using rotator::AzEl;
using rotator::RotatorPosition;

AzEl Unit::adjusted(double az, double el) const {
  return AzEl{rotator::wrap360(az + s_.az_offset_deg - s_.north_offset_deg), std::max(el + s_.el_offset_deg, min_el())};
}

std::optional<orbit::Observation> Unit::observe(orbit::UtcTime t) const {
  if (!sgp4_) return std::nullopt;
  orbit::Observation o = orbit::observe(*sgp4_, model_.station.observer(), t);
  if (!o.ok()) return std::nullopt;
  return o;
}

const orbit::Pass* Unit::pass_at(orbit::UtcTime t) {
  if (!sgp4_ || !elements_) return nullptr;
  // The station's one pass cache (tracker/pass_memo.h): searched again when the station moves,
  // these elements change, the threshold changes (part of the key), the pass sets or the clock
  // goes back; the same rules as the tracker's, the events' and the page's.
  orbit::PassOptions po;
  po.horizon_deg = s_.el_threshold_deg;
  po.precision_s = 1.0;
  po.mask = model_.station.mask();  // above the station's horizon mask where it is higher (issue 57)
  const orbit::Observer where = model_.station.observer();
  const orbit::Sgp4& sgp4 = *sgp4_;
  pass_ = station_.tracker().passes().get(
      *elements_, where, t, [&] { return orbit::next_pass(sgp4, where, t, kPassSearchDays, po); }, "satrak", po);
  return pass_ && t <= pass_->los ? &*pass_ : nullptr;
}

const rotator::PassPlan* Unit::plan_for(const orbit::Pass& p) {
  if (plan_cache_ && plan_cache_->aos == p.aos && plan_cache_->generation == pointing_generation_) return &plan_cache_->plan;
  std::vector<rotator::TrackPoint> track;
  for (const orbit::UtcTime t : rotator::pass_sample_times(p.aos, p.tca, p.los)) {
    const auto o = observe(t);
    if (!o) break;
    const AzEl a = adjusted(o->look.az_deg, std::max(o->look.el_deg, s_.el_threshold_deg));
    track.push_back({t, a.az, a.el});
  }
  const auto& st = station_.rotator().status();
  const std::optional<double> travel = st.has_position ? std::optional(st.az.travel) : std::nullopt;
  plan_cache_ = PlanCache{p.aos, pointing_generation_,
                          rotator::plan_pass(track, rotator::PassGeometry::from(station_.rotator().model()), travel)};
  return &plan_cache_->plan;
}

void Unit::pointing_changed() {
  ++pointing_generation_;
  plan_cache_.reset();
}

bool Unit::start_tracking() {
  if (take_antenna()) return false;  // standby, or another's exclusive hold: said in the log
  move_.reset();
  tracking_ = true;
  tracking_stopped_fault_ = false;
  owner_ = Owner::track;
  // Whatever moved the antenna before stops; tracking commands it from here.
  station_.rotator().stop();
  commanded_.reset();
  track(clock_.now());
  return true;
}

void Unit::stop_tracking(bool fault) {
  const bool was = tracking_;
  tracking_ = false;
  auto_started_ = false;
  last_track_target_.reset();
  if (fault && was) tracking_stopped_fault_ = true;
  if (was) station_.remote_follow(std::nullopt);
  if (owner_ == Owner::track) {
    station_.rotator().stop();
    release();
  }
}

void Unit::track(orbit::UtcTime now) {
  if (!sgp4_) {
    spdlog::warn("satrak: tracking stopped: no element set");
    stop_tracking(true);
    return;
  }
  const orbit::UtcTime t = now + std::chrono::milliseconds(s_.time_offset_ms);
  const auto o = observe(t);
  if (!o) {
    spdlog::warn("satrak: tracking stopped: {} cannot be propagated (decayed?)", elements_ ? elements_->label() : "?");
    stop_tracking(true);
    return;
  }
  // The station keeps the radio on this satellite and names it on the status line.
  station_.control().heard(holder_, station_.now());  // its TRACK is the client's hold going on
  station_.remote_follow(tracker::StationLoop::RemoteFollow{"Satrak", elements_->label(), elements_->catalog_number, *o});
  const orbit::Pass* p = pass_at(t);
  if (o->look.el_deg >= s_.el_threshold_deg) {
    const AzEl a = adjusted(o->look.az_deg, o->look.el_deg);
    last_track_target_ = a;
    const rotator::PassPlan* plan = (p && p->aos <= t) ? plan_for(*p) : nullptr;
    if (plan) {
      command(plan->map_at(t, a.az, a.el));
    } else {
      const auto& st = station_.rotator().status();
      command(station_.rotator().model().target_for(a, st.has_position ? st.az.travel : current_position().az_travel));
    }
    return;
  }
  last_track_target_.reset();
  // Below the threshold: wait, and go to the start of the next pass `go to start before` ahead.
  if (p && p->aos > t && s_.go_to_start_before_ms > 0 &&
      seconds_between(t, p->aos) * 1000.0 <= static_cast<double>(s_.go_to_start_before_ms)) {
    command(plan_for(*p)->aos);
  }
}

TrackStatus Unit::track_status() const {
  if (!s_.window) return TrackStatus::not_in_track_time;
  const orbit::UtcTime now = clock_.now();
  if (now >= s_.window->stop) return TrackStatus::completed;
  if (now >= s_.window->start) return TrackStatus::in_track_time;
  if (s_.go_to_start_before_ms > 0 && now >= s_.window->start - std::chrono::milliseconds(s_.go_to_start_before_ms))
    return TrackStatus::start_before;
  return TrackStatus::not_in_track_time;
}

void Unit::preposition(orbit::UtcTime start) {
  const orbit::UtcTime t = start + std::chrono::milliseconds(s_.time_offset_ms);
  const auto o = observe(t);
  if (!o) return;
  const orbit::Pass* p = pass_at(t);
  const auto& st = station_.rotator().status();
  const double travel = st.has_position ? st.az.travel : current_position().az_travel;
  if (o->look.el_deg >= s_.el_threshold_deg) {
    const AzEl a = adjusted(o->look.az_deg, o->look.el_deg);
    const rotator::PassPlan* plan = (p && p->aos <= t) ? plan_for(*p) : nullptr;
    command(plan ? plan->map_at(t, a.az, a.el) : station_.rotator().model().target_for(a, travel));
  } else if (p && s_.window && p->aos < s_.window->stop + std::chrono::milliseconds(s_.time_offset_ms)) {
    command(plan_for(*p)->aos);
  } else {
    command(station_.rotator().model().target_for(adjusted(o->look.az_deg, o->look.el_deg), travel));
  }
}

void Unit::update_window(orbit::UtcTime) {
  const TrackStatus st = track_status();
  if (auto_started_ && st != TrackStatus::in_track_time) {
    spdlog::info("satrak: track window over: tracking stopped");
    stop_tracking(false);
  }
  if (!s_.auto_track || !s_.window) return;
  switch (st) {
    case TrackStatus::start_before:
      if (tracking_ || window_started_ || !sgp4_) break;
      if (!window_prepositioned_) {
        window_prepositioned_ = true;
        if (take_antenna()) break;  // standby, or another's exclusive hold: the antenna stays
        move_.reset();
        station_.rotator().stop();
        commanded_.reset();
        owner_ = Owner::track;
        spdlog::info("satrak: going to the start position of the track window");
      }
      if (owner_ == Owner::track) preposition(s_.window->start);
      break;
    case TrackStatus::in_track_time:
      if (window_started_) break;
      window_started_ = true;
      if (tracking_) break;  // already tracking (TRACK=,1): the window takes nothing over
      if (!sgp4_) {
        tracking_stopped_fault_ = true;
        spdlog::warn("satrak: track window open but no satellite to track");
        break;
      }
      spdlog::info("satrak: track window open: tracking {}", elements_->label());
      auto_started_ = start_tracking();
      break;
    default: break;
  }
}

bool Unit::sspa_on() const {
  switch (s_.sspa_manual) {
    case 0: return false;
    case 1: return true;
    default: break;
  }
  const bool tracking = tracking_;
  bool carrier = false;  // stand-in for carrier lock: the satellite is at or above the threshold
  if (const auto o = observe(clock_.now() + std::chrono::milliseconds(s_.time_offset_ms)))
    carrier = o->look.el_deg >= s_.el_threshold_deg;
  switch (s_.sspa_auto_option) {
    case 0: return tracking;
    case 1: return carrier;
    case 2: return tracking && carrier;
    default: return tracking || carrier;
  }
}

void Unit::tick() {
  const orbit::UtcTime now = clock_.now();
  if (station_.position_generation() != position_generation_seen_) {  // the station moved (GPS, menu 4)
    position_generation_seen_ = station_.position_generation();
    plan_cache_.reset();  // the pass cache searches the new place's pass by itself
  }
  // SETTINGS X1: the RTC follows GPS time by itself when the receiver has a fix and they differ.
  if (s_.rtc_auto_update && station_.gps() && station_.gps()->clock_warned() && update_rtc_from_gps()) changed();
  check_takeover();
  update_window(now);
  if (tracking_) track(now);
  check_file(now);
  schedule_download(now);
  if (const bool sspa = sspa_on(); sspa_last_ != sspa) {
    if (sspa_last_) spdlog::info("satrak: SSPA {}", sspa ? "on" : "off");
    sspa_last_ = sspa;
  }
}
}  // namespace tb::satrak
