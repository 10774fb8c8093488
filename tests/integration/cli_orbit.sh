#!/bin/bash
# The orbit command line as a script uses it: trakbox propagate against Vallado's tcppver.out
# (Debian python3-sgp4), the stop-time line, the error line of a decaying set, --name=value and
# negative values, and the one-line, exit-2 errors for bad arguments.
# Environment: TRAKBOX_BIN, TRAKBOX_SGP4_DATA_DIR (SGP4-VER.TLE, tcppver.out).
set -u
BIN=${TRAKBOX_BIN:?set TRAKBOX_BIN to the trakbox program}
DATA=${TRAKBOX_SGP4_DATA_DIR:-/usr/lib/python3/dist-packages/sgp4}
TLE=$DATA/SGP4-VER.TLE
REF=$DATA/tcppver.out
PY=/usr/bin/python3
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
checks=0
fails=0

ok() { checks=$((checks + 1)); }
bad() { checks=$((checks + 1)); fails=$((fails + 1)); echo "FAIL: $*"; }
expect() { if eval "$2"; then ok; else bad "$1"; fi; }

for f in "$TLE" "$REF"; do
  [ -r "$f" ] || { echo "cli_orbit: $f not found (Debian package python3-sgp4)"; exit 1; }
done

# compare SAT FILE: every state line of FILE must be in SAT's block of tcppver.out at the same
# tsince, each of the six numbers within 2e-7 km or km/s (python-sgp4's own limit), and in the same
# columns (" %16.8f" x 4, " %12.9f" x 3: fields end at columns 17, 34, 51, 68, 81, 94, 107).
# Prints "lines maxdiff"; returns non-zero on a mismatch.
compare() {
  awk -v sat="$1" -v tol=2e-7 '
    FNR == NR { if ($2 == "xx") cur = $1; else if (cur == sat) ref[sprintf("%.8f", $1)] = $0; next }
    /^#/ { next }
    {
      n++
      key = sprintf("%.8f", $1)
      if (!(key in ref)) { print "no tcppver line for tsince " key > "/dev/stderr"; bad = 1; next }
      if (length($0) != 107) { print "line length " length($0) ": " $0 > "/dev/stderr"; bad = 1 }
      split("17 34 51 68 81 94 107", ends, " ")
      for (i = 1; i <= 7; i++)
        if (substr($0, ends[i], 1) !~ /[0-9]/ || (i < 7 && substr($0, ends[i] + 1, 1) != " ")) {
          print "column " ends[i] " out of place: " $0 > "/dev/stderr"; bad = 1; break
        }
      split(ref[key], r, " ")
      for (i = 2; i <= 7; i++) {
        d = $i - r[i]; if (d < 0) d = -d
        if (d > max) max = d
        if (d > tol) { print "tsince " key " field " i ": " $i " vs " r[i] > "/dev/stderr"; bad = 1 }
      }
    }
    END { printf "%d %.3g\n", n, max; exit bad }' "$REF" "$2"
}

# 1. Whole verification blocks, each set with its own start/stop/step from SGP4-VER.TLE.
total_lines=0
worst=0
for sat in 00005 04632 06251 09998 11801 14128 23333 23599 25954 28129 29238 88888; do
  read -r start stop step < <(awk -v s="$sat" '$1 == "2" && $2 == s { sub(/\r$/, ""); print substr($0, 70) }' "$TLE")
  "$BIN" propagate "$TLE" --sat "$sat" --start "$start" --stop "$stop" --step "$step" >"$TMP/$sat.out" 2>"$TMP/$sat.err"
  rc=$?
  if [ $rc -ne 0 ]; then bad "propagate $sat exit $rc: $(head -c 300 "$TMP/$sat.err")"; continue; fi
  if res=$(compare "$((10#$sat))" "$TMP/$sat.out"); then ok; else bad "propagate $sat differs from tcppver.out ($res)"; fi
  read -r n m <<<"$res"
  total_lines=$((total_lines + n))
  worst=$($PY -c "print(max($worst, $m))")
done
echo "cli_orbit: $total_lines propagate lines match tcppver.out, max difference $worst"

