// The station's pass plans and the passes outside clients follow (issue 57): the plan of the pass
// trakbox tracks or a client's targets are recognised to follow, a SatNOGS job's own pass, the
// pre-positioning before a job's window, and the keyhole's schedule run on time for a client.
// Part of StationLoop (station_loop.h); station_loop.cpp has the loop itself.
#include "tracker/station_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orbit/elements.h"
#include "orbit/observe.h"

namespace tb::tracker {

rotator::AzEl StationLoop::point_held(rotator::AzEl compass, std::string_view client, std::string_view kind) {
  const std::optional<rotator::RotatorPosition> planned =
      client.empty() ? std::nullopt : client_plan_target(compass, client, kind);
  if (!planned) client_lead_.reset();
  const rotator::RotatorPosition p = planned ? rotator_->set_target(*planned)
                                             : rotator_->set_target(compass, rotator::Controller::Piece::containing);
  wake();
  return rotator::AzEl{rotator_->model().compass_from_travel(p.az_travel), p.el};
}

std::optional<rotator::RotatorPosition> StationLoop::client_plan_target(rotator::AzEl compass, std::string_view client,
                                                                        std::string_view kind) {
  const orbit::UtcTime now = clock_.now();
  std::vector<SkyPosition> sky;
  for (int i = 0; i < static_cast<int>(model_.db.satellites.size()); ++i)
    if (const auto s = tracker_.observe(i, now); s && s->obs.ok())
      sky.push_back({i, s->name, s->obs.look.az_deg, s->obs.look.el_deg});
  const SkyTarget target = sky_target(compass.az, compass.el);
  // A SatNOGS job's own elements while its window holds: matched first, planned with them.
  const Window* w = control_.window_at(now);
  if (const orbit::Sgp4* job = w && w->kind == "satnogs" ? job_orbit(*w) : nullptr)
    if (const orbit::Observation ob = orbit::observe(*job, model_.station.observer(), now); ob.ok())
      sky.push_back({kJobKey, w->satellite, ob.look.az_deg, ob.look.el_deg, true});
  const auto m = client_match_.feed(client, now, target, sky);
  if (m && m->db_index == kJobKey) return job_plan_target(*w, target, kind);
  const auto s = m ? tracker_.observe(m->db_index, now, true) : std::nullopt;
  if (!s || !s->pass) {
    end_client_follow("no satellite's");
    return std::nullopt;
  }
  const rotator::PassPlan* plan = plan_for(*s);
  if (!plan) return std::nullopt;
  if (m->recognised) {
    client_follow_ = ClientFollow{std::string(kind), s->name, s->pass->los, plan->flip};
    if (m->newly_recognised) spdlog::info("control: {} ({})", client_follow_text(), client);
  } else {
    end_client_follow("another satellite's");
  }
  return client_mapped(s->db_index, *plan, target);
}

rotator::RotatorPosition StationLoop::client_mapped(int key, const rotator::PassPlan& plan, SkyTarget target) {
  const orbit::UtcTime now = clock_.now();
  if (plan.lead.empty()) client_lead_.reset();
  else client_lead_ = ClientLead{key, now};
  return plan.map_at(now, target.az_deg, target.el_deg);
}

void StationLoop::client_keyhole(orbit::UtcTime now) {
  if (!client_lead_ || !planned_ || planned_->db_index != client_lead_->key) return;
  const rotator::PassPlan& plan = planned_->plan;
  // Only while the client keeps sending (a target in the last 10 s) and holds the antenna.
  if (plan.lead.empty() || now < plan.lead.front().time || plan.lead.back().time < now ||
      orbit::minutes_between(client_lead_->at, now) * 60.0 > 10.0 || control_.tracking_drives(Resource::antenna)) {
    if (!plan.lead.empty() && plan.lead.back().time < now) client_lead_.reset();
    return;
  }
  // The satellite's elevation now, from the elements the plan was made with.
  std::optional<orbit::Observation> o;
  if (client_lead_->key == kJobKey) {
    if (job_ && job_->sgp4) o = orbit::observe(*job_->sgp4, model_.station.observer(), now);
  } else if (const auto s = tracker_.observe(client_lead_->key, now, true)) {
    o = s->obs;
  }
  if (!o || !o->ok()) return;
  rotator_->set_target(plan.map_at(now, o->look.az_deg, std::max(0.0, o->look.el_deg)));
}

std::optional<std::string> StationLoop::pass_due(orbit::UtcTime now, orbit::UtcTime until) const {
  const auto hhmm = [](orbit::UtcTime t) {
    const auto c = orbit::to_civil(t);
    return fmt::format("{:02}:{:02}", c.hour, c.minute);
  };
  std::optional<std::pair<orbit::UtcTime, std::string>> first;
  const auto consider = [&](orbit::UtcTime at, const std::string& what) {
    if (at <= until && (!first || at < first->first)) first = std::make_pair(at, what);
  };
  if (tracker_.mode() != Mode::off)
    for (const SatNow& s : tracker_.candidates())
      if (s.pass && s.pass->los > now) consider(std::max(now, s.pass->aos), s.name + "'s pass at " + hhmm(s.pass->aos));
  for (const Window& w : control_.windows())
    if (w.end > now) consider(std::max(now, w.start), (w.kind == "satnogs" ? "SatNOGS job " + w.id : "the window") +
                                                          " at " + hhmm(w.start));
  if (!first) return std::nullopt;
  return first->second;
}

void StationLoop::unwind_after_pass(orbit::UtcTime now) {
  if (!unwind_after_ || now < orbit::add_seconds(*unwind_after_, 30.0)) return;
  // A client still holding the antenna: later, when it is trakbox's again.
  if (!control_.tracking_drives(Resource::antenna)) return;
  const auto& st = rotator_->status();
  if (!st.has_position || !rotator_->control_enabled()) return;
  const Decision::Antenna d = tracker_.mode() == Mode::off ? Decision::Antenna::hold : tracker_.last_decision().antenna;
  const auto back = rotator_->model().unwound_travel(st.az.travel);
  if (!back || d == Decision::Antenna::point || d == Decision::Antenna::preposition || d == Decision::Antenna::park) {
    unwind_after_.reset();  // not wound, or tracking (or parking) has it: that decides where it goes
    return;
  }
  unwind_after_.reset();
  if (const auto due = pass_due(now, orbit::add_minutes(now, kUnwindClearMinutes))) {
    spdlog::info("antenna: left at travel {:.1f}, a turn from the stop: {} is due, its plan takes it from there",
                 st.az.travel, *due);
    return;
  }
  spdlog::info("antenna: unwinding after the pass: travel {:.1f} -> {:.1f} (azimuth {:.1f}; no pass due in {:.0f} minutes)",
               st.az.travel, *back, st.az.deg, kUnwindClearMinutes);
  rotator_->set_target(rotator::RotatorPosition{*back, st.el.deg});
  wake();
}

const orbit::Sgp4* StationLoop::job_orbit(const Window& w) {
  if (w.tle1.empty() || w.tle2.empty()) return nullptr;
  if (job_ && job_->id == w.id) return job_->sgp4.get();
  job_ = JobOrbit{w.id, nullptr};
  const auto read = orbit::parse_nasa(w.satellite + "\n" + w.tle1 + "\n" + w.tle2 + "\n", "SatNOGS job " + w.id);
  if (read.sets.size() == 1) job_->sgp4 = std::make_unique<orbit::Sgp4>(read.sets[0]);
  else spdlog::warn("control: SatNOGS job {}'s elements (tle1, tle2) do not read: its pass is not planned", w.id);
  return job_->sgp4.get();
}

bool StationLoop::preposition_for_job(orbit::UtcTime now) {
  const Window* next = nullptr;
  for (const Window& w : control_.windows())  // in start order
    if (w.kind == "satnogs" && w.start > now) {
      next = &w;
      break;
    }
  if (!next || orbit::minutes_between(now, next->start) > Tracker::kPrepositionMinutes) return false;
  const orbit::Sgp4* job = job_orbit(*next);
  if (!job) return false;
  const orbit::Observer here = model_.station.observer();
  orbit::PassOptions po;
  po.precision_s = 1.0;
  po.mask = model_.station.mask();  // the job's pass above the horizon mask: the plan starts out of it
  const auto pass = tracker_.passes().get(
      job->elements(), here, now, [&] { return orbit::next_pass(*job, here, now, 1.0, po); }, "satnogs job", po);
  // The job's pass: the one its window opens in (a window is its pass, a little inside it).
  if (!pass || pass->los < next->start || orbit::minutes_between(next->end, pass->aos) > 0.0) return false;
  const rotator::PassPlan* plan = plan_of(kJobKey, next->satellite, *pass, [&](orbit::UtcTime t) {
    return std::optional<orbit::Observation>(orbit::observe(*job, here, t));
  });
  if (!plan) return false;
  if (prepositioned_ != next->id)
    spdlog::info("antenna: to the start of SatNOGS job {}'s {} pass (travel {:.1f}, el {:.1f}) before its window "
                 "at {}", next->id, next->satellite, plan->aos.az_travel, plan->aos.el,
                 orbit::format_iso8601(next->start));
  prepositioned_ = next->id;
  rotator_->set_target(plan->aos);
  return true;
}

std::optional<rotator::RotatorPosition> StationLoop::job_plan_target(const Window& w, SkyTarget target,
                                                                     std::string_view kind) {
  const orbit::Sgp4& job = *job_->sgp4;
  const orbit::Observer here = model_.station.observer();
  const orbit::UtcTime now = clock_.now();
  orbit::PassOptions po;
  po.precision_s = 1.0;
  po.mask = model_.station.mask();  // the job's pass above the horizon mask: the plan starts out of it
  // The station's one pass cache, under the job's elements.
  const auto pass = tracker_.passes().get(
      job.elements(), here, now, [&] { return orbit::next_pass(job, here, now, 1.0, po); }, "satnogs job", po);
  if (!pass || now > pass->los) {
    end_client_follow("no pass of the job's");
    return std::nullopt;
  }
  const rotator::PassPlan* plan = plan_of(kJobKey, w.satellite, *pass, [&](orbit::UtcTime t) {
    return std::optional<orbit::Observation>(orbit::observe(job, here, t));
  });
  if (client_match_.current() && client_match_.current()->recognised) {
    const bool said = client_follow_ && client_follow_->name == w.satellite;
    client_follow_ = ClientFollow{std::string(kind), w.satellite, pass->los, plan->flip};
    if (!said)
      spdlog::info("control: {} (SatNOGS job {}'s elements)", client_follow_text(), w.id);
  }
  return client_mapped(kJobKey, *plan, target);
}

// why: what the targets now are ("no satellite's", "another satellite's") or "the hold ended".
void StationLoop::end_client_follow(std::string_view why) {
  if (client_follow_)
    spdlog::info("control: {}'s targets no longer follow {}'s pass ({}): the way nearest the antenna",
                 client_follow_->kind, client_follow_->name, why);
  client_follow_.reset();
}

std::string StationLoop::client_follow_text() const {
  if (!client_follow_) return "";
  const auto c = orbit::to_civil(client_follow_->los);
  return fmt::format("following {}'s targets on the planned way round{} for {} (pass to {:02}:{:02})",
                     client_follow_->kind, client_follow_->flip ? ", over the top," : "", client_follow_->name,
                     c.hour, c.minute);
}

const rotator::PassPlan* StationLoop::plan_for(const SatNow& s) {
  if (!s.pass) return nullptr;
  return plan_of(s.db_index, s.name, *s.pass, [&](orbit::UtcTime t) -> std::optional<orbit::Observation> {
    const auto p = tracker_.observe(s.db_index, t);
    if (!p) return std::nullopt;
    return p->obs;
  });
}

const rotator::PassPlan* StationLoop::plan_of(int key, const std::string& name, const orbit::Pass& pass,
                                              const Look& look) {
  unwind_after_ = pass.los;
  if (planned_ && planned_->db_index == key && planned_->aos == pass.aos) return &planned_->plan;
  // Sample the whole pass (AOS to LOS) and let the rotator plan it against its stop.
  std::vector<rotator::TrackPoint> track;
  for (const orbit::UtcTime t : rotator::pass_sample_times(pass.aos, pass.tca, pass.los)) {
    const auto o = look(t);
    if (!o || !o->ok()) break;
    track.push_back({t, o->look.az_deg, std::max(0.0, o->look.el_deg)});
  }
  const auto& st = rotator_->status();
  const std::optional<double> travel = st.has_position ? std::optional(st.az.travel) : std::nullopt;
  // Limits that split the travel and may be crossed: the planner may choose the other piece only
  // between passes (this one has not begun); the antenna crosses while it pre-positions.
  const bool before_aos = clock_.now() < pass.aos;
  const auto g = rotator::PassGeometry::from(rotator_->model(), before_aos, model_.pass_events.rotor_start_el_deg);
  planned_ = PlannedPass{key, pass.aos, rotator::plan_pass(track, g, travel)};
  if (planned_->plan.geometry.piece != rotator_->model().az_piece())
    rotator_->select_az_piece(planned_->plan.geometry.piece);
  if (const rotator::PassPlan& p = planned_->plan; p.over_top)
    spdlog::info("tracker: {} pass at {}: over the top in the plane of azimuth {:.1f} (its azimuth turns {:.1f} "
                 "deg/s near the zenith, the motor {:.1f}): at most {:.1f} deg off",
                 name, orbit::format_iso8601(pass.aos), p.plane_az, p.peak_az_rate_deg_s, g.az_rate_deg_s,
                 p.max_error_deg);
  if (const std::string k = planned_->plan.keyhole_text(); !k.empty())
    spdlog::info("tracker: {} pass at {}: {} (its azimuth turns {:.1f} deg/s near the culmination, the motor {:.1f})",
                 name, orbit::format_iso8601(pass.aos), k, planned_->plan.peak_az_rate_deg_s, g.az_rate_deg_s);
  if (!planned_->plan.coverage.full()) {
    const std::string what =
        name + " pass at " + orbit::format_iso8601(pass.aos) + ": " + planned_->plan.coverage_text();
    if (planned_->plan.coverage.followed == 0)
      spdlog::warn("tracker: {}", what);
    else
      spdlog::info("tracker: {}", what);
  }
  return &planned_->plan;
}

}  // namespace tb::tracker
