"""Satrak motion on the real program (issue 19, items 2, 3 and 7), with the exact bytes on the wire.

trakbox runs with its simulated rotator (real-time clock, so that motion is measured in wall time)
and the Satrak server on a free loopback port. Two plain TCP clients (the harness's own Satrak
client: frames and checksums computed by the test) send framed commands and check each reply's
checksum and payload exactly; STATUS? and TPOS? are polled every ~20 ms to measure what the
antenna does:

  2. STEP=,1,0 / STEP=,-1,0 / STEP=,0,1 / STEP=,0,-1 move by the step (to a count: 0.35 deg az,
     0.18 deg el), although 1 deg of azimuth is inside the 3-count dead band; so does a GOTO
     0.7 deg away.
  3. MOVE=,1,0 moves steadily (every 0.5 s window advances, about 1 deg/s, X12 = 1 throughout);
     MOVE=,1,-1 moves both axes with X12 = 1, X13 = -1; STOP= stops within the coast and the flags
     go 0 only once the antenna no longer moves (never a change after a 0); STOP= during a
     full-speed GOTO likewise.
  7. While one client tracks, MOVE/STEP/GOTO from any client are refused (ERR,8) and tracking goes
     on (X8 = 1 for both); STOP= from the other client ends it, then its GOTO is accepted.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SOURCE, Failure, Satrak, check, free_port, reap, run_test  # noqa: E402

AZ_COUNT = 360.0 / 1023  # factory span: one ADC count of azimuth, degrees
EL_COUNT = 90.0 / 511


class Client(Satrak):
    """The harness's Satrak client (its own frames and checksums), with what these checks ask of it."""

    def exact(self, payload, reply):
        """Sends `payload`; the reply's payload must be exactly `reply` (its frame checked by ask)."""
        got = self.ask(payload)
        check(got == reply, f"{payload!r} -> {got!r}, expected {reply!r}")
        return got

    def fields(self, payload):
        return self.ask(payload).split(",")[1:]

    def status(self):
        """(true az, el, X12, X13, X8) from STATUS?."""
        f = self.fields("STATUS?")
        check(len(f) == 16, f"STATUS? has 16 fields: {f}")
        return float(f[1]), float(f[2]), int(f[11]), int(f[12]), int(f[7])


# A STATUS? that took longer than this to answer says trakbox was not running for a while (a busy
# machine): its motion around that sample says nothing about the rotator's steadiness.
SLOW_REPLY = 0.1


def sample(c, seconds, rtts=None):
    """STATUS? every ~20 ms for `seconds`: a list of (t, az, el, x12, x13), t the middle of the
    exchange; each exchange's round trip goes to `rtts` when given."""
    out = []
    t0 = time.monotonic()
    while time.monotonic() - t0 < seconds:
        sent = time.monotonic()
        az, el, fx, fy, _ = c.status()
        got = time.monotonic()
        out.append(((sent + got) / 2 - t0, az, el, fx, fy))
        if rtts is not None:
            rtts.append(got - sent)
        time.sleep(0.02)
    return out


def settle(c, limit=30):
    """Waits until both flags are 0 and the position has not changed for 1 s; returns (az, el)."""
    deadline = time.time() + limit
    last, since = None, time.time()
    while time.time() < deadline:
        az, el, fx, fy, _ = c.status()
        if (az, el) != last or fx or fy:
            last, since = (az, el), time.time()
        elif time.time() - since >= 1.0:
            return az, el
        time.sleep(0.05)
    raise Failure(f"the antenna never came to rest (last {last})")


def after_stop(c, seconds=2.5):
    """Samples after a STOP=: checks that no position change follows a sample with both flags 0
    and returns (samples, seconds until the flags went 0, seconds until the last change)."""
    s = sample(c, seconds)
    zero_at = next((t for (t, _, _, fx, fy) in s if fx == 0 and fy == 0), None)
    check(zero_at is not None, f"flags still set {seconds} s after STOP=: {s[-1]}")
    last_change = 0.0
    for a, b in zip(s, s[1:]):
        if (a[1], a[2]) != (b[1], b[2]):
            last_change = b[0]
            check(not (a[3] == 0 and a[4] == 0),
                  f"the antenna moved ({a[1]},{a[2]} -> {b[1]},{b[2]}) after STATUS? said 0,0 at {a[0]:.2f} s")
    # Once 0, the flags stay 0.
    check(all(fx == 0 and fy == 0 for (t, _, _, fx, fy) in s if t >= zero_at), "flags set again after 0")
    return s, zero_at, last_change


def coast_bound(rate):
    """How far the azimuth may read on after STOP= at `rate` deg/s: the simulated motor's coast
    (rate * 0.15 s), the age of the reading STATUS? gave before the STOP= (up to one 100 ms tick)
    and a count at each end."""
    return rate * 0.15 + rate * 0.1 + 2 * AZ_COUNT


