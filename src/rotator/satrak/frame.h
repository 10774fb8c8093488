// Satrak ACU frames (docs/satrak.md, "Framing"): `$` + payload + `*` + two hex digits + CR LF.
// The checksum is the XOR of every payload byte (between `$` and `*`, both excluded):
//
//   encode("DATETIMEG?=,2016,12,22,15,55,40,10") == "$DATETIMEG?=,2016,12,22,15,55,40,10*6F\r\n"
//
// Pure: values in, values out, no I/O. The encoder is exact (upper-case hex, CR LF); the decoder
// is liberal in what it takes (missing CR, a bare CR, lower-case hex, garbage before `$`, binary
// bytes) and reports everything it cannot take instead of dropping it silently.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tb::satrak {

// XOR of the payload bytes.
std::uint8_t checksum(std::string_view payload);
// "$" + payload + "*" + HH + "\r\n", HH upper-case.
std::string encode(std::string_view payload);

// What the decoder found on one line.
struct Decoded {
  enum class Kind {
    frame,         // a frame whose checksum matches: payload is the command
    bad_checksum,  // well formed, but the checksum does not match: never act on payload
    malformed,     // a `$` but no `*` + two hex digits after the payload: payload is what followed `$`
    overlong,      // a line longer than the bound: payload is its first bytes (up to the bound)
  };
  Kind kind = Kind::frame;
  std::string payload;
  std::uint8_t expected = 0;  // bad_checksum: the checksum of the payload
  std::uint8_t found = 0;     // bad_checksum: the checksum the frame carried
  friend bool operator==(const Decoded&, const Decoded&) = default;
};

// A streaming decoder: feed it bytes as they arrive, in pieces of any size; complete lines come out.
//  * A line ends at LF or CR (CR LF, LF alone and CR alone all end one line; empty lines are skipped).
//  * The frame starts at the last `$` of the line; anything before it is noise and ignored. A line
//    with no `$` at all is noise (a terminal's stray newline, line garbage) and produces nothing.
//  * The checksum is the two characters after the last `*`, either case; spaces or tabs after them
//    are ignored. Anything else there makes the line malformed.
//  * A line longer than max_line bytes is reported once, as soon as it overflows, and the rest of it
//    is discarded up to the next line end: memory stays bounded whatever a peer sends.
class Decoder {
 public:
  static constexpr std::size_t kDefaultMaxLine = 512;
  explicit Decoder(std::size_t max_line = kDefaultMaxLine) : max_line_(max_line) {}

  // Appends what the bytes complete to `out`.
  void feed(std::string_view bytes, std::vector<Decoded>& out);
  std::vector<Decoded> feed(std::string_view bytes) {
    std::vector<Decoded> out;
    feed(bytes, out);
    return out;
  }
  // Bytes of the current, unfinished line held (at most max_line).
  std::size_t pending() const { return line_.size(); }
  std::size_t max_line() const { return max_line_; }

 private:
  void finish_line(std::vector<Decoded>& out);
  std::size_t max_line_;
  std::string line_;
  bool discarding_ = false;  // inside an overlong line (already reported)
};

// Decodes one complete line (without its line end) the way Decoder does; false for noise (no `$`).
bool decode_line(std::string_view line, Decoded& out);

}  // namespace tb::satrak
