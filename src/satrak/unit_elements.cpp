// The Satrak unit's element sources: the TLE file in the unit's directory (watched for changes),
// the HTTP and FTP downloads, and the faults ERRSTATUS? reports.
#include <algorithm>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>

#include <spdlog/spdlog.h>

#include "satrak/redact.h"
#include "satrak/source_files.h"
#include "satrak/unit.h"
#include "satrak/unit_internal.h"
#include "store/state_file.h"
#include "util/text.h"

namespace tb::satrak {
using namespace detail;
namespace fs = std::filesystem;

std::string Unit::active_file() const { return s_.source == TleSource::ftp ? s_.ftp.file : s_.tle_file; }
std::string Unit::active_satellite() const { return s_.source == TleSource::ftp ? s_.ftp.satellite : s_.satellite; }
double Unit::active_period_days() const {
  switch (s_.source) {
    case TleSource::web: return s_.http.period_days;
    case TleSource::ftp: return s_.ftp.period_days;
    default: return s_.tle_period_days;
  }
}

std::optional<Unit::Source> Unit::default_source() {
  const store::Database& db = model_.db;
  const store::Satellite* first = db.listed(1);
  if (!first && !db.satellites.empty()) first = &db.satellites.front();
  if (!first) return std::nullopt;
  const orbit::Elements& e = first->elements;
  // The name as SATELLITE= would take it; a name the frame cannot carry is looked up by number.
  const std::string name = !e.name.empty() && valid_text_field(e.name, limits::kNameMax) && e.name == text::trim(e.name)
                               ? e.name
                               : std::to_string(e.catalog_number);
  // A TLE file, unless a satellite's number is beyond what a TLE holds (OMM only, since 2026):
  // then the whole database as OMM JSON, which the unit reads as well.
  const bool tle = std::none_of(db.satellites.begin(), db.satellites.end(),
                                [](const store::Satellite& s) { return orbit::nasa_unwritable(s.elements); });
  const char* file = tle ? kDatabaseTleFile : kDatabaseOmmFile;
  const fs::path path = opt_.tle_dir / file;
  if (!stat_file(path)) {
    std::string text;
    if (tle) {
      for (const auto& s : db.satellites) text += orbit::format_nasa(s.elements);
    } else {
      std::vector<orbit::Elements> sets;
      for (const auto& s : db.satellites) sets.push_back(s.elements);
      text = orbit::format_omm(sets, orbit::OmmEncoding::json);
    }
    std::string err;
    if (!store::write_file_atomically(path, text, err, 0644)) spdlog::warn("satrak: {}", err);
    else spdlog::info("satrak: no satellite chosen yet: the station's database is {}", path.string());
  }
  return Source{file, name};
}

namespace {
const orbit::Elements* find_satellite(const std::vector<orbit::Elements>& sets, const std::string& name) {
  for (const auto& e : sets)
    if (e.name == name) return &e;
  const std::string want = text::lower(text::trim(name));
  for (const auto& e : sets)
    if (text::lower(text::trim(e.name)) == want) return &e;
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
  download::DownloadRequest r;
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
  if (!downloader_) downloader_ = std::make_unique<download::Downloader>();
  spdlog::info("satrak: downloading {}", redact_url(r.url));
  std::weak_ptr<int> alive = alive_;
  boost::asio::io_context& io = io_;
  downloader_->submit(std::move(r), [this, alive, &io, src, gen](download::DownloadResult res) {
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

void Unit::on_download(TleSource src, std::uint64_t gen, download::DownloadResult r) {
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
  // A receiver is expected (--gps, or GPS mode chosen) and cannot be heard: none, no gpsd, gpsd
  // without a receiver, gpsd gone. A receiver without a fix is heard: GPS_DATA? X3 says 0.
  const gps::Monitor* g = station_.gps();
  f.gps = g ? g->comm_error() : model_.gps.follow;
  return f;
}
}  // namespace tb::satrak
