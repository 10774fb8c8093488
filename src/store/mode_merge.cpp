// The merge engine of store/mode_import.h: fields, their sources, matching and merging.
#include <algorithm>
#include <cctype>
#include <cstdlib>

#include <fmt/format.h>

#include "store/mode_import.h"
#include "util/text.h"

namespace tb::store {

namespace {

constexpr radio::Hz kSameDownlinkHz = 5000;
constexpr unsigned kFieldCount = static_cast<unsigned>(ModeField::count);

ModeField field_at(unsigned i) { return static_cast<ModeField>(i); }

std::string tone_text(int tenths) { return fmt::format("{}.{} Hz", tenths / 10, tenths % 10); }

std::string mhz(radio::Hz hz) { return radio::format_mhz(hz) + " MHz"; }

bool is_list_source(const std::string& s) { return !s.empty() && s != "operator" && s != "freqmode"; }

// Sets field f of `to` from `from`.
void copy_field(radio::SatelliteMode& to, const radio::SatelliteMode& from, ModeField f) {
  radio::SatelliteRadio& t = to.radio;
  const radio::SatelliteRadio& s = from.radio;
  switch (f) {
    case ModeField::downlink: t.downlink_hz = s.downlink_hz; break;
    case ModeField::uplink: t.uplink_hz = s.uplink_hz; break;
    case ModeField::downlink_mode: t.downlink_mode = s.downlink_mode; break;
    case ModeField::uplink_mode: t.uplink_mode = s.uplink_mode; break;
    case ModeField::passbands:
      t.downlink_low_hz = s.downlink_low_hz, t.downlink_high_hz = s.downlink_high_hz;
      t.uplink_low_hz = s.uplink_low_hz, t.uplink_high_hz = s.uplink_high_hz;
      break;
    case ModeField::inverting: t.inverting = s.inverting; break;
    case ModeField::tone: t.ctcss_tenths_hz = s.ctcss_tenths_hz; break;
    case ModeField::arm: to.arm_tone_tenths_hz = from.arm_tone_tenths_hz; break;
    case ModeField::count: break;
  }
}

// Upper case letters and digits only, leading zeros of a number dropped: "AO-07" and "ao 7" are "AO7".
std::string name_key(std::string_view name) {
  std::string k;
  bool in_number = false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      in_number = false;
      continue;
    }
    const bool digit = std::isdigit(static_cast<unsigned char>(c)) != 0;
    if (digit && c == '0' && !in_number) continue;
    in_number = digit;
    k.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return k;
}

std::optional<std::size_t> find_satellite(const Database& db, const ListedMode& l) {
  if (l.catalog > 0)
    for (std::size_t i = 0; i < db.satellites.size(); ++i)
      if (db.satellites[i].elements.catalog_number == l.catalog) return i;
  for (const std::string& n : l.names)
    for (std::size_t i = 0; i < db.satellites.size(); ++i)
      if (!name_key(n).empty() && name_key(n) == name_key(db.satellites[i].name())) return i;
  return std::nullopt;
}

bool same_frequency(const radio::SatelliteMode& have, const radio::SatelliteMode& offered) {
  const radio::SatelliteRadio& h = have.radio;
  const radio::SatelliteRadio& o = offered.radio;
  if (!o.has_downlink()) return false;
  // Transponders by their passbands overlapping (SatNOGS' "Mode A" transponder is AO-07's Mode-A);
  // a spot inside a passband (RS-44's FT4, a CW beacon) is a mode of its own unless named the same.
  if (h.has_passbands() || o.has_passbands())
    return h.has_passbands() && o.has_passbands() && o.downlink_low_hz <= h.downlink_high_hz &&
           h.downlink_low_hz <= o.downlink_high_hz;
  return std::llabs(h.downlink_hz - o.downlink_hz) <= kSameDownlinkHz && h.downlink_mode == o.downlink_mode;
}

// The mode of `modes` the offered one is: same name, else same frequency (overlapping passbands, or
// a downlink within 5 kHz in the same radio mode); not one taken already.
std::optional<std::size_t> find_mode_index(const std::vector<radio::SatelliteMode>& modes, const ListedMode& l,
                                           const std::vector<bool>& taken) {
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (!taken[i] && text::iequals(modes[i].name, l.mode.name)) return i;
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (!taken[i] && same_frequency(modes[i], l.mode)) return i;
  return std::nullopt;
}

// A canonical value (field_value) as field_shown shows it.
std::string value_shown(ModeField f, const std::string& v) {
  if (v.empty()) return "nothing";
  radio::SatelliteMode m;
  radio::SatelliteRadio& r = m.radio;
  const auto num = [&v](std::size_t from = 0, std::size_t to = std::string::npos) {
    return std::atoll(v.substr(from, to == std::string::npos ? to : to - from).c_str());
  };
  switch (f) {
    case ModeField::downlink: r.downlink_hz = num(); break;
    case ModeField::uplink: r.uplink_hz = num(); break;
    case ModeField::downlink_mode:
    case ModeField::uplink_mode: return v;
    case ModeField::passbands: {
      const std::size_t d1 = v.find('-'), s = v.find('/'), d2 = v.find('-', s);
      if (d1 == std::string::npos || s == std::string::npos || d2 == std::string::npos) return v;
      r.downlink_low_hz = num(0, d1), r.downlink_high_hz = num(d1 + 1, s);
      r.uplink_low_hz = num(s + 1, d2), r.uplink_high_hz = num(d2 + 1);
      break;
    }
    case ModeField::inverting: r.inverting = v == "y"; break;
    case ModeField::tone: r.ctcss_tenths_hz = static_cast<int>(num()); break;
    case ModeField::arm: m.arm_tone_tenths_hz = static_cast<int>(num()); break;
    case ModeField::count: break;
  }
  return field_shown(m, f);
}

// `name`, or when the satellite has a mode of that name (case aside) "NAME-2", "NAME-3" ... cut
// to fit radio::kMaxModeName.
std::string unique_name(const std::vector<radio::SatelliteMode>& modes, const std::string& name) {
  const auto used = [&modes](const std::string& n) {
    return std::any_of(modes.begin(), modes.end(), [&n](const radio::SatelliteMode& x) { return text::iequals(x.name, n); });
  };
  std::string out = name;
  for (int k = 2; used(out); ++k) {
    const std::string suffix = "-" + std::to_string(k);
    out = name.substr(0, radio::kMaxModeName - suffix.size()) + suffix;
  }
  return out;
}

std::string source_shown(const std::string& s) { return s == "freqmode" ? "freq/mode file" : s; }

struct Merger {
  bool replace;
  MergeReport& report;
  std::string from;

