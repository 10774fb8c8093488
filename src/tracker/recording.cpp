#include "tracker/recording.h"

#include <cmath>

#include <fmt/format.h>

#include "util/text.h"

namespace tb::tracker {

bool records_satellite(const radio::RadioConfig& c, std::string_view name) {
  if (c.record == radio::Record::off) return false;
  if (text::trim(c.record_satellites).empty()) return true;
  const std::string wanted = text::lower(text::trim(name));
  for (const std::string_view item : text::split(c.record_satellites, ','))
    if (text::lower(text::trim(item)) == wanted) return true;
  return false;
}

std::string recording_file_name(std::string_view receiver, radio::Record kind, orbit::UtcTime start, radio::Hz hz) {
  if (receiver != "GQRX" || kind != radio::Record::audio) return {};
  const orbit::CivilTime c = orbit::to_civil(start);
  return fmt::format("gqrx_{:04d}{:02d}{:02d}_{:02d}{:02d}{:02d}_{}.wav", c.year, c.month, c.day, c.hour, c.minute,
                     static_cast<int>(std::floor(c.second)), hz);
}

}  // namespace tb::tracker
