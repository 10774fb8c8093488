"""`trakbox calibrate sun|moon|undo` (issue 58): "this is the Sun" on the real binary.

A simulated rotator mounted 2.0 deg off in azimuth and -1.0 in elevation (`--rotator
simulated:mount=2.0,-1.0`: it reads that much more than where the antenna points) is peaked on the
Sun by hand (the page's goto, to where the Sun reads through that error) at Munich, 2026-03-20
09:00 UTC; the Sun's position there is PyEphem 4.1.4's (test_sky.cpp's table). `trakbox calibrate
sun` through the running station sets offsets that cancel the mounting error (within the ADC's
count), shown by status and stored; tracking the Sun then puts the antenna itself on it; `calibrate
undo` restores the offsets before. The page's endpoint does the same. With no station running, the
state file takes a reading the operator gives: the correction is then exactly the reading's error
(to the Sun model's 0.01 deg)."""
import os
import subprocess
import sys
import tempfile
from datetime import datetime, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, load_state, poll, run_test  # noqa: E402
from _web import WebStation  # noqa: E402

MUNICH = "48.1458,11.625,520"
SUN_AZ, SUN_EL = 136.5630, 32.9341  # PyEphem, Munich, 2026-03-20 09:00:00 UTC, refraction off
MOUNT_AZ, MOUNT_EL = 2.0, -1.0
AZ_COUNT, EL_COUNT = 360.0 / 1023, 90.0 / 511  # one ADC count of the factory spans


def run(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True, timeout=30)
    return r.returncode, r.stdout, r.stderr


def when(doc):
    return datetime.fromisoformat(doc["time"].rstrip("Z")).replace(tzinfo=timezone.utc)


def offsets(doc):
    k = doc["antenna"]["sky_calibration"]
    return k["az_offset_deg"], k["el_offset_deg"], k["source"], k["time"]


def running_station(state):
    for key in ("rotator.az_dead_band", "rotator.el_dead_band"):
        rc, _, err = run("settings", "set", key, "0", "--state", state)
        check(rc == 0, f"settings set {key} 0: {err}")
    w = WebStation("--station", MUNICH, "--rotor-control", "on", "--rotator", f"simulated:mount={MOUNT_AZ},{MOUNT_EL}",
                   state=state, clock="2026-03-20T08:58:30Z", rate="4")
    try:
        # The operator peaks the antenna on the Sun: through the mounting error it reads 2.0 more, 1.0 less.
        status, r = w.post("/api/v1/rotor", {"goto": {"az": SUN_AZ + MOUNT_AZ, "el": SUN_EL + MOUNT_EL}})
        check(status == 200, f"goto: {status} {r}")
        nine = datetime(2026, 3, 20, 9, 0, 0, tzinfo=timezone.utc)
        poll("on the Sun at 09:00:00", lambda: when(w.status()) >= nine and w.status()["antenna"]["on_target"], 60)
        rc, out, err = run("calibrate", "sun", "--state", state)
        check(rc == 0 and out.startswith("ok: SUN computed at az 136.5"), f"calibrate sun: {rc} {out} {err}")
        print(out.strip())
        st = w.status()
        az, el, source, at = offsets(st)
        print(f"offsets {az:+.3f} {el:+.3f}: the mounting error left {MOUNT_AZ + az:+.3f} az, {MOUNT_EL + el:+.3f} el")
        check(abs(MOUNT_AZ + az) < AZ_COUNT + 0.02 and abs(MOUNT_EL + el) < EL_COUNT + 0.02,
              f"the offsets cancel the mounting error within a count: {az} {el}")
        check(source == "sun" and at.startswith("2026-03-20T09:00:0"), f"the record: {source} {at}")
        pos = st["antenna"]["position"]
        check(abs(pos["az_deg"] - SUN_AZ) < 0.05 and abs(pos["el_deg"] - SUN_EL) < 0.05,
              f"the reading is the Sun's position now: {pos}")
        rc, out, _ = run("calibrate", "--state", state)
        check(rc == 0 and "from the sun at 2026-03-20T09:00:0" in out, f"calibrate shows it: {out}")
        # Tracking the Sun: the reading on the Sun is now the antenna on it.
        status, r = w.post("/api/v1/track", {"satellite": "SUN"})
        check(status == 200, f"track SUN: {status} {r}")
        poll("SUN followed", lambda: w.status()["tracking"]["followed"] == "SUN", 20)
        # Undo: the offsets before (none); the page's endpoint calibrates on the Moon the same way.
        rc, out, err = run("calibrate", "undo", "--state", state)
        check(rc == 0 and "undone: offsets az +0.00 el +0.00 deg" in out, f"calibrate undo: {rc} {out} {err}")
        check(offsets(w.status())[:3] == (0.0, 0.0, ""), f"undone: {offsets(w.status())}")
        status, r = w.post("/api/v1/calibrate", {"body": "moon"})
        check(status == 200 and r["note"].startswith("MOON computed at az"), f"the page's calibrate: {status} {r}")
        check(offsets(w.status())[2] == "moon", f"the Moon's record: {offsets(w.status())}")
        status, r = w.post("/api/v1/calibrate", {"undo": True})
        check(status == 200 and offsets(w.status())[:3] == (0.0, 0.0, ""), f"the page's undo: {status} {r}")
        status, r = w.post("/api/v1/calibrate", {"body": "venus"})
        check(status == 400 and "expected" in r["error"], f"a bad body refused: {status} {r}")
        rc, _, err = run("calibrate", "sun", "--reading", "1,2", "--state", state)
        check(rc == 2 and "a station runs on this state" in err, f"--reading with a station running: {rc} {err}")
    finally:
        w.stop()


