"""Who has the antenna (issue 44) on the real binary: trakbox --service tracks ISS (chosen through
the web API) while Hamlib's own `rotctl -m 2`, one connection fed a `P 200 30` every second on its
standard input, drives trakbox's rotctld. status --json says control.antenna.kind "rotctld" within
2 s, with the client's address in the label; the radio is still held by trakbox's tracking and its
Doppler goes on (the downlink moves); the tracking is suspended, not stopped (tracking.mode stays
single) and antenna.target is where rotctl sent it. When rotctl disconnects, tracking holds the
antenna again and it follows ISS. A plain client that sends one P and then stays connected and
silent hands the antenna back after --handback seconds of station time (30 s at --clock-rate 10:
3 s). A rigctld F takes the radio only. `trakbox events` carries a `control` event for each change.
The hand-back times are printed."""
import json
import os
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, OutputLines, check, free_port, need, poll, run_test, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

RATE = 10
HANDBACK = 30  # station seconds: 3 s of real time at RATE
START = "2026-05-21T12:09:40Z"  # ISS is up (AOS 12:09:10 at the factory station), LOS 12:15:37


def control_events(lines):
    return [json.loads(l) for l in lines.lines if '"control"' in l and json.loads(l).get("event") == "control"]


def wait_for(what, pred, seconds):
    """What pred() gave, and how long it took to give it."""
    start = time.time()
    return poll(what, pred, seconds, every=0.1), time.time() - start


def wrap(d):
    return abs((d + 180.0) % 360.0 - 180.0)


