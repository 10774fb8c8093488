"""A satellite that never sets (QO-100, geostationary, seen from Berlin) is 'always up', with no
AOS or LOS made up for it (issue 39): `next` says so and prints no LOS, `passes` marks its row as
up at both ends of the window and says what the marks mean; seen from the factory station (Amami,
128.7 E, where it is below the horizon) it has no pass at all."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SOURCE, check, run_test, sh  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
BERLIN = "52.52,13.40,35"


def main():
    code, out, err = sh(BIN, "next", "QO-100", "--elements", TLE, "--station", BERLIN, "--start", CLOCK)
    check(code == 0, f"next QO-100: {code} {err}")
    line = out.strip().split("\n")[-1]
    check(line.startswith("QO-100") and "always up" in line, f"next QO-100 is always up: {line!r}")
    rest = line.replace("no AOS or LOS", "")
    check("LOS" not in rest and "AOS" not in rest, f"and has no AOS or LOS time: {line!r}")
    m = re.search(r"az +(\d+) el +(\d+\.\d)", line)
    check(m and 150 <= int(m.group(1)) <= 175 and 25 <= float(m.group(2)) <= 35,
          f"where it stands from Berlin (south, ~29 deg up): {line!r}")

    code, out, err = sh(BIN, "passes", TLE, "--sat", "QO-100", "--station", BERLIN, "--start", CLOCK, "--hours", "24")
    check(code == 0, f"passes QO-100: {code} {err}")
    rows = [ln for ln in out.split("\n") if ln.startswith("QO-100")]
    check(len(rows) == 1, f"one row for the whole window: {out}")
    check(re.search(r"Z?< .*>", rows[0]), f"marked up at the start (<) and at the end (>): {rows[0]!r}")
    check("< up already at the start of the window (no AOS in it); > still up at its end (no LOS in it)" in out,
          f"the marks are explained: {out}")

    code, out, err = sh(BIN, "next", "QO-100", "--elements", TLE, "--station", "27.391,128.657,50", "--start", CLOCK)
    check(code == 0 and "no pass within 10 days" in out, f"below the horizon from Amami: no pass: {out}")


if __name__ == "__main__":
    run_test(main)
