#pragma once
// Reading the logbook in bounded pieces (docs/logbook.md, "Paging"): a page is at most `limit`
// records in (time_on, id) order after a cursor; the cursor of the last record starts the next.
// Every front end that lists or exports the log (the web API, the station socket, `trakbox log`)
// asks page by page, so one request never holds the whole log (issue 56, item 4). Pure but for
// the one query of Logbook::page.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logbook/logbook.h"

namespace tb::logbook {

inline constexpr std::size_t kDefaultPage = 500;   // records a page has when the request says none
inline constexpr std::size_t kMaxPage = 1000;      // the most one request may ask

struct Cursor {
  std::int64_t time_on = INT64_MIN;  // the start: before every record
  std::int64_t id = 0;
};

// "TIME_ON.ID" of a record (e.g. "1796161460.42"): where the page after it starts.
std::string cursor_text(const Qso& q);
// The text back; nullopt when it is not two integers joined by '.'.
std::optional<Cursor> parse_cursor(std::string_view s);

struct Page {
  std::vector<Qso> qsos;
  std::optional<std::string> next;  // the cursor of the next page; none at the end of the log
};

// At most `limit` records with time_on >= since after `from`; `next` set when more may follow.
Page read_page(const Logbook& b, std::int64_t since, Cursor from, std::size_t limit);

// A page as ADIF: the file's header (write_adif's) only on the first page, then its records; the
// pages joined are the export of the whole log. The warnings are appended to `warnings`.
std::string adif_page(const std::vector<Qso>& qsos, bool first, std::string_view program_version,
                      std::int64_t created, std::vector<std::string>& warnings);

}  // namespace tb::logbook
