#include "satrak/unit.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <boost/asio/post.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "satrak/redact.h"
#include "store/state_file.h"

namespace tb::satrak {
namespace fs = std::filesystem;
using rotator::AzEl;
using rotator::RotatorPosition;

namespace {

constexpr double kMaxRateDegS = 90.0;   // MOVE: faster requests are out of range
constexpr double kMaxStepDeg = 360.0;   // STEP
constexpr double kMoveLeadS = 1.0;      // MOVE: the moving target runs this far ahead of the clock
constexpr std::uintmax_t kMaxFileBytes = 4u << 20;
constexpr double kPassSearchDays = 1.0;

std::string b(bool v) { return v ? "1" : "0"; }
std::string f2(double v) { return format_fixed(v, 2); }
std::string num_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// A reply field must not break the frame: no `,`, `*`, `$`, control bytes.
std::string field_text(std::string_view s) {
  std::string out;
  for (unsigned char c : s) out += (c < 0x20 || c == ',' || c == '*' || c == '$' || c >= 0x7F) ? ' ' : static_cast<char>(c);
  return out;
}

bool is_leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
int days_in_month(int y, int m) {
  static constexpr int d[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && is_leap(y) ? 29 : d[m - 1];
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::string trim_copy(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

// Field readers: the first problem is kept, later reads are skipped.
class Reader {
 public:
  explicit Reader(const std::vector<std::string>& f) : f_(f) {}
  bool ok() const { return !err_; }
  Error error() const { return err_.value_or(Error::internal); }
  const std::string& text(std::size_t i) const { return f_[i]; }
  bool unchanged(std::size_t i) const { return f_[i] == "?"; }
  void fail(Error e) {
    if (!err_) err_ = e;
  }

  double number(std::size_t i, double lo, double hi) {
    if (err_) return 0.0;
    const auto v = parse_number(f_[i]);
    if (!v) {
      fail(Error::bad_value);
      return 0.0;
    }
    if (*v < lo || *v > hi) fail(Error::out_of_range);
    return *v;
  }
  // A whole number; "12.0" is taken as 12.
  long long integer(std::size_t i, long long lo, long long hi) {
    if (err_) return 0;
    auto v = parse_integer(f_[i]);
    if (!v) {
      const auto d = parse_number(f_[i]);
      if (d && std::floor(*d) == *d && std::abs(*d) < 9e15) v = static_cast<long long>(*d);
    }
    if (!v) {
      fail(Error::bad_value);
      return 0;
    }
    if (*v < lo || *v > hi) fail(Error::out_of_range);
    return *v;
  }
  bool flag(std::size_t i) {
    if (err_) return false;
    if (f_[i] == "0") return false;
    if (f_[i] == "1") return true;
    const auto v = parse_integer(f_[i]);
    fail(v ? Error::out_of_range : Error::bad_value);
    return false;
  }
  // H, M, S, D, Mo, Y from field i on. A two-digit year is 20YY.
  orbit::UtcTime civil(std::size_t i) {
    const long long h = integer(i, 0, 23), mi = integer(i + 1, 0, 59), s = integer(i + 2, 0, 59);
    const long long d = integer(i + 3, 1, 31), mo = integer(i + 4, 1, 12);
    long long y = integer(i + 5, 0, 2099);
    if (err_) return {};
    if (y < 100) y += 2000;
    if (y < 1970) fail(Error::out_of_range);
    if (err_) return {};
    if (d > days_in_month(static_cast<int>(y), static_cast<int>(mo))) {
      fail(Error::out_of_range);
      return {};
    }
    return orbit::from_civil(static_cast<int>(y), static_cast<int>(mo), static_cast<int>(d), static_cast<int>(h),
                             static_cast<int>(mi), static_cast<double>(s));
  }

 private:
  const std::vector<std::string>& f_;
  std::optional<Error> err_;
};

// Hour, minute, second, day, month, year[, ms] of t.
std::vector<std::string> civil_fields(orbit::UtcTime t, bool with_ms, bool two_digit_year = false) {
  const auto secs = std::chrono::floor<std::chrono::seconds>(t);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t - secs).count();
  const orbit::CivilTime c = orbit::to_civil(orbit::UtcTime(secs));
  std::vector<std::string> out = {std::to_string(c.hour),  std::to_string(c.minute),
                                  std::to_string(static_cast<int>(c.second)), std::to_string(c.day),
                                  std::to_string(c.month), std::to_string(two_digit_year ? c.year % 100 : c.year)};
  if (with_ms) out.push_back(std::to_string(ms));
  return out;
}

std::string read_small_file(const fs::path& p, bool& too_big) {
  too_big = false;
  std::error_code ec;
  const auto size = fs::file_size(p, ec);
  if (!ec && size > kMaxFileBytes) {
    too_big = true;
    return {};
  }
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::optional<std::pair<std::int64_t, std::uintmax_t>> stat_file(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  const std::int64_t us = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000 + st.st_mtim.tv_nsec / 1000;
  return std::make_pair(us, static_cast<std::uintmax_t>(st.st_size));
}

std::string percent_encode(std::string_view s) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
        c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

std::string ftp_url(const FtpSource& f) {
  const std::string file = percent_encode(f.file);
  if (f.host.find("://") != std::string::npos) {
    std::string base = f.host;
    while (!base.empty() && base.back() == '/') base.pop_back();
    return base + "/" + file;
  }
  std::string host = f.host;
  if (host.find(':') != std::string::npos && host.front() != '[') host = "[" + host + "]";
  return "ftp://" + host + ":" + std::to_string(f.port) + "/" + file;
}

bool valid_http_url(std::string_view u) {
  const std::string l = lower(u);
  if (l.rfind("http://", 0) != 0 && l.rfind("https://", 0) != 0) return false;
  if (u.size() > limits::kUrlMax || !frame_text(u)) return false;
  for (unsigned char c : u)
    if (c == ' ' || c >= 0x7F) return false;
  return l.size() > (l[4] == 's' ? 8u : 7u);
}

bool valid_text_field(std::string_view s, std::size_t max_len) {
  if (s.size() > max_len || !frame_text(s)) return false;
  for (unsigned char c : s)
    if (c >= 0x7F) return false;
  return true;
}

double seconds_between(orbit::UtcTime a, orbit::UtcTime b) {
  return std::chrono::duration<double>(b - a).count();
}

// What SATELLITE_FTP? answers for a stored password: never the password itself (the Satrak protocol has
// no authentication: anyone who can reach the port would read it), and nothing with '*' or '$',
// which end or start a frame. Written back, it keeps the stored password (docs/satrak.md).
constexpr const char* kKeepPassword = "?";

// Why a latitude/longitude field did not parse: a number out of range, or not a coordinate at all.
Error coordinate_error(std::string_view s, std::string_view letters) {
  std::string t = trim_copy(s);
  if (!t.empty() && std::isalpha(static_cast<unsigned char>(t.back()))) {
    const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(t.back())));
    if (letters.find(up) == std::string_view::npos) return Error::bad_value;
    t.pop_back();
  }
  return parse_number(trim_copy(t)) ? Error::out_of_range : Error::bad_value;
}

}  // namespace

Unit::Unit(boost::asio::io_context& io, tracker::StationLoop& station, store::Model& model,
           station::RealTimeClock& clock, Settings settings, UnitOptions options, UnitHooks hooks)
    : io_(io),
      station_(station),
      model_(model),
      clock_(clock),
      s_(std::move(settings)),
      opt_(std::move(options)),
      hooks_(std::move(hooks)),
      timer_(io) {
  std::error_code ec;
  if (!opt_.tle_dir.empty()) fs::create_directories(opt_.tle_dir, ec);
  if (!opt_.image_dir.empty()) fs::create_directories(opt_.image_dir, ec);
  if (!active_file().empty() && !active_satellite().empty()) apply_load(load_file(active_file(), active_satellite()));
  if (s_.source != TleSource::file) next_download_ = clock_.now();
}

Unit::~Unit() {
  running_ = false;
  timer_.cancel();
  if (tracking_) station_.remote_follow(std::nullopt);
  downloader_.reset();  // aborts and joins: no callback runs after this
  alive_.reset();
}

void Unit::start() {
  if (running_) return;
  running_ = true;
  struct Loop {
    static void arm(Unit* u, std::weak_ptr<int> alive) {
      u->timer_.expires_after(u->opt_.period);
      u->timer_.async_wait([u, alive](const boost::system::error_code& ec) {
        if (ec || alive.expired() || !u->running_) return;
        u->tick();
        arm(u, alive);
      });
    }
  };
  Loop::arm(this, alive_);
}

void Unit::stop() {
  running_ = false;
  timer_.cancel();
}

void Unit::changed() {
  if (!hooks_.save) return;
  if (auto err = hooks_.save()) {
    save_failed_ = true;
    spdlog::error("satrak: the change is in memory but not on disk: {}", *err);
  }
}

// ---------------------------------------------------------------------------------------------
// Payloads

namespace {
// The head of a payload that does not parse as a command: the word as far as it can be read.
std::string guess_head(std::string_view payload) {
  if (const auto c = parse_payload(payload)) return c->head();
  std::size_t k = 0;
  while (k < payload.size() && payload[k] != '?' && payload[k] != '=' && payload[k] != ',') ++k;
  std::string w = sanitize_word(payload.substr(0, k));
  // "ERR" is the replies' own word: "ERR,ERR,4" would read as a refusal of a refusal.
  if (w.empty() || w == "ERR") return {};
  if (k < payload.size() && (payload[k] == '?' || payload[k] == '=')) w += payload[k];
  return w;
}
}  // namespace

std::string Unit::handle(const Decoded& d) {
  switch (d.kind) {
    case Decoded::Kind::frame: return handle(std::string_view(d.payload));
    case Decoded::Kind::bad_checksum: return reply_error(guess_head(d.payload), Error::bad_checksum);
    // Here the word is echoed only when the line reads as a command: garbage is not a word.
    case Decoded::Kind::malformed:
    case Decoded::Kind::overlong: {
      const auto c = parse_payload(d.payload);
      return reply_error(c ? c->head() : std::string(),
                         d.kind == Decoded::Kind::overlong ? Error::frame_too_long : Error::malformed_frame);
    }
  }
  return reply_error("", Error::internal);
}

std::string Unit::handle(std::string_view payload) {
  const auto c = parse_payload(payload);
  if (!c) return reply_error(guess_head(payload), Error::unknown_command);
  return dispatch(*c);
}

std::string Unit::dispatch(const Command& c) {
  struct Entry {
    const char* word;
    bool query, request;
    Reply (Unit::*fn)(const Command&);
  };
  static const Entry kTable[] = {
      {"VERSION", true, false, &Unit::cmd_version},
      {"MOVE", false, true, &Unit::cmd_move},
      {"STEP", false, true, &Unit::cmd_step},
      {"GOTO", false, true, &Unit::cmd_goto},
      {"STOP", false, true, &Unit::cmd_stop},
      {"STATUS", true, false, &Unit::cmd_status},
      {"ERRSTATUS", true, false, &Unit::cmd_errstatus},
      {"TIME", true, true, &Unit::cmd_time},
      {"START_STOP_TIME", true, true, &Unit::cmd_start_stop_time},
      {"SETTINGS", true, true, &Unit::cmd_settings},
      {"ANGLE_SETTINGS", true, true, &Unit::cmd_angle_settings},
      {"GPS_DATA", true, false, &Unit::cmd_gps_data},
      {"TPOS", true, false, &Unit::cmd_tpos},
      {"TRACK", false, true, &Unit::cmd_track},
      {"TRACK_AUTO_ENABLE", false, true, &Unit::cmd_track_auto},
      {"RTC_REUPDATE", false, true, &Unit::cmd_rtc_reupdate},
      {"GPS_SETTINGS", true, true, &Unit::cmd_gps_settings},
      {"SATELLITE", true, true, &Unit::cmd_satellite},
      {"SATELLITE_HTTP", true, true, &Unit::cmd_satellite_http},
      {"SATELLITE_FTP", true, true, &Unit::cmd_satellite_ftp},
      {"LOAD_IMAGE", true, true, &Unit::cmd_load_image},
      {"REDUCTION", true, true, &Unit::cmd_reduction},
  };
  for (const Entry& e : kTable) {
    if (c.word != e.word) continue;
    if ((c.kind == Kind::query && !e.query) || (c.kind == Kind::request && !e.request)) break;
    save_failed_ = false;
    Reply reply = (this->*e.fn)(c);
    // A setting that could not be stored is not acknowledged: it holds until the next start only.
    if (save_failed_ && reply == reply_ok(c.head())) return reply_error(c.head(), Error::internal);
    return reply;
  }
  return reply_error(c.head(), Error::unknown_command);
}

// ---------------------------------------------------------------------------------------------
// Antenna

void Unit::take_control() {
  if (!model_.rotor_control) station_.set_rotor_control(true);
}

void Unit::take_antenna() {
  if (station_.tracker().mode() != tracker::Mode::off) station_.tracker().stop();
}

void Unit::command(RotatorPosition p) { commanded_ = station_.rotator().set_target(p); }

void Unit::release() {
  owner_ = Owner::none;
  commanded_.reset();
  move_.reset();
}

double Unit::min_el() const { return s_.min_elevation_deg; }

RotatorPosition Unit::current_position() const {
  const auto& st = station_.rotator().status();
  if (st.mode == rotator::ControlMode::target && st.target) return *st.target;
  if (st.has_position) return RotatorPosition{st.az.travel, st.el.travel};
  return RotatorPosition{};
}

void Unit::check_takeover() {
  if (owner_ == Owner::none) return;
  bool lost = station_.tracker().mode() != tracker::Mode::off;
  const auto& st = station_.rotator().status();
  if (!lost) {
    if (commanded_)
      lost = st.mode != rotator::ControlMode::target || !st.target ||
             std::abs(st.target->az_travel - commanded_->az_travel) > 0.01 || std::abs(st.target->el - commanded_->el) > 0.01;
    else
      lost = st.mode != rotator::ControlMode::idle;
  }
  if (!lost) return;
  spdlog::info("satrak: the antenna was taken over by the station; Satrak {} stopped",
               tracking_ ? "tracking" : "motion");
  if (tracking_) {
    tracking_ = false;
    auto_started_ = false;
    tracking_stopped_fault_ = true;
    last_track_target_.reset();
    station_.remote_follow(std::nullopt);
  }
  release();
}

// ---------------------------------------------------------------------------------------------
// Tracking

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
  if (!sgp4_) return nullptr;
  PassCache& c = pass_cache_;
  if (c.valid && t >= c.searched_at) {
    if (c.pass && t <= c.pass->los) return &*c.pass;
    if (!c.pass && t < c.valid_until) return nullptr;
  }
  orbit::PassOptions po;
  po.horizon_deg = s_.el_threshold_deg;
  po.precision_s = 1.0;
  c.pass = orbit::next_pass(*sgp4_, model_.station.observer(), t, kPassSearchDays, po);
  c.searched_at = t;
  c.valid_until = c.pass ? c.pass->los : orbit::add_minutes(t, 60.0);
  c.valid = true;
  return c.pass ? &*c.pass : nullptr;
}

const rotator::PassPlan* Unit::plan_for(const orbit::Pass& p) {
  if (plan_cache_ && plan_cache_->aos == p.aos && plan_cache_->generation == pointing_generation_) return &plan_cache_->plan;
  std::vector<rotator::TrackPoint> track;
  const double minutes = orbit::minutes_between(p.aos, p.los);
  const int steps = std::clamp(static_cast<int>(minutes * 6.0), 2, 600);
  for (int k = 0; k <= steps; ++k) {
    const orbit::UtcTime t = orbit::add_minutes(p.aos, minutes * k / steps);
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

void Unit::start_tracking() {
  take_antenna();
  move_.reset();
  tracking_ = true;
  tracking_stopped_fault_ = false;
  owner_ = Owner::track;
  // Whatever moved the antenna before stops; tracking commands it from here.
  station_.rotator().stop();
  commanded_.reset();
  track(clock_.now());
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
  station_.remote_follow(tracker::StationLoop::RemoteFollow{"Satrak", elements_->label(), elements_->catalog_number, *o});
  const orbit::Pass* p = pass_at(t);
  if (o->look.el_deg >= s_.el_threshold_deg) {
    const AzEl a = adjusted(o->look.az_deg, o->look.el_deg);
    last_track_target_ = a;
    const rotator::PassPlan* plan = (p && p->aos <= t) ? plan_for(*p) : nullptr;
    if (plan) {
      command(plan->map(a.az, a.el));
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
    command(plan ? plan->map(a.az, a.el) : station_.rotator().model().target_for(a, travel));
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
        take_antenna();
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
      start_tracking();
      auto_started_ = true;
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
  check_takeover();
  update_window(now);
  if (owner_ == Owner::move && move_) {
    const double dt = std::max(0.0, seconds_between(move_->t0, now)) + kMoveLeadS;
    const rotator::AdcModel& m = station_.rotator().model();
    RotatorPosition p = move_->origin;
    if (move_->az_rate != 0.0) p.az_travel = m.az_travel_range().clamp(p.az_travel + move_->az_rate * dt);
    if (move_->el_rate != 0.0) {
      rotator::Range r = m.el_range();
      r.lo = std::min(std::max(r.lo, min_el()), r.hi);
      p.el = r.clamp(p.el + move_->el_rate * dt);
    }
    command(p);
  }
  if (tracking_) track(now);
  check_file(now);
  schedule_download(now);
  if (const bool sspa = sspa_on(); sspa_last_ != sspa) {
    if (sspa_last_) spdlog::info("satrak: SSPA {}", sspa ? "on" : "off");
    sspa_last_ = sspa;
  }
}

// ---------------------------------------------------------------------------------------------
// Element sets

std::string Unit::active_file() const { return s_.source == TleSource::ftp ? s_.ftp.file : s_.tle_file; }
std::string Unit::active_satellite() const { return s_.source == TleSource::ftp ? s_.ftp.satellite : s_.satellite; }
double Unit::active_period_days() const {
  switch (s_.source) {
    case TleSource::web: return s_.http.period_days;
    case TleSource::ftp: return s_.ftp.period_days;
    default: return s_.tle_period_days;
  }
}

namespace {
const orbit::Elements* find_satellite(const std::vector<orbit::Elements>& sets, const std::string& name) {
  for (const auto& e : sets)
    if (e.name == name) return &e;
  const std::string want = lower(trim_copy(name));
  for (const auto& e : sets)
    if (lower(trim_copy(e.name)) == want) return &e;
  if (const auto n = parse_integer(name); n && *n > 0)
    for (const auto& e : sets)
      if (e.catalog_number == *n) return &e;
  return nullptr;
}
}  // namespace

Unit::Loaded Unit::load_file(const std::string& file, const std::string& satellite) const {
  Loaded l;
  if (!safe_file_name(file)) {
    l.error = Error::bad_value;
    return l;
  }
  const fs::path path = opt_.tle_dir / file;
  if (!stat_file(path)) {
    l.error = Error::file_not_found;
    return l;
  }
  bool too_big = false;
  const std::string text = read_small_file(path, too_big);
  if (too_big) {
    l.error = Error::invalid_file;
    return l;
  }
  const orbit::ParseResult parsed = orbit::parse_elements(text, file);
  if (parsed.sets.empty()) {
    l.error = Error::invalid_file;
    return l;
  }
  const orbit::Elements* e = find_satellite(parsed.sets, satellite);
  if (!e) {
    l.error = Error::satellite_not_found;
    return l;
  }
  l.elements = *e;
  return l;
}

void Unit::apply_load(const Loaded& l) {
  tle_missing_ = !l.elements && l.error == Error::file_not_found;
  sat_missing_ = !l.elements && (l.error == Error::satellite_not_found || l.error == Error::invalid_file);
  if (const auto st = stat_file(opt_.tle_dir / active_file())) {
    file_seen_ = true;
    file_size_ = st->second;
    last_file_check_ = clock_.now();
    file_stat_us_ = st->first;
  } else {
    file_seen_ = false;
  }
  if (l.elements) set_elements(l.elements);
}

void Unit::set_elements(std::optional<orbit::Elements> e) {
  elements_ = std::move(e);
  sgp4_ = elements_ ? std::make_unique<orbit::Sgp4>(*elements_) : nullptr;
  if (sgp4_ && sgp4_->init_error() != orbit::Sgp4Error::none) {
    spdlog::warn("satrak: {}: {}", elements_->label(), orbit::describe(sgp4_->init_error()));
    sgp4_.reset();
  }
  pass_cache_ = {};
  plan_cache_.reset();
}

void Unit::check_file(orbit::UtcTime now) {
  if (s_.source != TleSource::file || s_.tle_file.empty() || s_.satellite.empty()) return;
  if (now >= last_file_check_ && now - last_file_check_ < opt_.file_check) return;
  last_file_check_ = now;
  const auto st = stat_file(opt_.tle_dir / s_.tle_file);
  if (!st) {
    if (!tle_missing_) spdlog::warn("satrak: TLE file {} is gone; tracking continues from the last data", s_.tle_file);
    tle_missing_ = true;
    file_seen_ = false;
    return;
  }
  if (file_seen_ && st->first == file_stat_us_ && st->second == file_size_ && !tle_missing_) return;
  spdlog::info("satrak: TLE file {} changed: reading it again", s_.tle_file);
  const Loaded l = load_file(s_.tle_file, s_.satellite);
  if (!l.elements) spdlog::warn("satrak: {}: {}; tracking continues from the last data", s_.tle_file, describe(l.error));
  apply_load(l);
}

void Unit::schedule_download(orbit::UtcTime now) {
  if (s_.source == TleSource::file || download_in_flight_ || !next_download_) return;
  if (now >= *next_download_) start_download();
}

void Unit::start_download() {
  DownloadRequest r;
  if (s_.source == TleSource::web) {
    r.url = s_.http.url;
  } else if (s_.source == TleSource::ftp) {
    r.url = ftp_url(s_.ftp);
    r.user = s_.ftp.user;
    r.password = s_.ftp.password;
  } else {
    return;
  }
  r.total_timeout = opt_.download_timeout;
  r.connect_timeout = std::min(opt_.download_timeout, std::chrono::milliseconds(10000));
  download_in_flight_ = true;
  next_download_.reset();
  const std::uint64_t gen = ++download_generation_;
  const TleSource src = s_.source;
  if (!downloader_) downloader_ = std::make_unique<Downloader>();
  spdlog::info("satrak: downloading {}", redact_url(r.url));
  std::weak_ptr<int> alive = alive_;
  boost::asio::io_context& io = io_;
  downloader_->submit(std::move(r), [this, alive, &io, src, gen](DownloadResult res) {
    boost::asio::post(io, [this, alive, src, gen, res = std::move(res)]() mutable {
      if (alive.expired()) return;
      on_download(src, gen, std::move(res));
    });
  });
}

void Unit::download_failed() {
  download_failed_ = true;
  next_download_ = clock_.now() + opt_.retry_after;
  const ErrorAction action = s_.source == TleSource::ftp ? s_.ftp.on_error : s_.http.on_error;
  if (action == ErrorAction::stop_tracking && tracking_) {
    spdlog::warn("satrak: element update failed: tracking stopped (update error action 0)");
    stop_tracking(true);
  } else if (elements_) {
    spdlog::info("satrak: element update failed: continuing from the last data");
  }
}

void Unit::on_download(TleSource src, std::uint64_t gen, DownloadResult r) {
  if (gen != download_generation_) return;  // settings changed since: a newer download runs
  download_in_flight_ = false;
  if (src != s_.source) return;
  if (!r.ok) {
    spdlog::warn("satrak: download failed: {}", r.error);
    download_failed();
    return;
  }
  const std::string file = active_file();
  const orbit::ParseResult parsed = orbit::parse_elements(r.body, file);
  const orbit::Elements* e = find_satellite(parsed.sets, active_satellite());
  if (!e) {
    spdlog::warn("satrak: downloaded {} bytes without '{}' in them", r.body.size(), active_satellite());
    sat_missing_ = true;
    download_failed();
    return;
  }
  const orbit::Elements found = *e;
  std::string err;
  if (!store::write_file_atomically(opt_.tle_dir / file, r.body, err, 0644)) spdlog::warn("satrak: {}", err);
  const orbit::UtcTime now = clock_.now();
  tle_missing_ = sat_missing_ = download_failed_ = false;
  last_download_ok_ = now;
  const double period = active_period_days();
  if (period > 0) next_download_ = now + std::chrono::microseconds(static_cast<std::int64_t>(period * 86400e6));
  if (const auto st = stat_file(opt_.tle_dir / file)) {
    file_seen_ = true;
    file_stat_us_ = st->first;
    file_size_ = st->second;
  }
  spdlog::info("satrak: elements of {} updated from {}", found.label(), src == TleSource::web ? "the web" : "FTP");
  set_elements(found);
}

Faults Unit::faults() const {
  Faults f;
  const auto& st = station_.rotator().status();
  f.link = !st.link.ok();
  const double period = active_period_days();
  if (period > 0 && elements_) {
    std::optional<orbit::UtcTime> since;
    if (s_.source == TleSource::file) {
      if (file_seen_) since = orbit::UtcTime(std::chrono::microseconds(file_stat_us_));
    } else {
      since = last_download_ok_;
      if (!since && file_seen_) since = orbit::UtcTime(std::chrono::microseconds(file_stat_us_));
    }
    if (since) f.tle_stale = seconds_between(*since, clock_.now()) > period * 86400.0;
  }
  f.tle_missing = tle_missing_;
  f.sat_missing = sat_missing_;
  f.download = download_failed_;
  f.tracking_stopped = tracking_stopped_fault_;
  const auto problems = rotator::validate(model_.rotator);
  f.setup = !problems.empty();
  f.x_motor = st.az.stalled;
  f.y_motor = st.el.stalled;
  const bool span_bad_az = model_.rotator.az_span.width() <= 0, span_bad_el = model_.rotator.el_span.width() <= 0;
  f.x_sensor = !st.has_position ? 2 : (span_bad_az ? 1 : 0);
  f.y_sensor = !st.has_position ? 2 : (span_bad_el ? 1 : 0);
  f.gps = s_.gps_auto;
  return f;
}

// ---------------------------------------------------------------------------------------------
// Commands

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
  take_control();
  const auto& st = station_.rotator().status();
  if (x == 0.0 && y == 0.0) {
    // Both rates zero: the button released.
    if (owner_ == Owner::move) {
      station_.rotator().stop();
      release();
    }
    return reply_ok(c.head());
  }
  if (!st.has_position) return reply_error(c.head(), Error::not_allowed);
  take_antenna();
  if (tracking_) stop_tracking(false);
  const rotator::RotatorConfig& cfg = station_.rotator().config();
  Move m;
  m.az_rate = std::clamp(x, -cfg.az_rate_deg_s, cfg.az_rate_deg_s);
  m.el_rate = std::clamp(y, -cfg.el_rate_deg_s, cfg.el_rate_deg_s);
  m.origin = RotatorPosition{st.az.travel, st.el.travel};
  m.t0 = clock_.now();
  move_ = m;
  owner_ = Owner::move;
  tick();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_step(const Command& c) {
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const double x = r.number(0, -kMaxStepDeg, kMaxStepDeg);
  const double y = r.number(1, -kMaxStepDeg, kMaxStepDeg);
  if (!r.ok()) return reply_error(c.head(), r.error());
  take_control();
  const auto& st = station_.rotator().status();
  if (!st.has_position && !st.target) return reply_error(c.head(), Error::not_allowed);
  RotatorPosition p = current_position();
  take_antenna();
  if (tracking_) stop_tracking(false);
  move_.reset();
  p.az_travel += x;
  if (y != 0.0) p.el = std::max(p.el + y, min_el());
  command(p);
  owner_ = Owner::go;
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_goto(const Command& c) {
  if (c.fields.size() != 2) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool az_none = lower(c.fields[0]) == "none", el_none = lower(c.fields[1]) == "none";
  const double az = az_none ? 0.0 : r.number(0, 0.0, 360.0);
  const double el = el_none ? 0.0 : r.number(1, -90.0, 180.0);
  if (!r.ok()) return reply_error(c.head(), r.error());
  take_control();
  const auto& st = station_.rotator().status();
  if ((az_none || el_none) && !st.has_position && !st.target) return reply_error(c.head(), Error::not_allowed);
  const RotatorPosition base = current_position();
  take_antenna();
  if (tracking_) stop_tracking(false);
  move_.reset();
  RotatorPosition p = base;
  if (!az_none) {
    const double axis_az = rotator::wrap360(az - s_.north_offset_deg);
    p.az_travel = station_.rotator().model().target_for(AzEl{axis_az, 0.0}, st.has_position ? st.az.travel : base.az_travel).az_travel;
  }
  if (!el_none) p.el = std::max(el, min_el());
  command(p);
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
  station_.stop_antenna();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_status(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  const auto& st = station_.rotator().status();
  const Faults f = faults();
  const double x = st.has_position ? st.az.deg : 0.0, y = st.has_position ? st.el.deg : 0.0;
  const double true_az = st.has_position ? rotator::wrap360(x + s_.north_offset_deg) : 0.0;
  return reply_values(c.head(), {b(f.any()), f2(true_az), f2(y), b(st.az.at_high_limit), b(st.az.at_low_limit),
                                 b(st.el.at_high_limit), b(st.el.at_low_limit), b(tracking_),
                                 std::to_string(static_cast<int>(track_status())), "0", "0",
                                 std::to_string(rotator::sign(st.az.motion)), std::to_string(rotator::sign(st.el.motion)),
                                 f2(x), f2(y), b(s_.auto_track)});
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
  model_.clock_offset = clock_.offset();
  pass_cache_ = {};
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
    if ((n.source == TleSource::web && (n.http.url.empty() || n.tle_file.empty() || n.satellite.empty())) ||
        (n.source == TleSource::ftp && (n.ftp.host.empty() || n.ftp.file.empty() || n.ftp.satellite.empty())) ||
        (n.source == TleSource::file && (n.tle_file.empty() || n.satellite.empty())))
      return reply_error(c.head(), Error::not_allowed);
  }
  const bool pointing = n.time_offset_ms != s_.time_offset_ms || n.az_offset_deg != s_.az_offset_deg ||
                        n.el_offset_deg != s_.el_offset_deg || n.min_elevation_deg != s_.min_elevation_deg ||
                        n.north_offset_deg != s_.north_offset_deg || n.el_threshold_deg != s_.el_threshold_deg;
  const bool threshold = n.el_threshold_deg != s_.el_threshold_deg;
  const bool source = n.source != s_.source;
  s_ = n;
  if (threshold) pass_cache_ = {};
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
    return reply_values(c.head(), {std::to_string(s_.az_sensor_ref), f2(m.az_deg_from_raw(s_.az_sensor_ref)),
                                   std::to_string(s_.el_sensor_ref), f2(m.el_deg_from_raw(s_.el_sensor_ref))});
  }
  if (c.fields.size() != 5) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const bool automatic = r.flag(0);
  long long sx = r.integer(1, -100000, 100000);
  const double ax = r.number(2, -360.0, 360.0);
  long long sy = r.integer(3, -100000, 100000);
  const double ay = r.number(4, -90.0, 180.0);
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (automatic) {
    const auto raw = station_.rotator().raw_counts();
    if (!raw) return reply_error(c.head(), Error::not_allowed);
    sx = raw->az;
    sy = raw->el;
  }
  // The skew that makes sensor count sx read angle ax (and sy read ay): menu 6-3's skew.
  rotator::RotatorConfig cfg = model_.rotator;
  const double start = m.start_deg();
  const double here = m.az_travel_from_counts(m.corrected(rotator::Axis::az, static_cast<double>(sx)));
  double travel = rotator::wrap360(ax - start);
  for (int k = -2; k <= 2; ++k) {
    const double t = rotator::wrap360(ax - start) + 360.0 * k;
    if (std::abs(t - here) < std::abs(travel - here)) travel = t;
  }
  const double az_skew = std::round(m.counts_from_az_travel(travel) - static_cast<double>(sx));
  const double el_skew = std::round(m.counts_from_el(ay) - static_cast<double>(sy));
  if (std::abs(az_skew) > 1023 || std::abs(el_skew) > 1023) return reply_error(c.head(), Error::out_of_range);
  cfg.az_skew = static_cast<int>(az_skew);
  cfg.el_skew = static_cast<int>(el_skew);
  if (!rotator::validate(cfg).empty()) return reply_error(c.head(), Error::out_of_range);
  model_.rotator = cfg;
  s_.az_sensor_ref = static_cast<int>(sx);
  s_.el_sensor_ref = static_cast<int>(sy);
  station_.reconfigure();
  if (commanded_) commanded_ = station_.rotator().status().target;
  pointing_changed();
  spdlog::info("satrak: angle references set: skew {} / {} counts", cfg.az_skew, cfg.el_skew);
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_gps_data(const Command& c) {
  if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
  std::vector<std::string> v = {format_latitude(model_.station.lat_deg), format_longitude(model_.station.lon_deg), "0"};
  const auto t = civil_fields(clock_.now(), false, true);
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
  take_control();
  if (!sgp4_) return reply_error(c.head(), active_satellite().empty() ? Error::not_allowed : Error::satellite_not_found);
  spdlog::info("satrak: tracking {}", elements_->label());
  start_tracking();
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
  return reply_error(c.head(), Error::not_allowed);  // no GPS receiver: never locked
}

Unit::Reply Unit::cmd_gps_settings(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {b(s_.gps_auto), format_latitude(model_.station.lat_deg),
                                   format_longitude(model_.station.lon_deg)});
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
  s_.gps_auto = automatic;
  if (lat || lon) {
    if (lat) model_.station.lat_deg = *lat;
    if (lon) model_.station.lon_deg = *lon;
    station_.reconfigure();
    if (commanded_) commanded_ = station_.rotator().status().target;
    pass_cache_ = {};
    pointing_changed();
  }
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_satellite(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    double max_el = 0.0;
    if (const orbit::Pass* p = pass_at(clock_.now() + std::chrono::milliseconds(s_.time_offset_ms))) max_el = p->max_el_deg;
    return reply_values(c.head(), {field_text(active_file()), field_text(active_satellite()), num_text(active_period_days()),
                                   std::to_string(elements_ ? elements_->catalog_number : 0), f2(max_el)});
  }
  if (c.fields.size() != 4) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  const std::string& file = c.fields[0];
  const std::string& name = c.fields[1];
  if (!safe_file_name(file) || name.empty() || !valid_text_field(name, limits::kNameMax)) r.fail(Error::bad_value);
  const double period = r.number(2, 0.0, limits::kPeriodDays);
  const bool keep_tracking = r.flag(3);
  if (!r.ok()) return reply_error(c.head(), r.error());
  const bool web = s_.source == TleSource::web;
  const Loaded l = load_file(file, name);
  if (!l.elements && !(web && l.error == Error::file_not_found)) {
    // Refused: nothing changes, but ERRSTATUS tells what the last load found.
    tle_missing_ = l.error == Error::file_not_found;
    sat_missing_ = l.error == Error::satellite_not_found || l.error == Error::invalid_file;
    return reply_error(c.head(), l.error);
  }
  s_.tle_file = file;
  s_.satellite = name;
  s_.tle_period_days = period;
  if (!web) s_.source = TleSource::file;
  if (!keep_tracking && tracking_) stop_tracking(false);
  apply_load(l);
  if (!l.elements) {
    set_elements(std::nullopt);
    if (tracking_) stop_tracking(true);
  }
  if (web) {
    ++download_generation_;
    download_in_flight_ = false;
    start_download();
  }
  tracking_stopped_fault_ = false;
  changed();
  if (tracking_) track(clock_.now());
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_satellite_http(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {field_text(s_.http.url), num_text(s_.http.period_days),
                                   std::to_string(static_cast<int>(s_.http.on_error))});
  }
  if (c.fields.size() != 4) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  if (!valid_http_url(c.fields[0])) r.fail(Error::bad_value);
  const double period = r.number(1, 0.0, limits::kPeriodDays);
  const bool cont = r.flag(2);
  const bool keep_tracking = r.flag(3);
  if (!r.ok()) return reply_error(c.head(), r.error());
  // The HTTP settings name no file or satellite: those of SATELLITE= are used.
  if (s_.tle_file.empty() || s_.satellite.empty()) return reply_error(c.head(), Error::not_allowed);
  s_.http = HttpSource{c.fields[0], period, cont ? ErrorAction::continue_last_data : ErrorAction::stop_tracking};
  s_.source = TleSource::web;
  if (!keep_tracking && tracking_) stop_tracking(false);
  download_failed_ = false;
  ++download_generation_;
  download_in_flight_ = false;
  start_download();
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_satellite_ftp(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {field_text(s_.ftp.host), field_text(s_.ftp.user),
                                   s_.ftp.password.empty() ? "" : kKeepPassword, std::to_string(s_.ftp.port),
                                   field_text(s_.ftp.file), field_text(s_.ftp.satellite), num_text(s_.ftp.period_days),
                                   std::to_string(static_cast<int>(s_.ftp.on_error))});
  }
  // 8 fields as listed; 6 as the seed's example (no file and satellite name: those in force stay).
  if (c.fields.size() != 8 && c.fields.size() != 6) return reply_error(c.head(), Error::parameter_count);
  const bool full = c.fields.size() == 8;
  Reader r(c.fields);
  FtpSource f = s_.ftp;
  f.host = c.fields[0];
  if (f.host.empty() || !valid_text_field(f.host, limits::kUrlMax) || f.host.find(' ') != std::string::npos)
    r.fail(Error::bad_value);
  // "?" (as SATELLITE_FTP? shows a stored password) keeps it, so a client that reads the settings and
  // writes them back changes nothing; "***", what trakbox answered before, is read the same way.
  const bool keep_password = c.fields[2] == kKeepPassword || c.fields[2] == "***";
  if (!valid_text_field(c.fields[1], limits::kNameMax) ||
      (!keep_password && !valid_text_field(c.fields[2], limits::kNameMax)))
    r.fail(Error::bad_value);
  f.user = c.fields[1];
  if (!keep_password) f.password = c.fields[2];
  f.port = static_cast<int>(r.integer(3, 1, 65535));
  std::size_t i = 4;
  if (full) {
    if (!safe_file_name(c.fields[4]) || c.fields[5].empty() || !valid_text_field(c.fields[5], limits::kNameMax))
      r.fail(Error::bad_value);
    f.file = c.fields[4];
    f.satellite = c.fields[5];
    i = 6;
  }
  f.period_days = r.number(i, 0.0, limits::kPeriodDays);
  f.on_error = r.flag(i + 1) ? ErrorAction::continue_last_data : ErrorAction::stop_tracking;
  if (!r.ok()) return reply_error(c.head(), r.error());
  if (f.file.empty() || f.satellite.empty()) return reply_error(c.head(), Error::not_allowed);
  const bool new_satellite = f.file != s_.ftp.file || f.satellite != s_.ftp.satellite || s_.source != TleSource::ftp;
  s_.ftp = f;
  s_.source = TleSource::ftp;
  download_failed_ = false;
  if (new_satellite) {
    // What is already on disk under that name serves until the download arrives.
    const Loaded l = load_file(f.file, f.satellite);
    if (l.elements) apply_load(l);
  }
  ++download_generation_;
  download_in_flight_ = false;
  start_download();
  changed();
  return reply_ok(c.head());
}

Unit::Reply Unit::cmd_load_image(const Command& c) {
  if (c.kind == Kind::query) {
    if (!c.fields.empty()) return reply_error(c.head(), Error::parameter_count);
    return reply_values(c.head(), {std::to_string(image_status_)});
  }
  if (c.fields.size() != 1) return reply_error(c.head(), Error::parameter_count);
  const std::string& name = c.fields[0];
  if (!safe_file_name(name)) return reply_error(c.head(), Error::bad_value);
  auto fail = [&](Error e, const std::string& why) {
    image_status_ = 2;
    spdlog::warn("satrak: image {} refused: {}", name, why);
    return reply_error(c.head(), e);
  };
  const fs::path path = opt_.image_dir / name;
  if (!stat_file(path)) return fail(Error::file_not_found, "no such file in " + opt_.image_dir.string());
  bool too_big = false;
  const std::string text = read_small_file(path, too_big);
  if (too_big) return fail(Error::invalid_file, "larger than 4 MiB");
  // The image is a state document: format, checksum, then every field of the data.
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return fail(Error::invalid_file, "not a JSON document");
  if (doc.value("format", "") != "trakbox-state") return fail(Error::invalid_file, "not a trakbox state document");
  if (!doc.contains("data") || !doc.contains("checksum") || !doc["checksum"].is_string())
    return fail(Error::invalid_file, "data or checksum missing");
  char sum[9];
  std::snprintf(sum, sizeof sum, "%08x", store::crc32(doc["data"].dump()));
  if (doc["checksum"].get<std::string>() != sum) return fail(Error::invalid_file, "checksum does not match");
  store::Model m;
  Settings ns = s_;
  try {
    m = store::model_from_json(doc["data"]);
    if (doc["data"].contains("satrak")) ns = settings_from_json(doc["data"]["satrak"], "satrak");
  } catch (const std::exception& e) {
    return fail(Error::invalid_file, e.what());
  }
  // Valid as a whole: now it replaces what is in force.
  m.clock_offset = clock_.offset();  // the clock keeps running as it is
  if (tracking_) stop_tracking(false);
  if (owner_ != Owner::none) {
    station_.rotator().stop();
    release();
  }
  station_.tracker().stop();
  model_ = std::move(m);
  s_ = std::move(ns);
  station_.reconfigure();
  window_started_ = window_prepositioned_ = false;
  tracking_stopped_fault_ = download_failed_ = false;
  ++download_generation_;
  download_in_flight_ = false;
  next_download_.reset();
  set_elements(std::nullopt);
  tle_missing_ = sat_missing_ = false;
  if (!active_file().empty() && !active_satellite().empty()) apply_load(load_file(active_file(), active_satellite()));
  if (s_.source != TleSource::file) next_download_ = clock_.now();
  pointing_changed();
  image_status_ = 1;
  spdlog::info("satrak: configuration image {} loaded", name);
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