def az_diff(a, b):
    return (a - b + 540.0) % 360.0 - 180.0


def items_2_step(c):
    c.exact("GOTO=,200,10", "GOTO=,OK")
    az0, el0 = settle(c)
    check(abs(az0 - 200) <= 1.1 and abs(el0 - 10) <= 0.2, f"GOTO=,200,10 ended at {az0},{el0}")
    for payload, daz, dxl in (("STEP=,1,0", 1.0, 0.0), ("STEP=,-1,0", -1.0, 0.0),
                              ("STEP=,0,1", 0.0, 1.0), ("STEP=,0,-1", 0.0, -1.0)):
        az, el = settle(c)
        c.exact(payload, payload.split(",")[0] + ",OK")
        s = sample(c, 0.5)
        moved = any(fx or fy for (_, _, _, fx, fy) in s)
        az2, el2 = settle(c)
        print(f"  {payload}: {az:.2f},{el:.2f} -> {az2:.2f},{el2:.2f} (flags seen moving: {moved})")
        check(abs(az_diff(az2, az) - daz) <= AZ_COUNT + 0.01, f"{payload}: azimuth moved {az_diff(az2, az):.2f}")
        check(abs((el2 - el) - dxl) <= EL_COUNT + 0.01, f"{payload}: elevation moved {el2 - el:.2f}")
        check(moved, f"{payload}: STATUS? never showed the motion")
    # A GOTO 0.7 deg away (two counts, inside the dead band) moves too.
    az, el = settle(c)
    c.exact(f"GOTO=,{az + 0.7:.2f},NONE", "GOTO=,OK")
    az2, _ = settle(c)
    print(f"  GOTO=,{az + 0.7:.2f},NONE: {az:.2f} -> {az2:.2f}")
    check(abs(az_diff(az2, az) - 0.7) <= AZ_COUNT / 2 + 0.01, f"GOTO 0.7 deg away moved {az_diff(az2, az):.2f}")


def item_3_move_stop(c):
    az0, el0 = settle(c)
    c.exact("MOVE=,1,0", "MOVE=,OK")
    time.sleep(0.3)  # spin-up and the first pulses
    rtts = []
    s = sample(c, 4.0, rtts)
    flags = {(fx, fy) for (_, _, _, fx, fy) in s}
    check(flags == {(1, 0)}, f"MOVE=,1,0: flags {flags}, expected (1, 0) throughout")
    azs = [(t, az) for (t, az, _, _, _) in s]
    check(all(az_diff(b, a) >= 0 for (_, a), (_, b) in zip(azs, azs[1:])), "MOVE=,1,0 went backwards")
    rate = az_diff(azs[-1][1], azs[0][1]) / (azs[-1][0] - azs[0][0])
    # Steady: every 0.5 s window advances by 0.5 deg to within a count and a half; no pause, no
    # burst (the defect: held 0.8 s, then 1.8 deg in 0.5 s).
    # A window in which this client was not scheduled for over 0.15 s between two samples, or in
    # which trakbox took over SLOW_REPLY to answer, says nothing about the antenna (a busy machine;
    # the test suite runs beside other work): skipped, and counted.
    worst = (1e9, -1e9)
    judged = skipped = 0
    for i, (t, a) in enumerate(azs):
        j = next((k for k in range(i, len(azs)) if azs[k][0] >= t + 0.5), None)
        if j is None:
            break
        if (any(azs[k + 1][0] - azs[k][0] > 0.15 for k in range(i, j)) or
                any(rtts[k] > SLOW_REPLY for k in range(i, j + 1))):
            skipped += 1
            continue
        judged += 1
        d = az_diff(azs[j][1], a) * 0.5 / (azs[j][0] - t)
        worst = (min(worst[0], d), max(worst[1], d))
    print(f"  MOVE=,1,0: {rate:.3f} deg/s over {azs[-1][0] - azs[0][0]:.1f} s; every 0.5 s window "
          f"{worst[0]:.2f}..{worst[1]:.2f} deg ({judged} judged, {skipped} skipped: the machine was busy); "
          f"flags {sorted(flags)}")
    check(judged > 0, "every 0.5 s window was skipped: the machine was too busy to judge steadiness")
    check(abs(rate - 1.0) <= 0.15, f"MOVE=,1,0 ran at {rate:.3f} deg/s")
    check(worst[0] >= 0.5 - 1.5 * AZ_COUNT and worst[1] <= 0.5 + 1.5 * AZ_COUNT, f"MOVE=,1,0 not steady: {worst}")

    az_stop = c.status()[0]
    c.exact("STOP=", "STOP=,OK")
    s, zero_at, last_change = after_stop(c)
    coast = az_diff(s[-1][1], az_stop)
    print(f"  STOP= after MOVE=,1,0: coasted {coast:.2f} deg, last change {last_change:.2f} s, flags 0 at {zero_at:.2f} s")
    check(0 <= coast <= coast_bound(1.0), f"coasted {coast:.2f} deg after STOP= at 1 deg/s")
    check(last_change <= 0.8, f"still moving {last_change:.2f} s after STOP=")

    # Both axes: X + and Y -.
    c.exact("MOVE=,1,-1", "MOVE=,OK")
    time.sleep(0.3)
    s = sample(c, 2.0)
    flags = {(fx, fy) for (_, _, _, fx, fy) in s}
    daz, de = az_diff(s[-1][1], s[0][1]), s[-1][2] - s[0][2]
    print(f"  MOVE=,1,-1: az {daz:+.2f} el {de:+.2f} deg in {s[-1][0] - s[0][0]:.1f} s; flags {sorted(flags)}")
    check(flags == {(1, -1)}, f"MOVE=,1,-1: flags {flags}, expected (1, -1) throughout")
    check(1.4 <= daz <= 2.6 and -2.6 <= de <= -1.4, f"MOVE=,1,-1 moved az {daz:.2f} el {de:.2f} in 2 s")
    c.exact("STOP=", "STOP=,OK")
    after_stop(c)

    # STOP= during a full-speed GOTO.
    az, el = settle(c)
    c.exact(f"GOTO=,{(az + 60) % 360:.2f},NONE", "GOTO=,OK")
    time.sleep(1.5)
    az_stop, _, fx, _, _ = c.status()
    check(fx == 1, "the GOTO is under way")
    c.exact("STOP=", "STOP=,OK")
    s, zero_at, last_change = after_stop(c)
    coast = az_diff(s[-1][1], az_stop)
    print(f"  STOP= during GOTO at 6 deg/s: coasted {coast:.2f} deg, last change {last_change:.2f} s, "
          f"flags 0 at {zero_at:.2f} s")
    check(0 <= coast <= coast_bound(6.0), f"coasted {coast:.2f} deg after STOP=")
    check(last_change <= 0.8, f"still moving {last_change:.2f} s after STOP=")
    check(zero_at <= 1.0, f"flags went 0 only {zero_at:.2f} s after STOP=")


