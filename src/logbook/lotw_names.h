#pragma once
// The satellite names LoTW matches (TQSL's satellite list, its SAT_NAME) by NORAD catalog number:
// the shipped table data/lotw-satellites.txt (its source and refresh rule are in its header and
// in data/README.md). A satellite not in it has no LoTW name: the export warns and leaves SAT_NAME
// out rather than guess.
#include <map>
#include <string>
#include <string_view>

namespace tb::logbook {

struct LotwNames {
  std::map<int, std::string> by_norad;
  std::string error;  // "line 7: ..." when the table is malformed (then by_norad is empty)
  std::string name(int norad) const;  // "" when not known
};

// "NORAD NAME [# comment]" per line; '#' lines and blank lines are comments.
LotwNames parse_lotw_names(std::string_view text);
// The table of a file (error set when it cannot be read).
LotwNames load_lotw_names(const std::string& path);

}  // namespace tb::logbook
