#include "orbit/pass_tools.h"

#include <algorithm>
#include <cstdio>

#include "orbit/observe.h"
#include "orbit/time.h"

namespace tb::orbit {

std::vector<Pass> mutual_passes(const Sgp4& sat, const Observer& here, const Observer& there, UtcTime start,
                                UtcTime stop, const PassOptions& options) {
  PassOptions every = options;
  every.min_max_elevation_deg = -90.0;
  const std::vector<Pass> a = find_passes(sat, here, start, stop, every);
  const std::vector<Pass> b = find_passes(sat, there, start, stop, every);
  std::vector<Pass> out;
  for (const Pass& pa : a)
    for (const Pass& pb : b) {
      const UtcTime lo = std::max(pa.aos, pb.aos), hi = std::min(pa.los, pb.los);
      if (!(lo < hi)) continue;
      Pass p = pa;
      p.aos = lo;
      p.los = hi;
      p.up_at_start = pa.up_at_start && lo == pa.aos;
      p.up_at_end = pa.up_at_end && hi == pa.los;
      const Observation o_lo = observe(sat, here, lo), o_hi = observe(sat, here, hi);
      if (!o_lo.ok() || !o_hi.ok()) continue;
      p.aos_az_deg = o_lo.look.az_deg;
      p.los_az_deg = o_hi.look.az_deg;
      // Over one pass the elevation rises to TCA and falls: outside the shared time, its maximum
      // there is at the end nearer TCA.
      if (pa.tca < lo || hi < pa.tca) {
        const Observation& top = pa.tca < lo ? o_lo : o_hi;
        p.tca = pa.tca < lo ? lo : hi;
        p.max_el_deg = top.look.el_deg;
        p.tca_az_deg = top.look.az_deg;
      }
      if (p.max_el_deg >= options.min_max_elevation_deg) out.push_back(p);
    }
  std::sort(out.begin(), out.end(), [](const Pass& x, const Pass& y) { return x.aos < y.aos; });
  return out;
}

std::vector<std::vector<int>> overlaps(const std::vector<NamedPass>& passes) {
  std::vector<std::vector<int>> out(passes.size());
  for (std::size_t i = 0; i < passes.size(); ++i)
    for (std::size_t j = i + 1; j < passes.size(); ++j) {
      const Pass &a = passes[i].pass, &b = passes[j].pass;
      if (a.aos < b.los && b.aos < a.los) {
        out[i].push_back(static_cast<int>(j));
        out[j].push_back(static_cast<int>(i));
      }
    }
  return out;
}

std::string ical_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\' || c == ';' || c == ',') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') out += c;
  }
  return out;
}

std::string ical_line(std::string_view line) {
  // At most 75 octets a line, the continuation's leading blank included; never inside a UTF-8
  // sequence (a continuation byte is 10xxxxxx).
  std::string out;
  std::size_t room = 75;
  while (line.size() > room) {
    std::size_t cut = room;
    while (cut > 1 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) --cut;
    out.append(line.substr(0, cut));
    out += "\r\n ";
    line.remove_prefix(cut);
    room = 74;
  }
  out.append(line);
  out += "\r\n";
  return out;
}

namespace {

// 20260521T134512Z
std::string ical_time(UtcTime t) {
  std::string s;
  for (const char c : format_iso8601(t, 0))
    if (c != '-' && c != ':') s += c;
  return s;
}

std::string degrees(double v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

}  // namespace

std::string ical_passes(const std::vector<NamedPass>& passes, UtcTime stamp, std::string_view where) {
  std::string out;
  for (const char* l : {"BEGIN:VCALENDAR", "VERSION:2.0", "PRODID:-//trakbox//satellite passes//EN", "CALSCALE:GREGORIAN",
                        "METHOD:PUBLISH"})
    out += ical_line(l);
  for (const NamedPass& n : passes) {
    const Pass& p = n.pass;
    std::string id;
    for (const char c : n.satellite) id += (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ? c : '-';
    out += ical_line("BEGIN:VEVENT");
    out += ical_line("UID:" + id + "-" + ical_time(p.aos).substr(0, 13) + "@trakbox");
    out += ical_line("DTSTAMP:" + ical_time(stamp));
    out += ical_line("DTSTART:" + ical_time(p.aos));
    out += ical_line("DTEND:" + ical_time(p.los));
    out += ical_line("SUMMARY:" + ical_text(n.satellite + " pass, max " + degrees(p.max_el_deg) + " deg"));
    out += ical_line("DESCRIPTION:" + ical_text(n.satellite + " over " + std::string(where) + ": AOS " +
                                                format_iso8601(p.aos) + " at azimuth " + degrees(p.aos_az_deg) +
                                                ", TCA " + format_iso8601(p.tca) + " at " + degrees(p.max_el_deg) +
                                                " deg elevation, azimuth " + degrees(p.tca_az_deg) + ", LOS " +
                                                format_iso8601(p.los) + " at azimuth " + degrees(p.los_az_deg)));
    out += ical_line("TRANSP:TRANSPARENT");
    out += ical_line("END:VEVENT");
  }
  out += ical_line("END:VCALENDAR");
  return out;
}

}  // namespace tb::orbit
