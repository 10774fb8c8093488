#include "web/page.h"

namespace tb::web {

// Generated from src/web/page/ (cmake/embed_files.cmake).
extern const PageFile kPageFiles[];
extern const std::size_t kPageFileCount;

const PageFile* find_page_file(std::string_view path) {
  for (std::size_t i = 0; i < kPageFileCount; ++i)
    if (kPageFiles[i].path == path) return &kPageFiles[i];
  return nullptr;
}

std::size_t first_load_bytes() {
  std::size_t n = 0;
  for (const char* p : {"/index.html", "/style.css", "/app.js", "/live.js"})
    if (const PageFile* f = find_page_file(p)) n += f->body.size();
  return n;
}

}  // namespace tb::web
