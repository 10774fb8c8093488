// The state document: what store::StateFile::load reads back from disk, and what
// store::model_from_json and satrak::settings_from_json make of its data.
//
// First byte even: the rest is the JSON text of the data (nlohmann parse, then the strict readers).
// First byte odd: the rest is the whole state file, loaded by StateFile from a scratch directory.
// Properties:
//  * the readers accept or throw a std::exception whose message names the field (a bare
//    "[json.exception...]" from inside nlohmann says nothing about where);
//  * what they accept is saved and read back the same (else the next start loses the state);
//  * a state file refused as corrupt is kept aside byte for byte, never lost.
#include "fuzz_station.h"
#include "satrak/settings.h"
#include "store/state_file.h"

using namespace tb;
using nlohmann::json;

namespace {

void check_message(const std::exception& e, const std::string& input) {
  const std::string what = e.what();
  TB_FUZZ_CHECK(!what.empty(), input);
  TB_FUZZ_CHECK(what.rfind("[json.exception", 0) != 0, what + "\n" + input);
}

void read_data(const json& data, const std::string& input) {
  try {
    const store::Model m = store::model_from_json(data);
    const json saved = store::to_json(m);
    store::Model back;
    try {
      back = store::model_from_json(saved);
    } catch (const std::exception& e) {
      fuzz::violated("a model model_from_json accepted does not read back", std::string(e.what()) + "\n" + input);
    }
    TB_FUZZ_CHECK(store::to_json(back) == saved, input);
  } catch (const std::exception& e) {
    check_message(e, input);
  }
  for (const json* j : {&data, data.is_object() && data.contains("satrak") ? &data["satrak"] : nullptr}) {
    if (!j) continue;
    try {
      const satrak::Settings s = satrak::settings_from_json(*j);
      const json saved = satrak::to_json(s);
      satrak::Settings back;
      try {
        back = satrak::settings_from_json(saved);
      } catch (const std::exception& e) {
        fuzz::violated("settings settings_from_json accepted do not read back", std::string(e.what()) + "\n" + input);
      }
      TB_FUZZ_CHECK(satrak::to_json(back) == saved, input);
    } catch (const std::exception& e) {
      check_message(e, input);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string input(fuzz::as_text(data + 1, size - 1));
  if ((data[0] & 1) == 0) {
    const json doc = json::parse(input, nullptr, false);
    if (!doc.is_discarded()) read_data(doc, input);
    return 0;
  }

  static const fuzz::fs::path dir = fuzz::scratch_dir() / "state";
  std::error_code ec;
  fuzz::fs::remove_all(dir, ec);
  fuzz::fs::create_directories(dir);
  const store::StateFile file(dir);
  fuzz::write_file(file.path(), input);
  const store::LoadOutcome out = file.load();
  switch (out.kind) {
    case store::LoadOutcome::Kind::fresh:
      fuzz::violated("a state file that is there loaded as fresh", input);
    case store::LoadOutcome::Kind::corrupt:
      TB_FUZZ_CHECK(!out.reason.empty(), input);
      TB_FUZZ_CHECK(!fuzz::fs::exists(file.path()), input);
      TB_FUZZ_CHECK(fuzz::read_file(out.kept_aside) == input, out.kept_aside.string());
      break;
    case store::LoadOutcome::Kind::loaded:
      read_data(out.data, input);
      break;
  }
  return 0;
}
