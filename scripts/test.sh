#!/usr/bin/env bash
# Installs what is missing and runs every test through CTest in two builds, then the package:
#  * build/ (-Werror, hardened as the package is): trakbox and the benchmarks; the integration tests
#    run the binary this build makes, and scripts/package-check.sh packs that same binary.
#  * build-asan/ (-Werror, AddressSanitizer + UndefinedBehaviorSanitizer + libstdc++'s assertions):
#    the unit-test programs and the fuzz-corpus replays, run there and only there (a plain second
#    run of them found nothing the sanitized one does not). The unit-test programs compile there in
#    unity batches (TRAKBOX_UNITY_TESTS), which cuts their CPU about in half.
# The sanitized build compiles, and then replays the fuzz corpora, at nice 19 while the integration
# tests run: those mostly wait on ptys, sockets and simulated clocks, and leave most of the two cores
# idle (docs/ARCHITECTURE.md, "Tests").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh all
jobs=$(nproc)

start=$SECONDS
# CMAKE_SKIP_INSTALL_ALL_DEPENDENCY: cpack installs what was built here instead of building `all`
# (which would compile the unit tests and fuzz replays a second time, unsanitized).
# TRAKBOX_UNITY: the program's libraries in unity batches, as scripts/run.sh builds them (CMakeLists.txt).
cmake -S . -B build -G Ninja -DTRAKBOX_WERROR=ON -DTRAKBOX_HARDENING=ON -DTRAKBOX_TESTS=ON -DTRAKBOX_UNITY=ON \
      -DCMAKE_SKIP_INSTALL_ALL_DEPENDENCY=ON >/dev/null
mapfile -t bench_targets < <(cmake --build build --target help | sed -n 's/^\(bench_[a-z0-9_]*\):.*/\1/p')
cmake --build build -j"$jobs" --target trakbox tb_compressed_docs "${bench_targets[@]}"
echo "== build (trakbox, ${#bench_targets[@]} benchmarks): $((SECONDS - start)) s"

cmake -S . -B build-asan -G Ninja -DTRAKBOX_WERROR=ON -DTRAKBOX_SANITIZE=ON -DTRAKBOX_BENCH=OFF \
      -DTRAKBOX_UNITY_TESTS=ON -DTRAKBOX_UNITY=ON -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 >/dev/null
mapfile -t unit_targets < <(cmake --build build-asan --target help | sed -n 's/^\(unit_[a-z0-9_]*\):.*/\1/p')
mapfile -t fuzz_targets < <(cmake --build build-asan --target help | sed -n 's/^\(fuzz_replay_[a-z0-9_]*\):.*/\1/p')
san_env=(ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
         "LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0")
# In the background at nice 19: the sanitized build, the unit-test programs first (build.rc says
# when they are made: the unit tests wait for them), then the fuzz replays, which then run in it
# (their own CTest run in build-asan/tests/fuzz, so that its Testing/ files are apart from the unit
# tests'). The replays are computation only, with no clock or peer of their own: they use the CPU
# the integration tests leave idle, and what is left of them runs beside the unit tests. The unit
# tests, some of which wait on ptys and sockets in real time, run after the integration tests at
# normal priority.
rm -f build-asan/build.rc build-asan/fuzz.log
setsid nice -n 19 env "${san_env[@]}" bash -c '
  cmake --build build-asan -j"$1" --target $2 >build-asan/build.log 2>&1
  rc=$?
  echo $rc >build-asan/build.rc
  [ $rc -eq 0 ] || exit $rc
  cmake --build build-asan -j"$1" --target $3 >>build-asan/build.log 2>&1 || { echo "== FAILED: the fuzz replays did not build" >build-asan/fuzz.log; tail -n 80 build-asan/build.log >>build-asan/fuzz.log; exit 1; }
  cd build-asan/tests/fuzz && ctest --output-on-failure -j"$1" -L fuzz >../../fuzz.log 2>&1' _ "$jobs" "${unit_targets[*]}" "${fuzz_targets[*]}" &
san_job=$!
trap 'kill -- -$san_job 2>/dev/null || kill $san_job 2>/dev/null || true' EXIT

integ_rc=0
# A timing-dependent integration test that fails is run once more (--repeat until-pass:2): the
# failure stays in the log above the pass, to be mended (the unit tests get no second try).
# One more test at a time than there are cores: they mostly wait on simulated clocks, ptys and
# sockets (on 2 cores, 3 at a time: 654 s instead of about 960, using 18 % of the CPU).
(cd build && ctest --output-on-failure -j"$((jobs + 1))" -L integration --repeat until-pass:2) || integ_rc=$?
echo "== integration tests: $((SECONDS - start)) s"

while [ ! -e build-asan/build.rc ] && kill -0 $san_job 2>/dev/null; do sleep 1; done
san_rc=$(cat build-asan/build.rc 2>/dev/null || echo 1)
if [ "$san_rc" -ne 0 ]; then
  tail -n 80 build-asan/build.log
  echo "== sanitizer build FAILED (build-asan/build.log)"
  exit "$san_rc"
fi
echo "== sanitizer build (${#unit_targets[@]} unit-test programs): $((SECONDS - start)) s"
[ $integ_rc -eq 0 ] || { echo "== integration tests FAILED"; exit $integ_rc; }

unit_rc=0
(cd build-asan && env "${san_env[@]}" ctest --output-on-failure -j"$jobs" -L unit) || unit_rc=$?
echo "== unit tests under the sanitizers: $((SECONDS - start)) s"
fuzz_rc=0
wait $san_job || fuzz_rc=$?
trap - EXIT
cat build-asan/fuzz.log
echo "== fuzz-corpus replays (${#fuzz_targets[@]} programs) under the sanitizers, built and run in the background: $((SECONDS - start)) s"
[ $unit_rc -eq 0 ] || { echo "== unit tests FAILED"; exit $unit_rc; }
[ $fuzz_rc -eq 0 ] || { echo "== fuzz-corpus replays FAILED"; exit $fuzz_rc; }
# What the idle station costs (issue 49): a check of its own, 20 s here, not a timed test; it fails
# only on a gross regression (the idle service over 20 wake-ups a second) and prints the figures.
python3 scripts/bench_idle.py --bin build/trakbox --seconds 20 || { echo "== idle benchmark FAILED"; exit 1; }
echo "== idle benchmark: $((SECONDS - start)) s"
# The Debian package: built from build/, installed, run from /, removed (issue 13).
scripts/package-check.sh build
echo "== all done: $((SECONDS - start)) s"
