#!/usr/bin/env bash
# Soak test (not in CI): trakbox --service on the simulated station, its clock 10x fast, with every
# endpoint on (Satrak, rotctld, rigctld, host mode), under the mixed clients of soak_clients.py for
# MINUTES (default 10). Every 10 s trakbox's VmRSS, open descriptors, threads and CPU time go into
# a CSV. At the end it prints first/last/max and fails (exit 1) when
#   - RSS grew more than 10% over its value at the end of the first minute,
#   - the descriptors open once the clients have left are more than before they came,
#   - a client request went unanswered, or trakbox died.
#
#   nice scripts/soak.sh [MINUTES]          TRAKBOX_BIN (default build/trakbox), SOAK_CSV (where
#                                           the samples go; default a temporary folder, kept)
#   SOAK_DRIVERS=hamlib nice scripts/soak.sh   the station's rotator and radio are Hamlib's dummies
#                                           behind rotctld -m 1 and rigctld -m 1 (driver worker
#                                           threads and Hamlib in the process), not the simulated ones
set -uo pipefail
cd "$(dirname "$0")/.."

MINUTES=${1:-10}
if ! [[ $MINUTES =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: scripts/soak.sh [MINUTES]   (a whole number of minutes, at least 1; got '$MINUTES')" >&2
  exit 2
fi
BIN=${TRAKBOX_BIN:-build/trakbox}
for tool in "$BIN" python3 rotctl rigctl; do
  if ! command -v "$tool" >/dev/null; then
    echo "soak: $tool not found (build trakbox first; Hamlib's rotctl and rigctl, python3)" >&2
    exit 2
  fi
done

WORK=$(mktemp -d /tmp/trakbox-soak.XXXXXX)
CSV=${SOAK_CSV:-$WORK/soak.csv}
read -r SATRAK ROTCTLD RIGCTLD HOSTP PEER_ROT PEER_RIG < <(python3 -c '
import socket
ss = [socket.socket() for _ in range(6)]
for s in ss: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in ss])')

DRIVERS=()
PEERS=()
case ${SOAK_DRIVERS:-simulated} in
  simulated) ;;
  hamlib)
    rotctld -m 1 -T 127.0.0.1 -t "$PEER_ROT" >/dev/null 2>&1 & PEERS+=($!)
    rigctld -m 1 -T 127.0.0.1 -t "$PEER_RIG" >/dev/null 2>&1 & PEERS+=($!)
    for port in "$PEER_ROT" "$PEER_RIG"; do  # listening within 10 s
      for _ in $(seq 100); do (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && break; sleep 0.1; done
    done
    DRIVERS=(--rotator "rotctld:127.0.0.1:$PEER_ROT" --radio "rigctld:127.0.0.1:$PEER_RIG") ;;
  *) echo "soak: SOAK_DRIVERS is simulated or hamlib, not '$SOAK_DRIVERS'" >&2; exit 2 ;;
esac

"$BIN" --service "${DRIVERS[@]}" --state "$WORK/state" --clock-rate 10 --satrak-port "$SATRAK" --rotctld-port "$ROTCTLD" \
  --rigctld-port "$RIGCTLD" --host-port "$HOSTP" 2>"$WORK/stderr.log" &
PID=$!
CLIENTS=
cleanup() {
  [[ -n $CLIENTS ]] && kill "$CLIENTS" 2>/dev/null
  kill "$PID" 2>/dev/null && wait "$PID" 2>/dev/null
  for p in "${PEERS[@]}"; do kill "$p" 2>/dev/null; done
}
trap cleanup EXIT

# Ready when the Satrak port answers (at most 15 s).
for _ in $(seq 150); do
  "$BIN" satrak "127.0.0.1:$SATRAK" VERSION? >/dev/null 2>&1 && break
  kill -0 "$PID" 2>/dev/null || { echo "soak: trakbox exited at start:"; cat "$WORK/stderr.log"; exit 1; }
  sleep 0.1
