// Issue 56 item 1: the one door for JSON from outside (util/json_limits.h): the nesting bound
// before the parse, a sentence for a refusal, nothing thrown.
#include "util/json_limits.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "util/redact.h"

using tb::json_limits::parse_bounded;

TEST_CASE("parse_bounded: the nesting bound first, then the parse; a refusal is a sentence") {
  std::string why;
  const auto ok = parse_bounded<nlohmann::json>(R"({"a":[1,{"b":"[[[["}]})", why);
  CHECK(why.empty());
  CHECK(ok["a"][1]["b"] == "[[[[");  // brackets in strings do not count
  // 100,000 deep (the crash of issue 56): refused before it is parsed.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  CHECK(parse_bounded<nlohmann::json>(deep, why).is_discarded());
  CHECK(why == "nested deeper than 64 levels");
  // At the bound and one over.
  CHECK_FALSE(parse_bounded<nlohmann::json>(std::string(64, '[') + std::string(64, ']'), why).is_discarded());
  CHECK(why.empty());
  CHECK(parse_bounded<nlohmann::ordered_json>(std::string(65, '[') + std::string(65, ']'), why).is_discarded());
  CHECK(why == "nested deeper than 64 levels");
  CHECK(parse_bounded<nlohmann::json>(R"({"type":{"x":1}})", why, 1).is_discarded());
  CHECK(why == "nested deeper than 1 levels");
  // Syntax: located.
  tb::json_limits::ParseFailure f;
  CHECK(parse_bounded<nlohmann::json>("{\"a\":tru}", why, 64, &f).is_discarded());
  CHECK(why == "not JSON (at byte 9)");
  CHECK(f.located);
  CHECK(f.byte == 9);
  CHECK_FALSE(f.too_deep);
  CHECK(parse_bounded<nlohmann::json>("", why).is_discarded());
  CHECK(why == "not JSON (at byte 1)");
}

TEST_CASE("redact::secret: every occurrence of a held secret, in any case; short ones left alone") {
  using tb::redact::secret;
  CHECK(secret("the key 'cl64KEY' is not valid; CL64key again", "cl64KEY") ==
        "the key '<redacted>' is not valid; <redacted> again");
  CHECK(secret("nothing here", "cl64KEY") == "nothing here");
  CHECK(secret("abc abc", "abc") == "abc abc");  // under 4 characters: no key
  CHECK(secret("anything", "") == "anything");
}
