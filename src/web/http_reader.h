// HTTP/1.1 requests read off a connection's bytes with every part bounded before it is held (issue
// 46): the transport hands over what it read (at most room() bytes at a time), the reader says when a
// whole request is there, or why it is refused. Boost.Beast's parser does the parsing (in
// http_reader.cpp, Beast's second file after server.cpp); the bounds, the one strict reading of
// Transfer-Encoding and the header checks are ours. No Beast type in this header. Pure: fuzzed
// (tests/fuzz/fuzz_web.cpp) and unit-tested.
//
// Bounds (docs/security.md, "Bounds"), each counted before any access check:
//   request line 2 kB (414), one header line 4 kB, 64 header lines, the request line and all headers
//   8 kB (431), the body 16 kB after the chunked coding is undone (413), inside a chunked body 1 kB
//   held at once: one chunk-size line with its extensions, or the last chunk with all its trailers
//   (413), and the read buffer itself 16 kB whatever the phase.
// Transfer-Encoding: only `chunked`, alone, on HTTP/1.1; a coding before it is 501, anything else
// (`xchunked`, `chunked, identity`, an empty list) 400. A body is never read as the next request:
// after a refusal the connection is answered and closed. Trailers are read and dropped (they never
// reach the request's headers). One Host header on HTTP/1.1, never two.
// An absolute-form target (`GET http://host:port/path HTTP/1.1`, RFC 9112 3.2.2) is taken as its
// path, its authority as the Host (the Host checks apply to it); another scheme or a user in the
// authority is 400. `Expect: 100-continue` on HTTP/1.1 is answered with 100 Continue before the body
// is read (take_continue()); any other expectation is 417.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "web/api.h"

namespace tb::web {

struct ReadLimits {
  std::size_t request_line = 2048;
  std::size_t field = 4096;
  std::size_t fields = 64;
  std::size_t header = 8 * 1024;
  std::size_t body = kMaxBody;
  std::size_t chunk_held = 1024;
  std::size_t buffer = 16 * 1024;
};

// A whole request as read: the API's facts (peer left empty) and what the transport needs.
struct ReadRequest {
  Request request;
  std::vector<std::pair<std::string, std::string>> fields;  // every header as sent (the WebSocket handshake)
  unsigned version = 11;                                     // 10 or 11
  bool keep_alive = false;
  bool head = false;
  bool upgrade = false;                                      // a WebSocket upgrade
};

class RequestReader {
 public:
  enum class State { more, done, refused };
  explicit RequestReader(ReadLimits limits = {});
  ~RequestReader();
  RequestReader(const RequestReader&) = delete;
  RequestReader& operator=(const RequestReader&) = delete;

  // How many bytes the transport may read now (0 when done or refused).
  std::size_t room() const;
  // Bytes as they came off the connection (at most room()); empty to go on with bytes already held
  // (a pipelined request after the one taken).
  State feed(std::string_view bytes = {});
  // After done: the request; the reader starts the next one with the bytes after it.
  ReadRequest take();
  // Once per request, when its header asked `Expect: 100-continue` and the body is still to come:
  // the transport writes "HTTP/1.1 100 Continue" before it reads on.
  bool take_continue();
  // After refused: the status (400, 413, 414, 431, 501) and a sentence naming the part.
  int status() const;
  const std::string& why() const;
  // Nothing of a request held (the client may go without a word).
  bool idle() const;
  // Bytes held now (for the tests: never more than limits.buffer).
  std::size_t held() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::web
