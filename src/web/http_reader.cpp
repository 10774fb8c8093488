// Beast's second file (after server.cpp): its parser, under our bounds (http_reader.h).
#include "web/http_reader.h"

#include <optional>

#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/rfc7230.hpp>
#include <boost/beast/http/string_body.hpp>

#include "util/text.h"

namespace tb::web {

namespace http = boost::beast::http;

namespace {

std::string lower_token(std::string_view s) { return text::lower(text::trim(s, " \t")); }

// An absolute-form target's authority and the rest (the path, "/" when empty); a refusal when the
// scheme is not http(s) or the authority is empty or names a user.
std::optional<std::pair<int, std::string>> split_absolute(std::string& target, std::string& authority) {
  const auto scheme_end = target.find("://");
  const std::string scheme = text::lower(std::string_view(target).substr(0, scheme_end));
  if (scheme != "http" && scheme != "https")
    return std::pair{400, "the request target: expected a path, or an http:// URL"};
  const std::size_t from = scheme_end + 3;
  const std::size_t end = target.find_first_of("/?#", from);
  authority = target.substr(from, end == std::string::npos ? std::string::npos : end - from);
  if (authority.empty() || authority.find('@') != std::string::npos)
    return std::pair{400, "the request target's authority: expected host[:port]"};
  std::string rest = end == std::string::npos ? std::string() : target.substr(end);
  if (rest.empty() || rest.front() != '/') rest.insert(0, "/");
  target = std::move(rest);
  return std::nullopt;
}

}  // namespace

struct RequestReader::Impl {
  ReadLimits limits;
  std::string buf;                  // bytes read and not yet parsed
  std::optional<http::request_parser<http::string_body>> parser;
  std::size_t header_used = 0;      // bytes of the request line and headers the parser has taken
  bool header_checked = false;
  bool continue_due = false;        // Expect: 100-continue, not yet answered
  ReadRequest facts;                // from the header, once checked (trailers never reach it)
  State state = State::more;
  int status = 0;
  std::string why;

  explicit Impl(ReadLimits l) : limits(l) { start(); }

  void start() {
    parser.emplace();
    parser->header_limit(static_cast<std::uint32_t>(limits.header));
    parser->body_limit(static_cast<std::uint64_t>(limits.body));
    header_used = 0;
    header_checked = false;
    continue_due = false;
    facts = {};
    state = State::more;
  }

  State refuse(int s, std::string sentence) {
    status = s;
    why = std::move(sentence);
    buf.clear();
    buf.shrink_to_fit();
    return state = State::refused;
  }

  std::size_t phase_cap() const {
    if (!parser->is_header_done()) return limits.header - std::min(limits.header, header_used);
    if (parser->chunked()) return limits.chunk_held;
    return limits.buffer;
  }

  // What the bytes held so far already break, while more are awaited.
  std::optional<std::pair<int, std::string>> partial_bounds() const {
    if (!parser->is_header_done()) {
      const auto last_line = buf.rfind('\n');
      const std::size_t open = last_line == std::string::npos ? buf.size() : buf.size() - last_line - 1;
      if (header_used == 0 && open >= limits.request_line)
        return std::pair{414, "the request line is over " + std::to_string(limits.request_line) + " bytes"};
      if (open >= limits.field)
        return std::pair{431, "a header line is over " + std::to_string(limits.field) + " bytes"};
      if (header_used + buf.size() >= limits.header)
        return std::pair{431, "the request line and headers are over " + std::to_string(limits.header) + " bytes"};
      return std::nullopt;
    }
    if (parser->chunked() && buf.size() >= limits.chunk_held)
      return std::pair{413, "a chunk-size line with its extensions, or the trailers, over " +
                                std::to_string(limits.chunk_held) + " bytes"};
    return std::nullopt;
  }

