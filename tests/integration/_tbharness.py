"""Helpers for driving the real trakbox binary as an operator or a peer would.

Standard library only. Every wait is bounded; every process started is cleaned up.
"""
import os
import re
import select
import shutil
import signal
import socket
import subprocess
import tempfile
import termios
import threading
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


SKIP = 77  # CTest's SKIP_RETURN_CODE for tests/integration (tests/CMakeLists.txt)


def in_ci():
    """CI set to anything but "", "0" or "false": every tool is installed (scripts/install-deps.sh)."""
    return os.environ.get("CI", "") not in ("", "0", "false")


def skip(message):
    """Ends the test as skipped (a tool it needs is missing), saying why; in CI, where every tool
    is installed, a missing tool fails the test instead (a skip there would hide a broken set-up)."""
    if in_ci():
        print(f"FAILED (CI={os.environ['CI']}: every tool must be installed): {message}")
        raise SystemExit(1)
    print(f"SKIPPED: {message}")
    raise SystemExit(SKIP)


def need(*tools):
    """skip() unless every one of `tools` is on PATH (the message names those missing)."""
    missing = [t for t in tools if not shutil.which(t)]
    if missing:
        skip(" and ".join(missing) + " not installed")


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


def poll(what, pred, seconds, every=0.2):
    """pred() until it returns something true (returned), or fail after `seconds`."""
    deadline = time.time() + seconds
    while time.time() < deadline:
        v = pred()
        if v:
            return v
        time.sleep(every)
    check(False, f"timed out waiting for {what}")


class OutputLines(threading.Thread):
    """A process's standard output (text), line by line as it comes, in `lines`."""

    def __init__(self, proc):
        super().__init__(daemon=True)
        self.proc, self.lines = proc, []
        self.start()

    def run(self):
        for line in self.proc.stdout:
            self.lines.append(line)


def free_port():
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_listening(port, what, within=10, proc=None):
    """Returns once 127.0.0.1:port accepts a connection; fails if `proc` exits first or the time
    runs out (a fixed sleep after starting a server is what fails on a loaded machine)."""
    import socket
    deadline = time.time() + within
    while True:
        if proc is not None and proc.poll() is not None:
            raise Failure(f"{what} exited with {proc.returncode} before listening on port {port}")
        try:
            socket.create_connection(("127.0.0.1", port), timeout=1).close()
            return
        except OSError:
            if time.time() > deadline:
                raise Failure(f"{what} did not listen on port {port} within {within} s")
            time.sleep(0.05)


