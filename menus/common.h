// What every menu of the manual shares: the satellite lists with their markers, prompts that show
// the current value (Enter keeps it), Y/N questions, and the formats of the manual's displays.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "menus/term/terminal.h"
#include "orbit/sky.h"
#include "orbit/time.h"
#include "util/text.h"   // text::trimmed, the menus' answers as read

namespace tb::menus {

// Thrown out of any prompt when the input has closed for good (the program then saves and exits).
struct InputClosed {};

// Thrown out of a line prompt by Esc in a menu that leaves unchanged on Esc (EscapeLeaves).
struct Escaped {};
// While alive, Esc at `t`'s line prompts throws Escaped (Terminal::set_escape_leaves).
class EscapeLeaves {
 public:
  explicit EscapeLeaves(term::Terminal& t) : t_(t), was_(t.escape_leaves()) { t.set_escape_leaves(true); }
  ~EscapeLeaves() { t_.set_escape_leaves(was_); }
  EscapeLeaves(const EscapeLeaves&) = delete;
  EscapeLeaves& operator=(const EscapeLeaves&) = delete;

 private:
  term::Terminal& t_;
  bool was_;
};

// Reads a line, throwing InputClosed when input ends (and Escaped on Esc under EscapeLeaves).
std::string read_line(term::Terminal& t, std::size_t max_length = 80);
// A [Y/N] question: prints the prompt, returns true for Y. Any other key is No.
bool ask_yes_no(term::Terminal& t, std::string_view prompt);
// A single-key choice among `keys` (upper-cased); Enter returns '\r' when allow_enter.
char ask_key(term::Terminal& t, std::string_view prompt, std::string_view keys, bool allow_enter = false);

// What a menu's choice did: go on asking (showing the menu again), `unknown` (only the prompt is
// asked again), or `back` (the menu returns).
enum class MenuStep { again, unknown, back };
// The loop of a menu of the manual: `show` prints the menu, then `prompt` is asked and an answer of
// one key (white space around it ignored) is handed upper-cased to `choose`. An answer that is not
// one key asks again without showing the menu, as `unknown` does. Returns when `choose` says `back`.
void run_menu(term::Terminal& t, const std::function<void()>& show, std::string_view prompt,
              const std::function<MenuStep(char key)>& choose);

// "Label : current " then the answer; Enter keeps the current value. validate returns an error
// message for a bad answer (the prompt is repeated), or nullopt when fine.
std::string edit_text(term::Terminal& t, std::string_view label, std::string_view current,
                      const std::function<std::optional<std::string>(const std::string&)>& validate = {});
// The same for numbers within [lo, hi]; `shown` is how the current value is printed.
double edit_number(term::Terminal& t, std::string_view label, double current, std::string_view shown, double lo,
                   double hi);
int edit_int(term::Terminal& t, std::string_view label, int current, int lo, int hi);

// Strict number parsing: the whole text must be a number.
std::optional<double> parse_number(std::string_view text);
std::optional<long> parse_integer(std::string_view text);

// The manual's satellite list: four to a row, "n. NAME" with '*' (or another marker) before the
// marked one. names[i] is entry i+1.
std::vector<std::string> format_satellite_list(const std::vector<std::string>& names, int marked_index,
                                               char marker = '*');
// Shows the list and asks "Select :"; Enter picks the marked entry. Returns the 0-based index, or
// nullopt for Q (or an empty list). With `body` (menus 1 and S), SUN or MOON (any case) is taken
// too: *body is set and the index returned is -1 (issue 58).
std::optional<int> choose_satellite(term::Terminal& t, std::string_view title, const std::vector<std::string>& names,
                                    int marked_index, char marker = '*', std::optional<orbit::Body>* body = nullptr);

// "1993/07/17" and "04:06:58".
std::string format_date(orbit::UtcTime t);
std::string format_time(orbit::UtcTime t);
// "[YY/MM/DD HH:MM:SS]" input (two-digit year, 57 pivot) -> time; nullopt when malformed.
std::optional<orbit::UtcTime> parse_yymmdd_hhmmss(std::string_view text);

}  // namespace tb::menus
