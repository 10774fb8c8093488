// The driver of the fuzz corpora in the normal test suite: runs every file under the directories
// (or files) named on the command line through the fuzz target's LLVMFuzzerTestOneInput once, in
// sorted order, as `fuzz_NAME -runs=0 corpus/NAME` does in the libFuzzer build. A violated property
// aborts (the targets' TB_FUZZ_CHECK), an exception escapes: either fails the CTest test, and the
// file being run is printed first so the failure names its input.
//
// `--shard K/N` (first argument) runs only the files whose index in the sorted list is K modulo N
// (0 <= K < N): CTest runs a large corpus as N tests of their own (tests/fuzz/CMakeLists.txt), which
// `ctest -j` spreads over the cores. Every input still runs in a fresh process state of its own
// target's making, so an input does the same in any shard as in the whole list.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

int main(int argc, char** argv) {
  if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
  namespace fs = std::filesystem;
  std::size_t shard = 0, shards = 1;
  int first = 1;
  if (argc > 2 && std::strcmp(argv[1], "--shard") == 0) {
    unsigned long k = 0, n = 0;
    char slash = 0, rest = 0;
    if (std::sscanf(argv[2], "%lu%c%lu%c", &k, &slash, &n, &rest) != 3 || slash != '/' || n == 0 || k >= n) {
      std::fprintf(stderr, "--shard %s: expected K/N with 0 <= K < N\n", argv[2]);
      return 2;
    }
    shard = k;
    shards = n;
    first = 3;
  }
  std::vector<fs::path> files;
  for (int i = first; i < argc; ++i) {
    const fs::path root = argv[i];
    if (fs::is_directory(root)) {
      for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (fs::is_regular_file(root)) {
      files.push_back(root);
    } else {
      std::fprintf(stderr, "%s: no such file or directory\n", argv[i]);
      return 2;
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<fs::path> mine;
  for (std::size_t i = shard; i < files.size(); i += shards) mine.push_back(files[i]);
  files.swap(mine);
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "%s\n", f.c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs replayed\n", files.size());
  return files.empty() ? 1 : 0;
}
