#include "app/app.h"

#include <cstdio>

namespace tb::app {
int main(int, char**) {
  std::puts("trakbox: under construction");
  return 0;
}
}  // namespace tb::app
