// Element sets: the mean orbital elements of one satellite at one epoch, and the file formats they
// travel in (NASA two/three-line, AMSAT verbose, gpredict, CCSDS OMM in JSON, XML, CSV and KVN).
// Parsing never throws for bad input: it returns the good sets and a list of problems, each naming
// file, line, column/field (an OMM object and keyword), what was found and what was expected. The
// caller decides what to do with them.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/time.h"

namespace tb::orbit {

// Where a set came from. The OMM encodings (CCSDS 502.0 Orbit Mean-Elements Message) carry the same
// SGP4 mean elements as a TLE, with catalog numbers of up to 9 digits.
enum class ElementFormat { nasa, amsat, omm_json, omm_xml, omm_csv, omm_kvn };
// "NASA TLE", "AMSAT", "OMM JSON", "OMM XML", "OMM CSV", "OMM KVN".
const char* describe(ElementFormat format);

// The largest catalog number any format here holds (OMM: 9 digits); a TLE holds up to 339999 (Z9999).
inline constexpr int kMaxCatalogNumber = 999'999'999;
inline constexpr int kMaxTleCatalogNumber = 339'999;

struct Elements {
  std::string name;                   // name line (3LE) or AMSAT "Satellite:"; may be empty
  int catalog_number = 0;             // NORAD number, Alpha-5 decoded (A0000 = 100000); OMM up to 999999999
  char classification = 'U';
  std::string international_designator;  // columns 10-17, trimmed ("98067A")
  int epoch_year = 2000;              // four digits
  double epoch_day = 1.0;             // day of year with fraction; 1.0 = Jan 1 00:00:00 UTC
  double ndot_over_2 = 0.0;           // rev/day^2  (first derivative of mean motion / 2)
  double nddot_over_6 = 0.0;          // rev/day^3  (second derivative / 6)
  double bstar = 0.0;                 // 1/earth radii; 0 for AMSAT-format sets
  int ephemeris_type = 0;
  int element_set_number = 0;
  double inclination_deg = 0.0;
  double raan_deg = 0.0;
  double eccentricity = 0.0;
  double arg_perigee_deg = 0.0;
  double mean_anomaly_deg = 0.0;
  double mean_motion_rev_per_day = 0.0;
  long revolution_number = 0;         // at epoch
  ElementFormat source = ElementFormat::nasa;

