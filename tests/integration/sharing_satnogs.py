"""SatNOGS windows (issue 44) on the real binary: a local HTTP server answers
/api/jobs/?ground_station=42 with two jobs carrying the Network's real field set (id, start, end,
ground_station, tle0-2, frequency, mode, transmitter, baud, max_altitude, norad_cat_id).
trakbox --satnogs-station 42 --satnogs-url http://127.0.0.1:PORT lists both in `reservations`,
asked without an Authorization header; in the first job's window trakbox's tracking yields (the
antenna and radio held by "SatNOGS observation ..."), a rotctld client holds under that name, a goto
from the page needs a confirmation, and after the window the tracking resumes. A station whose
server answers nonsense has a problem in status naming it. --rigctld-port 4532 with
--satnogs-station is warned about at the start."""
import datetime
import http.server
import json
import os
import socket
import sys
import threading

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import check, free_port, poll, run_test, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

RATE = 10
START = datetime.datetime(2026, 5, 21, 12, 9, 40, tzinfo=datetime.timezone.utc)
TLE1 = "1 43017U 17073E   26140.50000000  .00000500  00000-0  40000-4 0  9990"
TLE2 = "2 43017  97.6900 100.0000 0250000 200.0000 160.0000 14.78000000000000"


def iso(t):
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


# The first job begins 60 station seconds after the start and lasts 40; the second is tomorrow.
J1 = (START + datetime.timedelta(seconds=60), START + datetime.timedelta(seconds=100))
J2 = (START + datetime.timedelta(days=1), START + datetime.timedelta(days=1, minutes=10))
JOBS = [
    {"id": 12345678, "start": iso(J1[0]), "end": iso(J1[1]), "ground_station": 42, "tle0": "AO-91",
     "tle1": TLE1, "tle2": TLE2, "frequency": 145960000, "mode": "FM", "transmitter": "abcdefghijklmnopqrstuv",
     "baud": 0.0, "max_altitude": 61.3, "norad_cat_id": 43017},
    {"id": 12345679, "start": iso(J2[0]), "end": iso(J2[1]), "ground_station": 42, "tle0": "ISS",
     "tle1": TLE1, "tle2": TLE2, "frequency": 437800000, "mode": "AFSK1k2", "transmitter": "vutsrqponmlkjihgfedcba",
     "baud": 1200.0, "max_altitude": 23.0, "norad_cat_id": 25544},
]
seen = []


class Jobs(http.server.BaseHTTPRequestHandler):
    def do_GET(self):
        seen.append((self.path, dict(self.headers)))
        if self.path == "/api/jobs/?ground_station=42":
            body = json.dumps(JOBS).encode()
        else:
            body = b"<html>maintenance</html>"
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *a):
        pass


def wait_for(what, pred, seconds):
    return poll(what, pred, seconds, every=0.1)


def kind_is(web, resource, kind):
    s = web.status()
    return s if s["control"][resource]["kind"] == kind else None


def main():
    http_port = free_port()
    server = http.server.ThreadingHTTPServer(("127.0.0.1", http_port), Jobs)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{http_port}"
    rot = free_port()
    web = WebStation("--rotctld-port", str(rot), "--satnogs-station", "42", "--satnogs-url", url,
                     clock=iso(START), rate=str(RATE))
    bad = None
    try:
        wait_listening(rot, "rotctld", proc=web.proc)
        code, got = web.post("/api/v1/track", {"satellite": "ISS"})
        check(code == 200, f"track ISS: {code} {got}")
        s = wait_for("two reservations", lambda: (lambda s: s if len(s["reservations"]) == 2 else None)(web.status()), 10)
        r = s["reservations"]
        check([x["id"] for x in r] == ["12345678", "12345679"] and all(x["kind"] == "satnogs" for x in r),
              f"both jobs: {r}")
        check(r[0]["satellite"] == "AO-91" and r[0]["start"] == iso(J1[0]) and r[0]["end"] == iso(J1[1]) and
              r[0]["note"] == "FM 145960000 Hz", f"the first job: {r[0]}")
        check(s["satnogs"]["station"] == 42 and s["satnogs"]["error"] is None and s["satnogs"]["jobs"] == 2,
              f"satnogs: {s['satnogs']}")
        check(seen and seen[0][0] == "/api/jobs/?ground_station=42", f"the request: {seen}")
        check(all("authorization" not in {k.lower() for k in h} for _, h in seen), f"anonymous: {seen}")
        check(s["control"]["antenna"]["kind"] == "tracking", f"before the window: {s['control']}")

        s = wait_for("the window's hold", lambda: kind_is(web, "antenna", "satnogs"), 10)
        check(s["control"]["antenna"]["label"] == "SatNOGS observation 12345678 AO-91" and
              s["control"]["antenna"]["until"] == iso(J1[1]) and s["control"]["radio"]["kind"] == "satnogs",
              f"the window holds both: {s['control']}")
        check(s["antenna"]["action"] == "held", f"trakbox's tracking yields: {s['antenna']['action']}")
        with socket.create_connection(("127.0.0.1", rot), timeout=10) as c:
            c.sendall(b"P 120 40\n")
            check(c.recv(100).startswith(b"RPRT 0"), "the SatNOGS client's P is taken")
            s = web.status()
            check(s["control"]["antenna"]["label"].startswith("SatNOGS observation 12345678 AO-91 (rotctld 127.0.0.1:"),
                  f"the client holds under the observation's name: {s['control']['antenna']}")
            code, got = web.post("/api/v1/rotor", {"goto": {"az": 90, "el": 10}})
            check(code == 409 and got.get("confirm_needed"), f"a goto in the window asks to confirm: {code} {got}")
        s = wait_for("tracking after the window", lambda: kind_is(web, "antenna", "tracking"), 10)
        check(datetime.datetime.fromisoformat(s["time"].replace("Z", "+00:00")) >= J1[1], f"after its end: {s['time']}")
        check(s["control"]["radio"]["kind"] == "tracking", f"the radio too: {s['control']['radio']}")
        check(s["tracking"]["followed"] == "ISS", f"the tracking resumed what was chosen: {s['tracking']}")

        # A server that answers nonsense: a problem naming it; the flowgraph's port is warned about.
        probe = socket.socket()
        try:
            probe.bind(("127.0.0.1", 4532))
            port_4532 = ["--rigctld-port", "4532"]
        except OSError:
            port_4532 = []  # taken here: the warning is not checked
        finally:
            probe.close()
        bad = WebStation("--satnogs-station", "43", "--satnogs-url", url, *port_4532,
                         clock=iso(START), rate=str(RATE))
        s = wait_for("the problem", lambda: (lambda s: s if s.get("satnogs", {}).get("error") else None)(bad.status()), 10)
        check(any("SatNOGS jobs of station 43: the jobs answer is not a JSON list" in p for p in s["problems"]),
              f"problems: {s['problems']}")
        check(s["reservations"] == [], f"no reservations: {s['reservations']}")
        err = bad.stop()
        bad = None
        check(not port_4532 or "--rigctld-port 4532 with --satnogs-station" in err, f"the port warning: {err[-400:]!r}")
    finally:
        if bad:
            bad.stop()
        web.stop()
        server.shutdown()


if __name__ == "__main__":
    run_test(main)
