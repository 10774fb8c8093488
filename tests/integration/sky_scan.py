"""`trakbox calibrate sun --scan` (issue 58): the sun-noise scan on the real binary.

The station: the simulated rotator mounted 2.0 deg off in azimuth and -1.0 in elevation (`--rotator
simulated:mount=2.0,-1.0`: it reads that much more than where the antenna points), at Munich from
2026-03-20 09:00 UTC, the clock at 4 x. The receiver: a stand-in here speaking GQRX's remote control,
whose `l STRENGTH` is a Gaussian beam (8 deg at -3 dB, the Sun 6 dB over a -60 dBFS cold sky) around
the true Sun, seen where the antenna truly points: the rotator's reading (trakbox status) less the
offsets stored and the mounting error. The Sun's true place is the Astronomical Almanac's
low-precision formula, computed here and checked against PyEphem's 136.5630 / 32.9341 (test_sky.cpp).

The scan must find the correction (-2.0, +1.0) within a tenth of the beamwidth, store it, and
tracking the Sun afterwards must put the beam on it (within a tenth of the beam)."""
import math
import os
import socketserver
import subprocess
import sys
import tempfile
import threading
from datetime import datetime, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, poll, run_test  # noqa: E402
from _web import WebStation  # noqa: E402

LAT, LON, HEIGHT = 48.1458, 11.625, 520.0
MOUNT_AZ, MOUNT_EL = 2.0, -1.0
BEAM, Y_DB, COLD_DBFS = 8.0, 6.0, -60.0


def sun_azel(when):
    """The Sun's azimuth and elevation (degrees) at Munich: the Astronomical Almanac's low-precision
    formulas (about 0.01 deg), GMST from the same almanac."""
    n = when.timestamp() / 86400.0 + 2440587.5 - 2451545.0
    r = math.radians
    L = (280.460 + 0.9856474 * n) % 360.0
    g = r((357.528 + 0.9856003 * n) % 360.0)
    lam = r(L + 1.915 * math.sin(g) + 0.020 * math.sin(2 * g))
    eps = r(23.439 - 0.0000004 * n)
    ra = math.atan2(math.cos(eps) * math.sin(lam), math.cos(lam))
    dec = math.asin(math.sin(eps) * math.sin(lam))
    ha = r((280.46061837 + 360.98564736629 * n + LON) % 360.0) - ra
    lat = r(LAT)
    el = math.asin(math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(ha))
    az = math.atan2(-math.sin(ha) * math.cos(dec), math.cos(lat) * math.sin(dec) - math.sin(lat) * math.cos(dec) * math.cos(ha))
    return math.degrees(az) % 360.0, math.degrees(el)


def status(state):
    import json
    r = subprocess.run([BIN, "status", "--json", "--state", state], capture_output=True, text=True, timeout=20)
    return json.loads(r.stdout)


def when(doc):
    return datetime.fromisoformat(doc["time"].rstrip("Z")).replace(tzinfo=timezone.utc)


def true_pointing(doc):
    """Where the antenna truly points: the reading less the offsets and the mounting error."""
    a = doc["antenna"]
    k = a["sky_calibration"]
    return (a["position"]["az_deg"] - k["az_offset_deg"] - MOUNT_AZ, a["position"]["el_deg"] - k["el_offset_deg"] - MOUNT_EL)


def beam_error(doc):
    az, el = true_pointing(doc)
    sun_az, sun_el = sun_azel(when(doc))
    dx = math.remainder(az - sun_az, 360.0) * math.cos(math.radians(sun_el))
    return math.hypot(dx, el - sun_el)


class Receiver(socketserver.ThreadingTCPServer):
    daemon_threads = True
    allow_reuse_address = True

    def __init__(self, state):
        self.state = state
        self.asked = 0
        super().__init__(("127.0.0.1", 0), ReceiverHandler)


