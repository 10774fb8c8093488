// `trakbox radio import|diff` requests (store/mode_import.h), the same on the station's socket and
// on the state file: read the whole file, merge into a copy, one named edit through the owner.
#include <nlohmann/json.hpp>

#include "store/mode_import.h"
#include "store/owner.h"
#include "util/safe_text.h"

namespace tb::store {

using json = nlohmann::json;

namespace {

json refusal(std::string why) { return json{{"error", text::safe_text(why)}}; }

std::string string_field(const json& r, const char* key) {
  return r.contains(key) && r[key].is_string() ? r[key].get<std::string>() : std::string();
}

json import_request(ModelOwner& owner, const json& request, Origin origin) {
  const std::string file = string_field(request, "file"), content = string_field(request, "text");
  const std::string named = string_field(request, "format");
  std::optional<ListFormat> format = named.empty() ? guess_list_format(content, file) : parse_list_format(named);
  if (!format && !named.empty())
    return refusal("--format " + named + ": expected satnogs, trsp, sqf, subtone or oscarwatch");
  if (!format)
    return refusal(file + ": not a list trakbox knows by its name or content; give --format satnogs|trsp|sqf|subtone|oscarwatch");
  const ModeList list = read_mode_list(*format, content, file);
  if (!list.ok()) return refusal(list.error + "; nothing changed");
  Database db = owner.model().db;
  const bool replace = request.contains("replace") && request["replace"].is_boolean() && request["replace"].get<bool>();
  const MergeReport report = merge_modes(db, list, replace);
  if (report.changed) {
    const EditResult r = owner.edit(bit(Area::radio_entries), std::string("radio import ") + to_string(*format), origin,
                                    [&db](Model& m) { m.db = std::move(db); });
    if (!r.ok()) return refusal(*r.refusal + "; nothing changed");
  }
  return json{{"lines", report_lines(report, list)}, {"changed", report.changed}};
}

}  // namespace

json radio_request(ModelOwner& owner, const json& request, Origin origin) {
  const std::string action = request.is_object() ? string_field(request, "action") : "";
  if (action == "diff") {
    const std::string sat = string_field(request, "satellite");
    if (!sat.empty() && !owner.model().db.find(sat)) return refusal("no satellite named '" + sat + "' in the database");
    const bool conflicts = request.contains("conflicts") && request["conflicts"].is_boolean() && request["conflicts"].get<bool>();
    return json{{"lines", diff_lines(owner.model().db, sat, conflicts)}, {"changed", false}};
  }
  if (action == "import") return import_request(owner, request, origin);
  return refusal("expected radio import FILE or radio diff");
}

}  // namespace tb::store
