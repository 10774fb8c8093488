// Everything the operator sets, in one value: what TrakBox kept in battery-backed RAM.
// Saved as one document (state_file.h); to_json/from_json validate every field, so a document that
// passes its checksum but holds nonsense is still refused as a whole.
#pragma once
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "radio/config.h"
#include "rotator/config.h"
#include "station/station.h"
#include "store/database.h"
#include "store/refresh.h"

namespace tb::store {

// Elevations at which things happen around a pass, from the later firmware's STATION.DAT line 5.
// The tracker starts the rotor at rotor_start_el_deg; AOS is still reported at the manual's -2.0 deg,
// and the output line's elevations are stored and shown only: trakbox has no such line to drive
// (docs/menus/6-7-8.md, "STATION.DAT of the later firmware").
struct PassEvents {
  double rotor_start_el_deg = -2.0;  // the rotor starts following the satellite above this
  double output_on_el_deg = -2.0;    // the AOS/LOS output line ("P16") goes active at AOS above this
  double output_off_el_deg = -2.0;   // and inactive at LOS below this
  bool operator==(const PassEvents&) const = default;
};

// What the operator last chose to track (menu 1 or S, M, the selector, a station operation): what a
// restarted station, the service above all, tracks again. `list` is the rule for a state that holds
// no choice yet: the first multi_count of the tracking list when it has two or more, else the '*'.
struct TrackingChoice {
  enum class Mode { list, single, multi };
  Mode mode = Mode::list;
  int catalog_number = 0;  // single: the satellite (by catalog number: it outlives uploads)
  std::string name;        // its name then, for the messages when it is gone
  bool operator==(const TrackingChoice&) const = default;
};

// Sharing the station (issue 44, docs/sharing.md): how long an outside client's silence ends its
// hold (--handback, 0: never by silence), the kind of client that holds exclusively (--exclusive:
// "rotctld", "rigctld", "satrak" or "" for none), standby (nothing moves by itself).
struct Reservation {  // the operator's own (`trakbox reserve`, the web): a window trakbox's tracking yields to
  std::string id;
  std::int64_t start_unix = 0, end_unix = 0;
  std::string note;
  bool operator==(const Reservation&) const = default;
};
inline constexpr std::size_t kMaxReservations = 64;

struct Sharing {
  int handback_s = 30;
  std::string exclusive;
  bool standby = false;
  std::vector<Reservation> reservations;  // start order
  int satnogs_station = 0;                 // --satnogs-station (0: none)
  std::string satnogs_url;                 // --satnogs-url ("": the public Network)
  bool operator==(const Sharing&) const = default;
};

// The logger (--logger, --logger-key-file, --logger-station-id; docs/logbook.md): the key itself is
// never stored, only the file it is read from at the start.
struct LoggerConfig {
  std::string spec;       // "cloudlog:URL" or "wavelog:URL"; "": none
  std::string key_file;
  int station_id = 0;     // Cloudlog's station_profile_id (0: not given)
  bool operator==(const LoggerConfig&) const = default;
};

struct Model {
  station::StationConfig station;
  rotator::RotatorConfig rotator;
  radio::RadioConfig radio;
  Database db;
  std::chrono::microseconds clock_offset{0};  // menu 5: RTC = system time + offset
  bool rotor_control = false;                 // the E key, --rotor-control, menu 6-R
  TrackingChoice tracking;                    // what the station tracks after a restart
  bool priority_mode = false;                 // M: priority sub-mode
  RefreshSettings refresh;                    // menu 3-5: scheduled element refresh
  PassEvents pass_events;                     // STATION.DAT line 5 of the later firmware
  // --event-min-el: no AOS/LOS event (nor hook) for a pass whose maximum elevation is under this.
  double event_min_el_deg = 0.0;
  // STATION.DAT line 6 of the later firmware: a stalled rotator is declared in error (after
  // rotator.stall_s): the controller's stall watch (off: Controller::set_error_detection).
  bool rotator_error_detection = true;
  // --rotator and --radio as last given ("" or "simulated": the simulated station); a start
  // without them drives these (store/drivers.h).
  std::string rotator_driver;
  std::string radio_driver;
  station::GpsSettings gps;                   // --gps, menu 4: the receiver and the position's origin
  // --udp-events as last given: "HOST:PORT" or "[IPV6]:PORT" each (util/host_port.h), at most
  // kMaxUdpEvents; --udp-events none empties it.
  std::vector<std::string> udp_events;
  Sharing sharing;
  LoggerConfig logger;
};
inline constexpr std::size_t kMaxUdpEvents = 16;

// The factory defaults (menu 6-9 without a station file), with the shipped database when given.
Model factory_defaults();

nlohmann::json to_json(const Model& m);
// Throws std::runtime_error naming the field ("db.satellites[3].elements.eccentricity: ...").
Model model_from_json(const nlohmann::json& j);

}  // namespace tb::store
