// What the OMM readers share (private to src/orbit): each encoding's reader turns its text into
// objects of keyword/value pairs, with the line each came from; one function makes an element set of
// an object, or the problem that refuses it. elements_omm.cpp (JSON, CSV, KVN and the conversion),
// elements_omm_xml.cpp (XML), elements_omm_write.cpp (the writers).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "orbit/elements.h"

namespace tb::orbit::detail {

struct OmmField {
  std::string key;    // as written, e.g. "MEAN_MOTION"
  std::string value;  // the text of the value, units ("[rev/day]") and blanks around removed
  int line = 0;       // 1-based; 0 when the encoding has no lines to give
};

struct OmmObject {
  std::vector<OmmField> fields;
  int line = 0;  // where the object starts
  // A problem the reader found in the object's text itself (a broken KVN line, a JSON value that is
  // an array): the object is refused with it. Empty field means none.
  ParseProblem structural;
};

// Appends the set made from object number `index` (1-based) to out.sets, or the problem that
// refuses it to out.problems (and warnings for what was dropped, e.g. a malformed OBJECT_ID).
void add_omm_object(const OmmObject& object, int index, std::string_view file, ElementFormat format,
                    ParseResult& out);

// "object 2 (ISS (ZARYA) 25544)": the object's index and, when present, its name and number.
std::string omm_object_label(const OmmObject& object, int index);

// The line (1-based) of byte `offset` in text.
int line_of_offset(std::string_view text, std::size_t offset);

// "2026-05-21T03:57:45.045216" for an epoch, microseconds always written.
std::string omm_epoch_text(int year, double day);
// "1998-067A" for "98067A"; empty when the designator is not of that form.
std::string omm_object_id(std::string_view designator);

// The keywords in the order CelesTrak writes them, with how to print each (writers).
inline constexpr const char* kOmmMetadataKeys[] = {"OBJECT_NAME", "OBJECT_ID", "CENTER_NAME", "REF_FRAME",
                                                   "TIME_SYSTEM", "MEAN_ELEMENT_THEORY"};
inline constexpr const char* kOmmMeanElementKeys[] = {"EPOCH",          "MEAN_MOTION",       "ECCENTRICITY",
                                                      "INCLINATION",    "RA_OF_ASC_NODE",    "ARG_OF_PERICENTER",
                                                      "MEAN_ANOMALY"};
inline constexpr const char* kOmmTleParameterKeys[] = {"EPHEMERIS_TYPE", "CLASSIFICATION_TYPE", "NORAD_CAT_ID",
                                                       "ELEMENT_SET_NO", "REV_AT_EPOCH",        "BSTAR",
                                                       "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT"};

}  // namespace tb::orbit::detail
