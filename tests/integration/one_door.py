"""The one door of the station's state (issue 55), on the real binary.

Generated from the settings table (`trakbox settings --json`): for every number setting, a value
just outside its range is refused by `trakbox settings set` with the table's sentence, and by the
command line with the same sentence where an option sets it; a value at each end is taken and
survives a start of trakbox with no `.corrupt-` file. `--station 48.85,2.35,12000` is refused
naming the range. Host mode's QTH takes `48.85N,2.35E` as the command line does. A running
station is changed through its socket. SIGHUP re-reads freqmode.txt into the radio, not only the
database.
"""
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import urllib.error
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, free_port, poll, run_test  # noqa: E402

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "data")
START = "2026-05-21T12:00:00Z"  # AO-91 rises at 12:05:05 over the factory station


def run(*args, stdin=b""):
    return subprocess.run([BIN, *args], input=stdin, capture_output=True, timeout=60)


def settings(state):
    r = run("settings", "--json", "--state", state)
    check(r.returncode == 0, f"settings --json: {r.returncode} {r.stderr.decode()}")
    return {e["key"]: e for e in json.loads(r.stdout)["settings"]}


def no_corrupt(state):
    kept = glob.glob(os.path.join(state, "*.corrupt-*"))
    check(not kept, f"no state was set aside: {kept}")


def start_once(state):
    """A start of trakbox on the state (host mode, Q at once): what the next start reads."""
    r = run("host", "--state", state, "--satrak-port", "0", "--clock", START, stdin=b"Q\n")
    check(b"Data in RAM was lost" not in r.stdout + r.stderr, f"the state loads: {r.stdout + r.stderr}")
    no_corrupt(state)


def outside(e, below):
    lo, hi = (float(x) for x in e["range"].split(" ")[0:3:2])
    step = 1 if e["type"] == "integer" else max(0.1, (hi - lo) * 1e-3)
    v = lo - step if below else hi + step
    return str(int(v)) if e["type"] == "integer" else repr(round(v, 6))


def ends(e):
    lo, hi = e["range"].split(" ")[0:3:2]
    return lo, hi


def table_case(state):
    table = settings(state)
    numbers = [e for e in table.values() if e["type"] in ("number", "integer") and " .. " in e["range"]]
    check(len(numbers) >= 20, f"the table's number settings: {len(numbers)}")
    options = {"rotator.az_travel_deg": "--az-travel", "event_min_el_deg": "--event-min-el",
               "sharing.handback_s": "--handback", "gps.threshold_m": "--gps-threshold",
               "radio.dial_rest_ms": "--dial-rest", "refresh.interval_hours": "--elements-refresh-hours",
               "sharing.satnogs_station": "--satnogs-station", "logger.station_id": "--logger-station-id"}
    for e in numbers:
        key = e["key"]
        for below in (True, False):
            v = outside(e, below)
            r = run("settings", "set", key, v, "--state", state)
            err = r.stderr.decode()
            check(r.returncode != 0 and f"{key}: " in err and e["range"] in err,
                  f"settings set {key} {v} refused naming the range {e['range']}: {r.returncode} {err!r}")
            sentence = err.strip().removeprefix("refused: ")
            if key in options:
                c = run(options[key], v, "--state", state, "--satrak-port", "0", "--line")
                cerr = c.stderr.decode()
                check(c.returncode != 0 and sentence in cerr,
                      f"{options[key]} {v}: the same sentence as settings set ({sentence!r}): {cerr!r}")
        lo, hi = ends(e)
        for v in (lo, hi):
            r = run("settings", "set", key, v, "--state", state)
            if r.returncode != 0:
                # Only the whole-model rule (rotator::validate's cross-checks) may refuse an end.
                check(key.startswith("rotator."), f"{key} {v} at the end of its range taken: {r.stderr.decode()}")
                continue
        run("settings", "reset", key, "--state", state)
    start_once(state)
    print(f"{len(numbers)} number settings: both ends and just outside, through settings set and the options")


def station_case(state):
    r = run("--station", "48.85,2.35,12000", "--state", state, "--satrak-port", "0", "--line")
    err = r.stderr.decode()
    check(r.returncode != 0 and "station.height_m: 12000 is outside -500 .. 9000 m" in err,
          f"--station with 12000 m refused naming the range: {r.returncode} {err!r}")
    r = run("settings", "set", "station.height_m", "9000", "--state", state)
    check(r.returncode == 0, f"9000 m taken: {r.stderr.decode()}")
    start_once(state)
    check(settings(state)["station.height_m"]["value"] == 9000, "kept across a start")
    # Host mode's QTH reads what the command line reads, and keeps the height when none is given.
    r = run("host", "--state", state, "--satrak-port", "0", "--clock", START, stdin=b"QTH 48.85N,2.35E\nQ\n")
    out = r.stdout.decode()
    check("QTH 48.8500, 2.3500, 9000 m" in out, f"QTH 48.85N,2.35E taken, the height kept: {out!r}")
    r = run("host", "--state", state, "--satrak-port", "0", "--clock", START, stdin=b"QTH 1,2,12000\nQ\n")
    check("station.height_m: 12000 is outside -500 .. 9000 m" in r.stdout.decode(),
          f"QTH with 12000 m refused with the same sentence: {r.stdout.decode()!r}")
    start_once(state)
    s = settings(state)
    check(s["station.lat_deg"]["value"] == 48.85 and s["station.height_m"]["from"] == "state",
          f"the position stored: {s['station.lat_deg']}, {s['station.height_m']}")


