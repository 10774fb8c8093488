"""`trakbox passes --sat SUN|MOON` and `trakbox next SUN MOON` (issue 58): the rises, culminations
and sets of the Sun and the Moon in the table satellites get, from the real binary at a fixed start
(--start is these one-shot commands' clock), against PyEphem's times (the same figures as the unit
test, tests/integration/orbit_ref/sky_reference_values.py); mixed with a satellite; refusals."""
import csv
import io
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, run_test, sh  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
MUNICH = "48.1458,11.625,520"
START = "2026-03-20T00:00:00Z"
# PyEphem 4.1.4: centre at -2 deg, no refraction (rise, transit, set, elevation at transit).
PYEPHEM = {
    "SUN": ("2026-03-20T05:09:45", "2026-03-20T11:20:57", "2026-03-20T17:33:03", 41.7962),
    "MOON": ("2026-03-20T05:26:55", "2026-03-20T12:26:41", "2026-03-20T19:45:29", 51.8690),
}


def seconds(iso):
    from datetime import datetime, timezone
    return datetime.fromisoformat(iso.rstrip("Z")).replace(tzinfo=timezone.utc).timestamp()


def main():
    state = tempfile.mkdtemp(prefix="tb-sky-")
    base = ["--station", MUNICH, "--start", START, "--state", state]

    # CSV: one row per body for the day, at PyEphem's times.
    rc, out, err = sh(BIN, "passes", "--sat", "SUN", "--sat", "moon", "--hours", "24", "--csv", *base)
    check(rc == 0, f"passes --sat SUN --sat moon: exit {rc}: {err}")
    rows = list(csv.DictReader(io.StringIO(out)))
    check(sorted(r["sat"] for r in rows) == ["MOON", "SUN"], f"one SUN and one MOON row: {rows}")
    for r in rows:
        rise, transit, set_, max_el = PYEPHEM[r["sat"]]
        check(abs(seconds(r["aos_utc"]) - seconds(rise)) < 6, f"{r['sat']} rises at {rise}: {r['aos_utc']}")
        check(abs(seconds(r["los_utc"]) - seconds(set_)) < 6, f"{r['sat']} sets at {set_}: {r['los_utc']}")
        check(abs(seconds(r["tca_utc"]) - seconds(transit)) < 300, f"{r['sat']} culminates near {transit}: {r['tca_utc']}")
        check(abs(float(r["max_el_deg"]) - max_el) < 0.02, f"{r['sat']} culminates at {max_el}: {r['max_el_deg']}")

    # The table: the satellites' shape, with a line saying what the bodies' figures are.
    rc, out, err = sh(BIN, "passes", "--sat", "SUN", "--hours", "48", *base)
    check(rc == 0, f"passes --sat SUN table: exit {rc}: {err}")
    check("SAT" in out and "AOS (UTC)" in out and "MAX EL" in out, f"the table header: {out}")
    sun_lines = [ln for ln in out.splitlines() if ln.startswith("SUN ")]
    check(len(sun_lines) == 2, f"two days, two SUN rows: {out}")
    check("2026/03/20 05:09:4" in sun_lines[0] and " 41.8 " in sun_lines[0], f"the first row: {sun_lines[0]}")
    check("geometric (no refraction)" in out, f"the bodies' note: {out}")
    check("elements" not in out, f"no element ages without satellites: {out}")

    # JSON, mixed with a satellite from a file: both kinds, sorted by AOS.
    rc, out, err = sh(BIN, "passes", TLE, "--sat", "ISS", "--sat", "MOON", "--hours", "24", "--json", *base)
    check(rc == 0, f"passes with ISS and MOON: exit {rc}: {err}")
    doc = json.loads(out)
    names = {p["sat"] for p in doc}
    check(names == {"ISS", "MOON"}, f"both the satellite and the Moon: {names}")
    aos = [p["aos_utc"] for p in doc]
    check(aos == sorted(aos), f"sorted by AOS: {aos}")

    # next: the next rise, culmination and set of each.
    rc, out, err = sh(BIN, "next", "SUN", "MOON", *base)
    check(rc == 0, f"next SUN MOON: exit {rc}: {err}")
    lines = out.splitlines()
    check(lines[1].startswith("SUN ") and "AOS 2026/03/20 05:09:4" in lines[1] and "TCA 11:2" in lines[1],
          f"SUN first (rises first): {out}")
    check(lines[2].startswith("MOON ") and "AOS 2026/03/20 05:26:5" in lines[2] and "el 51.9" in lines[2],
          f"then MOON: {out}")
    check("LOS 17:33:0" in lines[1] and "LOS 19:45:" in lines[2], f"the sets: {out}")
    # From 10:00 the Sun is up: its pass is the one it is in.
    rc, out, err = sh(BIN, "next", "sun", "--station", MUNICH, "--start", "2026-03-20T10:00:00Z", "--state", state)
    check(rc == 0 and "UP, LOS in 7:33:0" in out, f"the Sun up at 10:00 sets in 7 h 33 min: {out} {err}")

    # Refusals: --with and --plot take satellites only.
    rc, out, err = sh(BIN, "passes", "--sat", "SUN", "--with", "JN58", *base)
    check(rc == 2 and "--with" in err and "SUN" in err, f"--with refused for SUN: {rc} {err}")
    rc, out, err = sh(BIN, "passes", "--sat", "MOON", "--plot", os.path.join(state, "p.png"), *base)
    check(rc == 2 and "--plot" in err, f"--plot refused for MOON: {rc} {err}")
    check(not os.path.exists(os.path.join(state, "p.png")), "no plot written")


if __name__ == "__main__":
    run_test(main)
