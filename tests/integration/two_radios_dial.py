"""Two radios and dial follow during an RS-44 pass (issue 17). Two Hamlib dummy rigs (`rigctld -m 1`)
on free loopback ports stand in for the downlink and the uplink radio (--radio, --uplink-radio);
trakbox tracks the RS-44 pass of 2026-05-21 10:47-11:09 UTC over the factory station from a minute
before its culmination (--clock). A second client turns the downlink dial up 10 kHz, as an operator
tuning across the transponder would; the test reads both rigs back: the downlink stays on the new
spot (with its Doppler) and the uplink, RS-44 being an inverting transponder, moves down 10 kHz.
Every wait polls for its condition with a deadline.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timedelta, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, free_port, hamlib_dummy, poll, reap, run_test, satellite_track, sh, skip  # noqa: E402

START = datetime(2026, 5, 21, 10, 57, 0, tzinfo=timezone.utc)
C = 299792.458


def read_freq(port):
    """The rig's frequency through a second client (rigctl), or None."""
    for _ in range(3):  # Hamlib 4.5's rigctld resets a connection now and then: ask again
        code, out, _ = sh("rigctl", "-m", "2", "-r", f"127.0.0.1:{port}", "f")
        m = re.search(r"^(\d+)", out.strip())
        if code == 0 and m:
            return int(m.group(1))
        time.sleep(0.1)
    return None


def expected(clock_at, down_spot, up_spot):
    """The radio frequencies for spots at the satellite at that moment: heard downlink
    F (1 - rr/c), sent uplink F / (1 - rr/c)."""
    row = satellite_track(clock_at, 1, sat="RS-44", freq=down_spot)[0]
    rr = -row["doppler_hz"] * C / down_spot  # doppler = -F rr / c
    return down_spot * (1 - rr / C), up_spot / (1 - rr / C)


def main():
    if not shutil.which("rigctld") or not shutil.which("rigctl"):
        skip("rigctld/rigctl (Hamlib) not installed")
    down_port, up_port = free_port(), free_port()
    while up_port == down_port:
        up_port = free_port()
    state = tempfile.mkdtemp(prefix="trakbox-two-radios-")
    procs = []
    try:
        for port in (down_port, up_port):
            procs.append(hamlib_dummy("rigctld", port))
        for port in (down_port, up_port):
            poll(f"rigctld on port {port}", lambda p=port: read_freq(p) is not None, 10)
        clock = START.strftime("%Y-%m-%dT%H:%M:%SZ")
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock", clock,
                               "--radio", f"rigctld:127.0.0.1:{down_port}",
                               "--uplink-radio", f"rigctld:127.0.0.1:{up_port}"],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        t0 = time.time()
        clock_now = lambda: START + timedelta(seconds=time.time() - t0)  # noqa: E731
        # S: single tracking; RS-44 is #12 of the shipped tracking list.
        tb.stdin.write(b"S\r12\r")
        tb.stdin.flush()

        # Both rigs on RS-44's spot 435.640 / 145.965 MHz with Doppler (within 12 kHz of it).
        d0 = poll("the downlink rig on 435.640 MHz", lambda: (lambda f: f if f and abs(f - 435_640_000) < 12_000 else None)(read_freq(down_port)), 30)
        u0 = poll("the uplink rig on 145.965 MHz", lambda: (lambda f: f if f and abs(f - 145_965_000) < 5_000 else None)(read_freq(up_port)), 30)
        e_down, e_up = expected(clock_now(), 435_640_000, 145_965_000)
        check(abs(d0 - e_down) < 400 and abs(u0 - e_up) < 400,
              f"before the turn: downlink {d0} (expected {e_down:.0f}), uplink {u0} (expected {e_up:.0f})")

        # The operator turns the downlink dial up 10 kHz.
        turned = d0 + 10_000
        code, _, err = sh("rigctl", "-m", "2", "-r", f"127.0.0.1:{down_port}", "F", str(turned))
        check(code == 0, f"rigctl F {turned}: {err}")

        # The uplink follows: 10 kHz down (RS-44 inverts), apart from a few seconds' Doppler drift.
        u1 = poll("the uplink to move down 10 kHz",
                  lambda: (lambda f: f if f and abs(f - (u0 - 10_000)) < 300 else None)(read_freq(up_port)), 20)
        # The downlink stays where the operator put it, tracking its Doppler from there: sample it
        # for a few seconds (until 3 readings 1 s apart), each within 400 Hz of the new spot's
        # Doppler-corrected frequency and never back near the old one.
        samples = []
        last_at = 0.0
        deadline = time.time() + 20
        while len(samples) < 3 and time.time() < deadline:
            if time.time() - last_at >= 1.0:
                f, at = read_freq(down_port), clock_now()
                if f:
                    samples.append((f, at))
                    last_at = time.time()
            time.sleep(0.1)
        check(len(samples) == 3, f"downlink readings after the turn: {samples}")
        for f, at in samples:
            e_down, _ = expected(at, 435_650_000, 145_955_000)
            check(abs(f - e_down) < 400, f"downlink {f} after the turn, expected {e_down:.0f} (spot 435.650 MHz)")
        u2 = read_freq(up_port)
        _, e_up = expected(clock_now(), 435_650_000, 145_955_000)
        check(u2 is not None and abs(u2 - e_up) < 400, f"uplink {u2} after the turn, expected {e_up:.0f} (spot 145.955)")

        tb.stdin.close()
        check(tb.wait(20) == 0, "trakbox leaves cleanly when input ends")
        log = open(os.path.join(state, "trakbox.log")).read()
        check("downlink dial turned" in log, "the log names the operator's turn of the downlink dial")
        print(f"two_radios_dial: downlink {d0}->{turned}, then {', '.join(str(f) for f, _ in samples)}; "
              f"uplink {u0}->{u1} ({u1 - u0:+d} Hz), then {u2}")
    finally:
        reap(procs)
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
