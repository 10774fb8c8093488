// The web page's files (src/web/page/: HTML, CSS, JavaScript, hand-written), compiled into the
// binary by cmake/embed_files.cmake: no download at run time, no CDN.
#pragma once
#include <cstddef>
#include <string_view>

namespace tb::web {

struct PageFile {
  std::string_view path;  // "/index.html"
  std::string_view type;  // "text/html; charset=utf-8"
  std::string_view body;
};

// The file served at `path`, or nullptr.
const PageFile* find_page_file(std::string_view path);
// What a browser fetches on the first load of "/": index.html, style.css and app.js.
std::size_t first_load_bytes();

}  // namespace tb::web
