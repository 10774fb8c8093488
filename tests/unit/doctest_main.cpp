// The unit test programs' main. No unit test reaches the network beyond loopback, also when a
// program is run by hand rather than by CTest: some send the documents' own examples, which name
// hosts on the Internet (the Satrak document's mockapi.io URL). libcurl reads the proxy variables,
// so every such transfer goes to a SOCKS proxy on a closed loopback port and fails at once; with
// socks5h the name is not even looked up. The tests' own loopback servers stay direct (no_proxy).
// tests/CMakeLists.txt gives the integration tests the same variables (TB_NO_INTERNET).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  for (const char* name : {"all_proxy", "ALL_PROXY", "http_proxy", "https_proxy", "HTTPS_PROXY", "ftp_proxy"})
    ::setenv(name, "socks5h://127.0.0.1:9", 1);
  for (const char* name : {"no_proxy", "NO_PROXY"}) ::setenv(name, "127.0.0.1,localhost,::1", 1);
  return doctest::Context(argc, argv).run();
}
