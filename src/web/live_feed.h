// What the WebSocket /api/v1/live sends of the live state (docs/web-api.md): the whole document
// once, then at each push only what changed, as a JSON merge patch (RFC 7386, web/merge_patch.h),
// each message numbered. A viewer that sees a gap in the numbers asks for the whole document again
// ({"type":"full"}). The document is built once per push and the patch dumped once, whatever the
// number of viewers. No sockets here: the server (server.cpp) sends what this returns.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace tb::web {

// The live state as the WebSocket carries it (applied by Api::live_document), so that a second's
// patch holds what a second changed: the tracking list as an object of its entries by position
// ("0", "1", ...: a merge patch replaces an array whole, and one entry changing would send them all;
// the page's live.js makes it the list again), each entry without where its satellite is now
// ("now", new every second for all of them, which the page does not draw; /api/v1/status has it),
// the element age to 0.01 day and the next pass's highest elevation to 0.01 degree (the page shows
// tenths and degrees; the pass search's last digits move from one second to the next); the radios
// and the satellites followed (status.tracking.satellites) by position too.
void shape_for_live(nlohmann::json& status);

class LiveFeed {
 public:
  LiveFeed();
  ~LiveFeed();
  LiveFeed(const LiveFeed&) = delete;
  LiveFeed& operator=(const LiveFeed&) = delete;

  // This push's message for every viewer: {"type":"patch","seq":N,"patch":{...}} with what changed
  // since the last document; the whole document with "seq" when there was none before or no merge
  // patch can say the change (a member that became null); nothing when nothing changed (the number
  // stays). `doc` is the live state, {"type":"state",...}.
  std::optional<std::string> next(nlohmann::json doc);
  // The last document whole, with its number (a new viewer's first, or one that asked); nothing
  // before the first next().
  std::optional<std::string> full();
  // The next push sends the whole document (nobody is watching, or the document failed).
  void forget();
  std::uint64_t seq() const { return seq_; }

  // Whether a viewer's message asks for the whole document: {"type":"full"}. Anything else a viewer
  // sends is ignored; never an exception.
  static bool asks_full(std::string_view message);

 private:
  std::unique_ptr<nlohmann::json> last_;
  std::optional<std::string> full_;  // last_ dumped with its number, made when first asked
  std::uint64_t seq_ = 0;
};

}  // namespace tb::web
