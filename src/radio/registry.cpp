#include "radio/registry.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "radio/factory.h"
#include "radio/registry_rows.h"
#include "radio/simulated.h"

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
    for (auto rows : {icom_rows(), kenwood_rows(), yaesu_rows(), hamlib_rows()}) v.insert(v.end(), rows.begin(), rows.end());
    return v;
  }();
  return all;
}

const RadioModel* find_radio_model(std::string_view name) {
  // "simulated" is the rotator's word for it, taken here too.
  const std::string_view key = std::string_view("simulated") == name ? std::string_view("sim") : name;
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
      return n + ":DEVICE[:BAUD]" + (m.caps.satellite_mode && m.protocol == Protocol::icom ? "[:maindown|:mainup]" : "");
    case SpecForm::hamlib: return n + ":MODEL:DEVICE[:BAUD][:split|:mainsub]";
    case SpecForm::rigctld: return n + "[:HOST[:PORT]][:split|:mainsub]";
  }
  return n;
}

std::string radio_model_names() {
  std::string out;
  for (const RadioModel& m : radio_models()) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

std::string radio_list_text() {
  std::string out = "radio spec                                   radio                              links sat read tone step  CI-V  baud hamlib  notes\n";
  char line[512];
  for (const RadioModel& m : radio_models()) {
    const std::string civ = m.civ_address ? [&] { char b[8]; std::snprintf(b, sizeof b, "%02Xh", m.civ_address); return std::string(b); }() : "-";
    const std::string form = spec_form(m);
    std::snprintf(line, sizeof line, "%-44s %-34s %5d %-3s %-4s %-4s %4lld %5s %5s %6s  %s\n", form.c_str(),
                  std::string(m.label).c_str(), m.caps.links, m.caps.satellite_mode ? "yes" : "no",
                  m.caps.reads ? "yes" : "no", m.caps.ctcss ? "yes" : "no", static_cast<long long>(m.caps.step_hz),
                  civ.c_str(), m.baud ? std::to_string(m.baud).c_str() : "-",
                  m.hamlib_model ? std::to_string(m.hamlib_model).c_str() : "-", std::string(m.note).c_str());
    out += line;
  }
  return out;
}

}  // namespace tb::radio
