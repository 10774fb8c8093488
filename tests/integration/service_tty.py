"""trakbox --service --tty DEV (issue 29): the service keeps the box's serial port. Its menus are on
the serial line (a socat pty pair at 9600 bps) and, at the same time, to an attach client; the serial
terminal answers a menu, a client attached meanwhile sees it, and Ctrl-] on the serial line does not
take the port away; a script on a pipe takes the keyboard, answers, and is detached when its input
has been used."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SerialPair, Terminal, check, reap, run_test, skip  # noqa: E402


def main():
    if not shutil.which("socat"):
        skip("socat is not installed")
    state = tempfile.mkdtemp(prefix="trakbox-svc-tty-")
    pair = SerialPair()
    fd = None
    procs = []
    try:
        svc = subprocess.Popen([BIN, "--service", "--state", state, "--satrak-port", "0", "--clock", CLOCK,
                                "--tty", pair.trakbox_side, "--baud", "9600"],
                               stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(svc)
        fd = os.open(pair.terminal_side, os.O_RDWR | os.O_NOCTTY)
        t = Terminal(fd)
        t.expect(r"Select \[1-8,S,M\]:", timeout=20)
        t.send("\x1d")  # the serial port never detaches
        t.send("4\r")
        t.expect(r"Callsign\s*: NOCALL")
        # An attach client (plain lines on a pipe) sees the same menus; its input ends at once, so
        # it detaches after what it was sent on arrival.
        r = subprocess.run([BIN, "attach", "--state", state], input=b"", capture_output=True, timeout=20)
        out = r.stdout.decode(errors="replace")
        check(r.returncode == 0, f"attach exit {r.returncode}: {r.stderr}")
        check("Callsign" in out and "detached from trakbox" in out, f"the client saw the serial terminal's menu:\n{out}")
        # A script: it takes the keyboard (Ctrl-T), keeps the callsign (Enter); its input ends, and
        # it is detached once the menus have taken its keys and answered them.
        r = subprocess.run([BIN, "attach", "--state", state], input=b"\x14\r", capture_output=True, timeout=20)
        out = r.stdout.decode(errors="replace")
        check(r.returncode == 0 and re.search(r"Latitude\s+\[deg\]", out) and "detached from trakbox" in out,
              f"the script's Enter was answered before it was detached:\n{out}")
        t.expect(r"Latitude\s+\[deg\]")  # the serial terminal saw it too
        check(svc.poll() is None, "the service runs on")
        svc.terminate()
        _, err = svc.communicate(timeout=60)
        check(svc.returncode == 0, f"service exit {svc.returncode}: {err.decode()[-1000:]}")
        check(f"the menus on {pair.trakbox_side} too" in err.decode(), "the journal says where the menus are")
    finally:
        if fd is not None:
            os.close(fd)
        reap(procs)
        pair.close()
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
