"""A rotctld client's pass followed on the planned way round (issue 57), on the real binary.

A simulated 450-degree North-stop rotator (rotor start north, az_travel_deg 450). A client like
satnogs-client follows HO-113's pass of 2026-05-21 03:27:11-03:41:41 at the factory station: once
a station second it reads the position (`p`) and, when the satellite has moved more than 4 degrees
from its last target, sends `P az el` (from `trakbox schedule`, the station's engine, which
orbit_vs_skyfield.py compares with Skyfield). The pass rises at azimuth 8, goes down through north
at 25 degrees of elevation (03:31:40) and sets at 200: on this rotator the way round is 368 -> 360
-> 200 in travel. Station time runs at --clock-rate 10; the client reads it from the status
document it polls.

With HO-113 in the database trakbox recognises the pass, says "following rotctld's targets on the
planned way round for HO-113 (pass to 03:42)" (log, status line, status document) and maps every
target through the pass's plan (LOS at -2 degrees, as trakbox's passes): from the antenna's
arrival at the first target (the slew there from where it was is not judged) to LOS the antenna's travel moves
at most 30 degrees between two readings and no target jumps more than 30 degrees, the pointing
error within the allowance (the client's 4-degree step, what the satellite moves in 2 s, the dead
band). The same stream with HO-113 not in the database (TRAKBOX_DATA without it) goes the nearest way:
at the crossing a target jumps ~350 degrees of travel and the antenna swings round, pointed away.
The figures of both runs are printed."""
import math
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timedelta, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, free_port, pointing_error, run_test, satellite_track, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

RATE = 10
SAT = "HO-113"
AOS = datetime(2026, 5, 21, 3, 27, 11, tzinfo=timezone.utc)
LOS = datetime(2026, 5, 21, 3, 41, 41, tzinfo=timezone.utc)
START = AOS - timedelta(seconds=10)
STEP = 4.0  # the client moves when the satellite has moved more than this (satnogs-client)
FOLLOWS = "following rotctld's targets on the planned way round for HO-113 (pass to 03:42)"
# The rotator's settings of each run; a test reusing this one (client_zenith_flip.py) changes them.
SETTINGS = [("station.rotor_start", "north"), ("rotator.az_travel_deg", "450")]
# Degrees of pointing error a plan may leave by design (over the top: 90 - the pass's maximum).
PLAN_ERROR = 0.0


def parse_time(text):
    return datetime.fromisoformat(text.replace("Z", "+00:00"))


class Sky:
    """The satellite's az/el at any station time, from one-second rows (azimuth unwrapped)."""

    def __init__(self):
        self.rows = satellite_track(START, int((LOS - START).total_seconds()) + 60, sat=SAT)

    def at(self, t):
        s = (t - START).total_seconds()
        i = max(0, min(len(self.rows) - 2, int(math.floor(s))))
        a, b = self.rows[i], self.rows[i + 1]
        f = max(0.0, min(1.0, s - i))
        d = (b["az_deg"] - a["az_deg"] + 180.0) % 360.0 - 180.0
        return (a["az_deg"] + f * d) % 360.0, a["el_deg"] + f * (b["el_deg"] - a["el_deg"])


def data_without(sat):
    """The shipped data with `sat` left out of the elements."""
    d = tempfile.mkdtemp(prefix="trakbox-data-")
    for name in os.listdir(os.path.join(SOURCE, "data")):
        shutil.copy(os.path.join(SOURCE, "data", name), d)
    lines = open(os.path.join(SOURCE, "data", "amateur.tle")).read().splitlines()
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == sat:
            i += 3
            continue
        out.append(lines[i])
        i += 1
    open(os.path.join(d, "amateur.tle"), "w").write("\n".join(out) + "\n")
    return d


def rotctl(sock, line):
    sock.sendall((line + "\n").encode())
    got = b""
    while not (got.endswith(b"\n") and (line.startswith("P") or got.count(b"\n") >= 2)):
        chunk = sock.recv(200)
        if not chunk:
            break
        got += chunk
    return got.decode()


