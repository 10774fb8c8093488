// satrak::Unit on a whole simulated station: what a monitor-and-control client sends over TCP.
//
// The input is cut into lines (at most 48). A line starting with '$' goes through the frame decoder
// (as the server feeds it) and each decoded line to Unit::handle(Decoded); any other line is a bare
// payload for Unit::handle(payload). A line "~N" lets N seconds pass (at most 10 h, in at most 20
// ticks): tracking windows, pre-positioning, file checks. After every line 1 s passes and the
// station and the unit tick, as the event loop would. Downloads never leave the machine
// (no_network.cpp); the TLE directory holds the shipped elements as amateur.txt and an AMSAT copy,
// the image directory a good image and a broken one.
// Properties: every reply is a payload a peer reads back unchanged from its frame (encode, then a
// 512-byte decoder: one frame, the same payload), holds no control byte, '$' or '*', and parses as a reply (WORD?/WORD= and fields), or
// is the refusal of something that is not a command ("ERR,n", "WORD,ERR,n"); the settings and the
// model the unit leaves read back.
#include <boost/asio/io_context.hpp>

#include "fuzz_station.h"
#include "rotator/satrak/commands.h"
#include "rotator/satrak/frame.h"
#include "satrak/settings.h"
#include "satrak/unit.h"
#include "store/state_file.h"

using namespace tb;

namespace {

struct Dirs {
  fuzz::fs::path tle, images;
};

const Dirs& dirs() {
  static const Dirs d = [] {
    Dirs r{fuzz::scratch_dir() / "tle", fuzz::scratch_dir() / "images"};
    fuzz::fs::create_directories(r.tle);
    fuzz::fs::create_directories(r.images);
    const std::string tle = fuzz::data_file("amateur.tle");
    fuzz::write_file(r.tle / "amateur.txt", tle);
    std::string amsat;
    for (const auto& e : orbit::parse_nasa(tle).sets) amsat += orbit::format_amsat(e) + "\n";
    fuzz::write_file(r.tle / "keps.txt", amsat);
    fuzz::write_file(r.tle / "empty.txt", "");
    // A good image (the shipped model, Satrak settings with a window) and a broken one.
    nlohmann::json data = store::to_json(fuzz::shipped_model());
    satrak::Settings s;
    s.tle_file = "amateur.txt";
    s.satellite = "ISS";
    data["satrak"] = satrak::to_json(s);
    std::string error;
    const store::StateFile f(r.images);
    if (!f.save(data, error)) fuzz::violated("cannot write the image", error);
    fuzz::fs::rename(f.path(), r.images / "image.json");
    std::string broken = fuzz::read_file(r.images / "image.json");
    broken[broken.size() / 2] ^= 1;
    fuzz::write_file(r.images / "broken.json", broken);
    return r;
  }();
  return d;
}

void check_reply(const std::string& reply, std::string_view input) {
  const std::string why = "reply '" + reply + "' to:\n" + std::string(input);
  const auto back = satrak::Decoder().feed(satrak::encode(reply));
  TB_FUZZ_CHECK(back.size() == 1 && back[0].kind == satrak::Decoded::Kind::frame && back[0].payload == reply, why);
  // "Sent: always exact": no control bytes, no '$' or '*' inside (docs/satrak.md, Framing).
  for (const unsigned char c : reply) TB_FUZZ_CHECK(c >= 0x20 && c != 0x7F && c != '$' && c != '*', why);
  if (satrak::parse_payload(reply)) return;
  // A refusal of something that is not a command: "ERR,n" or "WORD,ERR,n" (docs/satrak.md).
  // The word is what sanitize_word leaves (it may itself end in "ERR": "VERR,ERR,4").
  std::size_t err = 0;
  if (reply.rfind("ERR,", 0) != 0) {
    const std::size_t comma = reply.find(',');
    TB_FUZZ_CHECK(comma != std::string::npos && comma > 0 && satrak::sanitize_word(reply.substr(0, comma)) == reply.substr(0, comma), why);
    TB_FUZZ_CHECK(reply.compare(comma + 1, 4, "ERR,") == 0, why);
    err = comma + 1;
  }
  TB_FUZZ_CHECK(reply.find_first_not_of("0123456789", err + 4) == std::string::npos && reply.size() > err + 4, why);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = fuzz::as_text(data, size);
  const Dirs& d = dirs();

  store::Model m = fuzz::shipped_model();
  m.station.rotor_start = station::RotorStart::north;
  fuzz::Station st(std::move(m));
  boost::asio::io_context io;
  satrak::UnitOptions o;
  o.tle_dir = d.tle;
  o.image_dir = d.images;
  o.version = "9.9.9";
  o.file_check = std::chrono::seconds(1);
  o.retry_after = std::chrono::seconds(60);
  o.download_timeout = std::chrono::milliseconds(100);
  int saves = 0;
  satrak::Unit unit(io, *st.station, st.model, st.clock, {}, o, satrak::UnitHooks{[&saves]() -> std::optional<std::string> {
    ++saves;
    return std::nullopt;
  }});

  auto tick = [&](std::chrono::milliseconds dt) {
    st.step(dt);
    unit.tick();
  };
  for (const auto line : fuzz::split_lines(input, 48)) {
    if (line.size() >= 2 && line[0] == '~') {
      long seconds = 0;
      for (const char c : line.substr(1, 5))
        if (c >= '0' && c <= '9') seconds = seconds * 10 + (c - '0');
      seconds = std::min(seconds, 36000L);
      const auto step = std::chrono::milliseconds(std::max(1L, seconds * 1000 / 20));
      for (auto t = std::chrono::milliseconds(0); t < std::chrono::seconds(seconds); t += step) tick(step);
      continue;
    }
    if (!line.empty() && line[0] == '$') {
      satrak::Decoder dec;
      for (const auto& decoded : dec.feed(std::string(line) + "\r\n")) check_reply(unit.handle(decoded), input);
    } else {
      check_reply(unit.handle(line), input);
    }
    tick(std::chrono::seconds(1));
  }
  // What the program does with the settings at every save.
  const nlohmann::json saved = satrak::to_json(unit.settings());
  try {
    (void)satrak::settings_from_json(saved);
  } catch (const std::exception& e) {
    fuzz::violated("the unit's settings do not read back", std::string(e.what()) + "\n" + std::string(input));
  }
  fuzz::check_model_reads_back(st.model, input);
  return 0;
}