class ReceiverHandler(socketserver.StreamRequestHandler):
    def handle(self):
        for line in self.rfile:
            if line.strip() != b"l STRENGTH":
                self.wfile.write(b"RPRT 1\n")
                continue
            doc = status(self.server.state)
            d = beam_error(doc)
            cold = 10 ** (COLD_DBFS / 10)
            p = cold + cold * (10 ** (Y_DB / 10) - 1) * math.exp(-4 * math.log(2) * d * d / (BEAM * BEAM))
            self.server.asked += 1
            ripple = 0.05 * math.sin(1.3 * self.server.asked)  # a receiver's level is never still
            self.wfile.write(f"{10 * math.log10(p) + ripple:.1f}\n".encode())


def main():
    az, el = sun_azel(datetime(2026, 3, 20, 9, 0, 0, tzinfo=timezone.utc))
    check(abs(az - 136.5630) < 0.02 and abs(el - 32.9341) < 0.02, f"the stand-in's Sun against PyEphem: {az} {el}")
    state = tempfile.mkdtemp(prefix="trakbox-scan-")
    for key in ("rotator.az_dead_band", "rotator.el_dead_band"):
        subprocess.run([BIN, "settings", "set", key, "0", "--state", state], capture_output=True, check=True)
    rx = Receiver(state)
    threading.Thread(target=rx.serve_forever, daemon=True).start()
    w = WebStation("--station", f"{LAT},{LON},{HEIGHT:.0f}", "--rotor-control", "on",
                   "--rotator", f"simulated:mount={MOUNT_AZ},{MOUNT_EL}", state=state, clock="2026-03-20T09:00:00Z", rate="4")
    try:
        r = subprocess.run([BIN, "calibrate", "sun", "--scan", "--beam", str(BEAM), "--receiver",
                            f"gqrx:127.0.0.1:{rx.server_address[1]}", "--store", "--state", state],
                           capture_output=True, text=True, timeout=600)
        print(r.stdout.strip())
        check(r.returncode == 0, f"the scan: exit {r.returncode}: {r.stdout} {r.stderr}")
        check("33 points (0 skipped at the limits)" in r.stdout, f"a cross of 33 points: {r.stdout}")
        k = status(state)["antenna"]["sky_calibration"]
        print(f"stored offsets {k['az_offset_deg']:+.3f} {k['el_offset_deg']:+.3f} ({k['source']}, {k['time']}); "
              f"left of the mounting error: {MOUNT_AZ + k['az_offset_deg']:+.3f} az, {MOUNT_EL + k['el_offset_deg']:+.3f} el")
        check(abs(k["az_offset_deg"] + MOUNT_AZ) < BEAM / 10 and abs(k["el_offset_deg"] + MOUNT_EL) < BEAM / 10,
              f"the offsets found within a tenth of the beam: {k}")
        check(k["source"] == "sun scan", f"the record names the scan: {k}")
        y = float(r.stdout.split("Sun noise ")[1].split(" dB")[0])
        check(abs(y - Y_DB) < 0.5, f"the Sun's noise over cold sky: {y} dB (6.0)")
        # Tracking the Sun now puts the beam on it.
        status_code, reply = w.post("/api/v1/track", {"satellite": "SUN"})
        check(status_code == 200, f"track SUN: {status_code} {reply}")
        start = when(status(state))
        poll("20 s of tracking", lambda: (when(status(state)) - start).total_seconds() > 20, 60)
        errors = []
        poll("the beam on the Sun", lambda: errors.append(beam_error(status(state))) or errors[-1] < BEAM / 10, 30)
        print(f"tracking the Sun after the scan: the beam {errors[-1]:.3f} deg from it")
        # In standby the scan does not move the antenna: it says why, stores nothing, exits 1.
        before = status(state)["antenna"]["sky_calibration"]
        w.post("/api/v1/standby", {"on": True})
        r = subprocess.run([BIN, "calibrate", "sun", "--scan", "--beam", str(BEAM), "--receiver",
                            f"gqrx:127.0.0.1:{rx.server_address[1]}", "--store", "--state", state],
                           capture_output=True, text=True, timeout=120)
        check(r.returncode == 1 and "the scan stopped after 0 points: standby; nothing stored" in r.stderr,
              f"a scan in standby: {r.returncode} {r.stdout} {r.stderr}")
        check(status(state)["antenna"]["sky_calibration"] == before, "nothing stored")
    finally:
        w.stop()
        rx.shutdown()


if __name__ == "__main__":
    run_test(main)
