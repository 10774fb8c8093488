#!/usr/bin/env bash
# stress_suite.sh [BUILD_DIR [RUNS]]: the whole CTest suite RUNS times in a row (default 3) with
# `stress-ng --cpu 2` loading the machine beside it, the practice of issue 14: a test that waits
# must wait for a condition, not for a time, and pass on a machine busy past its cores. Needs a
# built tree (scripts/build.sh) and stress-ng (Debian package). Logs and a one-line summary per run
# in ${STRESS_OUT:-/tmp/trakbox-stress}; exits non-zero when any run failed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:-build}")
runs=${2:-3}
out=${STRESS_OUT:-/tmp/trakbox-stress}
command -v stress-ng >/dev/null || { echo "stress_suite.sh: stress-ng is not installed" >&2; exit 2; }
mkdir -p "$out"
: >"$out/summary"
stress-ng --cpu 2 --timeout 0 >/dev/null 2>&1 &
load=$!
trap 'kill $load 2>/dev/null; wait $load 2>/dev/null || true' EXIT
failed=0
for i in $(seq 1 "$runs"); do
  start=$(date +%s)
  rc=0
  (cd "$build" && ctest -j2 --output-on-failure) >"$out/run-$i.log" 2>&1 || rc=$?
  line="run $i: rc=$rc, $(($(date +%s) - start)) s, $(grep -E 'tests passed|tests failed' "$out/run-$i.log" | tail -1)"
  echo "$line" | tee -a "$out/summary"
  [ "$rc" -eq 0 ] || failed=1
done
exit $failed
