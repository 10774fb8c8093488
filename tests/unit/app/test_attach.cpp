// The pieces of issue 29 that are pure: the attach socket's input frames and key decoding, the
// state lock and its file, and --on-event's forms (docs/service.md).
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "live/attach_server.h"
#include "live/event_hooks.h"
#include "live/state_lock.h"
#include "menus/term/terminal.h"

using namespace tb;

TEST_CASE("client frames: bytes, a doubled 0xFF, window sizes, split anywhere") {
  const std::string stream = std::string("ab\xff\xff", 4) + app::encode_window_size(50, 132) + "c";
  CHECK(app::encode_window_size(50, 132) == std::string("\xffW\x00\x32\x00\x84", 6));
  for (std::size_t cut = 0; cut <= stream.size(); ++cut) {
    app::FrameDecoder d;
    auto a = d.feed(std::string_view(stream).substr(0, cut));
    auto b = d.feed(std::string_view(stream).substr(cut));
    CHECK(a.bytes + b.bytes == std::string("ab\xff" "c"));
    a.sizes.insert(a.sizes.end(), b.sizes.begin(), b.sizes.end());
    REQUIRE(a.sizes.size() == 1);
    CHECK(a.sizes[0] == std::pair{50, 132});
  }
}

TEST_CASE("keys: escape sequences dropped, a lone ESC kept, DEL is Backspace") {
  // xterm's Up (ESC [ A), F1 (ESC O P), F5 (ESC [ 1 5 ~), then '1', DEL, Enter, ESC alone.
  const auto keys = app::decode_keys("\x1b[A\x1bOP\x1b[15~1\x7f\r\x1b");
  CHECK(keys == std::vector<int>{'1', term::kBackspace, '\r', term::kEscape});
}

TEST_CASE("the lock file names the holder") {
  const auto h = app::parse_lock_file("pid 4242\nsocket /run/trakbox/trakbox.sock\n");
  CHECK(h.pid == 4242);
  CHECK(h.socket == "/run/trakbox/trakbox.sock");
  CHECK(app::parse_lock_file("garbage\n").pid == 0);
}

TEST_CASE("a second lock on a state directory fails and reads who holds it") {
  const auto dir = std::filesystem::temp_directory_path() / ("trakbox-lock-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  app::LockHolder holder;
  std::string error;
  auto first = app::StateLock::take(dir, holder, error);
  REQUIRE(first);
  first->announce("/tmp/x.sock");
  auto second = app::StateLock::take(dir, holder, error);
  CHECK_FALSE(second);
  CHECK(error.empty());
  CHECK(holder.pid == ::getpid());
  CHECK(holder.socket == "/tmp/x.sock");
  first.reset();  // released: the next one gets it
  CHECK(app::StateLock::take(dir, holder, error));
  std::filesystem::remove_all(dir);
}

TEST_CASE("--on-event: every kind, kinds named, a command with '=' of its own, a wrong kind") {
  std::string error;
  auto all = app::parse_event_hook("logger -t trakbox $TRAKBOX_EVENT", error);
  REQUIRE(all);
  CHECK(all->kinds.empty());
  CHECK(all->command == "logger -t trakbox $TRAKBOX_EVENT");
  auto some = app::parse_event_hook("aos,los=rec $TRAKBOX_SATELLITE", error);
  REQUIRE(some);
  CHECK(some->kinds == std::vector<std::string>{"aos", "los"});
  CHECK(some->command == "rec $TRAKBOX_SATELLITE");
  auto env = app::parse_event_hook("GAIN=3 /usr/local/bin/preamp on", error);
  REQUIRE(env);
  CHECK(env->kinds.empty());
  CHECK(env->command == "GAIN=3 /usr/local/bin/preamp on");
  CHECK_FALSE(app::parse_event_hook("aso=rec", error));
  CHECK(error == "unknown event kind in 'aso'; expected aos, los, recording, elements, link-lost, link-back, save-failed, control");
  CHECK_FALSE(app::parse_event_hook("los=  ", error));
  CHECK(error == "no command");
}

// Issue 38, crash 1: each of the attacker's greetings threw nlohmann's type_error out of the
// handler (SIGABRT). Each is now a refusal naming the field.
TEST_CASE("attach greeting: a wrong type is refused naming the field, never thrown") {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"rows":"x"})", "'rows' must be an integer, found string"},
      {R"({"term":5,"full_screen":true})", "'term' must be a string, found an integer"},
      {R"({"full_screen":"yes"})", "'full_screen' must be true or false, found string"},
      {R"({"tty":[1]})", "'tty' must be a string, found array"},
      {R"({"crlf":1})", "'crlf' must be true or false, found an integer"},
      {R"({"cols":80.5})", "'cols' must be an integer, found a number with a fraction"},
      {R"({"rows":{}})", "'rows' must be an integer, found object"},
      {R"({"term":"../../../tmp/evil"})", "'term' must be a terminal type (letters, digits, . _ + -), found '../../../tmp/evil'"},
      {R"({)", "the greeting is not a JSON object"},
      {R"([1,2])", "the greeting is not a JSON object"},
      {R"("attach")", "the greeting is not a JSON object"},
      {R"([[[[[[1]]]]]])", "the greeting is nested too deep"},
  };
  for (const auto& [text, why] : cases) {
    CAPTURE(text);
    std::string error;
    CHECK_FALSE(app::parse_attach_hello(text, error));
    CHECK(error == why);
  }
}