def hamlib_dummy(daemon, port, within=10):
    """Starts Hamlib's dummy rotator ("rotctld") or radio ("rigctld") on a loopback port and returns
    the process once the port accepts connections."""
    proc = subprocess.Popen([daemon, "-m", "1", "-T", "127.0.0.1", "-t", str(port)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        wait_listening(port, daemon, within, proc)
    except Failure:
        proc.kill()
        proc.wait()
        raise
    return proc


def sh(*args, timeout=20):
    """Runs a command; (exit status, stdout, stderr)."""
    p = subprocess.run(list(args), capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def read_log(state):
    """The trakbox.log of the state directory `state`."""
    with open(os.path.join(state, "trakbox.log")) as f:
        return f.read()


def stop_and_read_log(proc, state):
    """Ends a trakbox started on `state` (SIGTERM, as a service stop) and returns its trakbox.log."""
    proc.terminate()
    proc.wait(20)
    return read_log(state)


def leave_and_read_log(proc, state, procs=None):
    """Ends a trakbox running plain lines on a pipe as its operator would (the end of its input),
    checks that it left with 0, takes it off `procs` and returns its trakbox.log."""
    proc.stdin.close()
    check(proc.wait(20) == 0, "trakbox leaves cleanly")
    if procs is not None:
        procs.remove(proc)
    return read_log(state)


def start_line_trakbox(state, start, *args):
    """trakbox on the serial-line front end (its stdin a pipe, stdout discarded, stderr kept) with
    the state directory `state`, the clock starting at `start` (a datetime), the Satrak port
    off, and `args` (drivers, ports)."""
    clock = start.strftime("%Y-%m-%dT%H:%M:%SZ")
    return subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock", clock, *args],
                            stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


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


def run_test(main, name=None):
    """Runs main() and prints one result line (named after main's file unless `name` is given);
    exit status 0 on success."""
    name = name or os.path.basename(main.__code__.co_filename)
    try:
        main()
    except Failure as e:
        print(f"{name}: FAILED: {e}")
        raise SystemExit(1)
    print(f"{name}: passed")


# ---------------------------------------------------------------------------------------------
# Walking the manual's transcripts: the state document and test data in the manual's upload
# formats. One walkthrough is written once against the small `UI` interface of _tbui.py and run on
# both front ends (LineUI over a serial line, ScreenUI in tmux).

def load_state(path):
    """The model part ("data") of a trakbox state document."""
    import json
    with open(path) as f:
        doc = json.load(f)
    check(doc.get("format") == "trakbox-state", f"{path}: not a trakbox state document")
    return doc["data"]


def read_tle(path):
    """[(name, line1, line2)] of a three-line NASA file."""
    lines = [ln.rstrip() for ln in open(path) if ln.strip()]
    return [(lines[i], lines[i + 1], lines[i + 2]) for i in range(0, len(lines) - 2, 3)]


def tle_to_amsat(name, l1, l2):
    """The same element set as an AMSAT verbose block, with its checksum (the sum of the digits of
    the lines from Satellite: to Epoch rev:, +1 for each '-', +2 for each '+'), written here
    independently of trakbox's own writer."""
    def col(line, a, b):
        return line[a:b].strip()
    ndot = float(col(l1, 33, 43))
    lines = [
        f"Satellite: {name}",
        f"Catalog number: {col(l1, 2, 7)}",
        f"Epoch time:      {col(l1, 18, 32)}",
        f"Element set:     {col(l1, 64, 68)}",
        f"Inclination:      {col(l2, 8, 16)} deg",
        f"RA of node:       {col(l2, 17, 25)} deg",
        f"Eccentricity:    0.{col(l2, 26, 33)}",
        f"Arg of perigee:   {col(l2, 34, 42)} deg",
        f"Mean anomaly:     {col(l2, 43, 51)} deg",
        f"Mean motion:   {col(l2, 52, 63)} rev/day",
        f"Decay rate:       {ndot:.2e} rev/day^2",
        f"Epoch rev:           {int(l2[63:68])}",
    ]
    total = sum(int(c) for ln in lines for c in ln if c.isdigit())
    total += sum(ln.count("-") + 2 * ln.count("+") for ln in lines)
    return "\n".join(lines + [f"Checksum:              {total}"]) + "\n"


def in_temp_dir(prefix, body):
    """body(folder) on a new temporary folder, removed afterwards whatever happens; body's result."""
    d = tempfile.mkdtemp(prefix=prefix)
    try:
        return body(d)
    finally:
        shutil.rmtree(d, ignore_errors=True)


def factory_state():
    """The model a first start writes (factory defaults and the shipped database): trakbox on a
    pipe whose input ends at once saves and leaves."""
    def first_start(d):
        r = subprocess.run([BIN, "--state", d, "--line", "--satrak-port", "0", "--clock", CLOCK],
                           stdin=subprocess.DEVNULL, capture_output=True, timeout=30)
        check(r.returncode == 0, f"trakbox on an empty pipe: exit {r.returncode} {r.stderr[-500:]!r}")
        return load_state(os.path.join(d, "trakbox-state.json"))
    return in_temp_dir("trakbox-factory-", first_start)


# ---------------------------------------------------------------------------------------------
# A Satrak client of the tests' own (frames and checksums computed here, not by trakbox's code).

def frame(payload):
    """$PAYLOAD*HH CR LF, HH the XOR of the payload's bytes."""
    x = 0
    for b in payload.encode():
        x ^= b
    return ("$%s*%02X\r\n" % (payload, x)).encode()


class Satrak:
    """A minimal Satrak client: one request, one checked reply."""

    def __init__(self, port, limit=15):
        deadline = time.time() + limit
        while True:
            try:
                self.s = socket.create_connection(("127.0.0.1", port), timeout=5)
                break
            except OSError:
                if time.time() > deadline:
                    raise Failure(f"no Satrak server on {port}")
                time.sleep(0.1)
        self.buf = b""

    def ask(self, payload):
        self.s.sendall(frame(payload))
        while b"\r\n" not in self.buf:
            chunk = self.s.recv(4096)
            if not chunk:
                raise Failure(f"connection closed after {payload!r}")
            self.buf += chunk
        line, self.buf = self.buf.split(b"\r\n", 1)
        text = line.decode()
        check(text.startswith("$") and text[-3] == "*", f"malformed reply {text!r}")
        body = text[1:-3]
        x = 0
        for b in body.encode():
            x ^= b
        check("%02X" % x == text[-2:].upper(), f"bad checksum in {text!r}")
        return body

    def close(self):
        self.s.close()




def read_until_closed(s, enough=None):
    """What socket `s` sends until the peer closes it, its timeout passes, it fails, or
    enough(what came) says so."""
    got = b""
    try:
        while True:
            b = s.recv(65536)
            if not b:
                break
            got += b
            if enough and enough(got):
                break
    except OSError:  # a timeout or a reset: what came is the answer
        pass
    return got


def socket_lines(s):
    """The lines socket `s` sends (bytes, without their LF), each as it comes, until the peer closes
    it or it fails (a responder's loop: `for line in socket_lines(c): ... c.sendall(reply)`)."""
    buf = b""
    try:
        while True:
            data = s.recv(4096)
            if not data:
                return
            buf += data
            while b"\n" in buf:
                line, buf = buf.split(b"\n", 1)
                yield line
    except OSError:
        return


def tcp_exchange(port, data, until, source="127.0.0.1", limit=10):
    """Connects to 127.0.0.1:port from `source` (retrying while nothing listens, up to `limit` s),
    sends `data`, and returns the bytes that came back until `until` is among them or the server
    closed the connection."""
    deadline = time.time() + limit
    while True:
        try:
            s = socket.create_connection(("127.0.0.1", port), timeout=5, source_address=(source, 0))
            break
        except OSError:
            if time.time() > deadline:
                raise
            time.sleep(0.1)
    with s:
        s.sendall(data)
        got = b""
        try:
            while until not in got:
                chunk = s.recv(4096)
                if not chunk:
                    break
                got += chunk
        except (ConnectionResetError, socket.timeout):
            pass
        return got
