// The OMM writers: JSON (CelesTrak's layout, numbers as numbers), XML (an NDM of OMMs), CSV and
// KVN. Numbers are written as the shortest text that reads back to the same double; the epoch to
// the microsecond. The ephemeris type is always 0: what is in an Elements is SGP4 mean elements.
#include <charconv>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "orbit/elements_fields.h"
#include "orbit/elements_omm_internal.h"

namespace tb::orbit {
namespace {

std::string shortest(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "0";
}

// One keyword's value as text, and whether it is a number (unquoted in JSON).
struct Value {
  const char* key;
  std::string text;
  bool number;
};

std::vector<Value> values(const Elements& e, bool with_metadata) {
  std::vector<Value> v = {{"OBJECT_NAME", e.name, false}, {"OBJECT_ID", detail::omm_object_id(e.international_designator), false}};
  if (with_metadata) {
    v.push_back({"CENTER_NAME", "EARTH", false});
    v.push_back({"REF_FRAME", "TEME", false});
    v.push_back({"TIME_SYSTEM", "UTC", false});
    v.push_back({"MEAN_ELEMENT_THEORY", "SGP4", false});
  }
  const std::string classification(1, detail::is_upper(e.classification) ? e.classification : 'U');
  const std::vector<Value> rest = {
      {"EPOCH", detail::omm_epoch_text(e.epoch_year, e.epoch_day), false},
      {"MEAN_MOTION", shortest(e.mean_motion_rev_per_day), true},
      {"ECCENTRICITY", shortest(e.eccentricity), true},
      {"INCLINATION", shortest(e.inclination_deg), true},
      {"RA_OF_ASC_NODE", shortest(e.raan_deg), true},
      {"ARG_OF_PERICENTER", shortest(e.arg_perigee_deg), true},
      {"MEAN_ANOMALY", shortest(e.mean_anomaly_deg), true},
      {"EPHEMERIS_TYPE", "0", true},
      {"CLASSIFICATION_TYPE", classification, false},
      {"NORAD_CAT_ID", std::to_string(e.catalog_number), true},
      {"ELEMENT_SET_NO", std::to_string(e.element_set_number), true},
      {"REV_AT_EPOCH", std::to_string(e.revolution_number), true},
      {"BSTAR", shortest(e.bstar), true},
      {"MEAN_MOTION_DOT", shortest(e.ndot_over_2), true},
      {"MEAN_MOTION_DDOT", shortest(e.nddot_over_6), true},
  };
  v.insert(v.end(), rest.begin(), rest.end());
  return v;
}

// A JSON string; bytes that are not UTF-8 become U+FFFD, so the output is always valid JSON.
std::string json_quoted(std::string_view s) {
  return nlohmann::json(std::string(s)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string xml_escaped(std::string_view s) {
  std::string r;
  for (const char c : s) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      case '\'': r += "&apos;"; break;
      default:
        // XML 1.0 has no way to write other control characters: a blank stands in.
        r += static_cast<unsigned char>(c) < 0x20 && c != '\t' ? ' ' : c;
    }
  }
  return r;
}

std::string csv_cell(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos && s == text::trim(s)) return std::string(s);
  std::string r = "\"";
  for (const char c : s) {
    if (c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

// KVN holds one line per keyword: line breaks in a name become blanks.
std::string kvn_value(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c == '\n' || c == '\r') c = ' ';
  return r;
}

std::string write_json(const std::vector<Elements>& sets) {
  std::string out = "[";
  for (std::size_t i = 0; i < sets.size(); ++i) {
    out += i ? ",\n{" : "{";
    bool first = true;
    for (const Value& v : values(sets[i], false)) {
      out += (first ? "" : ",") + json_quoted(v.key) + ":" + (v.number ? v.text : json_quoted(v.text));
      first = false;
    }
    out += "}";
  }
  return out + "]\n";
}

std::string write_csv(const std::vector<Elements>& sets) {
  std::string out;
  const std::vector<Value> header = values(Elements{}, false);
  for (std::size_t k = 0; k < header.size(); ++k) out += (k ? "," : "") + std::string(header[k].key);
  out += "\r\n";  // CelesTrak's CSV ends its lines as RFC 4180 does
  for (const Elements& e : sets) {
    const std::vector<Value> row = values(e, false);
    for (std::size_t k = 0; k < row.size(); ++k) out += (k ? "," : "") + csv_cell(row[k].text);
    out += "\r\n";
  }
  return out;
}

std::string write_kvn(const std::vector<Elements>& sets) {
  std::string out;
  for (const Elements& e : sets) {
    out += "CCSDS_OMM_VERS = 2.0\n";
    for (const Value& v : values(e, true)) out += detail::printf_string("%-19s", v.key) + " = " + kvn_value(v.text) + "\n";
  }
  return out;
}

std::string write_xml(const std::vector<Elements>& sets) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ndm>\n";
  for (const Elements& e : sets) {
    const std::vector<Value> v = values(e, true);
    auto group = [&](const char* name, std::size_t first, std::size_t count) {
      std::string g = "        <" + std::string(name) + ">\n";
      for (std::size_t k = first; k < first + count; ++k)
        g += "          <" + std::string(v[k].key) + ">" + xml_escaped(v[k].text) + "</" + v[k].key + ">\n";
      return g + "        </" + name + ">\n";
    };
    out += "  <omm id=\"CCSDS_OMM_VERS\" version=\"2.0\">\n    <header></header>\n    <body>\n      <segment>\n";
    constexpr std::size_t kMeta = std::size(detail::kOmmMetadataKeys), kMean = std::size(detail::kOmmMeanElementKeys);
    out += group("metadata", 0, kMeta);
    out += "        <data>\n";
    out += group("meanElements", kMeta, kMean);
    out += group("tleParameters", kMeta + kMean, std::size(detail::kOmmTleParameterKeys));
    out += "        </data>\n      </segment>\n    </body>\n  </omm>\n";
  }
  return out + "</ndm>\n";
}

}  // namespace

std::string format_omm(const std::vector<Elements>& sets, OmmEncoding encoding) {
  switch (encoding) {
    case OmmEncoding::json: return write_json(sets);
    case OmmEncoding::xml: return write_xml(sets);
    case OmmEncoding::csv: return write_csv(sets);
    case OmmEncoding::kvn: return write_kvn(sets);
  }
  return {};
}

}  // namespace tb::orbit