TEST_CASE("attach greeting: what trakbox attach sends, and its bounds") {
  std::string error;
  auto h = app::parse_attach_hello(R"( {"full_screen":true,"crlf":false,"rows":40,"cols":132,"term":"xterm-256color","tty":"/dev/pts/3"})", error);
  REQUIRE(h);
  CHECK(h->full_screen);
  CHECK_FALSE(h->crlf);
  CHECK(h->rows == 40);
  CHECK(h->cols == 132);
  CHECK(h->term == "xterm-256color");
  CHECK(h->tty == "/dev/pts/3");
  h = app::parse_attach_hello("", error);  // a bare "attach": lines, 24 x 80
  REQUIRE(h);
  CHECK(h->term.empty());
  CHECK(h->rows == 24);
  CHECK(h->cols == 80);
  h = app::parse_attach_hello(R"({"rows":-5,"cols":18446744073709551615,"term":null,"unknown":[1]})", error);
  REQUIRE(h);
  CHECK(h->rows == 0);
  CHECK(h->cols == 65535);
  // Text fields are made safe: an escape in the tty name never reaches a terminal or the log.
  h = app::parse_attach_hello(R"({"tty":"/dev/pts/\u001b[2J9"})", error);
  REQUIRE(h);
  CHECK(h->tty == "/dev/pts/\xEF\xBF\xBD[2J9");
  CHECK_FALSE(app::parse_attach_hello(R"({"tty":")" + std::string(65, 'a') + R"("})", error));
  CHECK(error == "'tty' is longer than 64 bytes");
}

// Issue 38, item 6: the lock was opened through a link, truncating and writing its target.
TEST_CASE("the lock is never taken through a symbolic link") {
  const auto dir = std::filesystem::temp_directory_path() / ("trakbox-locklink-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto target = dir / "target.txt";
  {
    std::FILE* f = std::fopen(target.c_str(), "w");
    REQUIRE(f);
    std::fputs("not yours\n", f);
    std::fclose(f);
  }
  std::filesystem::create_symlink(target, dir / "trakbox.lock");
  app::LockHolder holder;
  std::string error;
  CHECK_FALSE(app::StateLock::take(dir, holder, error));
  CHECK(error == (dir / "trakbox.lock").string() +
                     ": is a symbolic link; trakbox does not follow links in its state directory (remove the link)");
  CHECK(std::filesystem::file_size(target) == 10);
  std::filesystem::remove(dir / "trakbox.lock");
  std::filesystem::create_directory(dir / "trakbox.lock");
  CHECK_FALSE(app::StateLock::take(dir, holder, error));
  CHECK(error.find("trakbox.lock: ") != std::string::npos);
  std::filesystem::remove_all(dir);
}