def run(sky, planned, until):
    """One replay of the stream; readings and targets, the log and what the status said."""
    state = tempfile.mkdtemp(prefix="trakbox-plan-")
    data = None if planned else data_without(SAT)
    # The database a new state begins with (the first `settings set` makes it).
    if data:
        os.environ["TRAKBOX_DATA"] = data
    else:
        os.environ.pop("TRAKBOX_DATA", None)
    for key, value in SETTINGS:
        r = subprocess.run([BIN, "settings", "set", key, value, "--state", state], capture_output=True, text=True)
        check(r.returncode == 0, f"settings set {key} {value}: {r.stderr}")
    port = free_port()
    extra = ["--rotctld-port", str(port)]
    web = WebStation(*extra, state=state, clock=START.strftime("%Y-%m-%dT%H:%M:%SZ"), rate=str(RATE))
    readings, targets, follows, lines = [], [], set(), set()
    try:
        wait_listening(port, "rotctld", proc=web.proc)
        with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
            last_second, sent = None, None
            while True:
                code, st = web.get_json("/api/v1/status")
                check(code == 200, f"status: {code}")
                t = parse_time(st["time"])
                if t >= until:
                    break
                second = int((t - START).total_seconds())
                if second != last_second:
                    last_second = second
                    az, el = sky.at(t)
                    rotctl(c, "p")
                    if el >= 0.0 and (sent is None or pointing_error(az, el, *sent) > STEP):
                        sent = (az, max(el, 0.0))
                        got = rotctl(c, f"P {az:.2f} {sent[1]:.2f}")
                        check(got.startswith("RPRT 0"), f"P {az:.2f} {sent[1]:.2f}: {got!r}")
                        code, st = web.get_json("/api/v1/status")
                        tgt = st["antenna"]["target"]
                        targets.append((t, az, el, tgt["travel_deg"] if tgt else None))
                pos = st["antenna"]["position"]
                if pos and AOS <= t:
                    az, el = sky.at(t)
                    readings.append((t, pos["travel_deg"], pos["az_deg"], pos["el_deg"], az, el))
                if st["antenna"].get("follows"):
                    if not follows:
                        lines.add(web.status_text())  # `trakbox status`, once
                    follows.add(st["antenna"]["follows"])
                lines.add(st.get("status_line", ""))
                time.sleep(0.02)
        log = open(os.path.join(state, "trakbox.log")).read()
    finally:
        web.stop()
        os.environ.pop("TRAKBOX_DATA", None)
        shutil.rmtree(state, ignore_errors=True)
        if data:
            shutil.rmtree(data, ignore_errors=True)
    return readings, targets, follows, lines, log


def judge(sky, readings, targets):
    """From the first reading at the first target: the largest travel step between readings and between
    targets, the worst pointing error and the worst excess over the allowance."""
    def allowance(t):
        a0, e0 = sky.at(t - timedelta(seconds=2))
        a1, e1 = sky.at(t)
        return STEP + pointing_error(a0, e0, a1, e1) + 1.5 + PLAN_ERROR

    # The acquisition (the slew to the first target, from wherever the antenna was) is not judged:
    # from the first reading at the first target's travel.
    first = targets[0][3]
    on = next((i for i, r in enumerate(readings) if abs(r[1] - first) <= 3.0), None)
    check(on is not None, f"the antenna reaches the first target (travel {first:.1f})")
    rs = readings[on:]
    jump = max(abs(b[1] - a[1]) for a, b in zip(rs, rs[1:]))
    tt = [x[3] for x in targets if x[3] is not None and x[0] >= rs[0][0]]
    target_jump = max(abs(b - a) for a, b in zip(tt, tt[1:]))
    errors = [(pointing_error(r[2], r[3], r[4], max(r[5], 0.0)), allowance(r[0]), r) for r in rs]
    worst = max(errors, key=lambda e: e[0])
    over = max(e[0] - e[1] for e in errors)
    return {"from": rs[0][0], "readings": len(rs), "jump": jump, "target_jump": target_jump,
            "worst": worst[0], "worst_at": worst[2][0], "over": over, "travel": (min(r[1] for r in rs), max(r[1] for r in rs))}


def show(what, j):
    print(f"{what}: from {j['from']:%H:%M:%S}, {j['readings']} readings, travel {j['travel'][0]:.1f}..{j['travel'][1]:.1f}; "
          f"largest travel step between readings {j['jump']:.1f} deg, between targets {j['target_jump']:.1f} deg; "
          f"worst pointing error {j['worst']:.1f} deg at {j['worst_at']:%H:%M:%S} "
          f"({j['over']:+.1f} deg against the allowance)")


def main():
    sky = Sky()
    readings, targets, follows, lines, log = run(sky, True, LOS - timedelta(seconds=20))
    j = judge(sky, readings, targets)
    show("with the plan", j)
    check(FOLLOWS in follows, f"the status document says {FOLLOWS!r}: {follows}")
    check(any(FOLLOWS in l for l in lines), "the status line says it")
    text_lines = [t for l in lines for t in l.splitlines()]
    check(any(t.startswith("  antenna   ") and FOLLOWS in t for t in text_lines),
          "`trakbox status` says it on its antenna line")
    check(f"control: {FOLLOWS} (rotctld 127.0.0.1:" in log, "the log says it")
    check(j["jump"] <= 30.0, f"the travel moves at most 30 deg between readings: {j['jump']:.1f}")
    check(j["target_jump"] <= 30.0, f"no target jumps more than 30 deg of travel: {j['target_jump']:.1f}")
    check(j["over"] <= 0.0, f"the pointing error stays within the allowance: {j['over']:+.1f} deg over")
    check(j["travel"][1] > 360.0, f"followed through north in the overlap: travel up to {j['travel'][1]:.1f}")

    # The same stream, the satellite not in the database: the nearest way, as before. Up to 2 minutes
    # past the crossing of north (03:31:40), by when the swing round (~350 degrees at 6 deg/s) is over.
    readings, targets, follows, lines, log = run(sky, False, datetime(2026, 5, 21, 3, 33, 40, tzinfo=timezone.utc))
    n = judge(sky, readings, targets)
    show("without the plan", n)
    check(not follows, f"nothing recognised: {follows}")
    check(n["target_jump"] > 300.0, f"a target swings the antenna round: {n['target_jump']:.1f} deg")
    check(n["worst"] > 90.0, f"pointed away during the swing: {n['worst']:.1f} deg")


if __name__ == "__main__":
    run_test(main)
