"""Easycomm II and III natively (issue 48): `--rotator easycomm3:PTY` / `easycomm2:PTY` against a
controller written from the Easycomm text in Hamlib's source (rotators/easycomm/easycomm.txt) and
the SatNOGS firmware's answers, on a socat pty pair; and the bytes of set, read and stop against
Hamlib's own (`rotctl -m 204` / `-m 202` on a second pty pair, its bytes captured).

The controller: "AZ EL" answers "AZaaa.a ELeee.e\\n" where the antenna is; "AZa ELe" sets the target
(answers nothing; the antenna gets there at 10 deg/s); "SA SE" stops and answers the position (as
the SatNOGS firmware does); every byte trakbox sends is kept. It also sends an unsolicited "AL001"
alarm line once.

Checked, per version: trakbox reads the position back (status == the controller's), aims where a
rotctld client told it (`P 123.4 35.6` to trakbox's --rotctld-port), stops on `S`; the set, read and
stop lines are byte for byte those rotctl sends for the same position; the alarm is in the log once
and the link is not lost for it.
"""
import os
import re
import select
import shutil
import socket
import subprocess
import sys
import tempfile
import termios
import threading
import time
import tty

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, SerialPair, check, free_port, poll, reap, run_test, skip, wait_listening  # noqa: E402


class PtyLines:
    """The far end of a pty: lines in ("\\n"-ended, kept with their bytes), an answer function."""

    def __init__(self, path, answer):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)
        termios.tcflush(self.fd, termios.TCIOFLUSH)
        self.answer, self.lock, self.lines, self.stop = answer, threading.Lock(), [], False
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        buf = b""
        while not self.stop:
            r, _, _ = select.select([self.fd], [], [], 0.05)
            if not r:
                continue
            try:
                buf += os.read(self.fd, 256)
            except OSError:
                return
            while b"\n" in buf:
                line, buf = buf.split(b"\n", 1)
                with self.lock:
                    self.lines.append(line + b"\n")
                    reply = self.answer(line.decode(errors="replace"))
                if reply:
                    os.write(self.fd, reply.encode())

    def write(self, text):
        os.write(self.fd, text.encode())

    def seen(self):
        with self.lock:
            return list(self.lines)

    def close(self):
        self.stop = True
        self.thread.join(2)
        os.close(self.fd)


class Controller:
    """An Easycomm controller: position, target, 10 deg/s on each axis."""

    def __init__(self):
        self.az, self.el, self.target, self.at = 10.0, 5.0, None, time.time()

    def move(self):
        now = time.time()
        if self.target:
            step = 10.0 * (now - self.at)
            for axis, want in zip(("az", "el"), self.target):
                have = getattr(self, axis)
                setattr(self, axis, want if abs(want - have) <= step else have + step * (1 if want > have else -1))
        self.at = now

    def position(self):
        self.move()
        return f"AZ{self.az:.1f} EL{self.el:.1f}\n"

    def __call__(self, line):
        self.move()
        m = re.fullmatch(r"AZ(-?[\d.]+) EL(-?[\d.]+)", line.strip())
        if line.strip() == "AZ EL":
            return self.position()
        if m:
            self.target = (float(m.group(1)), float(m.group(2)))
            return ""
        if line.strip() == "SA SE":
            self.target = None
            return self.position()
        return ""


def rotctl_bytes(model, baud, *command):
    """The lines rotctl -m MODEL sends for one command, captured on a pty pair (a controller that
    answers the read)."""
    pair = SerialPair()
    far = PtyLines(pair.terminal_side, lambda line: "AZ10.0 EL5.0\n" if line.strip() == "AZ EL" else "")
    try:
        r = subprocess.run(["rotctl", "-m", str(model), "-r", pair.trakbox_side, "-s", str(baud), *command],
                           capture_output=True, text=True, timeout=20)
        check(r.returncode == 0, f"rotctl -m {model} {' '.join(command)}: {r.stderr}")
        time.sleep(0.2)
        return far.seen()
    finally:
        far.close()
        pair.close()


