"""Connected means answering (issue 48): every rotator and radio kind on a serial port, on a socat
pty pair whose far end is open and silent (the wrong speed, the controller off, a cable). Each kind
runs in its own trakbox, all at once, for WINDOW seconds of wall time.

Checked per kind: never "connected" in the log; the one problem said once ("no answer from ...:
check the speed, the cable, the power" for a rotator, "no answer: check the speed ..." for a radio);
at most one `link-lost` event and no `link-back`; the port reopened with backoff (the far end sees
the command again, fewer times than one poll per timeout would make). Printed: the events per
minute while silent and how often each kind asked.
"""
import os
import select
import shutil
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, SerialPair, check, reap, run_test, skip  # noqa: E402

WINDOW = 14.0

KINDS = [
    ("rotator", "hamlib:603:{pty}:9600", "the GS-232B"),
    ("rotator", "easycomm3:{pty}", "the Easycomm III rotator"),
    ("rotator", "easycomm2:{pty}", "the Easycomm II rotator"),
    ("radio", "ic9700:{pty}", "no answer: check the speed, the cable, the power"),
    ("radio", "ts2000:{pty}", "no answer: check the speed, the cable, the power"),
    ("radio", "ft847:{pty}", "no answer: check the speed, the cable, the power"),
    ("radio", "ft817:{pty}", "no answer: check the speed, the cable, the power"),
]


LOCAL = "file://" + os.path.join(SOURCE, "data", "amateur.tle")


class Silent:
    """The far end of a pty that reads everything and answers nothing; counts the bytes."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        self.bytes, self.chunks, self.stop = 0, 0, False
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        while not self.stop:
            r, _, _ = select.select([self.fd], [], [], 0.05)
            if r:
                try:
                    n = len(os.read(self.fd, 512))
                except OSError:
                    return
                self.bytes += n
                self.chunks += 1

    def close(self):
        self.stop = True
        self.thread.join(2)
        os.close(self.fd)


def main():
    if not shutil.which("socat"):
        skip("socat")
    runs = []
    procs = []
    try:
        for what, spec, said in KINDS:
            pair = SerialPair()
            far = Silent(pair.terminal_side)
            state = tempfile.mkdtemp(prefix="trakbox-silent-")
            opt = "--rotator" if what == "rotator" else "--radio"
            tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--elements-url", LOCAL, opt,
                                   spec.format(pty=pair.trakbox_side)],
                                  stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            procs.append(tb)
            runs.append((what, spec, said, pair, far, state, tb))
        time.sleep(WINDOW)
        report = []
        for what, spec, said, pair, far, state, tb in runs:
            tb.stdin.close()
            check(tb.wait(30) == 0, f"{spec}: trakbox leaves cleanly")
            with open(os.path.join(state, "trakbox.log")) as f:
                log = f.read()
            name = spec.split(":")[0]
            lines = [line for line in log.splitlines() if f"{what} " in line or f"{what}:" in line]
            connected = [line for line in lines if line.endswith(": connected") or "connected to" in line
                         or line.endswith("reconnected")]
            check(not connected, f"{name}: never connected to a silent port: {connected[:2]}")
            told = [line for line in lines if said in line and "no answer" in line and "rotator fault:" not in line]
            check(len(told) == 1, f"{name}: the problem said once ({len(told)}): " + "\n".join(lines))
            lost, back = log.count("event: link-lost"), log.count("event: link-back")
            check(lost <= 1 and back == 0, f"{name}: {lost} link-lost, {back} link-back events while silent")
            check(far.chunks >= 2, f"{name}: asked again ({far.chunks} writes)")
            report.append(f"{name} {lost} link-lost / {back} link-back, {far.chunks} writes in {WINDOW:.0f} s")
        print("silent_links: " + "; ".join(report))
    finally:
        reap(procs)
        for _, _, _, pair, far, state, _ in runs:
            far.close()
            pair.close()
            shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
