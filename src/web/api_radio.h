// POST /api/v1/radio's body into a StationOps operation (docs/web-api.md):
//   {"doppler":true|false}, {"spot_hz":N}, {"rx_offset_hz":N,"tx_offset_hz":N} (either or both),
//   {"tone_hz":X}. A malformed body is the 400 sentence returned; otherwise `done` is the result.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "tracker/operations.h"

namespace tb::web {

std::optional<std::string> radio_request(tracker::StationOps& ops, const nlohmann::json& body, tracker::OpResult& done);
// POST /api/v1/station: {"locator":"JN58td"} (its centre, height 0 unless "height_m") or
// {"lat_deg":N,"lon_deg":E,"height_m":M} (height optional: the stored one), with or without
// {"callsign":"W1AW"} (alone: the callsign only), and or else {"horizon_mask":"0 5; 214 25; 263 5"}
// (any form orbit::read_horizon_mask takes, pairs one a line too; "none" or "" for no mask; a
// malformed one is the 400 sentence, the reader's); all of it checked before anything changes.
std::optional<std::string> station_request(tracker::StationOps& ops, double stored_height_m, const nlohmann::json& body,
                                           tracker::OpResult& done);

}  // namespace tb::web