def item_7_owner(a, b, log_path):
    a.exact("SATELLITE=,amateur.txt,ISS,1,1", "SATELLITE=,OK")
    a.exact("TRACK=,1", "TRACK=,OK")
    check(a.status()[4] == 1 and b.status()[4] == 1, "X8 = 1 on both clients")
    b.exact("GOTO=,10,10", "GOTO=,ERR,8,TRACKING: STOP= FIRST")
    b.exact("MOVE=,1,0", "MOVE=,ERR,8,TRACKING: STOP= FIRST")
    b.exact("STEP=,1,0", "STEP=,ERR,8,TRACKING: STOP= FIRST")
    a.exact("GOTO=,10,10", "GOTO=,ERR,8,TRACKING: STOP= FIRST")  # the rule is the same for the client that tracks
    b.exact("MOVE=,0,0", "MOVE=,OK")      # a button release moves nothing: harmless
    check(a.status()[4] == 1 and b.status()[4] == 1, "still tracking after the refusals")
    b.exact("STOP=", "STOP=,OK")
    check(a.status()[4] == 0, "STOP= from the other client ended tracking")
    az0, el0, _, _, _ = b.status()
    goal = f"{(az0 + 5) % 360:.2f}"
    b.exact(f"GOTO=,{goal},{el0 + 2:.2f}", "GOTO=,OK")
    az, el = settle(b)
    check(abs(az_diff(az, az0 + 5)) <= 1.1 and abs(el - el0 - 2) <= 0.2, f"GOTO after STOP= ended at {az},{el}")
    with open(log_path, encoding="utf-8", errors="replace") as f:
        log = f.read()
    check(re.search(r"satrak: GOTO refused: the antenna is tracking ISS", log), "the log names the refusal")
    print("  two clients: MOVE/STEP/GOTO refused with ERR,8 while tracking; STOP= ends it; GOTO accepted after")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-motion-")
    os.makedirs(os.path.join(state, "tle"))
    shutil.copy(os.path.join(SOURCE, "data", "amateur.tle"), os.path.join(state, "tle", "amateur.txt"))
    port = free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", str(port)],
                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    clients = []
    try:
        a = Client(port)  # waits up to 15 s for the server
        clients.append(a)
        check(a.ask("VERSION?").startswith("VERSION?,TRAKBOX SATRAK CU V"), "VERSION?")
        items_2_step(a)
        item_3_move_stop(a)
        b = Client(port)
        clients.append(b)
        item_7_owner(a, b, os.path.join(state, "trakbox.log"))
        print("satrak_motion: ok")
    finally:
        for c in clients:
            c.close()
        reap([p])
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
