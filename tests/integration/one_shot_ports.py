"""One-shot commands never open a server port (issue 39): with a station's Satrak port (4001) taken,
`echo '?A' | trakbox host` answers and leaves, says nothing of a bind, and (under strace) asks the
kernel to bind no network port at all; nor do `next`, `passes` and `status`."""
import errno
import os
import shutil
import socket
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SOURCE, check, run_test, skip  # noqa: E402


def listener_on_4001():
    """A listener on 127.0.0.1:4001, ours, or the one already there (a station of another test)."""
    s = socket.socket()
    try:
        s.bind(("127.0.0.1", 4001))
        s.listen()
        return s
    except OSError as e:
        check(e.errno == errno.EADDRINUSE, f"4001: {e}")
        s.close()
        return None


def binds(args, stdin, state):
    """Runs trakbox under strace -f -e trace=bind: (exit status, stdout, stderr, the binds of network
    ports: AF_INET and AF_INET6; the station's own Unix socket in the state directory is no port)."""
    log = os.path.join(state, "strace.log")
    r = subprocess.run(["strace", "-f", "-qq", "-e", "trace=bind", "-o", log, BIN, *args], input=stdin,
                       capture_output=True, text=True, timeout=60)
    with open(log) as f:
        calls = [ln for ln in f if "bind(" in ln and "AF_INET" in ln]
    return r.returncode, r.stdout, r.stderr, calls


def main():
    if not shutil.which("strace"):
        skip("strace is not installed")
    state = tempfile.mkdtemp(prefix="trakbox-oneshot-")
    held = listener_on_4001()
    try:
        code, out, err, calls = binds(["host", "--state", state, "--clock", CLOCK], "?A\n", state)
        check(code == 0, f"trakbox host exits 0: {code} {err}")
        check("AZ" in out and "EL" in out, f"and answers ?A: {out!r}")
        check("bind" not in err and "Address already in use" not in err, f"no word of a bind: {err!r}")
        check(calls == [], f"no bind at all: {calls}")
        tle = os.path.join(SOURCE, "data", "amateur.tle")
        for args in (["next", "ISS", "--state", state, "--start", CLOCK],
                     ["passes", tle, "--sat", "ISS", "--station", "27.391,128.657,50", "--start", CLOCK, "--hours", "1"],
                     ["status", "--state", state]):
            code, out, err, calls = binds(args, "", state)
            check(calls == [], f"trakbox {args[0]} binds nothing: {calls}")
            check("Address already in use" not in err, f"trakbox {args[0]}: {err!r}")
    finally:
        if held:
            held.close()
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