  // One offered field into the mode; true when the mode changed. Empty and source are the field's
  // before this import (`before`): passbands filled now do not make "not inverting" anyone's value.
  bool field(const std::string& where, radio::SatelliteMode& m, const radio::SatelliteMode& before, const ListedMode& l,
             ModeField f) {
    const std::string now = field_value(m, f), offered = field_value(l.mode, f);
    const std::string key = to_string(f);
    if (now == offered) return false;
    const std::string src = field_source(before, f);
    if (!replace && !src.empty() && !is_list_source(src)) {
      radio::FieldSource& fs = m.sources[key];
      if (fs.from.empty()) fs = {src, now, {}, {}};
      const bool again = fs.offer_from == from && fs.offer_value == offered;
      fs.offer_from = from, fs.offer_value = offered;
      report.conflicts.push_back(fmt::format("{} {}: kept your {} ({}); {} says {}", where, key, field_shown(m, f),
                                             source_shown(src), from, offered.empty() ? "nothing" : field_shown(l.mode, f)));
      return !again;
    }
    const std::string was = src.empty() ? std::string() : field_shown(m, f) + ", " + source_shown(src);
    copy_field(m, l.mode, f);
    m.sources[key] = {from, field_value(m, f), {}, {}};
    report.updated.push_back(fmt::format("{} {}: {} from {}{}", where, key, field_shown(m, f), from,
                                         was.empty() ? "" : " (was " + was + ")"));
    return true;
  }

  bool into(const std::string& sat, radio::SatelliteMode& m, const ListedMode& l) {
    bool changed = false;
    const radio::SatelliteMode before = m;
    for (unsigned i = 0; i < kFieldCount; ++i)
      if (l.given & (1u << i)) changed = field(sat + " " + m.name, m, before, l, field_at(i)) || changed;
    return changed;
  }

  void add(const std::string& sat, std::vector<radio::SatelliteMode>& modes, const ListedMode& l) {
    if (modes.size() >= radio::kMaxModes) {
      report.skipped.push_back(fmt::format("{} {}: not added, the satellite has {} modes", sat, l.mode.name,
                                           radio::kMaxModes));
      return;
    }
    radio::SatelliteMode m = l.mode;
    m.sources.clear();
    m.name = unique_name(modes, m.name);
    mark_sources(m, from);
    std::string what = field_shown(m, ModeField::downlink) + " " + radio::to_string(m.radio.downlink_mode);
    if (m.radio.has_uplink()) what += ", up " + field_shown(m, ModeField::uplink) + " " + radio::to_string(m.radio.uplink_mode);
    report.added.push_back(fmt::format("{} {}: added from {} ({})", sat, m.name, from, what));
    modes.push_back(std::move(m));
  }