def main():
    need("rotctl")
    rot, rig = free_port(), free_port()
    web = WebStation("--rotctld-port", str(rot), "--rigctld-port", str(rig), "--handback", str(HANDBACK),
                     clock=START, rate=str(RATE))
    ev = rotctl = None
    try:
        wait_listening(rot, "rotctld", proc=web.proc)
        ev = subprocess.Popen([BIN, "events", "--state", web.state], stdout=subprocess.PIPE, text=True)
        lines = OutputLines(ev)
        code, got = web.post("/api/v1/track", {"satellite": "ISS"})
        check(code == 200, f"track ISS: {code} {got}")
        s, _ = wait_for("ISS followed", lambda: (lambda s: s if s["tracking"]["followed"] == "ISS" else None)(web.status()), 10)
        check(s["control"]["antenna"]["kind"] == "tracking" and s["control"]["radio"]["kind"] == "tracking",
              f"trakbox's tracking holds both: {s['control']}")
        check(s["control"]["radio"]["since"][:10] == s["time"][:10] and s["control"]["antenna"]["since"][:10] == s["time"][:10],
              f"held since the station started (its clock's day), not 1970: {s['control']}")
        check(s["standby"] is False and s["reservations"] == [], f"standby, reservations: {s['standby']} {s['reservations']}")

        # Hamlib's rotctl, one connection, a P every second.
        rotctl = subprocess.Popen(["rotctl", "-m", "2", "-r", f"127.0.0.1:{rot}"], stdin=subprocess.PIPE,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, text=True)
        stop_feeding = threading.Event()

        def feed():
            while not stop_feeding.is_set():
                try:
                    rotctl.stdin.write("P 200 30\n")
                    rotctl.stdin.flush()
                except (BrokenPipeError, ValueError):
                    return
                stop_feeding.wait(1.0)

        feeder = threading.Thread(target=feed, daemon=True)
        feeder.start()
        t0 = time.time()
        s, took = wait_for("control.antenna.kind rotctld",
                           lambda: (lambda s: s if s["control"]["antenna"]["kind"] == "rotctld" else None)(web.status()), 5)
        took = time.time() - t0
        check(took < 2.0, f"rotctld holds the antenna within 2 s: {took:.2f} s")
        print(f"rotctld holds the antenna {took:.2f} s after rotctl started")
        ant = s["control"]["antenna"]
        check(ant["label"].startswith("rotctld 127.0.0.1:"), f"the label names the client: {ant}")
        check(s["control"]["radio"]["kind"] == "tracking", f"the radio is still trakbox's: {s['control']['radio']}")
        check(s["tracking"]["mode"] == "single" and s["tracking"]["followed"] == "ISS",
              f"tracking is suspended, not stopped: {s['tracking']['mode']}")
        check(s["antenna"]["action"] == "held" and s["antenna"]["target"] is not None and
              wrap(s["antenna"]["target"]["az_deg"] - 200) < 0.2 and abs(s["antenna"]["target"]["el_deg"] - 30) < 0.2,
              f"antenna.target is where rotctl sent it: {s['antenna']}")
        check("rotctld 127.0.0.1:" in s["status_line"], f"the status line names the holder: {s['status_line']}")
        d1 = s["radios"][0]["downlink_hz"]
        check(s["radios"][0]["doppler"] == "on", f"Doppler on: {s['radios'][0].get('doppler')}")
        time.sleep(2.0)
        s = web.status()
        d2 = s["radios"][0]["downlink_hz"]
        check(s["control"]["antenna"]["kind"] == "rotctld", f"still held while rotctl sends: {s['control']}")
        check(d1 is not None and d2 is not None and d1 != d2, f"the Doppler goes on: downlink {d1} then {d2}")
        # The operator's goto from the page needs a confirmation while rotctld holds.
        code, got = web.post("/api/v1/rotor", {"goto": {"az": 90, "el": 10}})
        check(code == 409 and got.get("confirm_needed") and got["holder"]["kind"] == "rotctld",
              f"a goto from the page while rotctld holds: 409 naming it: {code} {got}")

        # rotctl goes: the antenna is tracking's again at once, and follows ISS.
        stop_feeding.set()
        rotctl.stdin.close()
        rotctl.wait(10)
        t0 = time.time()
        s, _ = wait_for("tracking again after rotctl left",
                        lambda: (lambda s: s if s["control"]["antenna"]["kind"] == "tracking" else None)(web.status()), 5)
        print(f"hand-back on disconnect: {time.time() - t0:.2f} s")

        def following():
            s = web.status()
            iss = [c for c in s["tracking"]["satellites"] if c["name"] == "ISS"]
            pos = s["antenna"]["position"]
            if iss and pos and wrap(pos["az_deg"] - iss[0]["az_deg"]) < 3.0:
                return s
            return None

        wait_for("the antenna following ISS again", following, 30)

        # A client that sends one P and stays silent: handed back after --handback station seconds.
        with socket.create_connection(("127.0.0.1", rot), timeout=10) as c:
            c.sendall(b"P 150 20\n")
            check(c.recv(100).startswith(b"RPRT 0"), "P 150 20 answered RPRT 0")
            wait_for("a silent client holding", lambda: web.status()["control"]["antenna"]["kind"] == "rotctld", 3)
            t0 = time.time()
            wait_for("hand-back by silence",
                     lambda: web.status()["control"]["antenna"]["kind"] == "tracking", HANDBACK / RATE + 5)
            silent = time.time() - t0
            print(f"hand-back by silence: {silent:.2f} s real ({silent * RATE:.0f} s of station time, --handback {HANDBACK})")
            check(silent > 0.5 * HANDBACK / RATE, f"not before the silence: {silent:.2f} s")

        # rigctld takes the radio, not the antenna.
        with socket.create_connection(("127.0.0.1", rig), timeout=10) as c:
            c.sendall(b"F 145950000\n")
            check(c.recv(100).startswith(b"RPRT 0"), "rigctld F answered RPRT 0")
            s = web.status()
            check(s["control"]["radio"]["kind"] == "rigctld" and s["control"]["antenna"]["kind"] == "tracking",
                  f"rigctld holds the radio only: {s['control']}")
            check(s["radios"][0]["doppler"].startswith("held by rigctld 127.0.0.1:"), f"{s['radios'][0]['doppler']}")
            check(s["radios"][0]["links"]["downlink"]["state"].startswith("Doppler held by rigctld 127.0.0.1:"), f"{s['radios'][0]['links']}")
        wait_for("the radio back to tracking", lambda: web.status()["control"]["radio"]["kind"] == "tracking", 5)

        time.sleep(0.5)
        kinds = [(e["resource"], e["from"]["kind"], e["to"]["kind"]) for e in control_events(lines)]
        for want in [("antenna", "tracking", "rotctld"), ("antenna", "rotctld", "tracking"),
                     ("radio", "tracking", "rigctld"), ("radio", "rigctld", "tracking")]:
            check(want in kinds, f"a control event {want}: {kinds}")
        check(kinds.count(("antenna", "tracking", "rotctld")) == 2, f"two holds by rotctld: {kinds}")
        log = open(os.path.join(web.state, "trakbox.log")).read()
        check("control: the antenna is held by rotctld 127.0.0.1:" in log, "the log says who took the antenna")
    finally:
        if rotctl and rotctl.poll() is None:
            rotctl.kill()
        if ev:
            ev.terminate()
        web.stop()


if __name__ == "__main__":
    run_test(main)