  // The header is whole: its checks, and the facts the request will carry.
  std::optional<std::pair<int, std::string>> check_header() {
    const auto& m = parser->get();
    ReadRequest& f = facts;
    f.version = m.version();
    if (m.target().size() > limits.request_line)
      return std::pair{414, "the request target is over " + std::to_string(limits.request_line) + " bytes"};
    std::vector<std::string> codings;
    int hosts = 0;
    bool websocket = false;
    std::optional<std::string> expect;
    for (const auto& field : m) {
      const std::string name(field.name_string());
      const std::string value(field.value());
      if (f.fields.size() >= limits.fields)
        return std::pair{431, "over " + std::to_string(limits.fields) + " header lines"};
      if (name.size() + 2 + value.size() > limits.field)
        return std::pair{431, "a header line is over " + std::to_string(limits.field) + " bytes"};
      f.fields.emplace_back(name, value);
      const std::string key = text::lower(name);
      if (key == "transfer-encoding") {
        for (std::string_view c : text::split(value, ',')) codings.push_back(lower_token(c));
      } else if (key == "host") {
        ++hosts;
        f.request.host = value;
      } else if (key == "origin" && f.request.origin.empty()) {
        f.request.origin = value;
      } else if (key == "cookie" && f.request.cookie.empty()) {
        f.request.cookie = value;
      } else if (key == "authorization" && f.request.authorization.empty()) {
        f.request.authorization = value;
      } else if (key == "content-type" && f.request.content_type.empty()) {
        f.request.content_type = value;
      } else if (key == "upgrade") {
        websocket = websocket || text::lower(value).find("websocket") != std::string::npos;
      } else if (key == "expect") {
        expect = lower_token(value);
      } else if (key == "x-forwarded-proto" && f.request.forwarded_proto.empty()) {
        f.request.forwarded_proto = value;
      }
    }
    if (hosts > 1) return std::pair{400, "more than one Host header"};
    if (hosts == 0 && f.version >= 11) return std::pair{400, "an HTTP/1.1 request without a Host header"};
    if (!codings.empty()) {
      if (f.version < 11) return std::pair{400, "Transfer-Encoding on an HTTP/1.0 request"};
      if (codings.size() > 1 && codings.back() == "chunked")
        return std::pair{501, "Transfer-Encoding: only chunked is understood, alone"};
      if (codings.size() != 1 || codings.front() != "chunked")
        return std::pair{400, "Transfer-Encoding: expected chunked (alone)"};
    }
    f.request.method = std::string(m.method_string());
    f.request.target = std::string(m.target());
    if (!f.request.target.empty() && f.request.target.front() != '/' && f.request.target.find("://") != std::string::npos) {
      std::string authority;
      if (auto r = split_absolute(f.request.target, authority)) return r;
      f.request.host = authority;  // RFC 9112 3.2.2: the target's authority, not the Host header
    }
    if (expect && f.version >= 11) {  // RFC 9110 10.1.1: HTTP/1.0's is ignored
      if (*expect != "100-continue") return std::pair{417, "Expect: only 100-continue is understood"};
      continue_due = !parser->is_done();
    }
    f.keep_alive = m.keep_alive();
    f.head = m.method() == http::verb::head;
    f.upgrade = parser->upgrade() && websocket && m.method() == http::verb::get;
    return std::nullopt;
  }

  static std::pair<int, std::string> refusal_of(const boost::system::error_code& ec, const ReadLimits& l) {
    if (ec == http::error::header_limit)
      return {431, "the request line and headers are over " + std::to_string(l.header) + " bytes"};
    if (ec == http::error::body_limit) return {413, "the request body is over " + std::to_string(l.body / 1024) + " kB"};
    if (ec == http::error::bad_transfer_encoding) return {400, "a bad Transfer-Encoding"};
    if (ec == http::error::bad_content_length) return {400, "a bad Content-Length"};
    if (ec == http::error::bad_chunk || ec == http::error::bad_chunk_extension) return {400, "a malformed chunk"};
    return {400, "a malformed HTTP request"};
  }

  State run() {
    while (state == State::more) {
      if (parser->is_header_done() && !header_checked) {
        header_checked = true;
        if (auto r = check_header()) return refuse(r->first, r->second);
      }
      if (parser->is_done()) return state = State::done;
      if (buf.empty()) return State::more;
      boost::system::error_code ec;
      const bool header_before = parser->is_header_done();
      const std::size_t n = parser->put(boost::asio::buffer(buf.data(), buf.size()), ec);
      if (!header_before) header_used += n;
      buf.erase(0, n);
      if (ec == http::error::need_more) {
        if (auto r = partial_bounds()) return refuse(r->first, r->second);
        if (!parser->is_header_done() || n == 0) return State::more;
        continue;
      }
      if (ec) {
        auto r = refusal_of(ec, limits);
        return refuse(r.first, r.second);
      }
      if (n == 0 && header_before == parser->is_header_done() && !parser->is_done()) return State::more;
    }
    return state;
  }
};

RequestReader::RequestReader(ReadLimits limits) : impl_(std::make_unique<Impl>(limits)) {}
RequestReader::~RequestReader() = default;

std::size_t RequestReader::room() const {
  const Impl& i = *impl_;
  if (i.state != State::more) return 0;
  const std::size_t cap = std::min(i.phase_cap(), i.limits.buffer);
  return cap > i.buf.size() ? cap - i.buf.size() : 0;
}

RequestReader::State RequestReader::feed(std::string_view bytes) {
  Impl& i = *impl_;
  if (i.state != State::more) return i.state;
  if (bytes.size() > room()) {
    // The transport read more than it was allowed: the bounds are not to be stepped over.
    if (auto r = i.partial_bounds()) return i.refuse(r->first, r->second);
    return i.refuse(i.parser->is_header_done() ? 413 : 431, "a request over the read buffer's " +
                                                                std::to_string(i.limits.buffer) + " bytes");
  }
  i.buf.append(bytes);
  return i.run();
}

ReadRequest RequestReader::take() {
  Impl& i = *impl_;
  ReadRequest r = std::move(i.facts);
  r.request.body = i.parser->release().body();
  i.start();
  return r;
}

bool RequestReader::take_continue() {
  Impl& i = *impl_;
  if (!i.continue_due || i.state != State::more) return false;
  i.continue_due = false;
  return true;
}

int RequestReader::status() const { return impl_->status; }
const std::string& RequestReader::why() const { return impl_->why; }
bool RequestReader::idle() const { return impl_->buf.empty() && !impl_->parser->got_some(); }
std::size_t RequestReader::held() const { return impl_->buf.size(); }

}  // namespace tb::web
