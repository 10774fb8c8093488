#!/usr/bin/env bash
# fuzz.sh [SECONDS [TARGET...]]: builds the libFuzzer targets of tests/fuzz with clang into
# build-fuzz/ (-DTRAKBOX_FUZZ=ON: the whole project under ASan + UBSan + coverage) and runs each
# target for SECONDS (default 60), one after the other, niced, seeded from tests/fuzz/corpus/NAME/
# with the dictionary tests/fuzz/dict/NAME.dict when there is one. TARGET: elements, state, ...
# (default: all).
#
# Outside the source tree (FUZZ_OUT, default ${TMPDIR:-/tmp}/trakbox-fuzz):
#   corpus/NAME/      inputs the runs found interesting (kept between runs: the next run goes on)
#   artifacts/NAME/   crash-*, leak-*, timeout-*, oom-*: inputs that failed (replay: build-fuzz/fuzz_NAME FILE)
#   logs/NAME.log     libFuzzer's output
# Exits non-zero when any target failed (a crash, hang, leak, sanitizer report or fuzz property).
# docs/fuzzing.md has the targets and what they check.
set -euo pipefail
cd "$(dirname "$0")/.."
src=$PWD
seconds=${1:-60}
shift || true
out=${FUZZ_OUT:-${TMPDIR:-/tmp}/trakbox-fuzz}
build=${FUZZ_BUILD:-build-fuzz}

# Longest input per target: enough for the seeds and a session, small enough to mutate quickly.
declare -A max_len=(
  [elements]=4096 [freqmode]=2048 [station_file]=1024 [state]=32768 [satrak_frame]=2048
  [satrak_unit]=2048 [host]=2048 [rotctl]=1024 [rigctl]=1024 [cat]=1024 [menus]=2048 [cli]=512 [omm]=8192 [satnogs]=8192 [attach_frames]=1024
)
if [ $# -gt 0 ]; then targets=("$@"); else targets=("${!max_len[@]}"); fi
IFS=$'\n' targets=($(sort <<<"${targets[*]}")); unset IFS

# FUZZ_SKIP_BUILD=1: the targets are built already (several fuzz.sh running side by side).
if [ -z "${FUZZ_SKIP_BUILD:-}" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DTRAKBOX_FUZZ=ON -DTRAKBOX_BENCH=OFF \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  nice -n 10 cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
failed=()
mkdir -p "$out"
summary=$out/summary.txt
printf '%-14s %8s %10s %8s %8s %s\n' target seconds execs exec/s cov ft >"$summary"
for t in "${targets[@]}"; do
  len=${max_len[$t]:-}
  if [ -z "$len" ]; then echo "fuzz.sh: no target '$t' (have: ${!max_len[*]})" >&2; exit 2; fi
  mkdir -p "$out/corpus/$t" "$out/artifacts/$t" "$out/logs"
  args=(-max_total_time="$seconds" -max_len="$len" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$out/artifacts/$t/")
  [ -f "$src/tests/fuzz/dict/$t.dict" ] && args+=(-dict="$src/tests/fuzz/dict/$t.dict")
  echo "== fuzz_$t: $seconds s, max_len $len"
  rc=0
  touch "$out/logs/$t.start"
  nice -n 10 "$build/fuzz_$t" "${args[@]}" "$out/corpus/$t" "$src/tests/fuzz/corpus/$t" \
    >"$out/logs/$t.log" 2>&1 || rc=$?
  # libFuzzer exits non-zero on a crash, leak, timeout or out-of-memory, after writing the input to
  # the artifact prefix. The last status line: "#N DONE cov: C ft: F corp: ... exec/s: E ..."
  last=$(grep -E '^#[0-9]+' "$out/logs/$t.log" | tail -1 || true)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/logs/$t.log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$out/logs/$t.log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  printf '%-14s %8s %10s %8s %8s %s\n' "$t" "$seconds" "${execs:--}" "${rate:--}" "${cov:--}" "${ft:--}" \
    | tee -a "$summary"
  if [ "$rc" -ne 0 ]; then
    failed+=("$t")
    echo "   FAILED (exit $rc): see $out/logs/$t.log"
    grep -E '^(==[0-9]+==ERROR|SUMMARY|\*\*\* fuzz property|.*runtime error)' "$out/logs/$t.log" | head -5 | sed 's/^/   /'
    find "$out/artifacts/$t" -type f -newer "$out/logs/$t.start" | sed 's/^/   artifact: /'
  fi
done
echo
cat "$summary"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: failures in: ${failed[*]} (artifacts in $out/artifacts)" >&2
  exit 1
fi
echo "fuzz.sh: no failures (corpus and logs in $out)"