  // SubTone.SQF: the tone to the satellite's FM voice modes (named FM, FM-2 ..., with an FM uplink),
  // not to its APRS or packet modes.
  bool tones(Satellite& s, std::vector<radio::SatelliteMode>& modes, const ListedMode& l) {
    bool changed = false, any = false;
    for (auto& m : modes) {
      const bool voice = text::iequals(m.name.substr(0, 2), "FM") && (m.name.size() == 2 || m.name[2] == '-');
      if (!voice || m.radio.uplink_mode != radio::Mode::fm || !m.radio.has_uplink()) continue;
      any = true;
      const std::size_t conflicts = report.conflicts.size();
      const bool c = field(s.name() + " " + m.name, m, radio::SatelliteMode(m), l, ModeField::tone);
      if (!c && report.conflicts.size() == conflicts) ++report.unchanged;
      changed = changed || c;
    }
    if (!any) report.skipped.push_back(fmt::format("{}: a tone for its FM uplink, but it has no FM mode with an uplink", s.name()));
    return changed;
  }

  // The list's modes of one satellite (in the list's order).
  void satellite(Satellite& s, const std::vector<const ListedMode*>& offered) {
    std::vector<radio::SatelliteMode> modes = modes_of(s);
    std::vector<bool> taken(modes.size() + offered.size(), false);
    bool changed = false;
    for (const ListedMode* l : offered) {
      if (l->fm_uplinks) {
        changed = tones(s, modes, *l) || changed;
        continue;
      }
      const auto i = find_mode_index(modes, *l, taken);
      if (!i) {
        const std::size_t before = modes.size();
        add(s.name(), modes, *l);
        changed = changed || modes.size() != before;
        continue;
      }
      taken[*i] = true;
      const std::size_t conflicts = report.conflicts.size();
      const bool c = into(s.name(), modes[*i], *l);
      if (!c && report.conflicts.size() == conflicts) ++report.unchanged;
      changed = changed || c;
    }
    if (!changed) return;
    report.changed = true;
    const std::string chosen = chosen_mode(s);
    s.modes = std::move(modes);
    s.mode = chosen.empty() ? s.modes.front().name : chosen;
    for (const auto& m : s.modes)
      if (m.name == s.mode) s.radio = m.radio;
  }
};

}  // namespace

const char* to_string(ModeField f) {
  switch (f) {
    case ModeField::downlink: return "downlink";
    case ModeField::uplink: return "uplink";
    case ModeField::downlink_mode: return "downlink_mode";
    case ModeField::uplink_mode: return "uplink_mode";
    case ModeField::passbands: return "passbands";
    case ModeField::inverting: return "inverting";
    case ModeField::tone: return "tone";
    case ModeField::arm: return "arm";
    case ModeField::count: break;
  }
  return "";
}

std::string field_value(const radio::SatelliteMode& m, ModeField f) {
  const radio::SatelliteRadio& r = m.radio;
  const auto num = [](long long v) { return v > 0 ? std::to_string(v) : std::string(); };
  switch (f) {
    case ModeField::downlink: return num(r.downlink_hz);
    case ModeField::uplink: return num(r.uplink_hz);
    case ModeField::downlink_mode: return r.downlink_mode == radio::Mode::none ? "" : radio::to_string(r.downlink_mode);
    case ModeField::uplink_mode: return r.uplink_mode == radio::Mode::none ? "" : radio::to_string(r.uplink_mode);
    case ModeField::passbands:
      return r.has_passbands() ? fmt::format("{}-{}/{}-{}", r.downlink_low_hz, r.downlink_high_hz, r.uplink_low_hz,
                                             r.uplink_high_hz)
                               : "";
    case ModeField::inverting: return r.inverting ? "y" : "n";
    case ModeField::tone: return num(r.ctcss_tenths_hz);
    case ModeField::arm: return num(m.arm_tone_tenths_hz);
    case ModeField::count: break;
  }
  return "";
}

