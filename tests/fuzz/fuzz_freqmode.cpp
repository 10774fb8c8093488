// The freq/mode file of menu 3-3 (radio::parse_freqmode) and its field readers, the 1994 file and
// the later firmware's FREQ.DAT (comments, up to four uplinks, ir/kr) and trakbox's options (down= up= inv= tone=).
// Properties: every problem names a field and has a message; the records of a clean parse come
// back unchanged through write_freqmode (the file trakbox writes is one it reads); the MHz reader
// and writer agree.
#include "fuzz_station.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const auto r = radio::parse_freqmode(text);
  for (const auto& p : r.problems) {
    const std::string m = p.message();
    TB_FUZZ_CHECK(!m.empty() && p.line >= 1 && p.field >= 0 && (p.field <= 8 || p.option), m);
    (void)radio::freqmode_field_name(p.field);
  }
  if (r.ok() && !r.records.empty()) {
    const std::string written = radio::write_freqmode(r.records);
    const auto again = radio::parse_freqmode(written);
    std::string why = written;
    for (const auto& p : again.problems) why += p.message() + "\n";
    TB_FUZZ_CHECK(again.ok() && again.records.size() == r.records.size(), why);
    for (std::size_t i = 0; i < r.records.size(); ++i) {
      auto a = r.records[i], b = again.records[i];
      a.line = b.line = 0;
      TB_FUZZ_CHECK(a == b, why);
    }
  }
  // Each blank-separated word as a frequency field.
  std::size_t words = 0;
  for (std::size_t i = 0; i < text.size() && words < 16;) {
    const std::size_t end = text.find_first_of(" \t\r\n", i);
    const std::string_view w = text.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i);
    if (!w.empty()) {
      ++words;
      if (const auto hz = radio::parse_mhz(w)) {
        const std::string back = radio::format_mhz(*hz);
        TB_FUZZ_CHECK(radio::parse_mhz(back) == hz, std::string(w) + " -> " + back);
      }
      if (const auto f = radio::parse_frequency_field(w)) {
        const std::string back = radio::format_frequency_field(f->rf_hz, f->offset_hz);
        const auto g = radio::parse_frequency_field(back);
        TB_FUZZ_CHECK(g && g->rf_hz == f->rf_hz && g->offset_hz == f->offset_hz, std::string(w) + " -> " + back);
      }
      if (const auto u = radio::parse_uplink_field(w)) {
        TB_FUZZ_CHECK(!u->rf_hz.empty() && u->rf_hz.size() <= radio::kMaxUplinkChannels, std::string(w));
        for (const radio::Hz hz : u->rf_hz) TB_FUZZ_CHECK(hz >= 0, std::string(w));
      }
    }
    if (end == std::string_view::npos) break;
    i = end + 1;
  }
  return 0;
}
