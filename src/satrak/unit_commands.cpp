// The Satrak commands that move the antenna, report its state and set the clock and the unit's
// settings (docs/satrak.md, one handler per command word of Unit::dispatch's table).
#include <cmath>

#include <spdlog/spdlog.h>

#include "satrak/unit.h"
#include "satrak/unit_internal.h"
#include "tracker/operations.h"
#include "util/text.h"

namespace tb::satrak {
using namespace detail;
using rotator::AzEl;
using rotator::RotatorPosition;

Unit::Reply Unit::cmd_version(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  return reply_values(c.head(), {"TRAKBOX SATRAK CU V" + field_text(opt_.version),
                                 "DU " + field_text(station_.rotator().driver().description())});
}

Unit::Reply Unit::cmd_move(const Command& c) {
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const double x = r.number(0, -kMaxRateDegS, kMaxRateDegS);
  const double y = r.number(1, -kMaxRateDegS, kMaxRateDegS);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (x == 0.0 && y == 0.0) {
    // Both rates zero: the button released.
    if (owner_ == Owner::move) {
      station_.rotator().stop();
      station_.antenna_changed();
      release();
    }
    return reply_ok(c.head());
  }
  if (refused_while_tracking(c)) return reply_error(c.head(), Error::not_allowed, kTrackingReason);
  const auto& st = station_.rotator().status();
  if (!st.has_position) return reply_error(c.head(), Error::not_allowed, kNoPositionReason);
  if (const auto no = take_antenna()) return reply_error(c.head(), Error::not_allowed, *no);
  take_control();
  rotator::Controller& rot = station_.rotator();
  const rotator::RotatorConfig& cfg = rot.config();
  Move m;
  m.az_rate = std::clamp(x, -cfg.az_rate_deg_s, cfg.az_rate_deg_s);
  m.el_rate = std::clamp(y, -cfg.el_rate_deg_s, cfg.el_rate_deg_s);
  // Down stops at the minimum elevation; an antenna already at or below it does not go down.
  const double floor_el = std::max(rot.model().el_range().lo, min_el());
  if (m.el_rate < 0.0 && st.el.travel <= floor_el) m.el_rate = 0.0;
  // The controller jogs each axis steadily at its rate (drive pulses for a rate below the motor's)
  // until STOP=, MOVE=,0,0 or the end of its range; an axis at rate 0 stops.
  if (m.az_rate != 0.0) rot.jog(rotator::Axis::az, m.az_rate);
  if (m.el_rate != 0.0) rot.jog(rotator::Axis::el, m.el_rate, m.el_rate < 0.0 ? std::optional(floor_el) : std::nullopt);
  if (m.az_rate == 0.0) rot.manual(rotator::Axis::az, rotator::Drive::stop);
  if (m.el_rate == 0.0) rot.manual(rotator::Axis::el, rotator::Drive::stop);
  station_.antenna_changed();
  commanded_.reset();
  move_ = m;
  owner_ = m.az_rate != 0.0 || m.el_rate != 0.0 ? Owner::move : Owner::none;
  spdlog::info("satrak: MOVE at {} / {} deg/s", m.az_rate, m.el_rate);
  return reply_ok(c.head());
}

bool Unit::refused_while_tracking(const Command& c) {
  if (owner_ != Owner::track) return false;
  spdlog::info("satrak: {} refused: the antenna is {} (STOP= or TRACK=,0 first)", c.word,
               tracking_ ? "tracking " + (elements_ ? elements_->label() : std::string("?"))
                         : std::string("going to the track window's start"));
  return true;
}

Unit::Reply Unit::cmd_step(const Command& c) {
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const double x = r.number(0, -kMaxStepDeg, kMaxStepDeg);
  const double y = r.number(1, -kMaxStepDeg, kMaxStepDeg);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (refused_while_tracking(c)) return reply_error(c.head(), Error::not_allowed, kTrackingReason);
  const auto& st = station_.rotator().status();
  if (!st.has_position && !st.target) return reply_error(c.head(), Error::not_allowed, kNoPositionReason);
  RotatorPosition p = current_position();
  if (const auto no = take_antenna()) return reply_error(c.head(), Error::not_allowed, *no);
  take_control();
  move_.reset();
  p.az_travel += x;
  if (y != 0.0) p.el = std::max(p.el + y, min_el());
  // Exact: a step smaller than the dead band still moves (docs/satrak.md, "Motion").
  command(p, rotator::Controller::Approach::exact);
  station_.antenna_changed();
  owner_ = Owner::go;
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_goto(const Command& c) {
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool az_none = text::lower(c.fields[0]) == "none", el_none = text::lower(c.fields[1]) == "none";
  const double az = az_none ? 0.0 : r.number(0, 0.0, 360.0);
  const double el = el_none ? 0.0 : r.number(1, -90.0, 180.0);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (refused_while_tracking(c)) return reply_error(c.head(), Error::not_allowed, kTrackingReason);
  const auto& st = station_.rotator().status();
  if ((az_none || el_none) && !st.has_position && !st.target)
    return reply_error(c.head(), Error::not_allowed, kNoPositionReason);
  const RotatorPosition base = current_position();
  if (const auto no = take_antenna()) return reply_error(c.head(), Error::not_allowed, *no);
  take_control();
  move_.reset();
  RotatorPosition p = base;
  if (!az_none) {
    const double axis_az = rotator::wrap360(az - s_.north_offset_deg);
    p.az_travel = station_.rotator().model().target_for(AzEl{axis_az, 0.0}, st.has_position ? st.az.travel : base.az_travel).az_travel;
  }
  if (!el_none) p.el = std::max(el, min_el());
  // A GOTO stream that follows a pass goes the pass plan's way round (issue 57); the plan is in the
  // sky's azimuths, so only with no north offset.
  if (!az_none && !el_none && s_.north_offset_deg == 0.0)
    if (const auto planned = station_.client_plan_target(AzEl{rotator::wrap360(az), p.el}, client_, "satrak"))
      p = *planned;
  command(p, rotator::Controller::Approach::exact);
  station_.antenna_changed();
  owner_ = Owner::go;
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_stop(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  if (tracking_) station_.remote_follow(std::nullopt);
  tracking_ = false;
  auto_started_ = false;
  last_track_target_.reset();
  release();
  tracker::StationOps(station_, {tracker::HolderKind::satrak, "satrak"}).stop();  // the Satrak client's own stop
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_status(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  const auto& st = station_.rotator().status();
  const Faults f = faults();
  StatusFields r;
  r.fault = f.any();
  r.x_deg = st.has_position ? st.az.deg : 0.0;
  r.y_deg = st.has_position ? st.el.deg : 0.0;
  r.true_az_deg = st.has_position ? rotator::wrap360(r.x_deg + s_.north_offset_deg) : 0.0;
  r.el_deg = r.y_deg;
  r.x_plus_limit = st.az.at_high_limit;
  r.x_minus_limit = st.az.at_low_limit;
  r.y_plus_limit = st.el.at_high_limit;
  r.y_minus_limit = st.el.at_low_limit;
  r.tracking = tracking_;
  r.window_status = static_cast<int>(track_status());
  r.rtc_updated_by_gps = rtc_from_gps_;
  r.x_motion = rotator::sign(st.az.moving);
  r.y_motion = rotator::sign(st.el.moving);
  r.auto_track = s_.auto_track;
  return reply_values(c.head(), r.fields());
}

Unit::Reply Unit::cmd_errstatus(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  const Faults f = faults();
  return reply_values(c.head(), {b(f.link), b(f.tle_stale), b(f.tle_missing), b(f.sat_missing), b(f.download),
                                 b(f.tracking_stopped), b(f.setup), b(f.x_motor), b(f.y_motor),
                                 std::to_string(f.x_sensor), std::to_string(f.y_sensor), b(f.gps)});
}

Unit::Reply Unit::cmd_time(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), civil_fields(clock_.now(), true));
  }
  if (c.fields.size() != 6 && c.fields.size() != 7) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  orbit::UtcTime t = r.civil(0);
  if (c.fields.size() == 7) t += std::chrono::milliseconds(r.integer(6, 0, 999));
  if (!r.ok()) return reply_error(c.head(), r.error());
  clock_.set(t);
  store_clock_offset();
  last_file_check_ = {};
  spdlog::info("satrak: clock set to {}", orbit::format_iso8601(t, 3));
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_start_stop_time(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    if (!s_.window) return reply_values(c.head(), std::vector<std::string>(12, "0"));
    auto v = civil_fields(s_.window->start, false);
    const auto w = civil_fields(s_.window->stop, false);
    v.insert(v.end(), w.begin(), w.end());
    return reply_values(c.head(), v);
  }
  if (c.fields.size() != 12) return reply_error(c.head(), Error::parameter_count);
  std::optional<TrackWindow> win;
  const bool clear = std::all_of(c.fields.begin(), c.fields.end(), [](const std::string& f) { return f == "0"; });
  if (!clear) {
    Reader r(c.fields);
    TrackWindow w{r.civil(0), r.civil(6)};
    if (r.ok() && w.stop <= w.start) r.fail(Error::out_of_range);
    if (!r.ok()) return reply_error(c.head(), r.error());
    win = w;
  }
  s_.window = win;
  window_started_ = window_prepositioned_ = false;
  if (owner_ == Owner::track && !tracking_) {  // prepositioning for the old window
    station_.rotator().stop();
    release();
  }
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_settings(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {b(s_.rtc_auto_update), std::to_string(s_.time_offset_ms), f2(s_.az_offset_deg),
                                   f2(s_.el_offset_deg), std::to_string(s_.go_to_start_before_ms),
                                   std::to_string(s_.position_base), f2(s_.min_elevation_deg), f2(s_.north_offset_deg),
                                   std::to_string(s_.sspa_manual), std::to_string(s_.sspa_auto_option),
                                   std::to_string(static_cast<int>(s_.source)), f2(s_.el_threshold_deg)});
  }
  // 11 fields as the seed's SETTINGS=, or the 12 of SETTINGS? (X11 then is the TLE source).
  if (c.fields.size() != 11 && c.fields.size() != 12) return reply_error(c.head(), Error::parameter_count);
  const bool with_source = c.fields.size() == 12;
  Reader r(c.fields);
  using namespace limits;
  Settings n = s_;
  if (!r.unchanged(0)) n.rtc_auto_update = r.flag(0);
  if (!r.unchanged(1)) n.time_offset_ms = static_cast<int>(r.integer(1, -kTimeOffsetMs, kTimeOffsetMs));
  if (!r.unchanged(2)) n.az_offset_deg = r.number(2, -kAzOffsetDeg, kAzOffsetDeg);
  if (!r.unchanged(3)) n.el_offset_deg = r.number(3, -kElOffsetDeg, kElOffsetDeg);
  if (!r.unchanged(4)) n.go_to_start_before_ms = static_cast<int>(r.integer(4, 0, kGoToStartBeforeMs));
  if (!r.unchanged(5)) n.position_base = static_cast<int>(r.integer(5, 0, 1));
  if (!r.unchanged(6)) n.min_elevation_deg = r.number(6, kMinElevationLo, kMinElevationHi);
  if (!r.unchanged(7)) n.north_offset_deg = r.number(7, -kNorthOffsetDeg, kNorthOffsetDeg);
  if (!r.unchanged(8)) n.sspa_manual = static_cast<int>(r.integer(8, 0, 2));
  if (!r.unchanged(9)) n.sspa_auto_option = static_cast<int>(r.integer(9, 0, 3));
  std::size_t th = 10;
  if (with_source) {
    if (!r.unchanged(10)) n.source = static_cast<TleSource>(r.integer(10, 0, 2));
    th = 11;
  }
  if (!r.unchanged(th)) n.el_threshold_deg = r.number(th, kThresholdLo, kThresholdHi);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (n.source != s_.source) {
    // The source needs what its own command sets.
    if (n.source == TleSource::web && (n.http.url.empty() || n.tle_file.empty() || n.satellite.empty()))
      return reply_error(c.head(), Error::not_allowed, "NO HTTP SETTINGS: SATELLITE_HTTP= FIRST");
    if (n.source == TleSource::ftp && (n.ftp.host.empty() || n.ftp.file.empty() || n.ftp.satellite.empty()))
      return reply_error(c.head(), Error::not_allowed, "NO FTP SETTINGS: SATELLITE_FTP= FIRST");
    if (n.source == TleSource::file && (n.tle_file.empty() || n.satellite.empty()))
      return reply_error(c.head(), Error::not_allowed, "NO SATELLITE: SATELLITE= FIRST");
  }
  const bool pointing = n.time_offset_ms != s_.time_offset_ms || n.az_offset_deg != s_.az_offset_deg ||
                        n.el_offset_deg != s_.el_offset_deg || n.min_elevation_deg != s_.min_elevation_deg ||
                        n.north_offset_deg != s_.north_offset_deg || n.el_threshold_deg != s_.el_threshold_deg;
  const bool source = n.source != s_.source;
  s_ = n;
  if (pointing) pointing_changed();
  if (source) {
    ++download_generation_;
    download_in_flight_ = false;
    next_download_.reset();
    if (s_.source != TleSource::file) next_download_ = clock_.now();
    apply_load(load_file(active_file(), active_satellite()));
  }
  changed();
  if (tracking_ && pointing) track(clock_.now());
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_angle_settings(const Command& c) {
  const rotator::AdcModel& m = station_.rotator().model();
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    // The angle each sensor reference reads now; the angle as it was given while the skew in force
    // still makes the reference read it (to the half count the skew is rounded to), so a client
    // reads back what it wrote, not 159.94 for 160.0. Changed since (menu 6-3, an image): the reading.
    const double ax = m.az_deg_from_raw(adc_from_sensor(s_.az_sensor_ref));
    const double ay = m.el_deg_from_raw(adc_from_sensor(s_.el_sensor_ref));
    const double tol_az = 0.51 * m.deg_per_count(rotator::Axis::az), tol_el = 0.51 * m.deg_per_count(rotator::Axis::el);
    const auto given_az = s_.az_angle_ref.empty() ? std::nullopt : parse_number(s_.az_angle_ref);
    const auto given_el = s_.el_angle_ref.empty() ? std::nullopt : parse_number(s_.el_angle_ref);
    const bool az_holds = given_az && rotator::azimuth_distance(rotator::wrap360(*given_az), ax) <= tol_az;
    const bool el_holds = given_el && std::abs(*given_el - ay) <= tol_el;
    return reply_values(c.head(), {std::to_string(s_.az_sensor_ref), az_holds ? s_.az_angle_ref : f2(ax),
                                   std::to_string(s_.el_sensor_ref), el_holds ? s_.el_angle_ref : f2(ay)});
  }
  if (c.fields.size() != 5) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool automatic = r.flag(0);
  // The document's sensor counts are 16-bit (its example: 39049, 36838); trakbox's sensor is the
  // 10-bit ADC: the counts are scaled to it (adc_from_sensor), full scale to full scale.
  long long sx = r.integer(1, 0, limits::kSensorMaxCount);
  const double ax = r.number(2, -limits::kAzAngleRefDeg, limits::kAzAngleRefDeg);
  long long sy = r.integer(3, 0, limits::kSensorMaxCount);
  const double ay = r.number(4, limits::kElAngleRefLo, limits::kElAngleRefHi);
  if (!r.ok()) return reply_error(c.head(), r.error());
  double adc_x = adc_from_sensor(static_cast<double>(sx)), adc_y = adc_from_sensor(static_cast<double>(sy));
  if (automatic) {
    const auto raw = station_.rotator().raw_counts();
    if (!raw) return reply_error(c.head(), Error::not_allowed, "NO SENSOR READING");
    adc_x = raw->az;
    adc_y = raw->el;
    sx = sensor_from_adc(adc_x);
    sy = sensor_from_adc(adc_y);
  }
  // The skew that makes ADC count adc_x read angle ax (and adc_y read ay): menu 6-3's skew.
  rotator::RotatorConfig cfg = model_.rotator;
  const double start = m.start_deg();
  const double here = m.az_travel_from_counts(m.corrected(rotator::Axis::az, adc_x));
  // The travel nearest what the count reads now, among those a skew can reach (a second reference
  // after the document's first example would otherwise pick a travel 360 degrees off the sensor).
  double travel = rotator::wrap360(ax - start);
  bool reachable = false;
  for (int k = -2; k <= 2; ++k) {
    const double t = rotator::wrap360(ax - start) + 360.0 * k;
    const double skew = std::round(m.counts_from_az_travel(t) - adc_x);
    const bool ok = rotator::limits::kSkew.contains(static_cast<int>(skew));
    if ((ok && !reachable) || (ok == reachable && std::abs(t - here) < std::abs(travel - here))) {
      travel = t;
      reachable = ok;
    }
  }
  const double az_skew = std::round(m.counts_from_az_travel(travel) - adc_x);
  const double el_skew = std::round(m.counts_from_el(ay) - adc_y);
  if (std::abs(az_skew) > 1023 || std::abs(el_skew) > 1023) return reply_error(c.head(), Error::out_of_range);
  cfg.az_skew = static_cast<int>(az_skew);
  cfg.el_skew = static_cast<int>(el_skew);
  if (!rotator::validate(cfg).empty()) return reply_error(c.head(), Error::out_of_range);
  const store::EditResult kept = station_.owner().edit(store::bit(store::Area::rotator), "angle references",
                                                       store::Origin::satrak, [&](store::Model& mm) { mm.rotator = cfg; });
  if (!kept.ok()) return reply_error(c.head(), Error::out_of_range);
  s_.az_sensor_ref = static_cast<int>(sx);
  s_.el_sensor_ref = static_cast<int>(sy);
  s_.az_angle_ref = c.fields[2];
  s_.el_angle_ref = c.fields[4];
  if (commanded_) commanded_ = station_.rotator().status().target;
  pointing_changed();
  spdlog::info("satrak: angle references set: skew {} / {} counts", cfg.az_skew, cfg.el_skew);
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_gps_data(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  // The receiver's confirmed position and the GPS time of that report while it has a fix; without
  // one, its last confirmed position (else the station's), valid 0 and the RTC's time.
  const gps::Monitor* g = station_.gps();
  const auto& fix = g ? g->filter().confirmed() : std::nullopt;
  const bool valid = g && fix && g->filter().fixed() && g->link() == gps::Link::receiving;
  std::vector<std::string> v = {format_latitude(fix ? fix->lat_deg : model_.station.lat_deg),
                                format_longitude(fix ? fix->lon_deg : model_.station.lon_deg), b(valid)};
  const auto t = civil_fields(valid ? fix->time : clock_.now(), false, true);
  v.insert(v.end(), t.begin(), t.end());
  return reply_values(c.head(), v);
}

Unit::Reply Unit::cmd_tpos(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  const auto& st = station_.rotator().status();
  std::vector<std::string> v = {f2(st.has_position ? st.az.deg : 0.0), f2(st.has_position ? st.el.deg : 0.0)};
  const auto t = civil_fields(clock_.now(), true);
  v.insert(v.end(), t.begin(), t.end());
  return reply_values(c.head(), v);
}

Unit::Reply Unit::cmd_track(const Command& c) {
  if (c.fields.size() != 1) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool on = r.flag(0);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (!on) {
    stop_tracking(false);
    return reply_ok(c.head());
  }
  // Asked first: in standby or under another client's --exclusive hold neither the antenna nor
  // the radio follows a Satrak TRACK.
  if (const auto no = take_antenna()) return reply_error(c.head(), Error::not_allowed, *no);
  take_control();
  if (!sgp4_ && active_satellite().empty() && s_.source == TleSource::file) {
    // No SATELLITE= yet (the document's example on a fresh unit): the station's database and its
    // first satellite, as SATELLITE_HTTP= and SATELLITE_FTP= take them.
    if (const auto d = default_source()) {
      s_.tle_file = d->file;
      s_.satellite = d->satellite;
      apply_load(load_file(s_.tle_file, s_.satellite));
      changed();
    }
  }
  if (!sgp4_) {
    if (active_satellite().empty()) return reply_error(c.head(), Error::not_allowed, "NO SATELLITE: SATELLITE= FIRST");
    return reply_error(c.head(), Error::satellite_not_found);
  }
  spdlog::info("satrak: tracking {}", elements_->label());
  if (!start_tracking()) return reply_error(c.head(), Error::not_allowed, "THE ANTENNA IS HELD");
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_track_auto(const Command& c) {
  if (c.fields.size() != 1) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool on = r.flag(0);
  if (!r.ok()) return reply_error(c.head(), r.error());
  s_.auto_track = on;
  if (!on) {
    if (auto_started_) stop_tracking(false);
    if (owner_ == Owner::track && !tracking_) {
      station_.rotator().stop();
      release();
    }
  }
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_rtc_reupdate(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  if (!station_.gps()) return reply_error(c.head(), Error::not_allowed, "NO GPS RECEIVER");
  if (!update_rtc_from_gps()) return reply_error(c.head(), Error::not_allowed, "NO GPS FIX");
  changed();
  return reply_ok(c.head());
}

bool Unit::update_rtc_from_gps() {
  const gps::Monitor* g = station_.gps();
  if (!g || !g->filter().fixed() || g->link() != gps::Link::receiving || !g->clock_error_s()) return false;
  const auto error = std::chrono::microseconds(std::llround(*g->clock_error_s() * 1e6));
  clock_.set_offset(clock_.offset() + error);
  store_clock_offset();
  last_file_check_ = {};
  rtc_from_gps_ = true;
  spdlog::info("satrak: clock set from GPS time ({:+.3f} s)", *g->clock_error_s());
  return true;
}

Unit::Reply Unit::cmd_gps_settings(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    // As written (GPS_SETTINGS=,0,41.02N,...) while it still is the station's position; else (menu 4
    // changed it, or it was never written) four decimals.
    const auto lat_given = s_.gps_lat_text.empty() ? std::nullopt : parse_latitude(s_.gps_lat_text);
    const auto lon_given = s_.gps_lon_text.empty() ? std::nullopt : parse_longitude(s_.gps_lon_text);
    const bool lat_holds = lat_given && std::abs(*lat_given - model_.station.lat_deg) < 1e-9;
    const bool lon_holds = lon_given && std::abs(*lon_given - model_.station.lon_deg) < 1e-9;
    return reply_values(c.head(), {b(model_.gps.follow), lat_holds ? s_.gps_lat_text : format_latitude(model_.station.lat_deg),
                                   lon_holds ? s_.gps_lon_text : format_longitude(model_.station.lon_deg)});
  }
  if (c.fields.size() != 3) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool automatic = r.flag(0);
  std::optional<double> lat, lon;
  if (r.ok() && !r.unchanged(1)) {
    lat = parse_latitude(c.fields[1]);
    if (!lat) r.fail(coordinate_error(c.fields[1], "NS"));
  }
  if (r.ok() && !r.unchanged(2)) {
    lon = parse_longitude(c.fields[2]);
    if (!lon) r.fail(coordinate_error(c.fields[2], "EW"));
  }
  if (!r.ok()) return reply_error(c.head(), r.error());
  // Both checked before either is kept: the position by the settings table (the same rule as menu 4,
  // --station, host QTH and the page).
  if (lat || lon) {
    const auto& st = model_.station;
    const store::EditResult moved =
        station_.owner().set_position(lat.value_or(st.lat_deg), lon.value_or(st.lon_deg), st.height_m,
                                      store::Origin::satrak);
    if (!moved.ok()) return reply_error(c.head(), Error::out_of_range, *moved.refusal);
  }
  s_.gps_auto = automatic;
  // The same choice as menu 4's: the station follows the receiver.
  (void)station_.owner().set("gps.follow", automatic, store::Origin::satrak);
  // Kept as written for GPS_SETTINGS?. A form the state file would not keep or a reply could not
  // carry (over 40 bytes, a tab between number and letter) reads back in four decimals.
  auto as_written = [](const std::string& f) { return valid_text_field(f, 40) ? f : std::string(); };
  if (lat) s_.gps_lat_text = as_written(c.fields[1]);
  if (lon) s_.gps_lon_text = as_written(c.fields[2]);
  if (lat || lon) {
    if (commanded_) commanded_ = station_.rotator().status().target;
    pointing_changed();
  }
  if (automatic && station_.apply_gps_position()) {  // a confirmed fix is there: the station takes it
    spdlog::info("satrak: GPS_SETTINGS=,1: the station takes the receiver's position");
    if (commanded_) commanded_ = station_.rotator().status().target;
    pointing_changed();
  }
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_reduction(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {num_text(s_.reduction_x), num_text(s_.reduction_y)});
  }
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const double x = r.number(0, 0.0, limits::kReductionMax);
  const double y = r.number(1, 0.0, limits::kReductionMax);
  if (r.ok() && (x <= 0.0 || y <= 0.0)) r.fail(Error::out_of_range);
  if (!r.ok()) return reply_error(c.head(), r.error());
  s_.reduction_x = x;
  s_.reduction_y = y;
  changed();
  return reply_ok(c.head());
}

}  // namespace tb::satrak
