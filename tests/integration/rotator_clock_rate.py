"""The simulated rotator follows simulated time at an accelerated clock (issue 21, item 2).

trakbox runs with `--clock` and `--clock-rate 100`, its simulated rotator and the Satrak server on a
free loopback port. A GOTO 120 degrees of azimuth away must take about 20 seconds of SIMULATED time
(6 deg/s, the model's rate), about 0.2 s of wall time. The time is judged against the clock the
unit itself reports (Satrak TIME?, read before and after every STATUS?), never against wall time,
so a loaded machine widens the bounds but cannot fail the test:

  lower bound = last sample still short of the goal (its TIME? before STATUS?) - TIME? after GOTO
  upper bound = first sample at the goal (its TIME? after STATUS?)          - TIME? before GOTO

Before the fix the controller ticked every 100 ms of wall time and capped a drive pulse at 2.5 s of
simulated time: at 100x the slew took 80 simulated seconds (1.5 deg/s).

Also: a --clock-rate above the stated maximum (200) is refused with a message saying so.
"""
import datetime
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SOURCE, Failure, Satrak, check, free_port, reap, run_test, sh  # noqa: E402

RATE = 100
SLEW_DEG = 120.0
MODEL_S = SLEW_DEG / 6.0  # the simulated rotator's 6 deg/s
TOLERANCE_S = 1.5         # spin-up and coast (0.15 s), the dead band (1 deg), the tick (0.5 s at 100x)


class Client(Satrak):
    """The harness's Satrak client (its own frames and checksums), with TCP_NODELAY: the test times
    each exchange, so no request may wait for Nagle."""

    def __init__(self, port):
        super().__init__(port)
        self.s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def fields(self, payload):
        return self.ask(payload).split(",")[1:]

    def sim_time(self):
        """The unit's clock (TIME?: hour, minute, second, day, month, year, ms) as a datetime."""
        f = self.fields("TIME?")
        check(len(f) == 7, f"TIME? has 7 fields: {f}")
        h, mi, s, d, mo, y, ms = map(int, f)
        return datetime.datetime(y, mo, d, h, mi, s, ms * 1000)

    def status(self):
        """(az, el, moving az) from STATUS?."""
        f = self.fields("STATUS?")
        check(len(f) == 16, f"STATUS? has 16 fields: {f}")
        return float(f[1]), float(f[2]), int(f[11])

    def goto(self, az, el):
        f = self.fields(f"GOTO=,{az},{el}")
        check(f == ["OK"], f"GOTO=,{az},{el} -> {f}")


def az_diff(a, b):
    return (a - b + 180.0) % 360.0 - 180.0


def settle(c, az, limit_wall=20.0):
    """Waits (bounded) until the antenna rests within a degree of az."""
    end = time.time() + limit_wall
    while time.time() < end:
        a, _, moving = c.status()
        if moving == 0 and abs(az_diff(a, az)) <= 1.1:
            return
        time.sleep(0.01)
    raise Failure(f"the antenna never settled at {az}")


def slew(c, start, goal):
    """Simulated seconds (lower, upper bound) and wall seconds of a GOTO from start to goal."""
    settle(c, start)
    t_before = c.sim_time()
    wall0 = time.monotonic()
    c.goto(goal, 0)
    t_after = c.sim_time()
    last_short = t_after
    end = time.time() + 30
    while time.time() < end:
        ta = c.sim_time()
        az, _, _ = c.status()
        tb = c.sim_time()
        if abs(az_diff(az, goal)) <= 1.1:
            wall = time.monotonic() - wall0
            return (last_short - t_after).total_seconds(), (tb - t_before).total_seconds(), wall
        last_short = ta
    raise Failure(f"GOTO {goal} not reached in 30 s of wall time")


def main():
    # The maximum rate is stated and enforced.
    code, _, err = sh(BIN, "--clock-rate", "201", "--line")
    check(code != 0, "--clock-rate 201 is refused")
    check("--clock-rate: expected a rate > 0 and at most 200" in err, f"--clock-rate 201: {err!r}")

    state = tempfile.mkdtemp(prefix="trakbox-rate-")
    os.makedirs(os.path.join(state, "tle"))
    shutil.copy(os.path.join(SOURCE, "data", "amateur.tle"), os.path.join(state, "tle", "amateur.txt"))
    port = free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--clock-rate", str(RATE), "--line",
                          "--satrak-port", str(port)],
                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    c = None
    try:
        c = Client(port)  # waits up to 15 s for the server
        c.goto(10, 0)
        for start, goal in ((10, 10 + SLEW_DEG), (10 + SLEW_DEG, 10)):
            lo, hi, wall = slew(c, start, goal)
            print(f"  GOTO {start} -> {goal} at {RATE}x: {lo:.2f}..{hi:.2f} simulated s "
                  f"(model {MODEL_S:.1f} s), {wall:.3f} s wall")
            check(lo <= MODEL_S + TOLERANCE_S, f"the slew took at least {lo:.2f} simulated s (model {MODEL_S} s)")
            check(hi >= MODEL_S - TOLERANCE_S, f"the slew took at most {hi:.2f} simulated s (model {MODEL_S} s)")
        print("rotator_clock_rate: ok")
    finally:
        if c:
            c.close()
        reap([p])
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
