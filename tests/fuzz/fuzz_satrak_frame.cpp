// Satrak frames and payloads as a peer sends them (satrak::Decoder, decode_line, parse_payload,
// the field readers), also what trakbox's client reads from another ACU.
//
// The first byte sets the decoder's line bound, the second how the bytes are cut into reads.
// Properties: the decoder's memory stays within its bound; every line it reports is a frame, a bad
// checksum, malformed or overlong, with the payload within the bound; a frame's payload re-encoded
// decodes to itself; a parsed command's word is one the unit may echo (sanitize_word leaves it).
#include <algorithm>
#include <cmath>

#include "fuzz_station.h"
#include "rotator/satrak/commands.h"
#include "rotator/satrak/frame.h"

using namespace tb;

namespace {

void check_payload(std::string_view payload) {
  const auto c = satrak::parse_payload(payload);
  if (!c) return;
  // What the unit may echo: upper case letters, digits and '_', 32 at most (commands.h).
  TB_FUZZ_CHECK(!c->word.empty() && c->word.size() <= 32 && satrak::sanitize_word(c->word) == c->word, payload);
  const std::string head = c->head();
  (void)satrak::reply_ok(head);
  (void)satrak::reply_error(head, satrak::Error::bad_value);
  const std::string values = satrak::reply_values(head, c->fields);
  // A reply the client reads back.
  (void)satrak::parse_payload(values);
  for (const auto& f : c->fields) {
    if (const auto d = satrak::parse_number(f)) {
      TB_FUZZ_CHECK(std::isfinite(*d), f);
      (void)satrak::format_fixed(*d, 2);
    }
    (void)satrak::parse_integer(f);
    if (const auto lat = satrak::parse_latitude(f)) {
      TB_FUZZ_CHECK(*lat >= -90.0 && *lat <= 90.0, f);
      (void)satrak::format_latitude(*lat);
    }
    if (const auto lon = satrak::parse_longitude(f)) {
      TB_FUZZ_CHECK(*lon >= -180.0 && *lon <= 180.0, f);
      (void)satrak::format_longitude(*lon);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::size_t max_line = 8 + data[0] * 4;  // 8 .. 1028 (the server's is 512)
  const std::size_t chunk = 1 + data[1] % 64;
  const std::string_view bytes = fuzz::as_text(data + 2, size - 2);

  satrak::Decoder dec(max_line);
  std::vector<satrak::Decoded> out;
  for (std::size_t i = 0; i < bytes.size(); i += chunk) {
    dec.feed(bytes.substr(i, chunk), out);
    TB_FUZZ_CHECK(dec.pending() <= max_line, std::string(bytes));
  }
  for (const auto& d : out) {
    TB_FUZZ_CHECK(d.payload.size() <= max_line, d.payload);
    switch (d.kind) {
      case satrak::Decoded::Kind::frame: {
        const std::string again = satrak::encode(d.payload);
        if (again.size() - 2 <= max_line) {  // CR LF excluded
          const auto back = satrak::Decoder(max_line).feed(again);
          TB_FUZZ_CHECK(back.size() == 1 && back[0] == d, again);
        }
        check_payload(d.payload);
        break;
      }
      case satrak::Decoded::Kind::bad_checksum:
        TB_FUZZ_CHECK(d.expected == satrak::checksum(d.payload) && d.found != d.expected, d.payload);
        check_payload(d.payload);
        break;
      case satrak::Decoded::Kind::malformed:
      case satrak::Decoded::Kind::overlong:
        check_payload(d.payload);
        break;
    }
  }
  // Line by line, as the client reads replies and as `trakbox satrak` takes a command.
  for (const auto line : fuzz::split_lines(bytes, 64)) {
    satrak::Decoded d;
    if (satrak::decode_line(line, d)) check_payload(d.payload);
    check_payload(line);
  }
  return 0;
}
