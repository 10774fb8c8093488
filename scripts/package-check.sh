#!/usr/bin/env bash
# package-check.sh [BUILD_DIR]: builds the Debian package from the build tree (cpack -G DEB),
# checks it with lintian (no errors) and scripts/hardening-check.sh (the build's hardening), installs it with dpkg, runs the installed trakbox from / with
# an empty state directory (--version, passes on the installed data, host mode ?A through the
# unattended --service mode, man -w, systemd-analyze verify on the unit), then removes the package.
# Run by scripts/test.sh in CI (a fresh machine, as root); docs/install.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:-build}")
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
start=$SECONDS

(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls "$build"/trakbox_*.deb | head -1)
echo "== package: $deb"
lintian_out=$(lintian "$deb" 2>&1 | grep -v "running with root privileges" || true)
echo "${lintian_out:-lintian: nothing to report}"
if grep -q '^E:' <<<"$lintian_out"; then echo "lintian reports errors"; exit 1; fi
scripts/hardening-check.sh "$deb"

if dpkg-query -W -f='${Status}' trakbox 2>/dev/null | grep -q "install ok installed"; then
  echo "trakbox is installed already: not touching it"; exit 1
fi
$SUDO dpkg -i "$deb" >/dev/null
cleanup() { $SUDO dpkg -r trakbox >/dev/null 2>&1 || true; rm -rf "$state"; }
state=$(mktemp -d)
trap cleanup EXIT
dpkg -L trakbox | grep -E '^/usr/bin/trakbox$|^/usr/share/trakbox/amateur.tle$|trakbox.1.gz$|trakbox.service$' >/dev/null

cd /
rmdir "$state"  # an empty, not yet existing state directory: the service creates it (0700)
out=$(/usr/bin/trakbox --version); echo "$out"; [[ "$out" == trakbox\ * ]]
/usr/bin/trakbox passes /usr/share/trakbox/amateur.tle --sat ISS --station 32.259,-110.778,842 \
  --start 2026-05-21T00:00:00Z --hours 12 --min-el 10 | head -3
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
/usr/bin/trakbox --service --state "$state" --satrak-port 0 --host-port "$port" </dev/null 2>"$state.err" &
pid=$!
reply=$(python3 - "$port" <<'PY'
import socket, sys, time
deadline = time.time() + 20
while True:
    try:
        s = socket.create_connection(("127.0.0.1", int(sys.argv[1])), timeout=5)
        break
    except OSError:
        if time.time() > deadline:
            raise
        time.sleep(0.1)
s.sendall(b"?A\r\n")
data = b""
while data.count(b"TrakBox>>") < 2:
    chunk = s.recv(4096)
    if not chunk:
        break
    data += chunk
print(data.decode(errors="replace"))
PY
)
echo "$reply" | head -4
grep -Eq 'TrakBox>>AZ[0-9.]+ EL-?[0-9.]+' <<<"$reply"  # ?A answered by the service
kill -TERM "$pid"; wait "$pid"; code=$?
echo "service exit status $code; its standard error (the journal):"; cat "$state.err"; rm -f "$state.err"
[ "$code" -eq 0 ]
[ "$(stat -c %a "$state")" = 700 ] && [ "$(stat -c %a "$state/trakbox-state.json")" = 600 ]
man -w trakbox
systemd-analyze verify /usr/lib/systemd/system/trakbox.service
$SUDO dpkg -r trakbox >/dev/null
! dpkg-query -W -f='${Status}' trakbox 2>/dev/null | grep -q "install ok installed"
echo "== package check: $((SECONDS - start)) s"
