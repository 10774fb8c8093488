#!/usr/bin/env bash
# Installs what is missing, builds with -Werror, runs every test through CTest,
# then runs the unit tests again in an AddressSanitizer + UndefinedBehaviorSanitizer build.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh build -DTRAKBOX_WERROR=ON
(cd build && ctest --output-on-failure -j"$(nproc)")
scripts/build.sh build-asan -DTRAKBOX_WERROR=ON -DTRAKBOX_SANITIZE=ON -DTRAKBOX_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j"$(nproc)" -L unit)
