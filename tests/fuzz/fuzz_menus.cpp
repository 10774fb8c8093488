// The menus' input path: keys from the operator's terminal (or a serial line, or a pasted upload)
// into menus::main_menu on a whole simulated station, through the ScriptTerminal. Every wait for a
// key lets its timeout (1 s without one) pass on the station's clock and ticks the station, as the
// event loop would. The input ends the session (InputClosed), so the keys bound the work: libFuzzer's
// -max_len is the bound (scripts/fuzz.sh gives 2048).
//
// The first byte is the number of timed waits each live display sees before the next key (0..3):
// the realtime displays then redraw and track between keys. The corpus starts in the interesting
// places: uploads of menu 3-3 (elements, then freq/mode, each ended by Ctrl-Z), menu 6-9's station
// file, menu 4, 5, the realtime displays.
// Properties: no crash or hang whatever is typed; the model left behind reads back.
#include "fuzz_station.h"
#include "menus/menus.h"
#include "menus/term/script_terminal.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view keys = fuzz::as_text(data + 1, size - 1);

  fuzz::Station st(fuzz::shipped_model(), false);
  int saves = 0;
  menus::Services services{st.model, st.clock, st.tracker, *st.station,
                           [&saves]() -> std::optional<std::string> {
                             ++saves;
                             return std::nullopt;
                           },
                           "fuzz", {}};
  term::ScriptTerminal term{std::string(keys)};
  term.timeouts_before_key = data[0] & 3;
  term.on_wait = [&st](std::optional<term::Duration> timeout) {
    st.now += std::chrono::duration_cast<std::chrono::microseconds>(timeout.value_or(std::chrono::seconds(1)));
    st.station->tick();
  };
  try {
    menus::sign_on(term, services);
    menus::main_menu(term, services);
  } catch (const menus::InputClosed&) {
  }
  fuzz::check_model_reads_back(st.model, keys);
  return 0;
}