  UtcTime epoch() const { return from_year_day(epoch_year, epoch_day); }
  // Name if present, otherwise the catalog number.
  std::string label() const;
};

struct ParseProblem {
  std::string file;       // as given by the caller ("<upload>" for an upload)
  int line = 0;           // 1-based line number in the text
  int column = 0;         // 1-based column, 0 when the problem is a whole line or block
  std::string object;     // OMM: which object of the file, "object 2 (ISS (ZARYA) 25544)"; else empty
  std::string field;      // "checksum", "eccentricity", "Mean motion", an OMM keyword ...
  std::string found;      // what the text had
  std::string expected;   // what would have been accepted
  bool warning = false;   // true: the set was still accepted (e.g. AMSAT checksum when not strict)
  // "FILE:LINE:COL: FIELD: found 'X', expected Y" -- one line, for people.
  std::string message() const;
};

struct ParseResult {
  std::vector<Elements> sets;
  std::vector<ParseProblem> problems;
  bool ok() const;  // no problem that rejected a set (warnings allowed)
};

struct ParseOptions {
  bool verify_checksums = true;       // NASA: a wrong checksum rejects the set
  bool strict_amsat_checksum = false; // AMSAT: a wrong checksum rejects the block (else a warning);
                                      // a missing "Checksum:" line is a warning either way
};

// Names are the text of an element file that trakbox shows and stores (issue 38): parse_elements
// makes each printable UTF-8 (util/safe_text.h: invalid bytes and control characters become
// U+FFFD), and a name it had to clean is a warning located at its line. A caller of one format's
// parser on outside text (menu 3-3's upload) passes the result through clean_names itself.
ParseResult clean_names(ParseResult r, std::string_view text, std::string_view file_name);

// NASA two-line and three-line text. Blank lines and lines starting with '#' are skipped;
// CRLF and trailing blanks are accepted; extra text after column 69 is ignored.
ParseResult parse_nasa(std::string_view text, std::string_view file_name = "<text>",
                       const ParseOptions& options = {});
// AMSAT verbose blocks, with any free text around them (bulletin headers, "/EX").
ParseResult parse_amsat(std::string_view text, std::string_view file_name = "<text>",
                        const ParseOptions& options = {});
// CCSDS OMM (elements_omm*.cpp). JSON: CelesTrak's (an array of flat objects, or one object, numbers
// as numbers) or Space-Track's (every value a quoted string). XML: an `ndm` root of `omm` elements or
// one `omm` root. CSV: a header line of keywords, one row per object. KVN: `KEY = value` lines, each
// object starting at CCSDS_OMM_VERS. Only SGP4 mean elements (TEME, EARTH, UTC, SGP4, ephemeris
// type 0) are accepted; every other object is a problem naming it and the keyword, and the other
// objects still load.
ParseResult parse_omm_json(std::string_view text, std::string_view file_name = "<text>");
ParseResult parse_omm_xml(std::string_view text, std::string_view file_name = "<text>");
ParseResult parse_omm_csv(std::string_view text, std::string_view file_name = "<text>");
ParseResult parse_omm_kvn(std::string_view text, std::string_view file_name = "<text>");

// Detects the format from the content and parses it: '{' or '[' then '{' JSON, '<' XML, a CCSDS_OMM_VERS
// line KVN, a header line holding NORAD_CAT_ID and EPOCH CSV, "Satellite:" blocks AMSAT, TLE1= keys
// gpredict, else NASA lines. An empty text, or one that is not text (NUL bytes, mostly binary), is
// one problem saying so.
ParseResult parse_elements(std::string_view text, std::string_view file_name = "<text>",
                           const ParseOptions& options = {});
// Reads a file and parses it; an unreadable file is one problem with line 0.
ParseResult load_elements_file(const std::string& path, const ParseOptions& options = {});

// Writers. format_nasa emits the name line first when with_name and the name is non-empty,
// lines end in "\n", checksums are computed. Parsing the output gives back the same values.
// A set whose catalog number no TLE holds (above 339999, Alpha-5's Z9999) is not written: the
// result is empty, and nasa_unwritable() says why.
std::string format_nasa(const Elements& e, bool with_name = true);
// Why e cannot be written as a TLE ("catalog number 800123456 is beyond ..."), or nothing.
std::optional<std::string> nasa_unwritable(const Elements& e);
std::string format_amsat(const Elements& e);

// OMM writers (elements_omm_write.cpp): JSON as CelesTrak publishes it (an array, numbers as
// numbers), XML (an NDM of OMMs), CSV (CelesTrak's header and columns), KVN (one object after
// another). Every number is written so that it reads back to the same double; the epoch to the
// microsecond. Reading the output gives back the same sets.
enum class OmmEncoding { json, xml, csv, kvn };
std::string format_omm(const std::vector<Elements>& sets, OmmEncoding encoding);

// Checksums as the formats define them.
int nasa_checksum(std::string_view line);          // digits of columns 1-68, '-' counts 1, mod 10
int amsat_checksum(const std::vector<std::string_view>& lines);  // see docs/element-formats.md

// gpredict's satellite files (INI-like: [NNNNN], NAME=, TLE1=, TLE2=), e.g. Debian gpredict's
// /usr/share/gpredict/data/satdata/satellites.dat (979 sets): NAME becomes the set's name.
ParseResult parse_gpredict_satdata(std::string_view text, std::string_view file_name = "<text>",
                                   const ParseOptions& options = {});

// Alpha-5 catalog numbers: "25544" -> 25544, "A0000" -> 100000. -1 when invalid.
int decode_catalog_number(std::string_view five_chars);
// 5 characters, Alpha-5 above 99999; empty for a number no TLE holds (negative, above 339999).
std::string encode_catalog_number(int number);

}  // namespace tb::orbit
