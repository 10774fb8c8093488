// The sky calibration (issue 58): "this is the Sun / the Moon" and its undo, through the model's owner
// (tracker/operations.h; the mathematics in rotator/sky_calibration.h; docs/calibration.md).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orbit/sky.h"
#include "rotator/adc_model.h"
#include "rotator/sky_calibration.h"
#include "store/model.h"
#include "store/owner.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "util/text.h"

namespace tb::tracker {

namespace {

OpResult store_offsets(store::ModelOwner& owner, const rotator::OffsetChange& change, const char* what,
                       store::Origin origin) {
  if (!change.ok()) return OpResult::refuse(change.error);
  const store::EditResult r = owner.edit(store::bit(store::Area::rotator), what, origin,
                                         [&](store::Model& m) { m.rotator = change.after; });
  if (!r.ok()) return OpResult::refuse(*r.refusal);
  OpResult done;
  done.model_changed = r.changed;
  return done;
}

}  // namespace

std::string calibration_text(const rotator::RotatorConfig& c) {
  if (c.sky.source.empty())
    return fmt::format("offsets az {:+.2f} el {:+.2f} deg (no sky calibration recorded)", c.az_offset_deg, c.el_offset_deg);
  return fmt::format("offsets az {:+.2f} el {:+.2f} deg, from the {} at {}", c.az_offset_deg, c.el_offset_deg,
                     c.sky.source, c.sky.time);
}

OpResult calibrate_offsets(store::ModelOwner& owner, orbit::Body body, orbit::UtcTime t, rotator::AzEl reading,
                           store::Origin origin, const std::string& source) {
  const store::Model& m = owner.model();
  const orbit::LookAngles look = orbit::body_look(body, m.station.observer(), t);
  const rotator::BodyFix fix = rotator::body_fix(body, t, reading, look);
  if (!fix.ok()) return OpResult::refuse(fix.error);
  const rotator::RotatorConfig before = m.rotator;
  const std::string when = orbit::format_iso8601(t);
  OpResult r = store_offsets(owner, rotator::offsets_for(before, fix.correction,
                                                  source.empty() ? text::lower(orbit::body_name(body)) : source, when),
                             "sky calibration", origin);
  if (!r.ok()) return r;
  r.note = fmt::format("{} computed at az {:.2f} el {:.2f}, the rotator read az {:.2f} el {:.2f} at {}: correction "
                       "az {:+.2f} el {:+.2f} deg; offsets now az {:+.2f} el {:+.2f} (were {:+.2f} {:+.2f})",
                       orbit::body_name(body), look.az_deg, look.el_deg, reading.az, reading.el, when,
                       fix.correction.az_deg, fix.correction.el_deg, owner.model().rotator.az_offset_deg,
                       owner.model().rotator.el_offset_deg, before.az_offset_deg, before.el_offset_deg);
  return r;
}

OpResult undo_calibration(store::ModelOwner& owner, store::Origin origin) {
  const rotator::RotatorConfig before = owner.model().rotator;
  OpResult r = store_offsets(owner, rotator::undo_offsets(before), "sky calibration undone", origin);
  if (!r.ok()) return r;
  r.note = fmt::format("undone: {} (were az {:+.2f} el {:+.2f})", calibration_text(owner.model().rotator),
                       before.az_offset_deg, before.el_offset_deg);
  return r;
}

OpResult StationOps::calibrate(orbit::Body body, std::optional<rotator::AzEl> reading) {
  if (!reading) reading = station_.antenna();
  if (!reading) {
    const auto& link = station_.rotator().status().link;
    return OpResult::refuse("the rotator's position is not known" + (link.ok() ? std::string() : ": " + link.message));
  }
  OpResult r = calibrate_offsets(station_.owner(), body, station_.clock().now(), *reading, origin());
  if (!r.ok()) return r;
  spdlog::info("calibrate: {}", r.note);  // the station's log (trakbox.log)
  // The antenna stays where it was peaked: a direct target (a goto) was in the old readings' terms
  // and would now move it by the correction. Tracking, if on, points afresh at its next tick.
  if (station_.tracker().mode() == Mode::off) station_.rotator().stop();
  station_.antenna_changed();
  return r;
}

OpResult StationOps::calibrate_scan(orbit::UtcTime t, double az_correction_deg, double el_correction_deg) {
  // The reading that correction belongs to, against the Sun at t: calibrate_offsets finds it again.
  const orbit::LookAngles sun = orbit::body_look(orbit::Body::sun, model_.station.observer(), t);
  const rotator::AzEl reading{rotator::wrap360(sun.az_deg - az_correction_deg), sun.el_deg - el_correction_deg};
  OpResult r = calibrate_offsets(station_.owner(), orbit::Body::sun, t, reading, origin(), "sun scan");
  if (!r.ok()) return r;
  spdlog::info("calibrate: sun scan: {}", r.note);
  station_.antenna_changed();
  return r;
}

OpResult StationOps::calibrate_undo() {
  OpResult r = undo_calibration(station_.owner(), origin());
  if (!r.ok()) return r;
  spdlog::info("calibrate: {}", r.note);
  if (station_.tracker().mode() == Mode::off) station_.rotator().stop();  // as calibrate: stays where it is
  station_.antenna_changed();
  return r;
}

}  // namespace tb::tracker