def running_case(state, data):
    """A running station: settings through its socket; SIGHUP retunes the radio from freqmode.txt."""
    port = free_port()
    p = subprocess.Popen([BIN, "--service", "--state", state, "--data", data, "--satrak-port", "0", "--clock", START,
                          "--clock-rate", "20", "--http-port", str(port)], stdin=subprocess.DEVNULL,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        def status():
            r = run("status", "--state", state, "--json")
            try:
                doc = json.loads(r.stdout)
            except ValueError:
                return None
            return doc if doc.get("running") else None
        poll("the service's status", status, 20)
        # next and passes without --start look from the running station's clock, not the wall's (issue 60).
        r = run("next", "ISS", "--state", state)
        check(r.returncode == 0 and "from the running station's clock, 2026-05-21T12:" in r.stderr.decode()
              and "from 2026/05/21 12:" in r.stdout.decode(), f"next beside a --clock station: {r.stdout.decode()} {r.stderr.decode()}")
        r = run("passes", "--sat", "ISS", "--hours", "2", "--state", state)
        check(r.returncode == 0 and "from 2026-05-21T12:" in r.stdout.decode(), f"passes beside it: {r.stdout.decode()[:300]}")
        r = run("settings", "set", "sharing.handback_s", "45", "--state", state)
        check(r.returncode == 0 and "sharing.handback_s = 45 s" in r.stdout.decode(),
              f"set through the running station: {r.stdout.decode()} {r.stderr.decode()}")
        check(settings(state)["sharing.handback_s"]["from"] == "trakbox settings", "and it says where it came from")
        r = run("settings", "set", "station.height_m", "12000", "--state", state)
        check(r.returncode != 0 and "station.height_m: 12000 is outside -500 .. 9000 m" in r.stderr.decode(),
              f"the running station refuses with the same sentence: {r.stderr.decode()}")
        # The page's station endpoint: the same sentence, nothing changed.
        req = urllib.request.Request(f"http://127.0.0.1:{port}/api/v1/station",
                                     data=b'{"lat_deg":48.85,"lon_deg":2.35,"height_m":12000}',
                                     headers={"Content-Type": "application/json"}, method="POST")
        try:
            urllib.request.urlopen(req, timeout=10)
            check(False, "POST /api/v1/station with 12000 m refused")
        except urllib.error.HTTPError as e:
            body = e.read().decode()
            check(e.code in (400, 409) and "station.height_m: 12000 is outside -500 .. 9000 m" in body,
                  f"the page is refused with the same sentence: {e.code} {body}")
        check(settings(state)["station.height_m"]["value"] == 50, "and the height is as it was")
        # The radio follows AO-91 (chosen on the page); its freq/mode line edited, then SIGHUP.
        req = urllib.request.Request(f"http://127.0.0.1:{port}/api/v1/track", data=b'{"satellite":"AO-91"}',
                                     headers={"Content-Type": "application/json"}, method="POST")
        with urllib.request.urlopen(req, timeout=10) as answer:
            check(answer.status == 200, f"AO-91 chosen: {answer.status}")
        def tuning():
            s = status()
            return (s["radios"][0].get("tuning") or {}) if s else {}
        tuned = poll("AO-91 tuned", lambda: (lambda t: t if t.get("satellite") == "AO-91" else None)(tuning()), 30)
        before = tuned["downlink_spot_hz"]
        check(before == 145960000, f"AO-91's downlink as shipped: {before}")
        path = os.path.join(data, "freqmode.txt")
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace("AO-91 145.960 435.250", "AO-91 145.970 435.250"))
        p.send_signal(signal.SIGHUP)
        poll("the radio retuned to 145.970 MHz within 2 s",
             lambda: tuning().get("downlink_spot_hz") == 145970000, 2 + 1)
    finally:
        p.terminate()
        p.communicate(timeout=60)


def main():
    root = tempfile.mkdtemp(prefix="trakbox-door-")
    try:
        table_case(os.path.join(root, "table"))
        station_case(os.path.join(root, "station"))
        data = os.path.join(root, "data")
        shutil.copytree(DATA, data)
        running_case(os.path.join(root, "running"), data)
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
