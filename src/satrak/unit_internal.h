// What the parts of the Satrak unit share (unit.cpp, unit_tracking.cpp, unit_elements.cpp and the
// command files): limits of the commands, reply field formatting and the request field reader.
// Private to src/satrak: nothing outside includes it.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/time.h"
#include "rotator/satrak/commands.h"

namespace tb::satrak::detail {

inline constexpr double kMaxRateDegS = 90.0;   // MOVE: faster requests are out of range
inline constexpr double kMaxStepDeg = 360.0;   // STEP
inline constexpr double kPassSearchDays = 1.0;
// The TLE file a unit that has had no SATELLITE= uses: the station's database, written to the TLE
// directory under this name (Unit::default_source, docs/satrak.md).
inline constexpr const char* kDatabaseTleFile = "database.tle";
inline constexpr const char* kDatabaseOmmFile = "database.json";  // when a number is beyond a TLE's
// The reasons of ERR,8 for motion (MOVE, STEP, GOTO): the unit tracks (or goes to the track
// window's start) and keeps the antenna; the rotator has not reported a position yet.
inline constexpr const char* kTrackingReason = "TRACKING: STOP= FIRST";
inline constexpr const char* kNoPositionReason = "NO POSITION YET";

// What SATELLITE_FTP? answers for a stored password: never the password itself (the Satrak
// protocol has no authentication: anyone who can reach the port would read it), and nothing with
// '*' or '$', which end or start a frame. Written back, it keeps the stored password
// (docs/satrak.md).
inline constexpr const char* kKeepPassword = "?";

inline double seconds_between(orbit::UtcTime a, orbit::UtcTime b) {
  return std::chrono::duration<double>(b - a).count();
}

// Reply fields.
inline std::string b(bool v) { return v ? "1" : "0"; }
inline std::string f2(double v) { return format_fixed(v, 2); }
std::string num_text(double v);  // %.10g
// A reply field must not break the frame: no `,`, `*`, `$`, control bytes.
std::string field_text(std::string_view s);
// Hour, minute, second, day, month, year[, ms] of t.
std::vector<std::string> civil_fields(orbit::UtcTime t, bool with_ms, bool two_digit_year = false);

// STATUS?'s 16 fields by name, in the reply's order (the seed's X1..X16; docs/satrak.md "STATUS?
// (16 fields)").
struct StatusFields {
  bool fault = false;                  // X1: any ERRSTATUS flag set
  double true_az_deg = 0.0;            // X2: axis azimuth + north offset
  double el_deg = 0.0;                 // X3
  bool x_plus_limit = false;           // X4: CW end
  bool x_minus_limit = false;          // X5: CCW end
  bool y_plus_limit = false;           // X6: up
  bool y_minus_limit = false;          // X7: down
  bool tracking = false;               // X8
  int window_status = 0;               // X9: TrackStatus
  bool rtc_updated_by_gps = false;     // X10: the clock was set from GPS time
  int gps_lock_delay_s = 0;            // X11
  int x_motion = 0;                    // X12: -1, 0, 1
  int y_motion = 0;                    // X13
  double x_deg = 0.0;                  // X14: axis angles
  double y_deg = 0.0;                  // X15
  bool auto_track = false;             // X16
  std::vector<std::string> fields() const;
};

// Request fields.
bool valid_http_url(std::string_view u);
bool valid_text_field(std::string_view s, std::size_t max_len);
// Why a latitude/longitude field did not parse: a number out of range, or not a coordinate at all.
Error coordinate_error(std::string_view s, std::string_view letters);

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
  double number(std::size_t i, double lo, double hi);
  // A whole number; "12.0" is taken as 12.
  long long integer(std::size_t i, long long lo, long long hi);
  bool flag(std::size_t i);
  // H, M, S, D, Mo, Y from field i on. A two-digit year is 20YY.
  orbit::UtcTime civil(std::size_t i);

 private:
  const std::vector<std::string>& f_;
  std::optional<Error> err_;
};

}  // namespace tb::satrak::detail
