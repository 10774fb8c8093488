"""The Sun and the Moon as tracking targets (issue 58): `trakbox --service` on the simulated station at
Munich, told through the page's track endpoint to track SUN (then MOON), ends with the simulated
rotator's reading on the body's position at the simulated clock's 2026-03-20 09:00:00 UTC.

The independent values are PyEphem 4.1.4's (refraction off), the ones test_sky.cpp cites, printed by
tests/integration/orbit_ref/sky_reference_values.py. The dead bands are set to 0 first (the factory's
3 azimuth counts, about 1 degree, would let the body drift that far before the antenna follows); what
is left is the ADC's count (0.35 deg of azimuth, 0.18 deg of elevation) and the second of motion
between two readings. The choice is stored (a restart tracks the body again), the page's sky plot
draws the body's pass, and status shows the Moon's echo Doppler when the radio has a frequency."""
import os
import subprocess
import sys
import tempfile
from datetime import datetime, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, load_state, poll, pointing_error, run_test  # noqa: E402
from _web import WebStation  # noqa: E402

MUNICH = "48.1458,11.625,520"
AT = "2026-03-20T09:00:00"
# PyEphem 4.1.4, Munich (48.1458 N, 11.625 E, 520 m), 2026-03-20 09:00:00 UTC, pressure 0:
# (azimuth, elevation) of the centre, topocentric (test_sky.cpp's table).
PYEPHEM = {"SUN": (136.5630, 32.9341), "MOON": (115.5078, 32.4494)}


def when(doc):
    return datetime.fromisoformat(doc["time"].rstrip("Z")).replace(tzinfo=timezone.utc)


def settings_set(state, key, value):
    r = subprocess.run([BIN, "settings", "set", key, value, "--state", state], capture_output=True, text=True,
                       timeout=20)
    check(r.returncode == 0, f"settings set {key} {value}: {r.returncode} {r.stderr}")


def track_and_read(body):
    state = tempfile.mkdtemp(prefix="trakbox-sky-")
    settings_set(state, "rotator.az_dead_band", "0")
    settings_set(state, "rotator.el_dead_band", "0")
    w = WebStation("--station", MUNICH, "--rotor-control", "on", state=state, clock="2026-03-20T08:58:00Z", rate="4")
    try:
        status, r = w.post("/api/v1/track", {"satellite": body.lower()})
        check(status == 200 and r["ok"] and r["note"] == f"tracking {body}", f"track {body}: {status} {r}")
        poll(f"{body} followed", lambda: w.status()["tracking"]["followed"] == body, 20)
        target = datetime.fromisoformat(AT).replace(tzinfo=timezone.utc)
        doc = {}

        def at_nine():
            doc.update(w.status())
            return when(doc) >= target

        poll("the simulated clock at 09:00:00", at_nine, 60, every=0.1)
        late = (when(doc) - target).total_seconds()
        check(late < 3.0, f"a status document within 3 s of 09:00:00: {doc['time']}")
        pos = doc["antenna"]["position"]
        az, el = PYEPHEM[body]
        err = pointing_error(pos["az_deg"], pos["el_deg"], az, el)
        print(f"{body}: antenna {pos['az_deg']:.2f}/{pos['el_deg']:.2f} at {doc['time']}, PyEphem {az}/{el}: "
              f"{err:.3f} deg apart ({abs(pos['az_deg'] - az):.3f} az, {abs(pos['el_deg'] - el):.3f} el)")
        check(abs(pos["az_deg"] - az) < 0.5 and abs(pos["el_deg"] - el) < 0.5,
              f"{body}: the rotator reads {pos} at {doc['time']}, the body is at {az}/{el}")
        sat = doc["tracking"]["satellites"][0]
        check(sat["name"] == body and sat["body"] is True and sat["in_range"], f"status names the body: {sat}")
        check(sat["pass"] is not None, f"the body's pass (rise and set) in status: {sat}")
        if body == "MOON":
            check(abs(sat["range_km"] - 365822.8) < 20.0, f"the Moon's topocentric range: {sat['range_km']}")
            check("echo_doppler_hz" in sat, f"the Moon's echo Doppler field: {sat}")
        status, sky = w.get_json("/api/v1/sky")
        check(status == 200 and sky["satellite"]["name"] == body, f"the sky plot's target: {status} {sky.get('satellite')}")
        check(sky["pass"] is not None and len(sky["pass"]["track"]) > 10, f"the body's path in the sky plot: {sky['pass']}")
    finally:
        w.stop()
    tracking = load_state(os.path.join(state, "trakbox-state.json"))["tracking"]
    check(tracking["mode"] == "single" and tracking["name"] == body and tracking["catalog_number"] == 0,
          f"the choice stored for a restart: {tracking}")
    # A restart tracks the body again.
    w = WebStation("--station", MUNICH, state=state, clock="2026-03-20T09:30:00Z")
    try:
        poll(f"{body} resumed", lambda: w.status()["tracking"]["followed"] == body, 20)
    finally:
        w.stop()


def main():
    for body in ("SUN", "MOON"):
        track_and_read(body)


if __name__ == "__main__":
    run_test(main)
