"""A radio on the far end of a pseudo-terminal, for the integration tests' responders (_ic9700.py,
_ts2000.py): the raw port, the thread that reads it and hands what came in to feed() under the
lock, and the bytes counted both ways for the CAT line's load; and a pass tracked by trakbox with
such a radio (track_with). Not a test."""
import os
import select
import shutil
import subprocess
import tempfile
import termios
import threading
import time
import tty
from datetime import datetime, timedelta, timezone

from _tbharness import BIN, SerialPair, check, leave_and_read_log, poll as poll_every, reap, satellite_track

C = 299792.458
# The knob-rest delay the Tuner waits before moving the other link (issue 28b) is allowed on top of
# the 2 s the issue asks for.
KNOB_REST_S = 1.5


def poll(what, pred, seconds):
    return poll_every(what, pred, seconds, every=0.05)


def expected(clock_at, sat, down_spot, up_spot):
    """The downlink and uplink frequencies for two transponder spots at clock_at (Skyfield)."""
    row = satellite_track(clock_at, 1, sat=sat, freq=down_spot)[0]
    rr = -row["doppler_hz"] * C / down_spot
    return down_spot * (1 - rr / C), up_spot / (1 - rr / C)


# The passes the tests track: when trakbox's clock starts and the satellite's number in the shipped
# tracking list. RS-44 from a minute before its culmination, SO-50 near its culmination.
RS44_PASS = (datetime(2026, 5, 21, 10, 57, 0, tzinfo=timezone.utc), b"12")
SO50_PASS = (datetime(2026, 5, 21, 14, 10, 0, tzinfo=timezone.utc), b"5")

# The transponder spots the tests tune: (downlink, uplink) in Hz.
SPOTS = {"RS-44": (435_640_000, 145_965_000), "SO-50": (436_795_000, 145_850_000)}


def tuned(sat, get_down, get_up, where=("the downlink", "the uplink")):
    """Waits until both links are near the satellite's spots (Doppler and a first update's slack)."""
    down, up = SPOTS[sat]
    poll(f"{sat}'s downlink on {where[0]}", lambda: abs(get_down() - down) < 12_000, 30)
    poll(f"{sat}'s uplink on {where[1]}", lambda: abs(get_up() - up) < 5_000, 30)


def on_doppler(sat, get_down, get_up, clock_now, within):
    """Both links on the satellite's spots as its Doppler is now, within `within` Hz. Returns them."""
    e_down, e_up = expected(clock_now(), sat, *SPOTS[sat])
    d, u = get_down(), get_up()
    check(abs(d - e_down) < within and abs(u - e_up) < within, f"{sat} Doppler: downlink {d} ({e_down:.0f}), uplink {u} ({e_up:.0f})")
    return d, u


def listen(rig, seconds):
    """Lets the pass run `seconds`; returns its start, its end and the bytes per second on the line."""
    t1 = time.time()
    time.sleep(seconds)
    t2 = time.time()
    return t1, t2, rig.line_bytes(t1, t2) / (t2 - t1)


def rs44_knob_turn(get_down, get_up, turn_down, clock_now):
    """The operator turns the downlink dial of RS-44 (435.640 MHz down, 145.965 MHz up, inverting)
    up 10 kHz with turn_down(hz): the uplink must move down 10 kHz within 2 s plus the knob rest,
    and both then sit on the new pair's Doppler. Returns what happened, for the test's report."""
    d1, u1 = get_down(), get_up()
    # CAT has no compare-and-set: a turn between trakbox's read of the dial and its write right
    # after is overwritten, on a radio as here; the operator turns again, and so does this (twice
    # at most, said when it happens).
    for _ in range(3):
        turn_down(10_000)
        turned_at = time.time()
        time.sleep(0.3)
        if abs(get_down() - (d1 + 10_000)) < 400:
            break
        print(f"the turn fell between a read and a write of trakbox's (the dial shows {get_down()}); turned again")
        d1 = get_down()
    poll("the uplink to move down 10 kHz", lambda: abs(get_up() - (u1 - 10_000)) < 300, 2 + KNOB_REST_S + 3)
    moved_after = time.time() - turned_at
    check(moved_after <= 2 + KNOB_REST_S, f"uplink moved {moved_after:.2f} s after the turn")
    time.sleep(2)
    e_down, e_up = expected(clock_now(), "RS-44", 435_650_000, 145_955_000)
    d2, u2 = get_down(), get_up()
    check(abs(d2 - e_down) < 400, f"downlink kept on the new spot: {d2}, expected {e_down:.0f}")
    check(abs(u2 - e_up) < 400, f"uplink on the paired spot: {u2}, expected {e_up:.0f}")
    return (f"downlink {d1} -> {d1 + 10_000} (knob) -> {d2}; uplink {u1} -> {u2}, moved {moved_after:.2f} s "
            f"after the turn ({moved_after - 1.0:+.2f} s after the 1.0 s rest)")


