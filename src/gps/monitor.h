// What trakbox knows of its GPS receiver, and what it believes of it. Pure: the gpsd client
// (gpsd_client.h) feeds it the link's events and gpsd's reports on the event loop's thread, with the
// program clock's reading; it answers with the notes to log (each problem once) and keeps the
// confirmed position, the fix and the clock's error against GPS time (docs/gps.md).
//
// "Confirmed": a position is trusted only after kConfirmReports (3) reports in a row with a 2D or
// 3D fix, each a sane value (latitude within +-90, longitude within +-180, altitude -1000..20000 m)
// and each reachable from the one before at 300 m/s plus 50 m of noise. A report that is not (a
// jump) starts a second chain; the confirmed chain goes on if the receiver comes back to it, and the
// new place is taken only when it in turn holds for kConfirmReports reports. A lost fix ends the run:
// after it the receiver confirms again. The station (and so the antenna) moves only to confirmed
// positions (StationLoop::apply_gps_position).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "orbit/time.h"

namespace tb::gps {

inline constexpr int kConfirmReports = 3;
inline constexpr double kMaxSpeedMps = 300.0;      // faster than this between two reports is a jump
inline constexpr double kNoiseM = 50.0;            // what a fix may wander between reports
inline constexpr double kClockWarnS = 0.5;         // the clock is warned about beyond this
inline constexpr double kClockClearS = 0.25;       // and the warning ends below this
inline constexpr double kMinAltitudeM = -1000.0, kMaxAltitudeM = 20000.0;

// One position/time report of gpsd (a TPV): mode 0 not seen, 1 no fix, 2 2D, 3 3D.
struct Report {
  int mode = 0;
  std::optional<double> lat_deg, lon_deg, alt_m;  // alt_m: height above the WGS-84 ellipsoid
  std::optional<orbit::UtcTime> time;
};

struct Position {
  double lat_deg = 0.0, lon_deg = 0.0;
  std::optional<double> alt_m;  // none for a 2D fix
  orbit::UtcTime time{};        // GPS time of the report (the clock's when it had none)
  int mode = 0;
};

// Great-circle distance on the mean Earth sphere (R = 6371008.8 m), metres.
double distance_m(double lat1_deg, double lon1_deg, double lat2_deg, double lon2_deg);

// Why a report's values cannot be a position ("latitude 95.000000 is outside -90..90"), or nothing.
std::optional<std::string> nonsense(const Report& r);

// The chain-of-reports filter described above.
class PositionFilter {
 public:
  enum class Verdict { confirmed, confirming, no_fix, nonsense, jump, jump_taken };
  struct Result {
    Verdict verdict = Verdict::no_fix;
    std::string why;      // nonsense / jump: what was wrong
  };
  Result add(const Report& r, orbit::UtcTime clock_now);
  // The latest position of the confirmed chain, once confirmed (kept through a lost fix).
  const std::optional<Position>& confirmed() const { return confirmed_; }
  // The receiver has a confirmed fix now (not lost since).
  bool fixed() const { return fixed_; }
  // The receiver cannot be heard (gpsd gone): as a lost fix, without a report.
  void lose() {
    fixed_ = false;
    if (main_) main_->run = 0;
    other_.reset();
  }

 private:
  struct Chain {
    Position last;
    int run = 0;
  };
  static bool reachable(const Position& from, const Position& to);
  std::optional<Chain> main_, other_;
  std::optional<Position> confirmed_;
  bool fixed_ = false;
};

// The state of the link to gpsd, as the client reports it.
enum class Link { off, connecting, no_gpsd, no_receiver, receiving, lost };

struct Note {
  bool warning = false;
  std::string text;
};

class Monitor {
 public:
  explicit Monitor(std::string source = {}) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }  // "gpsd:localhost:2947"; "" none
  bool configured() const { return !source_.empty(); }

  // From the client. detail: gpsd's or the system's words for a failure.
  std::vector<Note> on_link(Link l, const std::string& detail = {});
  std::vector<Note> on_devices(int count);
  std::vector<Note> on_report(const Report& r, orbit::UtcTime clock_now);

  Link link() const { return link_; }
  const PositionFilter& filter() const { return filter_; }
  const std::optional<Report>& last_report() const { return last_; }
  // GPS time minus the program clock at the last report with a fix and a time: the receiver's
  // report arrives after its time (gpsd and the NMEA cycle: typically 0.1 to 0.5 s), which counts in.
  std::optional<double> clock_error_s() const { return clock_error_s_; }
  // The clock differs from GPS time by more than kClockWarnS (for kConfirmReports reports in a row;
  // cleared after as many within kClockClearS).
  bool clock_warned() const { return clock_warned_; }
  // ERRSTATUS X12: the receiver cannot be heard (no gpsd, gpsd without a receiver, gpsd gone).
  bool comm_error() const { return configured() && link_ != Link::receiving; }
  // For the status line: "" when all is well, else "GPS NO FIX", "NO GPSD", "GPS TIME +3600.0s", ...
  std::string status_word() const;
  // One line for menus and host mode: "3D fix 41.0100N 29.1700E 120 m at 2026-05-21 12:00:05 UTC".
  std::string describe() const;

 private:
  std::string source_;
  Link link_ = Link::off;
  std::string link_detail_;
  PositionFilter filter_;
  std::optional<Report> last_;
  std::optional<double> clock_error_s_;
  bool clock_warned_ = false;
  int far_run_ = 0, near_run_ = 0;  // reports in a row beyond kClockWarnS / within kClockClearS
  bool nonsense_said_ = false, no_fix_said_ = false;
};

}  // namespace tb::gps
