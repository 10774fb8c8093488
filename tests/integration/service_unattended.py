"""The operator's second hour (issue 39): an unattended station does what was asked. A fresh service
started with --rotor-control on, whose operator chose AO-91 (#8 of the tracking list) once in menu 1
through `trakbox attach`, tracks AO-91 through its pass after two restarts with nobody attached: the
choice and rotor control are kept in the state, saved when they change (the first start's tracking
list rule would have followed #1 and #2). The antenna is checked against the satellite at every
reading of `trakbox status --json` through the pass, on a clock 20 times real time."""
import json
import os
import subprocess
import sys
import tempfile
import shutil
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (SOURCE, BIN, Terminal, check, load_state, pointing_error, poll, reap,  # noqa: E402
                        run_test)

LOCAL_ELEMENTS = "file://" + os.path.join(SOURCE, "data", "amateur.tle")
# AO-91 rises at 12:05:05 (-2 deg) and sets at 12:17:34 over the factory station; the clock starts
# five minutes before, so the antenna waits at the AOS position first.
START = "2026-05-21T12:00:00Z"
LOS = "2026-05-21T12:17:34"
MAIN = r"Select \[1-8,S,M\]:"


def service(state, *extra):
    return subprocess.Popen([BIN, "--service", "--state", state, "--satrak-port", "0", "--clock", START,
                             "--clock-rate", "20", "--elements-url", LOCAL_ELEMENTS, *extra],
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=20)
    try:
        doc = json.loads(r.stdout)
    except ValueError:
        return None
    return doc if doc.get("running") else None  # (not yet started: the not-running document)


def started(state, proc):
    def up():
        check(proc.poll() is None, f"the service exited: {proc.returncode}")
        s = status(state)
        return s if s and s.get("running") else None
    return poll("the service's status", up, 20)


def stop(proc):
    proc.terminate()
    _, err = proc.communicate(timeout=60)
    check(proc.returncode == 0, f"the service stops with 0: {proc.returncode} {err.decode()}")
    return err.decode()


def choose_in_menu_1(state):
    """Attach (plain lines on a pty), menu 1, #8 AO-91, back to the main menu, detach."""
    import pty
    master, slave = pty.openpty()
    p = subprocess.Popen([BIN, "attach", "--state", state, "--line"], stdin=slave, stdout=slave, stderr=slave,
                         env=dict(os.environ, TERM="xterm"), start_new_session=True)
    os.close(slave)
    try:
        t = Terminal(master)
        t.expect(MAIN)
        t.send("1\r")
        t.expect(r"Select :")
        t.send("8\r")
        t.expect(r"\[Satellite:\*AO-91\]")
        t.send("q")
        t.expect(MAIN)
        t.send("\x1d")
        t.expect(r"detached from trakbox: the station goes on")
        p.wait(10)
    finally:
        reap([p])
        os.close(master)


def ao91_followed(state, when):
    """The status document once the station follows AO-91 (the socket answers before the first tick)."""
    return poll(f"AO-91 followed {when}",
                lambda: (lambda x: x if x and x["tracking"]["followed"] == "AO-91" else None)(status(state)), 20)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-unattended-")
    procs = []
    try:
        # status --json with no station running: still a document on stdout (exit 3).
        r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=20)
        check(r.returncode == 3, f"status of no station exits 3: {r.returncode}")
        doc = json.loads(r.stdout)
        check(doc["running"] is False and doc["schema"] == 1 and doc["healthy"] is False, f"and says so: {doc}")

        # 1. A fresh service with --rotor-control on: said at start and in status; the operator
        #    chooses AO-91 once.
        p = service(state, "--rotor-control", "on")
        procs.append(p)
        s = started(state, p)
        check(s["schema"] == 1, f"the status document's schema: {s.get('schema')}")
        check(s["station"] == {"callsign": "NOCALL", "lat_deg": 27.391, "lon_deg": 128.657, "height_m": 50.0,
                               "locator": "PL47hj", "position_from_gps": False}, f"the station: {s.get('station')}")
        check(s["antenna"]["rotor_control"] is True, f"status says rotor control on: {s['antenna']}")
        check(s["tracking"]["mode"] == "multiple", f"no choice yet: the tracking list's rule: {s['tracking']}")
        choose_in_menu_1(state)
        saved = load_state(os.path.join(state, "trakbox-state.json"))
        check(saved["tracking"] == {"mode": "single", "catalog_number": 43017, "name": "AO-91"},
              f"the choice was saved at once: {saved.get('tracking')}")
        check(saved["rotor_control"] is True, "and rotor control")
        err = stop(p)
        check("rotor control is on: the antenna follows" in err, f"the journal says rotor control: {err}")

        # 2. A restart, nobody attached: AO-91, rotor control still on.
        p = service(state)
        procs.append(p)
        s = ao91_followed(state, "after the first restart")
        check(s["tracking"]["mode"] == "single", f"tracked alone: {s['tracking']}")
        check(s["antenna"]["rotor_control"] is True, "rotor control kept")
        check("service: tracking AO-91, as last chosen" in stop(p), "the journal names the choice")

        # 3. The second restart: the antenna follows AO-91 through its pass.
        p = service(state)
        procs.append(p)
        started(state, p)
        # The socket answers from before the first tick: the choice is followed from that tick on.
        ao91_followed(state, "after the second restart")
        samples = []
        deadline = time.time() + 90
        while time.time() < deadline:
            s = status(state)
            if not s:
                continue
            if s["time"] >= LOS:
                break
            check(s["attached"] == [], "nobody attached")
            check(s["tracking"]["followed"] == "AO-91", f"AO-91 followed: {s['tracking']}")
            sat = s["tracking"]["satellites"][0]
            pos = s["antenna"]["position"]
            if sat["in_range"] and pos and "az_deg" in sat:
                samples.append((s["time"], pointing_error(pos["az_deg"], pos["el_deg"], sat["az_deg"], sat["el_deg"]),
                                sat["az_deg"], sat["el_deg"]))
            time.sleep(0.2)
        print("\n".join(f"{t} err {e:.1f} sat {a:.1f}/{el:.1f}" for t, e, a, el in samples)) if os.environ.get("TB_DEBUG") else None
        check(len(samples) >= 15, f"readings through the pass: {len(samples)}")
        # On the satellite from AOS to LOS: within the dead band (3 deg) and the rotator's lag, and at
        # the end within the factory South-start rotor stop, which holds the antenna at azimuth 180
        # while AO-91 sets at 186 (6.7 deg off at LOS).
        worst = max(x[1] for x in samples)
        check(samples[0][1] <= 3.0, f"at the AOS position before AOS: {samples[0]}")
        check(worst <= 8.0, f"the antenna on AO-91 through the pass: worst {worst:.1f} deg "
                            f"at {max(samples, key=lambda x: x[1])}")
        azs = [x[2] for x in samples]
        check(max(x[3] for x in samples) > 30.0, "a pass worth following: up past 30 deg")
        print(f"{len(samples)} readings from {samples[0][0]} to {samples[-1][0]}, az {min(azs):.0f}-{max(azs):.0f}, "
              f"worst pointing error {worst:.1f} deg")
        stop(p)
    finally:
        reap(procs)
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
