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
# Walking the manual's transcripts: the state document, test data in the manual's upload formats,
# and the full-screen front end in tmux. One walkthrough is written once against the small `UI`
# interface below and run on both front ends (LineUI over a serial line, ScreenUI in tmux).

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


class LineUI:
    """A walkthrough's view of the serial line: keys out, the transcript in.

    prompt(rx) waits for the next prompt and returns the transcript from the previous prompt on
    (that prompt, the answer echoed, what followed, and this prompt), with CR LF read as LF."""

    full_screen = False

    def __init__(self, terminal):
        self.t = terminal
        self._last = 0

    def send(self, keys, pace=0.0):
        self.t.send(keys, pace)

    def prompt(self, rx, timeout=10.0):
        m = self.t.expect(rx, timeout)
        out = self.t.transcript[self._last:m.end()].replace("\r\n", "\n")
        self._last = m.start()
        return out

    def wait(self, rx, timeout=10.0, after=None):
        """A live display: the transcript up to the next text matching rx (`after` is for screens:
        a stream has nothing old to skip)."""
        return self.prompt(rx, timeout)

    def upload(self, text, eof=True, timeout=10.0):
        """An ASCII upload a line at a time, as the manual asks of a terminal program; each line
        must come back echoed before the next is sent. Then Ctrl-Z."""
        for ln in text.splitlines():
            self.t.send(ln + "\r")
            self.t.expect(re.escape(ln) + r"\r\n", timeout)
        if eof:
            self.t.send("\x1a")


class ScreenUI:
    """A walkthrough's view of the full-screen front end in tmux (its own tmux server on a socket in
    a temporary folder, so parallel tests never share sessions): keys with send-keys, the screen
    with capture-pane.

    prompt(rx) waits until the screen has changed since the last keys and the text left of the
    cursor matches rx (the prompt trakbox waits at); it returns the whole screen."""

    full_screen = True

    def __init__(self, argv, cols=100, rows=40, env=None):
        self.socket_dir = tempfile.mkdtemp(prefix="trakbox-tmux-")
        self.socket = os.path.join(self.socket_dir, "tmux")
        self.session = "walk"
        self.rows = rows
        envs = " ".join(f"{k}={_shq(v)}" for k, v in (env or {}).items())
        cmd = (f"env TERM=xterm {envs} " + " ".join(_shq(a) for a in argv) +
               "; echo EXITED $?; sleep 120")
        r = self._tmux("new-session", "-d", "-s", self.session, "-x", str(cols), "-y", str(rows), "sh", "-c", cmd)
        check(r.returncode == 0, f"tmux new-session: {r.stderr}")
        self._before = None

    def _tmux(self, *args):
        return subprocess.run(["tmux", "-S", self.socket, "-f", "/dev/null", *args], capture_output=True,
                              text=True, timeout=10)

    def snapshot(self):
        """(screen text, cursor x, cursor y) read in one tmux command."""
        r = self._tmux("capture-pane", "-p", "-t", self.session, ";", "display-message", "-p", "-t",
                       self.session, "#{cursor_x},#{cursor_y}")
        text, _, cursor = r.stdout.rstrip("\n").rpartition("\n")
        try:
            x, y = (int(v) for v in cursor.split(","))
        except ValueError:
            x, y = 0, 0
        return text, x, y

    def screen(self):
        return self.snapshot()[0]

    def _text_area(self, snap):
        """The snapshot without the status line (the bottom row, which changes every second)."""
        text, x, y = snap
        return "\n".join(text.split("\n")[:self.rows - 1]), x, y

    def send(self, keys, pace=0.0):
        """Keys as the line front end takes them: '\\r' is Enter, '\\x1a' Ctrl-Z, '\\x03' Ctrl-C."""
        self._before = self._text_area(self.snapshot())
        chunk = ""
        for c in keys:
            special = {"\r": "Enter", "\x1a": "C-z", "\x03": "C-c", "\x7f": "BSpace"}.get(c)
            if special:
                if chunk:
                    self._tmux("send-keys", "-t", self.session, "-l", "--", chunk)
                    chunk = ""
                self._tmux("send-keys", "-t", self.session, special)
            else:
                chunk += c
        if chunk:
            self._tmux("send-keys", "-t", self.session, "-l", "--", chunk)
        if pace:
            time.sleep(pace * len(keys))

    def prompt(self, rx, timeout=10.0):
        """Waits until trakbox waits at rx: the text area changed since the last keys, the text left
        of the cursor (or the line above, when the cursor starts a line) matches rx, and the screen
        holds still for a moment (not half-way through printing)."""
        deadline = time.time() + timeout
        pattern = re.compile(rx + r"\s*$")
        last, seen = None, 0.0
        while True:
            snap = self.snapshot()
            area = self._text_area(snap)
            text, x, y = area
            rows = text.split("\n")
            if x > 0 or y == 0:
                at_cursor = rows[y].ljust(x)[:x] if y < len(rows) else ""  # the blanks it typed too
            else:
                at_cursor = rows[y - 1] if y - 1 < len(rows) else ""
            if area != self._before and pattern.search(at_cursor):
                if area != last:
                    last, seen = area, time.time()
                elif time.time() - seen >= 0.06:
                    self._before = area
                    return snap[0]
            else:
                last = None
            if time.time() > deadline:
                raise Failure(f"screen never waited at {rx!r}; cursor at ({x},{y}) after {at_cursor!r}; "
                              f"it shows:\n{snap[0]}")
            time.sleep(0.02)

    def wait(self, rx, timeout=10.0, after=None):
        """Waits until rx matches on the screen (a live display), below the last line containing
        `after` when given (what is above it is older); returns the screen."""
        return self.wait_match(rx, timeout, after).string

    def wait_match(self, rx, timeout=10.0, after=None):
        deadline = time.time() + timeout
        while True:
            text = self.screen()
            start = text.rfind(after) if after else 0
            m = re.compile(rx, re.M).search(text, max(start, 0)) if start >= 0 else None
            if m:
                return m
            if time.time() > deadline:
                raise Failure(f"screen never showed {rx!r}; it shows:\n{text}")
            time.sleep(0.03)

    def upload(self, text, eof=True, timeout=10.0):
        """The upload a line at a time (a terminal program's ASCII send), then Ctrl-Z."""
        for ln in text.splitlines():
            self.send(ln + "\r")
            self.wait(re.escape(ln), timeout)
        if eof:
            self.send("\x1a")

    def terminal_modes(self):
        """tmux's view of the terminal's modes: {'alternate_on': '0'|'1', 'cursor_flag': ..., ...}."""
        keys = ("alternate_on", "cursor_flag", "insert_flag", "keypad_cursor_flag", "keypad_flag")
        r = self._tmux("display-message", "-p", "-t", self.session, ",".join("#{%s}" % k for k in keys))
        return dict(zip(keys, r.stdout.strip().split(",")))

    def exited(self, timeout=15.0):
        """The exit status once trakbox has left (the session's shell prints it)."""
        m = self.wait_match(r"EXITED (\d+)", timeout)
        return int(m.group(1))

    def close(self):
        """Ends trakbox if it still runs (Ctrl-C: it saves first), then the tmux server."""
        try:
            if "EXITED" not in self.screen():
                self._tmux("send-keys", "-t", self.session, "C-c")
                self.exited(timeout=10)
        except (Failure, subprocess.TimeoutExpired):
            pass
        finally:
            self._tmux("kill-server")
            shutil.rmtree(self.socket_dir, ignore_errors=True)


