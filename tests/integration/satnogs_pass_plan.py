"""A SatNOGS job's pass followed whole (issue 57), on the real binary and a SatNOGS Network stand-in.

A local HTTP server answers /api/jobs/?ground_station=42 with one job carrying the Network's field
set: HO-113's pass of 2026-05-21 over the factory station (rises at azimuth 8 at 03:27:11, goes down
through north at 25 degrees of elevation, sets at 200), its window from 03:27:20 to 03:41:20, and
the job's own elements (tle0-2). HO-113 is left out of trakbox's database: the pass can only be
planned from the job. The rotator is a simulated 450-degree North-stop one (rotor start north,
az_travel_deg 450), starting at its stop (azimuth 0, travel 0).

Before the window opens trakbox moves the antenna to the plan's start: the satellite's position at
AOS in the overlap (travel ~368, the way round that reaches 200 through north without a swing).
In the window a satnogs-client-like rotctld client (it reads `p` once a station second and sends
`P az el` when the satellite has moved more than 4 degrees) follows the pass; its targets go the
job's planned way round: the travel never moves more than 30 degrees between two readings, no
target jumps more than 30 degrees, and the pointing error stays within the allowance (the client's
4-degree step, 2 s of the satellite's motion, 1.5 degrees of dead band). The figures are printed.
"""
import http.server
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
from datetime import timedelta

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, free_port, pointing_error, read_tle, run_test, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402
from client_pass_plan import AOS, LOS, SAT, STEP, Sky, data_without, judge, parse_time, rotctl, show  # noqa: E402

RATE = 10
# 2.5 minutes before AOS: inside trakbox's 5 minutes of pre-positioning from the first tick, and
# time for the slew from the stop to the plan's start (368 degrees at 6 deg/s, about a minute).
START = AOS - timedelta(seconds=150)
WINDOW = (AOS + timedelta(seconds=9), LOS - timedelta(seconds=21))


def iso(t):
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


def job():
    sets = {name.strip(): (l1, l2) for name, l1, l2 in read_tle(os.path.join(SOURCE, "data", "amateur.tle"))}
    l1, l2 = sets[SAT]
    return {"id": 98765432, "start": iso(WINDOW[0]), "end": iso(WINDOW[1]), "ground_station": 42, "tle0": SAT,
            "tle1": l1, "tle2": l2, "frequency": 436670000, "mode": "FM", "transmitter": "HO113transmitterUUID00",
            "baud": 0.0, "max_altitude": 66.6, "norad_cat_id": 50466}


class Jobs(http.server.BaseHTTPRequestHandler):
    body = b"[]"

    def do_GET(self):
        body = Jobs.body if self.path == "/api/jobs/?ground_station=42" else b"[]"
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *a):
        pass


def main():
    Jobs.body = json.dumps([job()]).encode()
    server = http.server.ThreadingHTTPServer(("127.0.0.1", free_port()), Jobs)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    sky = Sky()
    state = tempfile.mkdtemp(prefix="trakbox-satnogs-plan-")
    data = data_without(SAT)
    os.environ["TRAKBOX_DATA"] = data
    web = None
    try:
        for key, value in (("station.rotor_start", "north"), ("rotator.az_travel_deg", "450")):
            r = subprocess.run([BIN, "settings", "set", key, value, "--state", state], capture_output=True, text=True)
            check(r.returncode == 0, f"settings set {key} {value}: {r.stderr}")
        port = free_port()
        web = WebStation("--rotctld-port", str(port), "--rotor-control", "on", "--satnogs-station", "42", "--satnogs-url",
                         f"http://127.0.0.1:{server.server_address[1]}", state=state, clock=iso(START), rate=str(RATE))
        wait_listening(port, "rotctld", proc=web.proc)
        # Before the window: where the antenna waits.
        deadline = time.time() + 60
        while True:
            st = web.status()
            t = parse_time(st["time"])
            if t >= WINDOW[0] - timedelta(seconds=3):
                break
            check(time.time() < deadline and web.alive(), "the clock reaches the window")
            time.sleep(0.1)
        pos = st["antenna"]["position"]
        az0, el0 = sky.at(WINDOW[0])
        waited = pointing_error(pos["az_deg"], pos["el_deg"], az0, max(el0, 0.0))
        print(f"before the window ({t:%H:%M:%S}): antenna az {pos['az_deg']:.1f} el {pos['el_deg']:.1f} travel "
              f"{pos['travel_deg']:.1f}; the satellite at the window's start az {az0:.1f} el {el0:.1f}")
        check(waited < 5.0, f"the antenna waits at the pass's start before the window: {waited:.1f} deg off")
        check(pos["travel_deg"] > 360.0, f"in the overlap, the way round the plan takes: travel {pos['travel_deg']:.1f}")
        log = open(os.path.join(state, "trakbox.log")).read()
        check("before its window" in log and "98765432" in log, "the log says where the antenna went and why")

        readings, targets = [], []
        with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
            last_second, sent = None, None
            while True:
                st = web.status()
                t = parse_time(st["time"])
                if t >= WINDOW[1] - timedelta(seconds=5):
                    break
                second = int((t - START).total_seconds())
                if t >= WINDOW[0] and second != last_second:
                    last_second = second
                    az, el = sky.at(t)
                    rotctl(c, "p")
                    if el >= 0.0 and (sent is None or pointing_error(az, el, *sent) > STEP):
                        sent = (az, max(el, 0.0))
                        got = rotctl(c, f"P {az:.2f} {sent[1]:.2f}")
                        check(got.startswith("RPRT 0"), f"P {az:.2f} {sent[1]:.2f}: {got!r}")
                        tgt = web.status()["antenna"]["target"]
                        targets.append((t, az, el, tgt["travel_deg"] if tgt else None))
                pos = st["antenna"]["position"]
                if pos and t >= WINDOW[0]:
                    az, el = sky.at(t)
                    readings.append((t, pos["travel_deg"], pos["az_deg"], pos["el_deg"], az, el))
                time.sleep(0.02)
        follows = st["antenna"].get("follows") or ""
    finally:
        if web:
            web.stop()
        server.shutdown()
        os.environ.pop("TRAKBOX_DATA", None)
        shutil.rmtree(state, ignore_errors=True)
        shutil.rmtree(data, ignore_errors=True)
    j = judge(sky, readings, targets)
    show("the SatNOGS job's pass", j)
    print(f"status: {follows}")
    check(SAT in follows and "planned way round" in follows, f"the status says whose pass is followed: {follows!r}")
    check(j["jump"] <= 30.0, f"the travel moves at most 30 deg between readings: {j['jump']:.1f}")
    check(j["target_jump"] <= 30.0, f"no target jumps more than 30 deg of travel: {j['target_jump']:.1f}")
    check(j["over"] <= 0.0, f"the pointing error stays within the allowance: {j['over']:+.1f} deg over")
    check(j["travel"][1] > 360.0, f"followed through north in the overlap: travel up to {j['travel'][1]:.1f}")


if __name__ == "__main__":
    run_test(main)