def rotctld_command(port, line):
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(line.encode() + b"\n")
        return s.recv(256).decode()


def status(state):
    import json
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=30)
    return json.loads(r.stdout)


def one_version(kind, model, baud):
    pair = SerialPair()
    ctl = Controller()
    far = PtyLines(pair.terminal_side, ctl)
    state = tempfile.mkdtemp(prefix=f"trakbox-{kind}-")
    procs = []
    try:
        port = free_port()
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--rotctld-port", str(port),
                               "--rotator", f"{kind}:{pair.trakbox_side}",
                               "--elements-url", "file://" + os.path.join(SOURCE, "data", "amateur.tle")],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        wait_listening(port, "rotctld", proc=tb)
        # Read back: the status shows where the controller is.
        poll("the position read back", lambda: abs(((status(state)["antenna"].get("position") or {}).get("az_deg") or -99) - 10.0) < 0.5, 15)
        check(rotctld_command(port, "P 123.4 35.6").startswith("RPRT 0"), "rotctld P accepted")
        def set_line():
            for line in far.seen():
                m = re.fullmatch(rb"AZ(\d+\.\d) EL(\d+\.\d)\n", line)
                if m and abs(float(m.group(1)) - 123.4) < 0.5 and abs(float(m.group(2)) - 35.6) < 0.5:
                    return line, m.group(1).decode(), m.group(2).decode()
            return None
        mine_set, set_az, set_el = poll("the controller told to go to 123.4 / 35.6", set_line, 15)
        poll("the antenna read back on its way", lambda: ctl.az > 20.0 and
             abs(((status(state)["antenna"].get("position") or {}).get("az_deg") or 0) - ctl.az) < 5, 10)
        far.write("AL001\n")   # an alarm, unsolicited
        time.sleep(1.0)
        check(rotctld_command(port, "S").startswith("RPRT 0"), "rotctld S accepted")
        poll("the stop sent", lambda: b"SA SE \n" in far.seen(), 10)
        mine = far.seen()
        tb.stdin.close()
        check(tb.wait(20) == 0, "trakbox leaves cleanly")
        procs.remove(tb)
        with open(os.path.join(state, "trakbox.log")) as f:
            log = f.read()
        said = len(re.findall(r"rotator: Easycomm I+ on \S+ at \d+ baud reports an alarm: AL001", log))
        check(said == 1, f"the alarm is in the log once ({said})")
        check("lost " not in log and "no answer" not in log, "the link was never lost")
        # The same three commands from Hamlib's rotctl.
        theirs_set = rotctl_bytes(model, baud, "P", set_az, set_el)
        theirs_get = rotctl_bytes(model, baud, "p")
        theirs_stop = rotctl_bytes(model, baud, "S")
        check(theirs_set == [mine_set], f"set: trakbox {mine_set!r}, rotctl P {set_az} {set_el}: {theirs_set}")
        check(theirs_get == [b"AZ EL \n"] and b"AZ EL \n" in mine, f"read: rotctl {theirs_get}")
        check(theirs_stop == [b"SA SE \n"] and b"SA SE \n" in mine, f"stop: rotctl {theirs_stop}")
        odd = sorted({l for l in mine if l not in (b"AZ EL \n", b"SA SE \n") and not re.fullmatch(rb"AZ-?\d+\.\d EL-?\d+\.\d\n", l)})
        check(not odd, f"trakbox sent only set, read and stop lines: {odd[:5]}")
        reads = sum(1 for l in mine if l == b"AZ EL \n")
        print(f"easycomm_rotators {kind}: set {theirs_set[0]!r}, read {theirs_get[0]!r}, stop {theirs_stop[0]!r} "
              f"equal to rotctl -m {model}'s; {reads} reads, alarm logged once, link never lost")
    finally:
        reap(procs)
        far.close()
        pair.close()
        shutil.rmtree(state, ignore_errors=True)


def main():
    for tool in ("socat", "rotctl"):
        if not shutil.which(tool):
            skip(tool)
    one_version("easycomm3", 204, 19200)
    one_version("easycomm2", 202, 9600)


if __name__ == "__main__":
    run_test(main)
