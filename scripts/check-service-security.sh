#!/bin/bash
# The systemd unit's exposure as `systemd-analyze security --offline=true` rates it (issue 38): at most
# MAX (default 2.5). Without systemd-analyze: skipped (exit 77), but a failure in CI (CI set), where
# every tool is installed.
#   scripts/check-service-security.sh [UNIT [MAX]]
set -euo pipefail
unit=${1:-$(dirname "$0")/../packaging/trakbox.service}
max=${2:-2.5}
if ! command -v systemd-analyze >/dev/null; then
  if [[ -n "${CI:-}" && "${CI}" != 0 && "${CI}" != false ]]; then
    echo "FAILED (CI=$CI: every tool must be installed): systemd-analyze is missing"
    exit 1
  fi
  echo "SKIPPED: systemd-analyze is missing (apt install systemd)"
  exit 77
fi
out=$(systemd-analyze security --offline=true --no-pager "$unit" 2>&1) || true
score=$(sed -nE 's/.*Overall exposure level for [^:]*: ([0-9.]+).*/\1/p' <<<"$out")
if [[ -z "$score" ]]; then
  echo "FAILED: no exposure level in systemd-analyze's answer:"
  echo "$out"
  exit 1
fi
grep -E '^✗' <<<"$out" || true
if awk -v s="$score" -v m="$max" 'BEGIN { exit !(s <= m) }'; then
  echo "$unit: exposure $score (at most $max): passed"
else
  echo "FAILED: $unit: exposure $score, more than $max"
  exit 1
fi
