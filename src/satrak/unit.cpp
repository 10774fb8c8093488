// The Satrak unit: start and stop, payload dispatch over the command table, and who drives the
// antenna. The tracking state machine is in unit_tracking.cpp, the element sources in
// unit_elements.cpp, the commands in unit_commands.cpp and unit_source_commands.cpp.
#include "satrak/unit.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include <spdlog/spdlog.h>

#include "satrak/unit_internal.h"
#include "tracker/operations.h"

namespace tb::satrak {
namespace fs = std::filesystem;
using rotator::AzEl;
using rotator::RotatorPosition;

struct Unit::Timer {
  explicit Timer(boost::asio::io_context& io) : t(io) {}
  boost::asio::steady_timer t;
};

Unit::Unit(boost::asio::io_context& io, tracker::StationLoop& station, const store::Model& model,
           station::RealTimeClock& clock, Settings settings, UnitOptions options, UnitHooks hooks)
    : io_(io),
      station_(station),
      model_(model),
      clock_(clock),
      s_(std::move(settings)),
      opt_(std::move(options)),
      hooks_(std::move(hooks)),
      timer_(std::make_unique<Timer>(io)) {
  // GPS mode is the station's (menu 4, --gps-follow); a state written before it was, kept it here.
  if (s_.gps_auto && !model_.gps.follow) (void)station_.owner().set("gps.follow", true, store::Origin::satrak);
  s_.gps_auto = model_.gps.follow;
  position_generation_seen_ = station_.position_generation();
  std::error_code ec;
  if (!opt_.tle_dir.empty()) fs::create_directories(opt_.tle_dir, ec);
  if (!opt_.image_dir.empty()) fs::create_directories(opt_.image_dir, ec);
  if (!active_file().empty() && !active_satellite().empty()) apply_load(load_file(active_file(), active_satellite()));
  if (s_.source != TleSource::file) next_download_ = clock_.now();
}

Unit::~Unit() {
  running_ = false;
  timer_->t.cancel();
  if (tracking_) station_.remote_follow(std::nullopt);
  downloader_.reset();  // aborts and joins: no callback runs after this
  alive_.reset();
}

void Unit::start() {
  if (running_) return;
  running_ = true;
  struct Loop {
    static void arm(Unit* u, std::weak_ptr<int> alive) {
      // The period is simulated time: under --clock-rate R the check runs R times as often.
      u->timer_->t.expires_after(station::wall_wait(u->opt_.period, u->clock_.rate()));
      u->timer_->t.async_wait([u, alive](const boost::system::error_code& ec) {
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
  timer_->t.cancel();
}

void Unit::store_clock_offset() {
  (void)station_.owner().edit(store::bit(store::Area::other), "clock offset", store::Origin::satrak,
                              [this](store::Model& m) { m.clock_offset = clock_.offset(); });
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

std::string Unit::handle(const Decoded& d, std::string_view client) {
  switch (d.kind) {
    case Decoded::Kind::frame: return handle(std::string_view(d.payload), client);
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

std::string Unit::handle(std::string_view payload, std::string_view client) {
  client_ = client;
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
    station_.control().heard(client_, station_.now());  // a Satrak client that speaks keeps its hold
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
  if (!model_.rotor_control) tracker::StationOps(station_).rotor_control(true);
}

std::optional<std::string> Unit::take_antenna() {
  // The controller of record first (tracker/control.h): in standby and under another kind's
  // --exclusive hold nothing moves, and the station's tracking goes on.
  tracker::Control::Answer a =
      station_.control().request(tracker::Resource::antenna, {tracker::HolderKind::satrak, client_}, station_.now());
  station_.apply(a.changes);
  if (!a.granted) {
    const std::string why = a.refusal.value_or("the antenna is held");
    spdlog::info("satrak: {}: refused: {}", client_, why);
    return why;
  }
  // The Satrak client holds the antenna: status, the page and events say so.
  if (station_.tracker().mode() != tracker::Mode::off) station_.tracker().stop();
  holder_ = client_;
  return std::nullopt;
}

void Unit::client_left(std::string_view client) {
  station_.apply(station_.control().left(client, station_.now()));
  if (holder_ != client) return;
  // Its hold ended with it, and what held before drives again (trakbox's tracking when it has a
  // choice). Its tracking and a jog stop (nobody would end them); a GOTO already sent completes, as
  // a rotctld client's last P does.
  if (tracking_ || owner_ == Owner::track) stop_tracking(false);
  if (owner_ == Owner::move) station_.rotator().stop();
  release();
  holder_.clear();
  station_.antenna_changed();
}

void Unit::command(RotatorPosition p, rotator::Controller::Approach how) {
  commanded_ = station_.rotator().set_target(p, how);
}

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
  // The controller of record says who holds the antenna: a Satrak client's hold ends when another
  // takes it (the operator, another client), when it is handed back (silence, standby), not by
  // guessing from the rotator's target.
  const tracker::Holder& h = station_.control().holder(tracker::Resource::antenna);
  // (Inside a SatNOGS window the label names the window and the client: "... (satrak ADDR:PORT)".)
  const bool lost = h.kind != tracker::HolderKind::satrak || holder_.empty() || h.label.find(holder_) == std::string::npos;
  if (!lost) return;
  spdlog::info("satrak: the antenna is {}'s now; Satrak {} stopped", h.label, tracking_ ? "tracking" : "motion");
  holder_.clear();
  if (tracking_) {
    tracking_ = false;
    auto_started_ = false;
    tracking_stopped_fault_ = true;
    last_track_target_.reset();
    station_.remote_follow(std::nullopt);
  }
  release();
}


}  // namespace tb::satrak
