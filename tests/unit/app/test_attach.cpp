// The pieces of issue 29 that are pure: the attach socket's input frames and key decoding, the
// state lock and its file, and --on-event's forms (docs/service.md).
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>

#include "app/attach_server.h"
#include "app/event_hooks.h"
#include "app/state_lock.h"
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
  CHECK(error == "unknown event kind in 'aso'; expected aos, los, elements, link-lost, link-back, save-failed");
  CHECK_FALSE(app::parse_event_hook("los=  ", error));
  CHECK(error == "no command");
}
