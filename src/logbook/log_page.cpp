#include "logbook/log_page.h"

#include <charconv>

#include "logbook/adif.h"

namespace tb::logbook {

std::string cursor_text(const Qso& q) { return std::to_string(q.time_on) + "." + std::to_string(q.id); }

std::optional<Cursor> parse_cursor(std::string_view s) {
  const auto dot = s.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == s.size()) return std::nullopt;
  Cursor c;
  const auto a = std::from_chars(s.data(), s.data() + dot, c.time_on);
  const auto b = std::from_chars(s.data() + dot + 1, s.data() + s.size(), c.id);
  if (a.ec != std::errc() || a.ptr != s.data() + dot || b.ec != std::errc() || b.ptr != s.data() + s.size())
    return std::nullopt;
  return c;
}

Page read_page(const Logbook& b, std::int64_t since, Cursor from, std::size_t limit) {
  Page p;
  if (limit == 0) return p;
  p.qsos = b.page(since, from.time_on, from.id, limit);
  if (p.qsos.size() == limit) p.next = cursor_text(p.qsos.back());
  return p;
}

std::string adif_page(const std::vector<Qso>& qsos, bool first, std::string_view program_version,
                      std::int64_t created, std::vector<std::string>& warnings) {
  AdifExport e = write_adif(qsos, program_version, created);
  for (auto& w : e.warnings) warnings.push_back(std::move(w));
  if (first) return std::move(e.text);
  const auto eoh = e.text.find("<EOH>\n");
  return eoh == std::string::npos ? std::move(e.text) : e.text.substr(eoh + 6);
}

}  // namespace tb::logbook