def state_file(state):
    # No station: the reading the controller showed, and when.
    rc, out, err = run("calibrate", "sun", "--state", state)
    check(rc == 2 and "give the rotator's reading with --reading AZ,EL" in err, f"no reading: {rc} {err}")
    rc, out, err = run("calibrate", "sun", "--reading", f"{SUN_AZ + MOUNT_AZ},{SUN_EL + MOUNT_EL}",
                       "--at", "2026-03-20T09:00:00Z", "--state", state)
    check(rc == 0, f"calibrate on the state file: {rc} {out} {err}")
    print(out.strip())
    rot = load_state(os.path.join(state, "trakbox-state.json"))["rotator"]
    print(f"state file: offsets {rot['az_offset_deg']:+.4f} {rot['el_offset_deg']:+.4f}")
    check(abs(rot["az_offset_deg"] + MOUNT_AZ) < 0.01 and abs(rot["el_offset_deg"] + MOUNT_EL) < 0.01,
          f"exactly the reading's error, to the Sun model's 0.01 deg: {rot}")
    check(rot["sky_calibration"]["time"] == "2026-03-20T09:00:00Z", f"the time of the measurement: {rot}")
    rc, out, err = run("calibrate", "undo", "--state", state)
    check(rc == 0, f"undo on the state file: {rc} {out} {err}")
    rot = load_state(os.path.join(state, "trakbox-state.json"))["rotator"]
    check(rot["az_offset_deg"] == 0.0 and rot["el_offset_deg"] == 0.0, f"undone in the file: {rot}")
    for bad, words in ((["--reading", "north,10"], "expected AZ,EL"), (["--reading", "10,10", "--at", "soon"], "ISO 8601")):
        rc, _, err = run("calibrate", "sun", *bad, "--state", state)
        check(rc == 2 and words in err, f"{bad} refused: {rc} {err}")
    rc, _, err = run("calibrate", "sun", "--reading", "10,10", "--at", "2026-03-20T22:00:00Z", "--state", state)
    check(rc == 1 and "below the 2 deg a calibration needs" in err, f"the Sun down: {rc} {err}")
    rc, _, err = run("calibrate", "mars", "--state", state)
    check(rc == 2 and "expected sun, moon or undo" in err, f"mars: {rc} {err}")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-cal-")
    running_station(state)
    state_file(state)


if __name__ == "__main__":
    run_test(main)
