#!/usr/bin/env bash
# package-check.sh [BUILD_DIR]: builds the Debian package from the build tree (cpack -G DEB),
# checks it with lintian (no errors) and scripts/hardening-check.sh (the build's hardening), installs it with dpkg, runs the installed trakbox from / with
# an empty state directory (--version, passes on the installed data, host mode ?A through the
# unattended --service mode, man -w, systemd-analyze verify on the unit, the trakbox group and a
# member of it attaching to the service's socket), then removes the package.
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
svcpid=""
cleanup() {
  [ -n "$svcpid" ] && kill "$svcpid" 2>/dev/null
  for u in tbcheck-member tbcheck-other; do $SUDO userdel "$u" >/dev/null 2>&1 || true; done
  $SUDO dpkg -r trakbox >/dev/null 2>&1 || true
  rm -rf "$state"; $SUDO rm -rf "${rt:-}" "${svcstate:-}"
}
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

# The attach socket (docs/service.md): the package made the trakbox group; the unit runs the
# service in it with /run/trakbox (RuntimeDirectory, 0750) for its socket. systemd is not init
# here, so the service's user is played by hand as the unit sets it up: nobody, group trakbox, a
# runtime directory nobody:trakbox 0750. A member of the group attaches; another user may not.
getent group trakbox
unit=/usr/lib/systemd/system/trakbox.service
for line in '^Group=trakbox$' '^RuntimeDirectory=trakbox$' '^RuntimeDirectoryMode=0750$' \
            '^ExecStart=.* --socket /run/trakbox/trakbox.sock '; do
  grep -Eq -- "$line" "$unit" || { echo "$unit: no line matching $line"; exit 1; }
done
rt=$(mktemp -d); svcstate=$(mktemp -d)
$SUDO chown nobody:trakbox "$rt" "$svcstate"; $SUDO chmod 0750 "$rt"; $SUDO chmod 0700 "$svcstate"
$SUDO setpriv --reuid=nobody --regid=trakbox --clear-groups -- \
  /usr/bin/trakbox --service --state "$svcstate" --socket "$rt/trakbox.sock" --satrak-port 0 </dev/null 2>/dev/null &
svcpid=$!
for _ in $(seq 200); do [ -S "$rt/trakbox.sock" ] && break; sleep 0.1; done
stat -c '%n %a %U:%G' "$rt/trakbox.sock"
[ "$(stat -c '%a %G' "$rt/trakbox.sock")" = "660 trakbox" ]
$SUDO useradd --system --no-create-home --shell /usr/sbin/nologin -G trakbox tbcheck-member
$SUDO useradd --system --no-create-home --shell /usr/sbin/nologin tbcheck-other
# A member reads the status: exit 0 (healthy) or 1 (running with problems: on a machine with no
# network the shipped elements are old and the refresh fails), never 3 (not running) or a refusal.
st=0
$SUDO runuser -u tbcheck-member -- /usr/bin/trakbox status --socket "$rt/trakbox.sock" >"$rt.status" || st=$?
head -3 "$rt.status"; rm -f "$rt.status"
[ "$st" -le 1 ] || { echo "a member of trakbox could not read the status (exit $st)"; exit 1; }
attached=$(echo | $SUDO runuser -u tbcheck-member -- timeout 20 /usr/bin/trakbox attach --socket "$rt/trakbox.sock")
grep -q -- "----- MAIN MENU -----" <<<"$attached" || { echo "the member did not see the menus: $attached"; exit 1; }
grep -q "detached from trakbox" <<<"$attached"
echo "a member of trakbox attached: $(grep -c '' <<<"$attached") lines"
if $SUDO runuser -u tbcheck-other -- /usr/bin/trakbox status --socket "$rt/trakbox.sock" 2>"$rt.err"; then
  echo "a user outside the trakbox group could read the status"; exit 1
fi
grep -q "permission denied" "$rt.err"; cat "$rt.err"; rm -f "$rt.err"
kill -TERM "$svcpid"; wait "$svcpid"; svcpid=""
[ ! -e "$rt/trakbox.sock" ]
$SUDO dpkg -r trakbox >/dev/null
! dpkg-query -W -f='${Status}' trakbox 2>/dev/null | grep -q "install ok installed"
echo "== package check: $((SECONDS - start)) s"
