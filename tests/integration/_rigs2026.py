"""The rigs of issue 61 (IC-905, IC-7300, IC-7100, IC-706MKIIG, FT-857/897, FT-991A, FTX-1) on
pseudo-terminals: trakbox tracking one satellite with one radio for both links or one radio per
link, a --data directory of our own when the satellite's record is not the shipped one, and the
worst tuning error measured while the pass runs. A helper of the integration tests, not a test."""
import os
import shutil
import subprocess
import tempfile
import time
from datetime import timedelta

from _ptyradio import C
from _tbharness import BIN, SOURCE, SerialPair, check, leave_and_read_log, poll, reap, satellite_track

# The station the shipped tests track from (satellite_track's default) and one that sees QO-100.
HOME = "27.391,128.657,50"
BERLIN = "52.52,13.40,35"


def expected(at, sat, down_spot, up_spot, station=HOME):
    """The downlink and uplink frequencies at `at` for two transponder spots (trakbox's schedule)."""
    row = satellite_track(at, 1, sat=sat, station=station, freq=down_spot)[0]
    rr = -row["doppler_hz"] * C / down_spot
    return down_spot * (1 - rr / C), up_spot / (1 - rr / C)


def worst_error(sat, spots, get_down, get_up, clock_now, seconds, station=HOME):
    """Samples both links for `seconds` against the Doppler of the pass at that moment; returns the
    worst absolute error of each (Hz; None for a link not given)."""
    worst = [0.0 if get_down else None, 0.0 if get_up else None]
    end = time.time() + seconds
    while time.time() < end:
        e_down, e_up = expected(clock_now(), sat, *spots, station=station)
        if get_down:
            worst[0] = max(worst[0], abs(get_down() - e_down))
        if get_up:
            worst[1] = max(worst[1], abs(get_up() - e_up))
        time.sleep(0.2)
    return tuple(worst)


def data_dir(freqmode_lines):
    """A --data directory: the shipped elements and a freqmode.txt of these lines (the tracking
    list, in order)."""
    d = tempfile.mkdtemp(prefix="trakbox-rigs-data-")
    shutil.copy(os.path.join(SOURCE, "data", "amateur.tle"), d)
    with open(os.path.join(d, "freqmode.txt"), "w") as f:
        f.write("\n".join(freqmode_lines) + "\n")
    return d


def track(start_at, sat_key, down, test, up=None, extra=(), data=None):
    """trakbox tracking entry `sat_key` of the tracking list from `start_at` (--clock) with
    down = (spec, make_rig): `--radio SPEC` where SPEC has {} for the pty, the responder
    make_rig(path) on the other end; up likewise for `--uplink-radio`. data: freqmode lines for a
    --data directory of our own. test(rigs, trakbox, state, clock_now) gets the rig or the pair."""
    legs = [down] + ([up] if up else [])
    pairs = [SerialPair() for _ in legs]
    state = tempfile.mkdtemp(prefix="trakbox-rigs-")
    data_path = data_dir(data) if data else None
    procs = []
    rigs = [make(p.terminal_side) for (_, make), p in zip(legs, pairs)]
    try:
        t0 = time.time()
        args = ["--radio", legs[0][0].format(pairs[0].trakbox_side)]
        if up:
            args += ["--uplink-radio", legs[1][0].format(pairs[1].trakbox_side)]
        if data_path:
            args += ["--data", data_path]
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0",
                               "--clock", start_at.strftime("%Y-%m-%dT%H:%M:%SZ"), *args, *extra],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        tb.stdin.write(b"S\r" + sat_key + b"\r")
        tb.stdin.flush()
        test(tuple(rigs) if up else rigs[0], tb, state, lambda: start_at + timedelta(seconds=time.time() - t0))
    finally:
        reap(procs)
        for rig in rigs:
            rig.close()
        for p in pairs:
            p.close()
        shutil.rmtree(state, ignore_errors=True)
        if data_path:
            shutil.rmtree(data_path, ignore_errors=True)


def near(what, get, hz, within, seconds=30):
    """Waits until get() is within `within` Hz of hz."""
    poll(what, lambda: abs(get() - hz) < within, seconds, every=0.05)


def leave(tb, state):
    """trakbox's input ends: it must leave cleanly. Returns its log."""
    return leave_and_read_log(tb, state)


def limit_in_log(log, radio, limit):
    """The limit a refusal taught is in the log, said once, with the radio's name."""
    lines = [ln for ln in log.splitlines() if radio in ln and limit in ln]
    check(len(lines) >= 1, f"{radio}: '{limit}' learnt and logged")
    return lines[0]
