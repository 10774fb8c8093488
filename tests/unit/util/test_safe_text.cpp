// safe_text against Python's bytes.decode("utf-8", "replace") (the same maximal-subpart rule), with
// control characters then replaced by U+FFFD: the expected strings were printed by
//   python3 -c 'print(b"...".decode("utf-8","replace").encode().hex())'
#include "util/safe_text.h"

#include <doctest/doctest.h>

#include <string>

using namespace tb::text;

namespace {
const std::string R = "\xEF\xBF\xBD";  // U+FFFD
}

TEST_CASE("safe_text: the element name of issue 38's restart loop") {
  CHECK(safe_text("IS\xff\xfeS") == "IS" + R + R + "S");
  CHECK_FALSE(is_safe_text("IS\xff\xfeS"));
}

TEST_CASE("safe_text: printable UTF-8 is kept byte for byte") {
  for (const std::string s : {"", "ISS (ZARYA)", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "AO-7 \xc3\xa9t\xc3\xa9", "~"}) {
    CHECK(safe_text(s) == s);
    CHECK(is_safe_text(s));
  }
}

TEST_CASE("safe_text: ill-formed UTF-8, one U+FFFD per maximal subpart (as Python)") {
  CHECK(safe_text("\xe2\x82") == R);                 // cut short at the end
  CHECK(safe_text("\xe2\x82" "A") == R + "A");       // cut short by an ASCII byte
  CHECK(safe_text("\xed\xa0\x80") == R + R + R);     // a surrogate
  CHECK(safe_text("\xc0\xaf") == R + R);             // an overlong '/'
  CHECK(safe_text("\xf4\x90\x80\x80") == R + R + R + R);  // above U+10FFFF
  CHECK(safe_text("\x80") == R);                     // a stray continuation byte
  CHECK(safe_text("\xf0\x9f\x98") == R);             // a 4-byte sequence missing its last byte
}

TEST_CASE("safe_text: control characters, C0, DEL and C1, become U+FFFD") {
  // The escape sequences of issue 38: ESC[2J ESC[31m EVIL ESC]0;pwn BEL.
  CHECK(safe_text("\x1b[2J\x1b[31mEVIL\x1b]0;pwn\x07") == R + "[2J" + R + "[31mEVIL" + R + "]0;pwn" + R);
  CHECK(safe_text("a\tb\nc\rd") == "a" + R + "b" + R + "c" + R + "d");
  CHECK(safe_text(std::string("a\0b", 3)) == "a" + R + "b");
  CHECK(safe_text("\x7f") == R);
  CHECK(safe_text("a\xc2\x9b" "b") == "a" + R + "b");  // U+009B, the 8-bit CSI
  CHECK(safe_text("\xc2\xa0") == "\xc2\xa0");          // U+00A0 is not a control character
  CHECK_FALSE(is_safe_text("\x1b"));
  CHECK_FALSE(is_safe_text("\xc2\x9b"));
}

TEST_CASE("safe_text's result is always safe") {
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  CHECK(is_safe_text(safe_text(all)));
  CHECK(safe_text(safe_text(all)) == safe_text(all));
}

TEST_CASE("visible_bytes shows what the outside sent") {
  CHECK(visible_bytes("IS\xff\xfeS") == "IS\\xff\\xfeS");
  CHECK(visible_bytes("a\\b\x1b") == "a\\\\b\\x1b");
  CHECK(visible_bytes("") == "");
}
