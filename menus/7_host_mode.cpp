// Menu 7: Host mode on the operator's terminal: the banner, the command line, then "TrakBox>>"
// after every command until Q. The commands themselves are src/host/host_mode.h, which knows
// nothing of terminals (the same interpreter will serve stdio and TCP).
#include "host/host_mode.h"
#include "menus/menus.h"

namespace tb::menus {

void menu_7_host_mode(term::Terminal& t, Services& s) {
  host::Interpreter interpreter(s.station);
  for (const auto& l : host::Interpreter::greeting()) t.line(l);
  for (;;) {
    t.write(host::kPrompt);
    t.flush();
    const host::Reply r = interpreter.execute(read_line(t, 256));
    for (const auto& l : r.lines) t.line(l);
    if (r.quit) return;
  }
}

}  // namespace tb::menus