# 2. The stop time ends the output when the step does not land on it: 23333 runs 0..1600 by 120.
last=$(tail -n 1 "$TMP/23333.out" | awk '{print $1}')
before=$(tail -n 2 "$TMP/23333.out" | head -n 1 | awk '{print $1}')
expect "23333 ends at 1600 after 1560 (got $before, $last)" '[ "$last" = 1600.00000000 ] && [ "$before" = 1560.00000000 ]'
# A stop time that is not in tcppver.out: against python-sgp4 directly.
"$BIN" propagate "$TLE" --sat 5 --start 0 --stop 1000 --step 360 >"$TMP/stop.out" 2>/dev/null
expect "0..1000 by 360 gives 4 lines" '[ "$(wc -l <"$TMP/stop.out")" -eq 4 ]'
want=$($PY -c "
from sgp4.api import Satrec
l = [x for x in open('$TLE') if x.startswith(('1 00005', '2 00005'))]
s = Satrec.twoline2rv(l[0], l[1])
e, r, v = s.sgp4_tsince(1000.0)
print(' %16.8f %16.8f %16.8f %16.8f %12.9f %12.9f %12.9f' % ((1000.0,) + tuple(r) + tuple(v)))")
got=$(tail -n 1 "$TMP/stop.out")
if $PY -c "import sys; a, b = sys.argv[1].split(), sys.argv[2].split(); sys.exit(not all(abs(float(x) - float(y)) <= 2e-7 for x, y in zip(a, b)) or len(a) != 7)" "$got" "$want"; then ok
else bad "stop line: got '$got', python-sgp4 '$want'"; fi
# A step that lands on the stop time prints it once.
"$BIN" propagate "$TLE" --sat 5 --start 0 --stop 720 --step 360 >"$TMP/land.out" 2>/dev/null
expect "0..720 by 360 gives 3 lines" '[ "$(wc -l <"$TMP/land.out")" -eq 3 ]'

# 3. A decaying set: 28872 decays at 55 min (error 6). States up to 50 min, then the error line,
#    nothing for 55 min or later, exit status 1.
"$BIN" propagate "$TLE" --sat 28872 --start 0 --stop 60 --step 5 >"$TMP/decay.out" 2>"$TMP/decay.err"
rc=$?
expect "decay: exit 1 (got $rc)" '[ $rc -eq 1 ]'
expect "decay: 11 state lines then the error line" '[ "$(grep -vc "^#" "$TMP/decay.out")" -eq 11 ] && [ "$(wc -l <"$TMP/decay.out")" -eq 12 ]'
errline=$(tail -n 1 "$TMP/decay.out")
expect "decay: error line names code 6 and 55 min: '$errline'" '[[ "$errline" == "# sgp4 error 6 at tsince 55.00000000 min ("*"): "?* ]]'
if compare 28872 "$TMP/decay.out" >/dev/null; then ok; else bad "decay: states before the error differ from tcppver.out"; fi
# An error at the very first time: no state at all.
"$BIN" propagate "$TLE" --sat 28872 --start 60 --stop 100 --step 5 >"$TMP/decay2.out" 2>/dev/null
expect "decayed from the start: only the error line" '[ "$(wc -l <"$TMP/decay2.out")" -eq 1 ] && grep -q "^# sgp4 error 6 at tsince 60.00000000" "$TMP/decay2.out"'

# 4. --name=value and negative values: 9998 runs -1440..-720 by 60.
"$BIN" propagate "$TLE" --sat=09998 --start=-1440 --stop -720 --step=60 >"$TMP/neg.out" 2>/dev/null
expect "negative start: 13 lines" '[ "$(wc -l <"$TMP/neg.out")" -eq 13 ]'
if compare 9998 "$TMP/neg.out" >/dev/null; then ok; else bad "negative start differs from tcppver.out"; fi
expect "--sat=09998 and --sat 9998 agree" 'cmp -s "$TMP/neg.out" <("$BIN" propagate "$TLE" --sat 9998 --start -1440 --stop=-720 --step 60 2>/dev/null)'
# A negative station latitude as a separate word and after '='.
SCHED=(--sat 5 --start 2000-06-28T00:00:00Z --step 60 --count 5 --csv)
"$BIN" schedule "$TLE" "${SCHED[@]}" --station -77.85,166.67,10 >"$TMP/s1.csv" 2>"$TMP/s1.err"
"$BIN" schedule "$TLE" "${SCHED[@]}" --station=-77.85,166.67,10 >"$TMP/s2.csv" 2>/dev/null
expect "schedule --station -77.85,... works: $(head -c 200 "$TMP/s1.err")" '[ "$(wc -l <"$TMP/s1.csv")" -eq 6 ]'
expect "--station=-77.85,... equals --station -77.85,..." 'cmp -s "$TMP/s1.csv" "$TMP/s2.csv"'
expect "schedule CSV header" '[ "$(head -n 1 "$TMP/s1.csv")" = "utc,az_deg,el_deg,range_km,range_rate_km_s,alt_km,lat_deg,lon_deg,phase256,doppler_hz" ]'
"$BIN" schedule "$TLE" --sat 5 --start 2000-06-28T00:00:00Z --step 60 --count 3 --station 32.259,-110.778,842 --json >"$TMP/s.json" 2>/dev/null
expect "schedule --json parses, 3 rows" '$PY -c "import json,sys; r = json.load(open(sys.argv[1])); sys.exit(len(r) != 3 or r[0][\"utc\"] != \"2000-06-28T00:00:00Z\")" "$TMP/s.json"'
"$BIN" schedule "$TLE" --sat 5 --start 2000-06-28T00:00:00Z --step 60 --count 3 --station 32.259,-110.778,842 >"$TMP/s.txt" 2>/dev/null
expect "schedule table: header and 3 rows" '[ "$(grep -c "^2000/06/28 00:0" "$TMP/s.txt")" -eq 3 ] && grep -q "AZ/EL" "$TMP/s.txt"'

# 5. Bad arguments: exit 2, nothing on stdout, one line on stderr (besides warnings about the
#    element file) naming the argument.
badarg() {  # badarg ARGUMENT-NAMED-IN-MESSAGE trakbox-args...
  local name=$1; shift
  "$BIN" "$@" >"$TMP/bad.out" 2>"$TMP/bad.err"
  local rc=$?
  # Element-file problems (SGP4-VER.TLE has three bad checksums on purpose: errors, the sets
  # refused, as --no-checksum is not given) may come first; they name the file and line.
  grep -vE "^trakbox: (warning|error): [^ ]+:[0-9]+:[0-9]+: " "$TMP/bad.err" >"$TMP/bad.msg"
  if [ $rc -eq 2 ] && [ ! -s "$TMP/bad.out" ] && [ "$(wc -l <"$TMP/bad.msg")" -eq 1 ] &&
     grep -qF -- "$name" "$TMP/bad.msg"; then ok
  else bad "trakbox $* -> exit $rc, stderr '$(head -c 300 "$TMP/bad.err")', expected exit 2 naming '$name'"; fi
}
P=(propagate "$TLE" --sat 5)
badarg --step "${P[@]}" --start 0 --stop 10
badarg --step "${P[@]}" --start 0 --stop 10 --step abc
badarg "'abc'" "${P[@]}" --start 0 --stop 10 --step abc
badarg --step "${P[@]}" --start 0 --stop 10 --step 0
badarg --step "${P[@]}" --start 0 --stop 10 --step=-5
badarg --stop "${P[@]}" --start 0 --stop -5 --step 1
badarg --start "${P[@]}" --start --stop 10 --step 1
badarg --start "${P[@]}" --start 1e999 --stop 10 --step 1
badarg --frobnicate "${P[@]}" --start 0 --stop 10 --step 1 --frobnicate
badarg -x "${P[@]}" --start 0 --stop 10 --step 1 -x
badarg --stop "${P[@]}" --start 0 --stop 1 --stop 2 --step 1
badarg ELEMENTS propagate --start 0 --stop 10 --step 1
badarg ELEMENTS propagate /nonexistent/elements.tle --start 0 --stop 10 --step 1
badarg extra.tle "${P[@]}" extra.tle --start 0 --stop 10 --step 1
badarg --sat propagate "$TLE" --sat 12345 --start 0 --stop 10 --step 1
badarg --sat propagate "$TLE" --sat 28872 --sat 5 --start 0 --stop 10 --step 1
badarg ELEMENTS propagate "$TLE" --start 0 --stop 10 --step 1
S=(schedule "$TLE" --sat 5 --start 2000-06-28 --step 60 --count 3)
# No --station: the stored one (issue 30); a state that cannot be read is named, and kept as it is.
mkdir -p "$TMP/badstate" && echo 'not a state' >"$TMP/badstate/trakbox-state.json"
badarg --station "${S[@]}" --state "$TMP/badstate"
expect "a state the command line cannot read stays where it is" 'grep -q "not a state" "$TMP/badstate/trakbox-state.json"'
badarg --station "${S[@]}" --station 1,2,3,4
badarg --station "${S[@]}" --station 95,0,0
badarg --station "${S[@]}" --station 10,20,abc
badarg --start schedule "$TLE" --sat 5 --station 1,2,3 --start 2000-13-01 --step 60 --count 3
badarg --count schedule "$TLE" --sat 5 --station 1,2,3 --start 2000-06-28 --step 60 --count 0
badarg --count schedule "$TLE" --sat 5 --station 1,2,3 --start 2000-06-28 --step 60 --count 2.5
badarg --freq "${S[@]}" --station 1,2,3 --freq -5
badarg --dut1 "${S[@]}" --station 1,2,3 --dut1 1.5
badarg --json "${S[@]}" --station 1,2,3 --csv --json
badarg --csv "${S[@]}" --station 1,2,3 --csv=yes
badarg --hours passes "$TLE" --sat 5 --station 1,2,3 --start 2000-06-28 --hours 0
badarg --min-el passes "$TLE" --sat 5 --station 1,2,3 --start 2000-06-28 --hours 1 --min-el 91
badarg frobnicate frobnicate
# Honest answers (issue 12): the sets' ages in the headers, a warning past the orbit's limit, and
# passes that stop where SGP4 fails say so and exit 1.
ISS=${TRAKBOX_SOURCE_DIR:-.}/data/amateur.tle
"$BIN" passes "$ISS" --sat ISS --station 27.391,128.657,50 --start 2031-05-21T00:00:00Z --hours 3 >"$TMP/old.out" 2>"$TMP/old.err"; rc=$?
expect "passes 5 years on: exit 0 (got $rc)" '[ $rc -eq 0 ]'
expect "passes header gives the age: $(sed -n 2p "$TMP/old.out")" 'grep -qx "elements ISS (25544) epoch 2026-05-21T03:57:45Z, age 1825.8 days" "$TMP/old.out"'
expect "passes 5 years on warns: $(cat "$TMP/old.err")" 'grep -qx "trakbox passes: warning: ISS (25544): elements 1825.8 days old (more than 14 for a low orbit): positions are unreliable at 2031-05-21T00:00:00Z" "$TMP/old.err"'
"$BIN" passes "$ISS" --sat ISS --station 27.391,128.657,50 --start 2026-05-21T06:00:00Z --hours 3 >"$TMP/fresh.out" 2>"$TMP/fresh.err"
expect "passes on fresh elements: no warning: $(cat "$TMP/fresh.err")" '[ ! -s "$TMP/fresh.err" ]'
"$BIN" schedule "$ISS" --sat ISS --station 27.391,128.657,50 --start 2031-05-21T00:00:00Z --step 60 --count 2 >"$TMP/sold.out" 2>"$TMP/sold.err"
expect "schedule header gives the age: $(head -n 1 "$TMP/sold.out")" 'head -n 1 "$TMP/sold.out" | grep -q "elements epoch 2026-05-21T03:57:45Z, age 1825.8 days"'
expect "schedule 5 years on warns" 'grep -q "trakbox schedule: warning: ISS (25544): elements 1825.8 days old" "$TMP/sold.err"'
# 28872 decays 50-55 minutes after its epoch (Vallado: error 6 at 55 min in tcppver.out).
"$BIN" passes "$TLE" --no-checksum --sat 28872 --station 27.391,128.657,50 --start 2005-11-29T00:30:00Z --hours 3 >"$TMP/pdecay.out" 2>"$TMP/pdecay.err"; rc=$?
expect "passes of a decaying set: exit 1 (got $rc)" '[ $rc -eq 1 ]'
expect "passes says where SGP4 stops: $(grep 28872 "$TMP/pdecay.err" | tail -1)" 'grep -q "^trakbox passes: 28872: sgp4 error [0-9]* at 2005-11-29T01:[0-9:]*Z: .*; no passes from then on$" "$TMP/pdecay.err"'
"$BIN" passes "$TLE" --no-checksum --sat 33334 --station 27.391,128.657,50 --start 2005-11-29T00:00:00Z --hours 3 >/dev/null 2>"$TMP/pinit.err"; rc=$?
expect "passes of a set SGP4 refuses: exit 1, said: $(tail -1 "$TMP/pinit.err")" '[ $rc -eq 1 ] && grep -q "^trakbox passes: 33334: sgp4 error 3: .*; no passes$" "$TMP/pinit.err"'

expect "trakbox --help exits 0" '"$BIN" --help | grep -q propagate'
expect "trakbox propagate --help exits 0" '"$BIN" propagate --help | grep -q -- --step'

echo "cli_orbit: $checks checks, $fails failed"
[ $fails -eq 0 ]