done

rss_kb() { awk '/^VmRSS:/ {print $2}' "/proc/$PID/status"; }
fds() { ls "/proc/$PID/fd" | wc -l; }
threads() { awk '/^Threads:/ {print $2}' "/proc/$PID/status"; }
cpu_s() { awk -v tck="$(getconf CLK_TCK)" '{ sub(/.*\) /, ""); printf "%.2f", ($12 + $13) / tck }' "/proc/$PID/stat"; }

# Descriptors at rest: the count unchanged for 2 s (the readiness probe's connection closing, the
# drivers' links opening), within 15 s.
FDS_BEFORE=$(fds)
stable=0
for _ in $(seq 150); do
  sleep 0.1
  n=$(fds)
  if (( n == FDS_BEFORE )); then
    (( ++stable >= 20 )) && break
  else
    FDS_BEFORE=$n
    stable=0
  fi
done
echo "soak: trakbox pid $PID, ports satrak $SATRAK rotctld $ROTCTLD rigctld $RIGCTLD host $HOSTP;" \
     "drivers ${SOAK_DRIVERS:-simulated}; $MINUTES min; samples in $CSV"
python3 scripts/soak_clients.py --seconds $((MINUTES * 60)) --satrak "$SATRAK" --rotctld "$ROTCTLD" \
  --rigctld "$RIGCTLD" --host "$HOSTP" >"$WORK/clients.txt" 2>&1 &
CLIENTS=$!

echo "elapsed_s,rss_kb,fds,threads,cpu_s" >"$CSV"
START=$(date +%s)
while kill -0 "$CLIENTS" 2>/dev/null; do
  if ! kill -0 "$PID" 2>/dev/null; then
    echo "soak: FAILED: trakbox died"; tail -20 "$WORK/stderr.log"; exit 1
  fi
  echo "$(( $(date +%s) - START )),$(rss_kb),$(fds),$(threads),$(cpu_s)" >>"$CSV"
  sleep 10
done
wait "$CLIENTS"
CLIENTS_RC=$?
CLIENTS=
cat "$WORK/clients.txt"

# The clients have gone: the servers see them leave within moments (at most 15 s allowed).
FDS_AFTER=$(fds)
for _ in $(seq 150); do
  FDS_AFTER=$(fds)
  (( FDS_AFTER <= FDS_BEFORE )) && break
  sleep 0.1
done

python3 - "$CSV" "$FDS_BEFORE" "$FDS_AFTER" "$CLIENTS_RC" <<'EOF'
import csv, sys
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
before, after, clients_rc = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
if not rows:
    print("soak: FAILED: no samples"); sys.exit(1)
def fmt(r):
    return f"{r['elapsed_s']:.0f} s: RSS {r['rss_kb']:.0f} kB, {r['fds']:.0f} fds, {r['threads']:.0f} threads, CPU {r['cpu_s']:.1f} s"
print("first", fmt(rows[0]))
print("last ", fmt(rows[-1]))
print(f"max   RSS {max(r['rss_kb'] for r in rows):.0f} kB, {max(r['fds'] for r in rows):.0f} fds (clients connected)")
failed = False
settled = [r for r in rows if r["elapsed_s"] >= 60]
if settled:
    base = settled[0]["rss_kb"]
    top = max(r["rss_kb"] for r in settled)
    print(f"RSS after the first minute: {base:.0f} kB, at most {top:.0f} kB later ({100 * (top / base - 1):+.1f}%)")
    if top > base * 1.10:
        print("soak: FAILED: RSS grew more than 10% after the first minute"); failed = True
print(f"descriptors before the clients: {before}, after they left: {after}")
if after > before:
    print("soak: FAILED: descriptors grew"); failed = True
if clients_rc != 0:
    print("soak: FAILED: requests went unanswered (see above)"); failed = True
print("soak: " + ("FAILED" if failed else "passed"))
sys.exit(1 if failed else 0)
EOF
