"""Helpers for driving the real trakbox binary as an operator or a peer would.

Standard library only. Every wait is bounded; every process started is cleaned up.
"""
import os
import re
import select
import shutil
import signal
import subprocess
import tempfile
import termios
import time
import tty

BIN = os.environ.get("TRAKBOX_BIN", "build/trakbox")
SOURCE = os.environ.get("TRAKBOX_SOURCE_DIR", os.getcwd())

# A fixed clock so that what the screen shows does not depend on the wall clock.
CLOCK = "2026-05-21T12:08:30Z"


class Failure(Exception):
    pass


def check(cond, message):
    if not cond:
        raise Failure(message)


class SerialPair:
    """Two connected pseudo-terminals from socat: one for trakbox, one for the 'terminal'."""

    def __init__(self):
        self.proc = subprocess.Popen(
            ["socat", "-d", "-d", "pty,raw,echo=0", "pty,raw,echo=0"],
            stderr=subprocess.PIPE, text=True)
        names = []
        deadline = time.time() + 10
        while len(names) < 2 and time.time() < deadline:
            line = self.proc.stderr.readline()
            m = re.search(r"PTY is (\S+)", line)
            if m:
                names.append(m.group(1))
        check(len(names) == 2, "socat did not announce two ptys")
        self.trakbox_side, self.terminal_side = names

    def close(self):
        self.proc.terminate()
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:
            self.proc.kill()


class Terminal:
    """The operator's side of a serial line (or a pipe): send keys, expect text."""

    def __init__(self, fd, baud=termios.B9600):
        self.fd = fd
        if os.isatty(fd):
            tty.setraw(fd)
            attrs = termios.tcgetattr(fd)
            attrs[4] = attrs[5] = baud
            termios.tcsetattr(fd, termios.TCSANOW, attrs)
        self.transcript = ""

    def send(self, text, pace=0.0):
        data = text.encode("latin-1")
        if pace:
            for b in data:
                os.write(self.fd, bytes([b]))
                time.sleep(pace)
        else:
            os.write(self.fd, data)

    def read_some(self, timeout):
        r, _, _ = select.select([self.fd], [], [], timeout)
        if not r:
            return ""
        try:
            data = os.read(self.fd, 4096)
        except OSError:
            return ""
        text = data.decode("latin-1")
        self.transcript += text
        return text

    def expect(self, pattern, timeout=10.0):
        """Waits until the transcript (since the last expect) matches; returns the match."""
        deadline = time.time() + timeout
        start = getattr(self, "_mark", 0)
        rx = re.compile(pattern)
        while True:
            m = rx.search(self.transcript, start)
            if m:
                self._mark = m.end()
                return m
            left = deadline - time.time()
            if left <= 0:
                tail = self.transcript[start:][-1500:]
                raise Failure(f"timed out waiting for {pattern!r}; last output:\n{tail}")
            self.read_some(min(left, 0.2))

    def drain(self, seconds):
        end = time.time() + seconds
        while time.time() < end:
            self.read_some(0.05)


class Trakbox:
    """A trakbox process with its own state directory."""

    def __init__(self, args, state_dir=None, stdin=None, stdout=None):
        self.own_state = state_dir is None
        self.state_dir = state_dir or tempfile.mkdtemp(prefix="trakbox-it-")
        env = dict(os.environ)
        env.pop("TERM", None) if stdin is not None else None
        # The Satrak server is off unless a test asks for it: tests run in parallel and would race
        # for its default port.
        if not any(a.startswith("--satrak-port") for a in args):
            args = ["--satrak-port", "0"] + list(args)
        self.proc = subprocess.Popen([BIN, "--state", self.state_dir] + list(args), stdin=stdin, stdout=stdout,
                                     stderr=subprocess.PIPE, env=env)

    @property
    def state_file(self):
        return os.path.join(self.state_dir, "trakbox-state.json")

    def stop(self, timeout=10):
        """SIGTERM: trakbox saves and leaves."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise Failure("trakbox did not stop on SIGTERM")

    def cleanup(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        if self.own_state:
            shutil.rmtree(self.state_dir, ignore_errors=True)


def free_port():
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def sh(*args, timeout=20):
    """Runs a command; (exit status, stdout, stderr)."""
    p = subprocess.run(list(args), capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def reap(procs):
    """Kills and waits for every process still running (a test's finally)."""
    for p in procs:
        if p.poll() is None:
            p.kill()
            p.wait()


def pointing_error(az1, el1, az2, el2):
    """Angle between two antenna pointing directions, degrees (elevations over 90 allowed)."""
    import math
    a1, e1, a2, e2 = map(math.radians, (az1, el1, az2, el2))
    c = math.sin(e1) * math.sin(e2) + math.cos(e1) * math.cos(e2) * math.cos(a1 - a2)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def satellite_track(at, seconds, sat="ISS", station="27.391,128.657,50", freq=None):
    """Where a shipped satellite is, one row a second from `at` (a datetime), from trakbox's own
    schedule command (the engine is compared with Skyfield elsewhere): dicts with az_deg, el_deg,
    doppler_hz (with freq), ..."""
    import json
    args = [BIN, "schedule", os.path.join(SOURCE, "data", "amateur.tle"), "--sat", sat, "--station", station,
            "--start", at.strftime("%Y-%m-%dT%H:%M:%S.%fZ"), "--step", "1", "--count", str(seconds), "--json"]
    if freq:
        args += ["--freq", str(freq)]
    code, out, err = sh(*args)
    check(code == 0, f"schedule: {err}")
    return json.loads(out)


def run_test(main):
    """Runs main() and prints one result line; exit status 0 on success."""
    name = os.path.basename(main.__code__.co_filename)
    try:
        main()
    except Failure as e:
        print(f"{name}: FAILED: {e}")
        raise SystemExit(1)
    print(f"{name}: passed")
