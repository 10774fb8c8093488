// Element names from any element file through to what trakbox writes: the terminal (`trakbox
// elements`, `passes`, the menus), JSON (`passes --json`, the state file, status and events).
// Issue 38: IS\xff\xfeS in a name aborted every start (type_error.316 from dump()), escape sequences
// reached the terminal, and `passes --json` wrote invalid UTF-8.
//
// Properties: every name parse_elements gives, and every problem's message, is printable UTF-8
// (util/safe_text.h); the passes JSON writer's string of a name is JSON that reads back to the name;
// the names in the state's database dump without throwing, and read back to themselves.
#include <nlohmann/json.hpp>

#include "cli/cli_orbit_internal.h"
#include "fuzz_station.h"
#include "orbit/elements.h"
#include "store/database.h"
#include "store/model.h"
#include "util/safe_text.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const orbit::ParseResult r = orbit::parse_elements(text, "fuzz.tle");
  for (const orbit::ParseProblem& p : r.problems) TB_FUZZ_CHECK(text::is_safe_text(p.message()), p.message());
  for (const orbit::Elements& e : r.sets) {
    TB_FUZZ_CHECK(text::is_safe_text(e.name), e.name);
    const std::string quoted = app::orbit_cli::json_string(e.name);
    const nlohmann::json back = nlohmann::json::parse(quoted, nullptr, false);
    TB_FUZZ_CHECK(back.is_string() && back.get<std::string>() == e.name, quoted);
  }
  try {
    store::Model m = store::factory_defaults();
    m.db = store::make_database(r.sets, {});
    const std::string saved = store::to_json(m).dump();
    TB_FUZZ_CHECK(text::is_safe_text(saved), saved);
  } catch (const std::exception& e) {
    fuzz::violated("the names do not dump", std::string(e.what()) + "\n" + std::string(text));
  }
  return 0;
}
