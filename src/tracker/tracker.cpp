#include "tracker/tracker.h"

#include <algorithm>

namespace tb::tracker {
namespace {

bool same_elements(const orbit::Elements& a, const orbit::Elements& b) {
  return a.catalog_number == b.catalog_number && a.epoch_year == b.epoch_year && a.epoch_day == b.epoch_day &&
         a.ndot_over_2 == b.ndot_over_2 && a.nddot_over_6 == b.nddot_over_6 && a.bstar == b.bstar &&
         a.inclination_deg == b.inclination_deg && a.raan_deg == b.raan_deg && a.eccentricity == b.eccentricity &&
         a.arg_perigee_deg == b.arg_perigee_deg && a.mean_anomaly_deg == b.mean_anomaly_deg &&
         a.mean_motion_rev_per_day == b.mean_motion_rev_per_day;
}

constexpr double kPassSearchDays = 1.0;

}  // namespace

std::optional<orbit::Body> body_target(int index) {
  if (index == kSunTarget) return orbit::Body::sun;
  if (index == kMoonTarget) return orbit::Body::moon;
  return std::nullopt;
}

int target_index(orbit::Body b) { return b == orbit::Body::sun ? kSunTarget : kMoonTarget; }

bool Tracker::known(int index) const {
  return body_target(index) || (index >= 0 && index < static_cast<int>(model_.db.satellites.size()));
}

std::optional<std::size_t> choose_multi(const std::vector<bool>& in_range, std::optional<std::size_t> current,
                                        bool priority) {
  if (!priority && current && *current < in_range.size() && in_range[*current]) return current;
  for (std::size_t i = 0; i < in_range.size(); ++i)
    if (in_range[i]) return i;
  return std::nullopt;
}

Tracker::Tracker(const store::Model& model, const station::Clock& clock) : model_(model), clock_(clock) {}

void Tracker::track_single(int db_index) {
  mode_ = Mode::single;
  single_ = db_index;
  current_.reset();
  if (on_choice_) on_choice_();
}

void Tracker::track_multi(bool priority) {
  mode_ = Mode::multi;
  priority_ = priority;
  current_.reset();
  if (on_choice_) on_choice_();
}

void Tracker::stop() {
  mode_ = Mode::off;
  current_.reset();
  candidates_.clear();
}

Tracker::Cached& Tracker::cached(int db_index) const {
  const auto& e = model_.db.satellites[static_cast<std::size_t>(db_index)].elements;
  Cached& c = cache_[db_index];
  if (!c.sgp4 || !same_elements(c.elements, e)) {
    c.elements = e;
    c.sgp4 = std::make_unique<orbit::Sgp4>(e);  // the pass cache sees the new elements too
  }
  return c;
}

const orbit::Sgp4* Tracker::propagator(int db_index) const {
  if (db_index < 0 || db_index >= static_cast<int>(model_.db.satellites.size())) return nullptr;
  return cached(db_index).sgp4.get();
}

SatNow Tracker::compute_body(orbit::Body b, orbit::UtcTime t, bool with_pass) const {
  SatNow s;
  const orbit::Observer obs = model_.station.observer();
  s.db_index = target_index(b);
  s.name = std::string(orbit::body_name(b));
  s.obs.time = t;
  s.obs.look = orbit::body_look(b, obs, t);
  s.in_range = s.obs.look.el_deg >= horizon_at(s.obs.look.az_deg);  // above the horizon mask too (issue 57)
  if (with_pass) {
    // The one pass cache, keyed by an element set that names the body (catalog number = its index)
    // and never changes: the body's rise and set are searched again when the station moves, the
    // body has set or the clock goes back.
    orbit::Elements key;
    key.catalog_number = s.db_index;
    key.name = s.name;
    orbit::PassOptions po;
    po.precision_s = 1.0;
    po.mask = model_.station.mask();  // rise and set above the horizon mask, as a satellite's
    const auto pass = passes_.get(
        key, obs, t, [&] { return orbit::next_body_pass(b, obs, t, kPassSearchDays + 1.0, po); }, "tracker", po);
    if (pass && t <= pass->los) s.pass = pass;
  }
  return s;
}

SatNow Tracker::compute(int db_index, orbit::UtcTime t, bool with_pass) const {
  if (const auto b = body_target(db_index)) return compute_body(*b, t, with_pass);
  SatNow s;
  const auto& sat = model_.db.satellites[static_cast<std::size_t>(db_index)];
  Cached& c = cached(db_index);
  const orbit::Observer obs = model_.station.observer();
  s.db_index = db_index;
  s.list_number = model_.db.list_number(db_index);
  s.name = sat.name();
  s.obs = orbit::observe(*c.sgp4, obs, t);
  // Up: above the AOS rule and the station's horizon mask there.
  s.in_range = s.obs.ok() && s.obs.look.el_deg >= horizon_at(s.obs.look.az_deg);
  if (s.obs.ok() && sat.radio.has_downlink())
    s.downlink_doppler_hz =
        orbit::doppler_shift_hz(static_cast<double>(sat.radio.downlink_hz), s.obs.look.range_rate_km_s);
  if (with_pass && s.obs.ok()) {
    // The station's one pass cache (pass_memo.h): searched again when the elements change, the
    // station moves, the pass has set or the clock goes back.
    orbit::PassOptions po;
    po.precision_s = 1.0;
    po.mask = model_.station.mask();
    const orbit::Sgp4& sgp4 = *c.sgp4;
    const auto pass = passes_.get(
        sat.elements, obs, t, [&] { return orbit::next_pass(sgp4, obs, t, kPassSearchDays, po); }, "tracker", po);
    if (pass && t <= pass->los) s.pass = pass;
  }
  return s;
}

std::vector<orbit::Observation> Tracker::track(int db_index, orbit::UtcTime from, double minutes,
                                              int intervals) const {
  std::vector<orbit::Observation> out;
  if (intervals < 1 || !(minutes > 0.0)) return out;
  for (int k = 0; k <= intervals; ++k)
    if (const auto n = observe(db_index, orbit::add_minutes(from, minutes * k / intervals)); n && n->obs.ok())
      out.push_back(n->obs);
  return out;
}

std::vector<orbit::Observation> Tracker::orbit_track(int db_index, orbit::UtcTime from, int intervals) const {
  const orbit::Sgp4* sgp4 = propagator(db_index);
  if (!sgp4 || !sgp4->propagate(from).ok()) return {};
  return track(db_index, from, sgp4->period_minutes(), intervals);
}

std::vector<orbit::Observation> Tracker::pass_track(int db_index, const orbit::Pass& pass, int intervals) const {
  return track(db_index, pass.aos, orbit::minutes_between(pass.aos, pass.los), intervals);
}

std::optional<SatNow> Tracker::observe(int db_index, orbit::UtcTime t, bool with_pass) const {
  if (!known(db_index)) return std::nullopt;
  return compute(db_index, t, with_pass);
}

double Tracker::horizon_at(double az_deg) const {
  orbit::PassOptions po;
  po.mask = model_.station.mask();
  return orbit::horizon_at(po, az_deg);
}

std::optional<orbit::Pass> Tracker::pass_at(int db_index, orbit::UtcTime t) const {
  orbit::PassOptions po;
  po.precision_s = 1.0;
  if (const auto b = body_target(db_index)) {
    po.mask = model_.station.mask();
    // A body's pass lasts hours: searched from 18 hours before, the one overlapping t kept.
    const orbit::Observer where = model_.station.observer();
    for (const orbit::Pass& p : orbit::find_body_passes(*b, where, orbit::add_minutes(t, -18 * 60.0),
                                                        orbit::add_minutes(t, 42 * 60.0), po))
      if (p.los >= t) return p;
    return std::nullopt;
  }
  if (db_index < 0 || db_index >= static_cast<int>(model_.db.satellites.size())) return std::nullopt;
  const orbit::Sgp4& sgp4 = *cached(db_index).sgp4;
  // From half an hour before, so that a pass in progress at t is found from its AOS (a low orbit's
  // pass is shorter); one that ended before t is passed over. A pass still up at the start of that
  // search (a high orbit's, hours long) is searched again from 6 hours and then a day before; one
  // up even then (geostationary) is left as the half-hour search found it.
  const auto search = [&](double back_minutes) -> std::optional<orbit::Pass> {
    orbit::UtcTime from = orbit::add_minutes(t, -back_minutes);
    for (int k = 0; k < 32; ++k) {
      auto p = orbit::next_pass(sgp4, model_.station.observer(), from, kPassSearchDays, po);
      if (!p || p->los >= t) return p;
      from = orbit::add_minutes(p->los, 1.0 / 60.0);
    }
    return std::nullopt;
  };
  po.mask = model_.station.mask();
  const std::optional<orbit::Pass> near = search(30.0);
  if (!near || !near->up_at_start || near->up_at_end) return near;
  for (const double back : {360.0, 1440.0})
    if (auto p = search(back); p && !p->up_at_start) return p;
  return near;
}

const SatNow* Tracker::followed() const {
  if (!decision_.followed) return nullptr;
  for (const auto& c : candidates_)
    if (c.db_index == *decision_.followed) return &c;
  return nullptr;
}

Decision Tracker::tick() {
  const orbit::UtcTime t = clock_.now();
  last_time_ = t;
  candidates_.clear();
  Decision d;
  const int n_db = static_cast<int>(model_.db.satellites.size());

  if (mode_ == Mode::single && known(single_)) {
    candidates_.push_back(compute(single_, t, true));
    d.followed = single_;
  } else if (mode_ == Mode::multi) {
    const int n = std::min<int>(model_.db.multi_count, static_cast<int>(model_.db.selected.size()));
    std::vector<bool> up;
    std::optional<std::size_t> cur;
    for (int k = 0; k < n; ++k) {
      const int i = model_.db.selected[static_cast<std::size_t>(k)];
      if (i < 0 || i >= n_db) continue;
      candidates_.push_back(compute(i, t, true));
      up.push_back(candidates_.back().in_range);
      if (current_ && *current_ == i) cur = candidates_.size() - 1;
    }
    if (const auto pick = choose_multi(up, cur, priority_)) {
      d.followed = candidates_[*pick].db_index;
      current_ = d.followed;
    } else {
      current_.reset();
    }
  }

  const SatNow* f = nullptr;
  for (const auto& c : candidates_)
    if (d.followed && c.db_index == *d.followed) f = &c;

  // The rotor follows above the rotor start elevation (the later firmware's STATION.DAT line 5;
  // factory -2.0, the AOS rule). Up but below it, the antenna waits where the pass rises while the
  // satellite climbs, and stays where it is once it sets.
  const double rotor_start_el = model_.pass_events.rotor_start_el_deg;
  if (f && f->in_range && f->obs.look.el_deg >= std::max(rotor_start_el, horizon_at(f->obs.look.az_deg))) {
    d.antenna = Decision::Antenna::point;
    d.az_deg = f->obs.look.az_deg;
    d.el_deg = f->obs.look.el_deg;
  } else if (f && f->in_range) {
    if (f->pass && t < f->pass->tca) {
      d.antenna = Decision::Antenna::preposition;
      d.az_deg = f->pass->aos_az_deg;
      d.el_deg = std::max(0.0, horizon_at(d.az_deg));  // never into the horizon mask
    }
  } else {
    // Nobody up: move ahead of time to the soonest AOS among the candidates, else park.
    const SatNow* next = nullptr;
    for (const auto& c : candidates_) {
      if (mode_ == Mode::single && d.followed && c.db_index != *d.followed) continue;
      if (!c.pass || c.pass->aos < t) continue;
      if (orbit::minutes_between(t, c.pass->aos) > kPrepositionMinutes) continue;
      if (!next || c.pass->aos < next->pass->aos) next = &c;
    }
    if (next) {
      d.antenna = Decision::Antenna::preposition;
      d.az_deg = next->pass->aos_az_deg;
      d.el_deg = std::max(0.0, horizon_at(d.az_deg));  // never into the horizon mask
      if (mode_ == Mode::multi) d.followed = next->db_index;
    } else if (mode_ != Mode::off) {
      d.antenna = Decision::Antenna::park;
    }
  }
  decision_ = d;
  return d;
}

}  // namespace tb::tracker
