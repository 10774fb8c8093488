#!/usr/bin/env bash
# Installs what is missing, builds with -Werror, runs every test through CTest (unit, integration
# and the fuzz-corpus replay), then builds the unit tests and the fuzz replays again with
# AddressSanitizer + UndefinedBehaviorSanitizer (and libstdc++'s assertions) and runs them, then
# builds, installs, runs and removes the Debian package.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh all
jobs=$(nproc)

start=$SECONDS
# Hardened as the package is (Debian's flags and libstdc++'s assertions): the tests run the binary
# that package-check.sh then packs.
scripts/build.sh build -DTRAKBOX_WERROR=ON -DTRAKBOX_HARDENING=ON -DTRAKBOX_TESTS=ON
echo "== build: $((SECONDS - start)) s"
(cd build && ctest --output-on-failure -j"$jobs")
echo "== tests: $((SECONDS - start)) s"

cmake -S . -B build-asan -G Ninja -DTRAKBOX_WERROR=ON -DTRAKBOX_SANITIZE=ON -DTRAKBOX_BENCH=OFF \
      -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 >/dev/null
# The unit-test programs and the fuzz-corpus replays: the sanitizer pass runs those two labels
# (with libstdc++'s assertions on, an input that reads past a container or an empty optional fails
# here even where the plain replay passes).
mapfile -t san_targets < <(cmake --build build-asan --target help | sed -n 's/^\(unit_[a-z_]*\|fuzz_replay_[a-z_]*\):.*/\1/p')
cmake --build build-asan -j"$jobs" --target "${san_targets[@]}"
echo "== sanitizer build: $((SECONDS - start)) s"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
   LSAN_OPTIONS=suppressions=$PWD/../tests/lsan.supp:print_suppressions=0 \
   ctest --output-on-failure -j"$jobs" -L "unit|fuzz")
echo "== sanitizer tests: $((SECONDS - start)) s"
# The Debian package: built from build/, installed, run from /, removed (issue 13).
scripts/package-check.sh build
echo "== all done: $((SECONDS - start)) s"