def so50_doppler_goes_on(get_down, get_up, clock_now):
    """After SO-50's tone was refused the Doppler goes on: the downlink moves and both links sit on
    SO-50's Doppler (436.795 MHz down, 145.850 MHz up). Returns the first downlink and the last pair."""
    first_down = get_down()
    poll("Doppler updates after the refused tone", lambda: abs(get_down() - first_down) >= 100, 20)
    return (first_down, *on_doppler("SO-50", get_down, get_up, clock_now, 1000))


def so50_on_fm(get_down, get_up, where, modes, clock_now):
    """SO-50 on a pair of links: both on its spots, FM on both (modes() gives the two links' mode
    bytes, downlink first), and the Doppler goes on. Returns what so50_doppler_goes_on does."""
    tuned("SO-50", get_down, get_up, where)
    check(modes() == (0x08, 0x08), f"FM on {where[0]} and {where[1]}: {modes()}")
    return so50_doppler_goes_on(get_down, get_up, clock_now)


def leave(tb, state):
    """trakbox's input ends: it must leave cleanly. Returns its log."""
    return leave_and_read_log(tb, state)


def on_pass(which, make_rig, model, test, uplink_model=None):
    """track_with for one of the passes above (RS44_PASS, SO50_PASS)."""
    track_with(make_rig, model, which[0], which[1], test, uplink_model)


def track_with(make_rig, model, start_at, sat_key, test, uplink_model=None):
    """trakbox tracking one entry of the shipped list (single tracking, from start_at, --clock) with
    `--radio MODEL:PTY` and make_rig(path) on the other end: test(rig, trakbox, state_dir, clock_now).
    With uplink_model, a second radio carries the uplink (`--uplink-radio MODEL:PTY2`, make_rig on
    its pty too) and test gets the pair (downlink rig, uplink rig)."""
    pairs = [SerialPair() for _ in range(2 if uplink_model else 1)]
    state = tempfile.mkdtemp(prefix=f"trakbox-{model}-")
    procs = []
    rigs = [make_rig(p.terminal_side) for p in pairs]
    try:
        t0 = time.time()
        args = ["--radio", f"{model}:{pairs[0].trakbox_side}"]
        if uplink_model:
            args += ["--uplink-radio", f"{uplink_model}:{pairs[1].trakbox_side}"]
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0",
                               "--clock", start_at.strftime("%Y-%m-%dT%H:%M:%SZ"), *args],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        tb.stdin.write(b"S\r" + sat_key + b"\r")
        tb.stdin.flush()
        test(tuple(rigs) if uplink_model else rigs[0], tb, state, lambda: start_at + timedelta(seconds=time.time() - t0))
    finally:
        reap(procs)
        for rig in rigs:
            rig.close()
        for p in pairs:
            p.close()
        shutil.rmtree(state, ignore_errors=True)


class PtyRadio:
    def __init__(self, path):
        """Call last in a subclass's __init__: the reading thread starts here."""
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)
        termios.tcflush(self.fd, termios.TCIOFLUSH)
        self.lock = threading.Lock()
        self.bytes_in = []        # (time, count) read from the controller
        self.bytes_out = []       # (time, count) written to the controller
        self.stop = False
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def feed(self, chunk):
        """What the controller sent, as it came (lock held)."""
        raise NotImplementedError

    def close(self):
        self.stop = True
        self.thread.join(2)
        os.close(self.fd)

    def write(self, b):
        os.write(self.fd, b)
        self.bytes_out.append((time.time(), len(b)))

    def run(self):
        while not self.stop:
            r, _, _ = select.select([self.fd], [], [], 0.05)
            if not r:
                continue
            try:
                chunk = os.read(self.fd, 256)
            except OSError:
                return
            with self.lock:
                self.bytes_in.append((time.time(), len(chunk)))
                self.feed(chunk)

    def line_bytes(self, since, until):
        """Bytes on the CAT line (both directions) between two times."""
        return sum(n for t, n in self.bytes_in + self.bytes_out if since <= t < until)