std::string field_shown(const radio::SatelliteMode& m, ModeField f) {
  const radio::SatelliteRadio& r = m.radio;
  switch (f) {
    case ModeField::downlink: return mhz(r.downlink_hz);
    case ModeField::uplink: return r.has_uplink() ? mhz(r.uplink_hz) : "no uplink";
    case ModeField::downlink_mode: return radio::to_string(r.downlink_mode);
    case ModeField::uplink_mode: return radio::to_string(r.uplink_mode);
    case ModeField::passbands:
      return r.has_passbands() ? fmt::format("{}-{} / {}-{} MHz", radio::format_mhz(r.downlink_low_hz),
                                             radio::format_mhz(r.downlink_high_hz), radio::format_mhz(r.uplink_low_hz),
                                             radio::format_mhz(r.uplink_high_hz))
                               : "no passbands";
    case ModeField::inverting: return r.inverting ? "inverting" : "not inverting";
    case ModeField::tone: return r.ctcss_tenths_hz > 0 ? tone_text(r.ctcss_tenths_hz) : "no tone";
    case ModeField::arm: return m.arm_tone_tenths_hz > 0 ? tone_text(m.arm_tone_tenths_hz) : "no arming tone";
    case ModeField::count: break;
  }
  return "";
}

std::string field_source(const radio::SatelliteMode& m, ModeField f) {
  const std::string now = field_value(m, f);
  const auto it = m.sources.find(to_string(f));
  // An empty field (not inverting without passbands too) is no one's value: a list fills it.
  if (now.empty() || (f == ModeField::inverting && !m.radio.has_passbands() && !m.radio.inverting)) return "";
  if (it == m.sources.end() || it->second.from.empty()) return "operator";
  return it->second.value == now ? it->second.from : "operator";
}

void mark_sources(radio::SatelliteMode& m, const std::string& from) {
  for (unsigned i = 0; i < kFieldCount; ++i) {
    const ModeField f = field_at(i);
    const std::string v = field_value(m, f);
    if (f == ModeField::inverting && !m.radio.has_passbands() && !m.radio.inverting) continue;
    if (!v.empty()) m.sources[to_string(f)] = {from, v, {}, {}};
  }
}

MergeReport merge_modes(Database& db, const ModeList& list, bool replace) {
  MergeReport report;
  if (!list.ok()) return report;
  std::vector<std::vector<const ListedMode*>> per(db.satellites.size());
  for (const ListedMode& l : list.modes) {
    if (const auto i = find_satellite(db, l)) {
      per[*i].push_back(&l);
      continue;
    }
    // SatNOGS lists every satellite there is: those not in the database are counted, not named.
    if (list.format == ListFormat::satnogs) continue;
    const std::string who = l.names.empty() ? "catalog " + std::to_string(l.catalog) : l.names.front();
    report.skipped.push_back(fmt::format("{}{}: no such satellite in the database", who,
                                         l.line > 0 ? " (line " + std::to_string(l.line) + ")" : ""));
  }
  Merger merger{replace, report, source_name(list.format)};
  for (std::size_t i = 0; i < per.size(); ++i)
    if (!per[i].empty()) merger.satellite(db.satellites[i], per[i]);
  return report;
}

std::vector<std::string> report_lines(const MergeReport& r, const ModeList& list) {
  std::vector<std::string> out;
  for (const auto* part : {&r.added, &r.updated, &r.conflicts, &r.skipped})
    out.insert(out.end(), part->begin(), part->end());
  std::string last = fmt::format("{} added, {} updated, {} conflict{} (yours kept), {} unchanged", r.added.size(),
                                 r.updated.size(), r.conflicts.size(), r.conflicts.size() == 1 ? "" : "s", r.unchanged);
  if (list.format == ListFormat::satnogs)
    last += fmt::format("; {} transmitter{} not alive or not active, not offered", list.not_offered,
                        list.not_offered == 1 ? "" : "s");
  out.push_back(last);
  return out;
}

std::vector<std::string> diff_lines(const Database& db, std::string_view satellite, bool conflicts) {
  std::vector<std::string> out;
  for (const Satellite& s : db.satellites) {
    if (!satellite.empty() && s.name() != satellite) continue;
    for (const radio::SatelliteMode& m : modes_of(s))
      for (unsigned i = 0; i < kFieldCount; ++i) {
        const ModeField f = field_at(i);
        const std::string src = field_source(m, f);
        if (src.empty()) continue;
        std::string line = fmt::format("{} {} {} {} ({})", s.name(), m.name, to_string(f), field_shown(m, f),
                                       source_shown(src));
        const auto it = m.sources.find(to_string(f));
        const bool offered =
            it != m.sources.end() && !it->second.offer_from.empty() && it->second.offer_value != field_value(m, f);
        if (offered) line += fmt::format("; {} says {}", it->second.offer_from, value_shown(f, it->second.offer_value));
        if (offered || !conflicts) out.push_back(std::move(line));
      }
  }
  return out;
}

}  // namespace tb::store