def _shq(s):
    import shlex
    return shlex.quote(str(s))


class SerialSession:
    """trakbox --tty on one end of a socat pty pair at 9600 bps, a LineUI on the other."""

    def __init__(self, extra=(), state_dir=None, clock=CLOCK, baud=9600):
        self.pair = SerialPair()
        self.fd = None
        self.tb = None
        try:
            self.tb = Trakbox(["--tty", self.pair.trakbox_side, "--baud", str(baud), "--clock", clock, *extra],
                              state_dir=state_dir)
            self.fd = os.open(self.pair.terminal_side, os.O_RDWR | os.O_NOCTTY)
            self.term = Terminal(self.fd)
            self.ui = LineUI(self.term)
        except BaseException:
            self.close()
            raise

    @property
    def state_file(self):
        return self.tb.state_file

    def stop(self):
        """SIGTERM: trakbox saves and leaves; returns its exit status."""
        return self.tb.stop()

    def close(self):
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None
        if self.tb:
            self.tb.cleanup()
        self.pair.close()


class ScreenSession:
    """trakbox full screen in a 100x40 tmux pane (its own tmux server), a ScreenUI on it."""

    def __init__(self, extra=(), state_dir=None, clock=CLOCK, cols=100, rows=40):
        self.own_state = state_dir is None
        self.state_dir = state_dir or tempfile.mkdtemp(prefix="trakbox-walk-")
        argv = [BIN, "--state", self.state_dir, "--clock", clock, "--satrak-port", "0", *extra]
        self.ui = ScreenUI(argv, cols, rows)

    @property
    def state_file(self):
        return os.path.join(self.state_dir, "trakbox-state.json")

    def stop(self):
        """Ctrl-C, the full screen's way out: trakbox saves and leaves; returns its exit status."""
        self.ui.send("\x03")
        return self.ui.exited()

    def close(self):
        self.ui.close()
        if self.own_state:
            shutil.rmtree(self.state_dir, ignore_errors=True)


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
