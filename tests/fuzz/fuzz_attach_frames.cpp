// The attach socket's input as a client may send it (app::FrameDecoder, encode_window_size,
// decode_keys): any bytes, cut into reads at any points.
//
// The first byte sets how the bytes are cut into reads. Properties: the decoder gives the same
// keyboard bytes and window sizes however the input is cut, and never more bytes than came in;
// every size is 0..65535 and encode_window_size of it decodes to itself; keyboard bytes framed
// again (0xFF doubled) decode to themselves; decode_keys yields no more keys than bytes, each a
// byte value or Backspace (DEL becomes Backspace).
#include "live/attach_server.h"
#include "fuzz_station.h"
#include "menus/term/terminal.h"

using namespace tb;

namespace {

// Everything the decoder gives for `bytes` fed in reads of `chunk` bytes.
app::ClientFrames all_of(std::string_view bytes, std::size_t chunk) {
  app::FrameDecoder dec;
  app::ClientFrames out;
  for (std::size_t i = 0; i < bytes.size(); i += chunk) {
    app::ClientFrames part = dec.feed(bytes.substr(i, chunk));
    out.bytes += part.bytes;
    out.sizes.insert(out.sizes.end(), part.sizes.begin(), part.sizes.end());
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t chunk = 1 + data[0] % 16;
  const std::string_view bytes = fuzz::as_text(data + 1, size - 1);

  const app::ClientFrames whole = all_of(bytes, bytes.size() + 1);
  const app::ClientFrames cut = all_of(bytes, chunk);
  TB_FUZZ_CHECK(cut.bytes == whole.bytes && cut.sizes == whole.sizes, std::string(bytes));
  TB_FUZZ_CHECK(whole.bytes.size() <= bytes.size(), std::string(bytes));

  for (const auto& [rows, cols] : whole.sizes) {
    TB_FUZZ_CHECK(rows >= 0 && rows <= 65535 && cols >= 0 && cols <= 65535, std::string(bytes));
    app::FrameDecoder again;
    const auto back = again.feed(app::encode_window_size(rows, cols));
    TB_FUZZ_CHECK(back.bytes.empty() && back.sizes.size() == 1 && back.sizes[0] == std::make_pair(rows, cols),
                  std::string(bytes));
  }

  // Keyboard bytes framed as the client frames them decode to themselves.
  std::string framed;
  for (char c : whole.bytes) {
    framed.push_back(c);
    if (static_cast<unsigned char>(c) == 0xFF) framed.push_back(c);
  }
  app::FrameDecoder dec;
  const auto back = dec.feed(framed);
  TB_FUZZ_CHECK(back.bytes == whole.bytes && back.sizes.empty(), framed);

  const std::vector<int> keys = app::decode_keys(whole.bytes);
  TB_FUZZ_CHECK(keys.size() <= whole.bytes.size(), whole.bytes);
  for (int k : keys) TB_FUZZ_CHECK(k == term::kBackspace || (k >= 0 && k <= 255 && k != 127), whole.bytes);
  return 0;
}
