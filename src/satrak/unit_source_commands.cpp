// The Satrak commands that choose where element sets come from (a file, HTTP, FTP) and load an
// image (docs/satrak.md).
#include "util/json_limits.h"
#include "util/redact.h"
#include <spdlog/spdlog.h>

#include "satrak/source_files.h"
#include "satrak/unit.h"
#include "satrak/unit_internal.h"
#include "store/state_file.h"

namespace tb::satrak {
namespace fs = std::filesystem;
using namespace detail;

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
    // A password inside the URL is answered as <redacted>; writing that answer back keeps it.
    return reply_values(c.head(), {field_text(redact::url_credentials(s_.http.url)), num_text(s_.http.period_days),
                                   std::to_string(static_cast<int>(s_.http.on_error))});
  }
  if (c.fields.size() != 4) return reply_error(c.head(), Error::parameter_count);
  Reader r(c.fields);
  // What SATELLITE_HTTP? answered (the URL with its password as <redacted>) keeps the stored URL.
  const bool keep_url = !s_.http.url.empty() && c.fields[0] == redact::url_credentials(s_.http.url);
  const std::string url = keep_url ? s_.http.url : c.fields[0];
  if (!valid_http_url(url)) r.fail(Error::bad_value);
  const double period = r.number(1, 0.0, limits::kPeriodDays);
  const bool cont = r.flag(2);
  const bool keep_tracking = r.flag(3);
  if (!r.ok()) return reply_error(c.head(), r.error());
  // The HTTP settings name no file or satellite: those of SATELLITE= are used; on a unit that has
  // had none (the document's example on a fresh unit), the station's database and its first satellite.
  std::optional<Source> fallback;
  if (s_.tle_file.empty() || s_.satellite.empty()) {
    fallback = default_source();
    if (!fallback) return reply_error(c.head(), Error::not_allowed, "NO SATELLITE: SATELLITE= FIRST");
  }
  s_.http = HttpSource{url, period, cont ? ErrorAction::continue_last_data : ErrorAction::stop_tracking};
  if (fallback) {
    s_.tle_file = fallback->file;
    s_.satellite = fallback->satellite;
  }
  s_.source = TleSource::web;
  // The database file serves until the download arrives.
  if (fallback) apply_load(load_file(s_.tle_file, s_.satellite));
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
    return reply_values(c.head(), {field_text(redact::url_credentials(s_.ftp.host)), field_text(s_.ftp.user),
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
  // Credentials go in the user and password fields, never in the host ("ftp://u:PW@host" would be
  // answered back by SATELLITE_FTP? and written to the log).
  if (f.host.empty() || !valid_text_field(f.host, limits::kUrlMax) || f.host.find(' ') != std::string::npos ||
      f.host.find('@') != std::string::npos)
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
  if (f.file.empty() || f.satellite.empty()) {
    // The six-field form (the document's example) names no file or satellite and none is in force
    // for FTP: those of SATELLITE=, as SATELLITE_HTTP= uses them; on a unit that has had none, the
    // station's database and its first satellite.
    if (!s_.tle_file.empty() && !s_.satellite.empty()) {
      f.file = s_.tle_file;
      f.satellite = s_.satellite;
    } else if (const auto d = default_source()) {
      f.file = d->file;
      f.satellite = d->satellite;
    } else {
      return reply_error(c.head(), Error::not_allowed, "NO SATELLITE: SATELLITE= FIRST");
    }
  }
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
  std::string why;
  const nlohmann::json doc = json_limits::parse_bounded<nlohmann::json>(text, why);
  if (why.starts_with("nested")) return fail(Error::invalid_file, "JSON nested too deep");
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
  const store::EditResult kept = station_.owner().edit(store::kAllAreas, "LOAD_IMAGE", store::Origin::satrak,
                                                       [&](store::Model& mm) { mm = std::move(m); });
  if (!kept.ok()) return fail(Error::invalid_file, *kept.refusal);
  s_ = std::move(ns);
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

}  // namespace tb::satrak
