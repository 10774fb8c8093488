"""`trakbox next` for a person (issue 39): --watch on an 80x24 terminal redraws within 80 columns and
the terminal's rows (no wrapped line, so no stale copy left by the next redraw); elements 190 days
old are said once, not once per satellite."""
import fcntl
import os
import pty
import re
import select
import signal
import struct
import subprocess
import sys
import termios
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, run_test, sh  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
START = "2026-05-21T12:08:30Z"
ESC = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


def watch_on_a_terminal(cols, rows):
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
    p = subprocess.Popen([BIN, "next", "--elements", TLE, "--station", "27.391,128.657,50", "--start", START, "--watch"],
                         stdin=slave, stdout=slave, stderr=subprocess.DEVNULL, start_new_session=True)
    os.close(slave)
    out = b""
    try:
        deadline = time.time() + 15
        while out.count(b"\x1b[H") < 3 and time.time() < deadline:
            if select.select([master], [], [], 0.5)[0]:
                try:
                    out += os.read(master, 65536)
                except OSError:
                    break
    finally:
        os.killpg(p.pid, signal.SIGTERM)
        p.wait(10)
        os.close(master)
    return out.decode(errors="replace")


def main():
    out = watch_on_a_terminal(80, 24)
    frames = [f for f in out.split("\x1b[H") if f.strip()]
    check(len(frames) >= 2, f"--watch redraws: {len(frames)} frames")
    for frame in frames:
        lines = [ESC.sub("", ln).rstrip("\r") for ln in frame.split("\n")]
        lines = [ln for ln in lines if ln]
        check(len(lines) <= 23, f"a frame fits 24 rows: {len(lines)}")
        too_wide = [ln for ln in lines if len(ln) > 80]
        check(not too_wide, f"every line within 80 columns: {too_wide}")
        check(any(re.search(r"AOS \d\d:\d\d:\d\d az +\d+ max +-?\d+\.\d (LOS \d\d:\d\d:\d\d|LOS >10d) (UP, LOS )?in ", ln)
                  for ln in lines), f"the compact rows: {lines}")
        check("\x1b[K" in frame, "each line cleared to its end")

    # Elements 190 days old: one warning for all of them.
    code, out, err = sh(BIN, "next", "--elements", TLE, "--station", "27.391,128.657,50", "--start",
                        "2026-11-27T12:00:00Z")
    check(code in (0, 1), f"next: {code} {err}")
    warnings = [ln for ln in err.splitlines() if "warning" in ln]
    check(len(warnings) == 1, f"the age is said once: {warnings}")
    check(re.search(r"elements of \d+ satellites are \d+\.\d to \d+\.\d days old", warnings[0]), warnings[0])


if __name__ == "__main__":
    run_test(main)
