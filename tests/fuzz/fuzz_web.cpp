// The web endpoint's request handling (web::Api, web::Access) on a whole simulated station: the
// handlers and the JSON bodies, not Beast's parser (which is not ours to fuzz).
//
// First byte: bit 0 set gives the endpoint a secret (and a non-loopback listener), bit 1 public
// viewing, bit 2 starts with the tracker following the first satellite. The rest is cut at NUL bytes
// into at most 16 requests, each "METHOD TARGET" on the first line, then "Name: value" headers
// (Host, Origin, Cookie, Authorization, Content-Type, and X-Peer for the client's address) up to an
// empty line, then the body. After each, 0.5 s passes and the station ticks.
// Bit 3 (issue 46): each piece is instead raw HTTP/1.1 bytes (chunked bodies, extensions, trailers,
// Transfer-Encoding lists, pipelined requests) read by web::RequestReader as a socket would hand them
// over, in reads of 1 to 64 bytes chosen by the piece's own bytes; each whole request goes to the Api.
// Its properties: the reader never holds more than its buffer's bound, never takes more than room(),
// refuses only with 400, 413, 414, 431 or 501 and a sentence, and a request it hands over is one it
// checked (a Host, one Transfer-Encoding: chunked at most).
// Properties: nothing is thrown; every reply is 200, 303 or 4xx; a JSON reply parses, and an
// error is {"error": sentence}; the secret is in no reply; a refused POST leaves tracking, rotor
// control and the antenna's target alone; the model left behind reads back.
#include <algorithm>
#include <vector>

#include "fuzz_station.h"
#include "util/text.h"
#include "web/api.h"
#include "web/http_reader.h"

using namespace tb;

namespace {

constexpr const char* kSecret = "fuzz-secret-3f9a";

web::Request parse_request(std::string_view text) {
  web::Request r;
  r.peer = "127.0.0.1";
  const auto blank = text.find("\n\n");
  std::string_view head = text.substr(0, blank);
  if (blank != std::string_view::npos) r.body = std::string(text.substr(blank + 2));
  const auto lines = fuzz::split_lines(head, 32);
  if (lines.empty()) return r;
  const auto sp = lines[0].find(' ');
  r.method = std::string(lines[0].substr(0, sp));
  if (sp != std::string_view::npos) r.target = std::string(lines[0].substr(sp + 1));
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto colon = lines[i].find(':');
    if (colon == std::string_view::npos) continue;
    const std::string name = text::lower(lines[i].substr(0, colon));
    const std::string value(text::trim(lines[i].substr(colon + 1)));
    if (name == "host") r.host = value;
    else if (name == "origin") r.origin = value;
    else if (name == "cookie") r.cookie = value;
    else if (name == "authorization") r.authorization = value;
    else if (name == "content-type") r.content_type = value;
    else if (name == "x-peer") r.peer = value;
  }
  return r;
}

// Raw bytes through the reader, in reads sized by the bytes themselves; the requests it hands over.
std::vector<web::Request> read_raw(std::string_view bytes) {
  std::vector<web::Request> out;
  web::RequestReader reader;
  std::size_t at = 0;
  web::RequestReader::State st = web::RequestReader::State::more;
  while (out.size() < 16) {
    if (st == web::RequestReader::State::done) {
      web::ReadRequest r = reader.take();
      TB_FUZZ_CHECK(r.request.body.size() <= web::kMaxBody, r.request.target);
      TB_FUZZ_CHECK(!r.request.method.empty(), r.request.target);
      r.request.peer = "127.0.0.1";
      out.push_back(std::move(r.request));
      st = reader.feed();
      continue;
    }
    if (st == web::RequestReader::State::refused) {
      const int s = reader.status();
      TB_FUZZ_CHECK(s == 400 || s == 413 || s == 414 || s == 431 || s == 501, reader.why());
      TB_FUZZ_CHECK(!reader.why().empty(), std::to_string(s));
      TB_FUZZ_CHECK(reader.room() == 0, reader.why());
      break;
    }
    if (at >= bytes.size()) break;
    const std::size_t step = 1 + static_cast<unsigned char>(bytes[at]) % 64;
    const std::size_t n = std::min({step, reader.room(), bytes.size() - at});
    TB_FUZZ_CHECK(n > 0, "a reader waiting for bytes has room for them");
    st = reader.feed(bytes.substr(at, n));
    at += n;
    TB_FUZZ_CHECK(reader.held() <= web::ReadLimits{}.buffer, std::to_string(reader.held()));
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t mode = data[0];
  std::string_view input(reinterpret_cast<const char*>(data + 1), size - 1);
  fuzz::Station st;
  if (mode & 4) st.tracker.track_single(0);
  web::AccessOptions ao;
  if (mode & 1) ao.secret = kSecret, ao.loopback_only = false;
  ao.public_view = (mode & 2) != 0;
  web::Access access(ao);
  web::Api api(*st.station, access, web::ApiHooks{[] { return nlohmann::json{{"running", true}}; }, {}, {}, {}});
  auto now = std::chrono::steady_clock::time_point(std::chrono::hours(1));
  int n = 0;
  std::vector<web::Request> raw;
  if (mode & 8) {
    raw = read_raw(input);
    input = {};
  }
  std::size_t next_raw = 0;
  while (n++ < 16) {
    if ((mode & 8) && next_raw >= raw.size()) break;
    const auto cut = (mode & 8) ? std::string_view::npos : input.find('\0');
    const web::Request req = (mode & 8) ? raw[next_raw++] : parse_request(input.substr(0, cut));
    const auto target = st.station->rotator().status().target;
    const auto tracking = st.tracker.mode();
    const bool rotor = st.model.rotor_control;
    web::Response res;
    try {
      res = api.handle(req, now);
    } catch (...) {
      fuzz::violated("an exception left Api::handle", req.target);
    }
    TB_FUZZ_CHECK(res.status == 200 || res.status == 303 || (res.status >= 400 && res.status < 500), req.target);
    TB_FUZZ_CHECK(res.body.find(kSecret) == std::string::npos, res.body);
    for (const auto& [k, v] : res.headers) TB_FUZZ_CHECK(v.find(kSecret) == std::string::npos, v);
    if (res.content_type == "application/json" && !res.body.empty()) {
      const auto j = nlohmann::json::parse(res.body, nullptr, false);
      TB_FUZZ_CHECK(!j.is_discarded(), res.body);
      if (res.status >= 400) TB_FUZZ_CHECK(j.is_object() && j.contains("error") && j["error"].is_string(), res.body);
    }
    if (res.status >= 400 && req.method == "POST") {
      TB_FUZZ_CHECK(st.station->rotator().status().target == target, req.body);
      TB_FUZZ_CHECK(st.tracker.mode() == tracking, req.body);
      TB_FUZZ_CHECK(st.model.rotor_control == rotor, req.body);
    }
    (void)api.live_state();
    st.step();
    now += std::chrono::milliseconds(500);
    if (mode & 8) continue;
    if (cut == std::string_view::npos) break;
    input.remove_prefix(cut + 1);
  }
  fuzz::check_model_reads_back(st.model, std::string(input));
  return 0;
}
