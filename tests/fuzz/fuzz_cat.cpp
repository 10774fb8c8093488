// The CAT decoders of bytes that come back from a radio (src/radio/cat.h): the Icom CI-V frame
// reader, frame decoder, reply and frequency/mode decoders (what IcomLink reads from the bus), the
// Kenwood command splitter and decoders, the Yaesu FT-736 command decoder, the FT-847/FT-817 read
// answers, and from_hex (host
// mode's and the tests' byte strings).
//
// The first byte picks the family (and for Icom how the bytes are cut into reads).
// Properties: the frame reader hands out every byte it takes at most once, each frame is one
// FE FE ... FD (or a lone FC jam code); a decoded frame re-encodes to its bytes; a decoded
// Kenwood frequency re-encodes to its command; what the encoders write decodes to what they took.
#include <algorithm>
#include <stdexcept>

#include "fuzz_station.h"
#include "radio/cat.h"

using namespace tb;
using namespace tb::radio;

namespace {

void icom_family(std::span<const std::uint8_t> bytes, std::size_t chunk) {
  icom::FrameReader reader;
  std::size_t handed_out = 0;
  auto drain = [&] {
    for (int guard = 0; guard < 100000; ++guard) {
      const auto f = reader.next();
      if (!f) return;
      handed_out += f->size();
      TB_FUZZ_CHECK(!f->empty(), "empty frame");
      if (f->size() == 1) {
        TB_FUZZ_CHECK((*f)[0] == icom::kCollision, to_hex(*f));
        continue;
      }
      TB_FUZZ_CHECK((*f)[0] == icom::kPreamble && f->back() == icom::kEnd, to_hex(*f));
      (void)icom::parse_reply(*f);
      if (const auto fr = icom::decode_frame(*f)) {
        TB_FUZZ_CHECK(icom::frame(fr->to, fr->from, fr->cmd, fr->data) == *f, to_hex(*f));
        if (const auto hz = icom::decode_frequency(*fr)) {
          try {
            const auto w = fr->data.size() == 4 ? icom::FrequencyWidth::four_bytes : icom::FrequencyWidth::five_bytes;
            const Bytes again = icom::set_frequency(fr->to, *hz, w, fr->from);
            const auto back = icom::decode_frame(again);
            TB_FUZZ_CHECK(back && icom::decode_frequency(*back) == hz, to_hex(*f) + " -> " + to_hex(again));
          } catch (const std::invalid_argument&) {
          }
        }
        if (const auto m = icom::decode_mode(*fr)) (void)icom::mode_code(*m);
      }
    }
    fuzz::violated("FrameReader::next() never ran dry");
  };
  for (std::size_t i = 0; i < bytes.size(); i += chunk) {
    reader.feed(bytes.subspan(i, std::min(chunk, bytes.size() - i)));
    drain();
  }
  TB_FUZZ_CHECK(handed_out + reader.skipped() <= bytes.size(), to_hex(bytes));
}

void kenwood_family(std::string_view text) {
  std::string rest;
  const auto commands = kenwood::split_commands(text, &rest);
  std::size_t total = rest.size();
  for (const auto& c : commands) {
    total += c.size();
    TB_FUZZ_CHECK(!c.empty() && c.back() == ';', c);
    if (const auto f = kenwood::decode_frequency(c)) {
      try {
        TB_FUZZ_CHECK(kenwood::set_frequency(f->vfo, f->hz) == c, c);
      } catch (const std::invalid_argument&) {
      }
    }
    if (const auto m = kenwood::decode_mode(c)) (void)kenwood::set_mode(*m);
  }
  TB_FUZZ_CHECK(total == text.size(), std::string(text));
  (void)kenwood::decode_frequency(rest);
  (void)kenwood::decode_mode(rest);
}

void yaesu_family(std::span<const std::uint8_t> bytes) {
  for (std::size_t i = 0; i + 5 <= bytes.size(); i += 5) {
    const yaesu::Command c{bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3], bytes[i + 4]};
    const auto d = yaesu::decode(c);
    if (d.kind == yaesu::Decoded::Kind::frequency) {
      try {
        const auto again = yaesu::decode(yaesu::set_frequency(d.target, d.hz));
        TB_FUZZ_CHECK(again.kind == yaesu::Decoded::Kind::frequency && again.hz == d.hz, to_hex(c));
      } catch (const std::invalid_argument&) {
      }
    }
    // The same 5 bytes as an FT-847/FT-817 read answer (4 BCD bytes of 10 Hz and the mode): what
    // decodes re-encodes to the same digits.
    if (const auto hz = ft847::decode_read(std::span<const std::uint8_t>(c.data(), 5))) {
      const yaesu::Command w = ft847::set_frequency(yaesu::Target::sat_rx, *hz);
      TB_FUZZ_CHECK(std::equal(w.begin(), w.begin() + 4, c.begin()) && w[4] == 0x11, to_hex(c));
      TB_FUZZ_CHECK(ft817::set_frequency(*hz)[3] == c[3], to_hex(c));
    }
  }
}

void hex_family(std::string_view text) {
  if (const auto b = from_hex(text)) {
    const auto again = from_hex(to_hex(*b));
    TB_FUZZ_CHECK(again && *again == *b, std::string(text));
  }
  const std::span<const std::uint8_t> s(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  (void)decode_bcd_little_endian(s.first(std::min<std::size_t>(s.size(), 8)));
  (void)decode_bcd_big_endian(s.first(std::min<std::size_t>(s.size(), 8)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  switch (data[0] & 3) {
    case 0: icom_family(bytes, 1 + (data[0] >> 2)); break;
    case 1: kenwood_family(text); break;
    case 2: yaesu_family(bytes); break;
    default: hex_family(text); break;
  }
  return 0;
}
