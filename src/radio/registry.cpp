#include "radio/registry.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "radio/factory.h"
#include "radio/registry_rows.h"
#include "radio/simulated.h"
#include "util/text.h"

namespace tb::radio {

namespace {

MakeRadio make_simulated(const RadioModel&, const RadioSpec&, const RadioConfig&, const DriverTiming&, RadioRole) {
  return {std::make_unique<SimulatedRadio>(), {}};
}

MakeRadio make_cat(const RadioModel&, const RadioSpec& spec, const RadioConfig& config, const DriverTiming& t, RadioRole role) {
  const char* family = nullptr;
  switch (config.rig) {
    case Rig::icom: family = "icom"; break;
    case Rig::kenwood: family = "kenwood"; break;
    case Rig::yaesu: family = "yaesu"; break;
    case Rig::none:
      return {nullptr, "--radio cat:" + spec.device + ": no CAT rig is configured (menu 6-7: choose Kenwood, Yaesu or Icom)"};
  }
  const RadioModel& m = *find_radio_model(family);
  return m.make(m, spec, config, t, role);
}

// trakbox's own rows; each family's are in its folder (radio/icom/models.cpp ...).
const RadioModel kOwn[] = {
    {.name = "sim", .label = "trakbox simulated radio", .form = SpecForm::none,
     .caps = {.links = 2, .reads = true, .ctcss = true, .step_hz = 1}, .note = "the default; records what it is told",
     .make = make_simulated},
    {.name = "cat", .label = "the rig of menu 6-7", .protocol = Protocol::cat, .caps = {.links = 2},
     .note = "icom, kenwood or yaesu as menu 6-7 chose", .make = make_cat},
};

}  // namespace

std::span<const RadioModel> radio_models() {
  // In the order --radio list prints: trakbox's own, menu 6-7's rig, then each family's rows.
  static const std::vector<RadioModel> all = [] {
    std::vector<RadioModel> v(std::begin(kOwn), std::end(kOwn));
    for (auto rows : {icom_rows(), kenwood_rows(), yaesu_rows(), flex_rows(), hamlib_rows()}) v.insert(v.end(), rows.begin(), rows.end());
    return v;
  }();
  return all;
}

const RadioModel* find_radio_model(std::string_view name) {
  // "simulated" is the rotator's word for it, taken here too.
  // Any case: "IC9700" is the ic9700 (the names are lower case; Hamlib's are matched ignoring case too).
  const std::string lower = text::lower(name);
  const std::string_view key = lower == "simulated" ? std::string_view("sim") : std::string_view(lower);
  const auto models = radio_models();
  const auto it = std::ranges::find(models, key, &RadioModel::name);
  return it == models.end() ? nullptr : &*it;
}

const RadioModel* find_radio_model_by_hamlib(int hamlib_model) {
  if (hamlib_model <= 2) return nullptr;   // the dummy and NET rigctl are no radio
  for (const RadioModel& m : radio_models())
    if (m.hamlib_model == hamlib_model) return &m;
  return nullptr;
}

std::string spec_form(const RadioModel& m) {
  const std::string n(m.name);
  switch (m.form) {
    case SpecForm::none: return n;
    case SpecForm::device: return n + ":DEVICE";
    case SpecForm::device_baud:
      return n + ":DEVICE[:BAUD]" + (m.caps.satellite_mode && m.protocol == Protocol::icom ? "[:maindown|:mainup]" : "") +
             (m.xvtr_from ? "[:xvtr]" : "");
    case SpecForm::hamlib: return n + ":MODEL:DEVICE[:BAUD][:split|:mainsub]";
    case SpecForm::rigctld: return n + "[:HOST[:PORT]][:split|:mainsub]";
    case SpecForm::receiver: return n + "[:HOST[:PORT]]";
    case SpecForm::flex: return n + "[:HOST[:PORT]][:duplex]";
  }
  return n;
}

std::string radio_model_names() {
  std::string out;
  for (const RadioModel& m : radio_models()) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

std::string radio_list_text() {
  // 80 columns (a phone's terminal, the serial console): the spec on a line of its own, the radio and
  // what it can do under it, then its note wrapped four columns in.
  constexpr const char* kRow = "  %-33s %5s %-3s %-4s %-4s %4s %5s %5s %6s\n";
  char line[256];
  std::snprintf(line, sizeof line, kRow, "radio", "links", "sat", "read", "tone", "step", "CI-V", "baud", "hamlib");
  std::string out = "radio spec\n" + std::string(line);
  for (const RadioModel& m : radio_models()) {
    char civ[8] = "-";
    if (m.civ_address) std::snprintf(civ, sizeof civ, "%02Xh", m.civ_address);
    out += spec_form(m) + "\n";
    std::snprintf(line, sizeof line, kRow, std::string(m.label).c_str(), std::to_string(m.caps.links).c_str(),
                  m.caps.satellite_mode ? "yes" : "no", m.caps.reads ? "yes" : "no", m.caps.ctcss ? "yes" : "no",
                  std::to_string(m.caps.step_hz).c_str(), civ, m.baud ? std::to_string(m.baud).c_str() : "-",
                  m.hamlib_model ? std::to_string(m.hamlib_model).c_str() : "-");
    out += line;
    std::string note;   // word-wrapped at 78 columns
    for (std::string_view rest = m.note; !rest.empty();) {
      const std::size_t space = rest.find(' ');
      const std::string_view word = rest.substr(0, space);
      if (!note.empty() && note.size() + 1 + word.size() > 74) {
        out += "    " + note + "\n";
        note.clear();
      }
      note += (note.empty() ? "" : " ") + std::string(word);
      rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
    }
    if (!note.empty()) out += "    " + note + "\n";
  }
  return out;
}

}  // namespace tb::radio
