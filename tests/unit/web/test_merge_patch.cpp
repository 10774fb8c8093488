// web::merge_patch_diff against RFC 7386: the examples of its Appendix A and of section 3, each
// original and result given, the patch we write compared with the RFC's (the same one, or where the
// RFC's patch holds members that change nothing, the patch without them), and applied back with
// nlohmann::json::merge_patch (an implementation of the RFC's section 2, not ours).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "web/merge_patch.h"

using json = nlohmann::json;

namespace {
struct Case {
  const char* original;
  const char* result;
  const char* patch;  // what the diff must be
};

json applied(json target, const json& patch) {
  target.merge_patch(patch);
  return target;
}
}  // namespace

TEST_CASE("merge_patch_diff: RFC 7386 Appendix A") {
  const Case cases[] = {
      {R"({"a":"b"})", R"({"a":"c"})", R"({"a":"c"})"},
      {R"({"a":"b"})", R"({"a":"b","b":"c"})", R"({"b":"c"})"},
      {R"({"a":"b"})", R"({})", R"({"a":null})"},
      {R"({"a":"b","b":"c"})", R"({"b":"c"})", R"({"a":null})"},
      {R"({"a":["b"]})", R"({"a":"c"})", R"({"a":"c"})"},
      {R"({"a":"c"})", R"({"a":["b"]})", R"({"a":["b"]})"},
      // the RFC's patch is {"a":{"b":"d","c":null}}: "c" was not there, so removing it changes nothing
      {R"({"a":{"b":"c"}})", R"({"a":{"b":"d"}})", R"({"a":{"b":"d"}})"},
      {R"({"a":[{"b":"c"}]})", R"({"a":[1]})", R"({"a":[1]})"},
      {R"(["a","b"])", R"(["c","d"])", R"(["c","d"])"},
      {R"({"a":"b"})", R"(["c"])", R"(["c"])"},
      {R"({"a":"foo"})", R"(null)", R"(null)"},
      {R"({"a":"foo"})", R"("bar")", R"("bar")"},
      {R"({"e":null})", R"({"e":null,"a":1})", R"({"a":1})"},
      // the RFC's patch is {"a":"b","c":null}: the array becomes {} first, which has no "c"
      {R"([1,2])", R"({"a":"b"})", R"({"a":"b"})"},
      {R"({})", R"({"a":{"bb":{}}})", R"({"a":{"bb":{}}})"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.original);
    CAPTURE(c.result);
    const json original = json::parse(c.original), result = json::parse(c.result);
    const auto patch = tb::web::merge_patch_diff(original, result);
    REQUIRE(patch.has_value());
    CHECK(*patch == json::parse(c.patch));
    CHECK(applied(original, *patch) == result);
  }
}

TEST_CASE("merge_patch_diff: RFC 7386 section 3, the author example") {
  const json target = json::parse(R"({"title":"Goodbye!","author":{"givenName":"John","familyName":"Doe"},
                                      "tags":["example","sample"],"content":"This will be unchanged"})");
  const json result = json::parse(R"({"title":"Hello!","author":{"givenName":"John"},"tags":["example"],
                                      "content":"This will be unchanged","phoneNumber":"+01-555-1234"})");
  const auto patch = tb::web::merge_patch_diff(target, result);
  REQUIRE(patch.has_value());
  CHECK(*patch == json::parse(R"({"title":"Hello!","phoneNumber":"+01-555-1234","author":{"familyName":null},
                                  "tags":["example"]})"));
  CHECK(applied(target, *patch) == result);
}

TEST_CASE("merge_patch_diff: nothing changed, and what a merge patch cannot say") {
  const json doc = json::parse(R"({"a":{"b":[1,null,2]},"c":1.5})");
  CHECK(tb::web::merge_patch_diff(doc, doc) == json::object());
  CHECK(tb::web::merge_patch_diff(json::parse("[1]"), json::parse("[1]")) == json::parse("[1]"));
  // A member that becomes null (or a new one that is null) has no merge patch: null removes.
  CHECK_FALSE(tb::web::merge_patch_diff(json::parse(R"({"a":1})"), json::parse(R"({"a":null})")).has_value());
  CHECK_FALSE(tb::web::merge_patch_diff(json::parse(R"({"a":{}})"), json::parse(R"({"a":{"x":null}})")).has_value());
  CHECK_FALSE(tb::web::merge_patch_diff(json::parse("7"), json::parse(R"({"n":null})")).has_value());
  // Nulls inside arrays go as they are (the array is replaced whole).
  CHECK(*tb::web::merge_patch_diff(json::parse(R"({"a":[1]})"), json::parse(R"({"a":[null]})")) ==
        json::parse(R"({"a":[null]})"));
}
