#!/usr/bin/env bash
# Installs what running needs (only what is missing), builds the trakbox program alone (not the
# tests nor the benchmarks: scripts/test.sh builds those), and starts it on the simulated station
# with the shipped data. Arguments go to trakbox.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh run
dir=build
# A tree configured before (by scripts/test.sh, with the tests) keeps its settings; a new one is
# configured without the tests, so that doctest and Google Benchmark are not needed.
if [ -f "$dir/CMakeCache.txt" ]; then
  cmake -S . -B "$dir" >/dev/null
else
  # TRAKBOX_UNITY: the libraries in unity batches, a cold build in about half the CPU (CMakeLists.txt).
  cmake -S . -B "$dir" -G Ninja -DTRAKBOX_TESTS=OFF -DTRAKBOX_UNITY=ON >/dev/null
fi
cmake --build "$dir" -j"$(nproc)" --target trakbox
exec "$dir/trakbox" "$@"
