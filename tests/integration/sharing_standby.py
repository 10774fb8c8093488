"""Standby and the operator's reservations (issue 44) on the real binary: `trakbox standby on` through
the station socket holds both the antenna and the radio under `standby` (status --json, the status
line), refuses rotctld (RPRT -9), rigctld (RPRT -9) and the page (409) alike; `trakbox reserve`
keeps a window in `reservations`; both survive a restart; standby off hands back to trakbox's
tracking. A reservation a few station seconds ahead makes the tracking yield in its window (the
antenna held under "reserved by the operator") and resume after it."""
import datetime
import os
import socket
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, free_port, poll, run_test, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

RATE = 10
START = "2026-05-21T12:09:40Z"


def cli(state, *args):
    r = subprocess.run([BIN, *args, "--state", state], capture_output=True, text=True, timeout=20)
    return r.returncode, r.stdout + r.stderr


def ask(port, line):
    with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
        c.sendall(line.encode() + b"\n")
        return c.recv(200).decode()


def iso(t):
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


def when(s):
    return datetime.datetime.fromisoformat(s["time"].replace("Z", "+00:00"))


def wait_for(what, pred, seconds):
    return poll(what, pred, seconds, every=0.1)


def main():
    rot, rig = free_port(), free_port()
    extra = ("--rotctld-port", str(rot), "--rigctld-port", str(rig))
    web = WebStation(*extra, clock=START, rate=str(RATE))
    try:
        wait_listening(rot, "rotctld", proc=web.proc)
        code, got = web.post("/api/v1/track", {"satellite": "ISS"})
        check(code == 200, f"track ISS: {code} {got}")
        code, out = cli(web.state, "standby", "on")
        check(code == 0 and out.startswith("ok: standby on"), f"trakbox standby on: {code} {out!r}")
        s = web.status()
        check(s["standby"] is True and s["control"]["antenna"]["kind"] == "standby" and
              s["control"]["radio"]["kind"] == "standby", f"standby holds both: {s['control']}")
        check("STANDBY" in s["status_line"], f"the status line says so: {s['status_line']}")
        check(s["radios"][0]["doppler"] == "paused (standby)", f"radio: {s['radios'][0].get('doppler')}")
        check(ask(rot, "P 100 20").startswith("RPRT -9"), "rotctld P refused in standby")
        check(ask(rig, "F 145950000").startswith("RPRT -9"), "rigctld F refused in standby")
        code, got = web.post("/api/v1/rotor", {"goto": {"az": 90, "el": 10}})
        check(code == 409 and "standby" in got["error"], f"the page's goto in standby: {code} {got}")
        code, out = cli(web.state, "standby", "maybe")
        check(code == 1 and "expected standby on or standby off" in out, f"a bad word: {code} {out!r}")

        t = when(s)
        a, b = t + datetime.timedelta(minutes=20), t + datetime.timedelta(minutes=30)
        code, out = cli(web.state, "reserve", iso(a), iso(b), "EME", "test")
        check(code == 0 and out.startswith("ok: reserved"), f"trakbox reserve: {code} {out!r}")
        code, out = cli(web.state, "reserve", iso(b), iso(a))
        check(code == 1 and "ends after it starts" in out, f"a reservation backwards: {code} {out!r}")
        s = web.status()
        check(len(s["reservations"]) == 1 and s["reservations"][0]["kind"] == "operator" and
              s["reservations"][0]["note"] == "EME test" and s["reservations"][0]["start"] == iso(a),
              f"reservations: {s['reservations']}")
        shown = web.status_text()
        check(f"  reserved  {iso(a)} - {iso(b)} operator (EME test)" in shown, f"`trakbox status` lists it:\n{shown}")

        # A restart keeps both.
        web.stop()
        web.args[web.args.index("--clock") + 1] = s["time"]
        web.start()
        s = web.status()
        check(s["standby"] is True and s["control"]["antenna"]["kind"] == "standby", f"standby after a restart: {s['control']}")
        check(len(s["reservations"]) == 1 and s["reservations"][0]["note"] == "EME test",
              f"the reservation after a restart: {s['reservations']}")
        code, out = cli(web.state, "standby", "off")
        check(code == 0 and out.startswith("ok: standby off"), f"standby off: {code} {out!r}")
        s = web.status()
        check(s["standby"] is False and s["control"]["antenna"]["kind"] == "tracking", f"standby off: {s['control']}")
        check(s["tracking"]["followed"] == "ISS", f"tracking ISS again: {s['tracking']}")

        # A window 20 station seconds ahead, 40 long: tracking yields in it and resumes after.
        t = when(s)
        a, b = t + datetime.timedelta(seconds=20), t + datetime.timedelta(seconds=60)
        code, out = cli(web.state, "reserve", iso(a), iso(b), "manual")
        check(code == 0, f"reserve soon: {code} {out!r}")
        s = wait_for("the window's hold", lambda: (lambda s: s if s["control"]["antenna"]["kind"] == "menus" else None)(web.status()), 8)
        check(s["control"]["antenna"]["label"] == "reserved by the operator: manual" and
              s["control"]["antenna"]["until"] == iso(b), f"the window holds: {s['control']['antenna']}")
        check(when(s) >= a, f"not before its start: {s['time']} {iso(a)}")
        check(s["antenna"]["action"] == "held", f"tracking yields: {s['antenna']['action']}")
        s = wait_for("tracking after the window", lambda: (lambda s: s if s["control"]["antenna"]["kind"] == "tracking" else None)(web.status()), 8)
        check(when(s) >= b, f"not before its end: {s['time']} {iso(b)}")
    finally:
        web.stop()


if __name__ == "__main__":
    run_test(main)
