#include "gps/monitor.h"

#include <cmath>
#include <cstdio>

namespace tb::gps {

namespace {
constexpr double kEarthRadiusM = 6371008.8;  // IUGG mean radius
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

std::string fixed_text(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string lat_lon(double lat, double lon) {
  return fixed_text("%.4f", std::abs(lat)) + (lat < 0 ? "S " : "N ") + fixed_text("%.4f", std::abs(lon)) +
         (lon < 0 ? "W" : "E");
}
std::string where(const Position& p) {
  return lat_lon(p.lat_deg, p.lon_deg) + (p.alt_m ? " " + fixed_text("%.1f", *p.alt_m) + " m" : std::string(" (2D)"));
}
double seconds(orbit::UtcTime a, orbit::UtcTime b) {
  return std::chrono::duration<double>(a - b).count();
}
}  // namespace

double distance_m(double lat1_deg, double lon1_deg, double lat2_deg, double lon2_deg) {
  const double p1 = lat1_deg * kDegToRad, p2 = lat2_deg * kDegToRad;
  const double dp = p2 - p1, dl = (lon2_deg - lon1_deg) * kDegToRad;
  const double a = std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * kEarthRadiusM * std::asin(std::min(1.0, std::sqrt(a)));
}

std::optional<std::string> nonsense(const Report& r) {
  auto outside = [](const char* what, double v, double lo, double hi) -> std::optional<std::string> {
    if (std::isfinite(v) && v >= lo && v <= hi) return std::nullopt;
    return std::string(what) + " " + fixed_text("%.6f", v) + " is outside " + fixed_text("%g", lo) + ".." +
           fixed_text("%g", hi);
  };
  if (r.lat_deg)
    if (auto w = outside("latitude", *r.lat_deg, -90.0, 90.0)) return w;
  if (r.lon_deg)
    if (auto w = outside("longitude", *r.lon_deg, -180.0, 180.0)) return w;
  if (r.alt_m && r.mode >= 3)
    if (auto w = outside("altitude", *r.alt_m, kMinAltitudeM, kMaxAltitudeM)) return w;
  return std::nullopt;
}

bool PositionFilter::reachable(const Position& from, const Position& to) {
  const double dt = std::abs(seconds(to.time, from.time));
  return distance_m(from.lat_deg, from.lon_deg, to.lat_deg, to.lon_deg) <= kNoiseM + kMaxSpeedMps * dt;
}

PositionFilter::Result PositionFilter::add(const Report& r, orbit::UtcTime clock_now) {
  if (r.mode >= 2 && (!r.lat_deg || !r.lon_deg)) {
    // gpsd leaves out what it could not take (a latitude of 95 degrees): a fix without a position.
    if (main_) main_->run = 0;
    return {Verdict::nonsense, std::string("a ") + (r.mode >= 3 ? "3D" : "2D") + " fix without a " +
                                   (r.lat_deg ? "longitude" : "latitude") + " (gpsd left out a value it could not take)"};
  }
  if (r.mode < 2) {
    fixed_ = false;
    if (main_) main_->run = 0;
    other_.reset();
    return {Verdict::no_fix, {}};
  }
  if (auto why = nonsense(r)) {
    if (main_) main_->run = 0;  // a receiver that says nonsense confirms nothing until it stops
    return {Verdict::nonsense, *why};
  }
  const Position p{*r.lat_deg, *r.lon_deg, r.mode >= 3 ? r.alt_m : std::nullopt, r.time.value_or(clock_now), r.mode};
  if (!main_) {
    main_ = Chain{p, 1};
  } else if (reachable(main_->last, p)) {
    main_->last = p;
    ++main_->run;
    other_.reset();
  } else if (other_ && reachable(other_->last, p)) {
    other_->last = p;
    if (++other_->run < kConfirmReports) return {Verdict::confirming, {}};
    main_ = other_;
    other_.reset();
    confirmed_ = p;
    fixed_ = true;
    return {Verdict::jump_taken, {}};
  } else {
    const double d = distance_m(main_->last.lat_deg, main_->last.lon_deg, p.lat_deg, p.lon_deg);
    const double dt = std::abs(seconds(p.time, main_->last.time));
    other_ = Chain{p, 1};
    return {Verdict::jump, fixed_text("%.1f", d / 1000.0) + " km in " + fixed_text("%.1f", dt) + " s"};
  }
  if (main_->run < kConfirmReports) return {Verdict::confirming, {}};
  confirmed_ = p;
  fixed_ = true;
  return {Verdict::confirmed, {}};
}

std::vector<Note> Monitor::on_link(Link l, const std::string& detail) {
  std::vector<Note> notes;
  if (l == link_ && detail == link_detail_) return notes;
  const Link before = link_;
  link_ = l;
  link_detail_ = detail;
  if (l != Link::receiving) filter_.lose();  // confirmed again once it is heard again
  const std::string at = "gpsd at " + source_.substr(source_.find(':') + 1);
  const std::string why = detail.empty() ? std::string() : " (" + detail + ")";
  switch (l) {
    case Link::off:
    case Link::connecting:
      break;
    case Link::no_gpsd:
      // Said once: again and again while it stays away, and not after "went away".
      if (before != Link::no_gpsd && before != Link::lost)
        notes.push_back({true, "GPS: no " + at + why + "; the station keeps its position; trying again every 2 s"});
      break;
    case Link::lost:
      notes.push_back({true, "GPS: " + at + " went away" + why + "; the station keeps its position; trying again"});
      break;
    case Link::no_receiver:
      notes.push_back({true, "GPS: " + at + " has no receiver; the station keeps its position"});
      break;
    case Link::receiving:
      notes.push_back({false, "GPS: connected to " + at});
      break;
  }
  return notes;
}

std::vector<Note> Monitor::on_devices(int count) {
  if (count > 0) {
    if (link_ == Link::no_receiver) {
      link_ = Link::receiving;
      return {{false, "GPS: gpsd has a receiver again"}};
    }
    return {};
  }
  if (link_ == Link::no_receiver) return {};
  return on_link(Link::no_receiver);
}

std::vector<Note> Monitor::on_report(const Report& r, orbit::UtcTime clock_now) {
  std::vector<Note> notes;
  if (link_ != Link::receiving) {
    auto more = on_devices(1);
    if (link_ != Link::receiving) more = on_link(Link::receiving);
    notes.insert(notes.end(), more.begin(), more.end());
  }
  last_ = r;
  const bool was_fixed = filter_.fixed();
  const PositionFilter::Result res = filter_.add(r, clock_now);
  using V = PositionFilter::Verdict;
  if (res.verdict != V::nonsense) nonsense_said_ = false;
  switch (res.verdict) {
    case V::no_fix:
      if (was_fixed) {
        notes.push_back({true, "GPS: fix lost; the station keeps " + where(*filter_.confirmed())});
        no_fix_said_ = true;
      } else if (!no_fix_said_) {
        notes.push_back({false, "GPS: no fix yet"});
        no_fix_said_ = true;
      }
      break;
    case V::nonsense:
      if (!nonsense_said_) notes.push_back({true, "GPS: report ignored: " + res.why});
      nonsense_said_ = true;
      break;
    case V::jump:
      notes.push_back({true, "GPS: position jumped " + res.why + "; ignored unless it holds for " +
                                 std::to_string(kConfirmReports) + " reports"});
      break;
    case V::jump_taken:
      notes.push_back({true, "GPS: the new position held for " + std::to_string(kConfirmReports) +
                                 " reports: taken, " + where(*filter_.confirmed())});
      break;
    case V::confirmed:
      if (!was_fixed) notes.push_back({false, "GPS: fix confirmed, " + where(*filter_.confirmed())});
      no_fix_said_ = false;
      break;
    case V::confirming:
      break;
  }
  if (r.mode >= 2 && r.time && res.verdict != V::nonsense) {
    const double err = seconds(*r.time, clock_now);
    clock_error_s_ = err;
    // Like a position, a difference counts once kConfirmReports reports in a row show it, and so
    // does its end: a clock near the limit is not warned about and cleared every other second.
    far_run_ = std::abs(err) > kClockWarnS ? far_run_ + 1 : 0;
    near_run_ = std::abs(err) < kClockClearS ? near_run_ + 1 : 0;
    if (!clock_warned_ && far_run_ >= kConfirmReports) {
      clock_warned_ = true;
      notes.push_back({true, "GPS: the clock is " + fixed_text("%.3f", std::abs(err)) + " s " +
                                 (err > 0 ? "behind" : "ahead of") +
                                 " GPS time; menu 5 (G) or RTC_REUPDATE= sets it from GPS"});
    } else if (clock_warned_ && near_run_ >= kConfirmReports) {
      clock_warned_ = false;
      notes.push_back({false, "GPS: the clock agrees with GPS time again (" + fixed_text("%+.3f", err) + " s)"});
    }
  }
  return notes;
}

std::string Monitor::status_word() const {
  if (!configured()) return {};
  switch (link_) {
    case Link::off:
    case Link::connecting:
      return "GPS CONNECTING";
    case Link::no_gpsd:
      return "NO GPSD";
    case Link::lost:
      return "GPSD LOST";
    case Link::no_receiver:
      return "NO GPS RECEIVER";
    case Link::receiving:
      break;
  }
  std::string w = filter_.fixed() ? std::string() : std::string("GPS NO FIX");
  if (clock_warned_ && clock_error_s_) w += (w.empty() ? "" : " ") + fixed_text("GPS TIME %+.1fs", *clock_error_s_);
  return w;
}

std::string Monitor::describe() const {
  if (!configured()) return "no GPS";
  std::string s;
  const auto& c = filter_.confirmed();
  if (filter_.fixed() && c) s = std::string(c->mode >= 3 ? "3D" : "2D") + " fix " + where(*c);
  else s = c ? "no fix (last " + where(*c) + ")" : "no fix";
  if (c) s += " at " + orbit::format_iso8601(c->time);
  const std::string w = status_word();
  if (!w.empty() && w != "GPS NO FIX") s += " [" + w + "]";
  return s;
}

}  // namespace tb::gps
