#pragma once
// A satellite QSO as the logbook keeps it, and the checks every front end's input goes through
// (pure: values in, values out). Frequencies in Hz; time on in UTC seconds since 1970.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace tb::logbook {

enum class Source { web, menus, host, cli, import };

struct Qso {
  std::int64_t id = 0;          // 0 until stored
  int version = 1;              // 1 when made, +1 at each edit (the previous kept in qso_version)
  bool deleted = false;         // delete is a mark
  std::string call;             // theirs, upper case
  std::string grid;             // theirs, Maidenhead ("" when not given)
  std::string rst_sent, rst_rcvd;
  std::int64_t time_on = 0;     // UTC, to the second
  std::string sat_name;         // the database's name ("RS-44")
  std::string lotw_name;        // TQSL's spelling ("RS-44", "ARISS"); "" when not known
  int norad = 0;                // 0 when not known
  std::string mode;             // the emission: FM, SSB, CW, ... (never "SAT")
  std::string submode;          // ADIF's SUBMODE of it: FT4 (of MFSK), "" for none
  std::int64_t uplink_hz = 0, downlink_hz = 0;              // nominal (the transponder's)
  std::int64_t uplink_tuned_hz = 0, downlink_tuned_hz = 0;  // as tuned (Doppler applied)
  std::string band, band_rx;    // ADIF bands of the uplink and the downlink ("2m", "70cm")
  std::string my_grid, station_call;
  double power_w = 0;           // 0: not given
  std::string note;
  Source source = Source::cli;
  bool operator==(const Qso&) const = default;
};

std::string_view source_name(Source s);
std::optional<Source> source_from_name(std::string_view name);

// The refusals name the field: "call: ..." ; nullopt when the value is good.
std::optional<std::string> check_callsign(std::string_view field, std::string_view call);
std::optional<std::string> check_grid(std::string_view field, std::string_view grid);
std::optional<std::string> check_rst(std::string_view field, std::string_view rst);
// The mode against ADIF's Mode enumeration ("" allowed: not known); the refusal names the field
// ("mode: 'FT4' is a submode in ADIF; log it as MFSK"). What goes to a logger or a file is then
// one of the names its parser knows (and never text that could end a record).
bool is_adif_mode(std::string_view mode);
std::optional<std::string> check_mode(std::string_view mode);
// The whole record (after normalize): the first problem, naming its field.
std::optional<std::string> check_qso(const Qso& q);

// Upper-case calls, grids as "FN31pr", the mode as adif_mode has it (USB -> SSB), bands filled from
// the frequencies when empty.
Qso normalized(Qso q);

// The ADIF band of a frequency ("2m", "70cm", "13cm"); "" outside every amateur band.
std::string band_of(std::int64_t hz);
// The lower and upper edge of an ADIF band (Hz); nullopt for a name not in ADIF's table.
std::optional<std::pair<std::int64_t, std::int64_t>> band_edges(std::string_view band);
// The satellite mode code of an uplink and a downlink ("U/V": up on 70 cm, down on 2 m); "" when
// either band has no letter.
std::string sat_mode(std::int64_t uplink_hz, std::int64_t downlink_hz);
// The emission of a radio mode name as ADIF has it: "usb"/"lsb" -> "SSB", "fm" -> "FM",
// "cw"/"cwr" -> "CW"; other names upper-cased.
std::string adif_mode(std::string_view radio_mode);
// A satellite mode's name (store's modes: "FT4", "SSB", "APRS", "Mode-A") as ADIF's MODE and
// SUBMODE: FT4 -> MFSK / FT4, PSK31 -> PSK / PSK31, FM -> FM / "", APRS -> PKT / ""; nothing for a
// name that is neither (the radio's link mode says it then).
std::optional<std::pair<std::string, std::string>> adif_of_mode_name(std::string_view name);

// Days since 1970 of a civil date, and back (Howard Hinnant's algorithms).
std::int64_t days_from_civil(int y, unsigned m, unsigned d);
void civil_from_days(std::int64_t z, int& y, unsigned& m, unsigned& d);
// "2026-12-01 21:44:20" of UTC seconds.
std::string utc_text(std::int64_t t);
// "2026-12-01" or "2026-12-01T21:44[:20][Z]" (or a space for T) into UTC seconds.
std::optional<std::int64_t> parse_utc(std::string_view s);

}  // namespace tb::logbook
