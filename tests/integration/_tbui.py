"""The operator's two views of trakbox's menus for the walkthroughs and the front-end tests: the
serial line (LineUI, on a SerialSession: trakbox --tty on a socat pty pair) and the full screen in
tmux (ScreenUI, on a ScreenSession). Standard library only; every wait is bounded.
"""
import os
import re
import shutil
import subprocess
import tempfile
import time

from _tbharness import BIN, CLOCK, Failure, SerialPair, Terminal, Trakbox, check


class TmuxPane:
    """One tmux session's pane as the tests drive it by hand: keys with send-keys, the screen read
    with capture-pane, a pattern waited for (ScreenUI is the menus' own driver over the same)."""

    def __init__(self, session):
        self.session = session

    def tmux(self, *args):
        return subprocess.run(["tmux", *args], capture_output=True, text=True, timeout=10)

    def screen(self):
        return self.tmux("capture-pane", "-t", self.session, "-p").stdout

    def wait_for(self, pattern, timeout=10.0):
        deadline = time.time() + timeout
        while True:
            s = self.screen()
            if re.search(pattern, s):
                return s
            if time.time() > deadline:
                raise Failure(f"screen never showed {pattern!r}; it shows:\n{s}")
            time.sleep(0.2)

    def keys(self, *k):
        self.tmux("send-keys", "-t", self.session, *k)

    def start(self, command, cols=100, rows=34):
        """A new session (an old one of the same name ended first) running `command` under sh, with
        its exit status printed and the pane kept for a minute so the screen can still be read."""
        self.tmux("kill-session", "-t", self.session)
        r = self.tmux("new-session", "-d", "-s", self.session, "-x", str(cols), "-y", str(rows), "env", "TERM=xterm",
                      "sh", "-c", f"{command}; echo EXITED $?; sleep 60")
        check(r.returncode == 0, f"tmux: {r.stderr}")


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

    def leave(self):
        """Q at the main menu, Y to "leave trakbox? [Y/N]": trakbox exits with 0."""
        self.send("Q")
        self.prompt(r"leave trakbox\? \[Y/N\]")
        self.send("Y")
        check(self.exited() == 0, "Q, Y leaves trakbox with 0")

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
