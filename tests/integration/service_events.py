"""trakbox status and trakbox events on the real binary running as --service (issue 29): status --json
checked against the station's own rotctld/rigctld answers, its state and `trakbox passes`; the exit
status for a healthy station, one with a dead rotator link and none running; the AOS and LOS
events at the times `trakbox passes` predicts for the same station and clock (within a tick), in
the JSON lines of `trakbox events` and through --on-event hooks: one that writes a file, one that
hangs and is killed at its limit; none for a pass whose maximum stays under --event-min-el (2 deg
here: ISS's pass of 12:09, which peaks at 1.2 deg; issue 39)."""
import datetime
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (BIN, CLOCK, SOURCE, OutputLines, check, free_port, load_state, reap,  # noqa: E402
                        run_test, sh, tcp_exchange, wait_listening)

# A fresh state refreshes from CelesTrak (issue 30), which the tests cannot reach: a failed refresh
# is a problem `status` reports (exit 1). The station's own shipped file is a source that works.
LOCAL_ELEMENTS = "file://" + os.path.join(SOURCE, "data", "amateur.tle")

RATE = 10
UNTIL = "2026-05-21T12:18:00Z"  # after the LOS of AO-91, the last of the passes up at the start
TICK_S = 1.0                    # --tick-ms 1000 of clock time
MIN_EL = 2.0                    # --event-min-el


def iso(text):
    return datetime.datetime.fromisoformat(text.replace("Z", "+00:00"))


def wrap(d):
    return abs((d + 180.0) % 360.0 - 180.0)


def status(state, *extra):
    r = subprocess.run([BIN, "status", "--state", state, *extra], capture_output=True, text=True, timeout=30)
    return r.returncode, r.stdout, r.stderr


def check_status(state, svc, rot, rig):
    deadline = time.time() + 10
    while True:  # the first tick of the stored tracking
        code, out, err = status(state, "--json")
        if code != 0 or json.loads(out)["tracking"]["satellites"] or time.time() > deadline:
            break
        time.sleep(0.1)
    p = tcp_exchange(rot, b"p\n", b"\n").decode().split()
    f = int(tcp_exchange(rig, b"f\n", b"\n").decode().split()[0])
    check(code == 0, f"status of a healthy station exits 0: {code} {err}")
    s = json.loads(out)
    data = load_state(os.path.join(state, "trakbox-state.json"))
    check(s["running"] and s["service"] and s["pid"] == svc.pid, f"pid {s['pid']} is the service's {svc.pid}")
    check(s["state_dir"] == state and s["healthy"] and s["problems"] == [], f"healthy: {s['problems']}")
    check(s["tracking"]["mode"] == "multiple", f"multiple tracking of the stored list: {s['tracking']['mode']}")
    names = [data["db"]["satellites"][i]["elements"]["name"] for i in data["db"]["selected"]]
    check([e["name"] for e in s["tracking_list"]] == names, "the tracking list is the stored one")
    check([c["name"] for c in s["tracking"]["satellites"]] == names[:data["db"]["multi_count"]],
          "the multi-tracked satellites are the first of the list")
    pos = s["antenna"]["position"]
    check(wrap(pos["az_deg"] - float(p[0])) < 5 and abs(pos["el_deg"] - float(p[1])) < 5,
          f"antenna {pos} where rotctld says {p[:2]}")
    check(abs(s["radios"][0]["downlink_hz"] - f) < 5000, f"radio {s['radios'][0]['downlink_hz']} Hz, rigctld {f}")
    servers = {srv["name"]: srv for srv in s["servers"]}
    check(set(servers) == {"rotctld", "rigctld"}, f"the servers that run: {sorted(servers)}")
    check(servers["rotctld"]["port"] == rot and servers["rigctld"]["port"] == rig, "with their ports")
    check(all(servers[n][k] == 0 for n in servers for k in servers[n] if k.startswith("refused")),
          f"nothing refused yet: {servers}")
    # The next passes: those `trakbox passes` predicts for the same station from the status's time.
    st = data["station"]
    code, out, err = sh(BIN, "passes", os.path.join(SOURCE, "data", "amateur.tle"), "--station",
                        f"{st['lat_deg']},{st['lon_deg']},{st['height_m']}", "--start", s["time"], "--hours", "24",
                        "--json")
    check(code == 0, f"passes: {err}")
    first = {}
    for p in json.loads(out):
        first.setdefault(p["sat"], p)
    compared = 0
    for e in s["tracking_list"]:
        if e["next_pass"] is None or e["name"] not in first:
            continue
        want = first[e["name"]]
        got = e["next_pass"]
        if got["in_progress"]:
            continue  # a pass already up: its AOS is the search's start, not a prediction
        check(abs((iso(got["aos"]) - iso(want["aos_utc"])).total_seconds()) <= 1.5,
              f"{e['name']}: next AOS {got['aos']}, passes says {want['aos_utc']}")
        check(abs(got["max_el_deg"] - want["max_el_deg"]) < 0.5, f"{e['name']}: max elevation")
        compared += 1
    check(compared >= 5, f"next passes compared: {compared}")
    code, text, _ = status(state)
    check(code == 0 and "running" in text and "tracking  multiple" in text, f"the text form:\n{text}")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-events-")
    other = tempfile.mkdtemp(prefix="trakbox-events-dead-")
    scratch = tempfile.mkdtemp(prefix="trakbox-events-hooks-")
    procs = []
    try:
        code, _, err = status(state)
        check(code == 3 and "no trakbox is running" in err, f"nothing running: exit 3: {code} {err}")

        hook_file = os.path.join(scratch, "events.txt")
        rot, rig = free_port(), free_port()
        svc = subprocess.Popen(
            [BIN, "--service", "--state", state, "--satrak-port", "0", "--clock", CLOCK, "--clock-rate", str(RATE),
             "--elements-url", LOCAL_ELEMENTS, "--rotctld-port", str(rot), "--rigctld-port", str(rig), "--hook-timeout", "2",
             "--event-min-el", str(MIN_EL),
             "--on-event", f'aos,los=echo "$TRAKBOX_EVENT $TRAKBOX_SATELLITE $TRAKBOX_TIME $TRAKBOX_MAX_EL_DEG" >> {hook_file}',
             "--on-event", "aos=echo waiting for $TRAKBOX_SATELLITE; sleep 600"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(svc)
        wait_listening(rot, "rotctld", proc=svc)
        wait_listening(rig, "rigctld", proc=svc)
        ev = subprocess.Popen([BIN, "events", "--state", state], stdout=subprocess.PIPE, text=True)
        procs.append(ev)
        lines = OutputLines(ev)

        check_status(state, svc, rot, rig)

        # A station with a dead rotator link: running, not healthy.
        dead = free_port()
        bad = subprocess.Popen([BIN, "--service", "--state", other, "--satrak-port", "0", "--clock", CLOCK,
                                "--rotator", f"rotctld:127.0.0.1:{dead}"],
                               stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        procs.append(bad)
        deadline = time.time() + 20
        while True:
            code, out, _ = status(other, "--json")
            if code == 1:
                break
            check(time.time() < deadline, f"status of a station whose rotator is unreachable exits 1: {code}")
            time.sleep(0.3)
        check(any("rotator link" in p for p in json.loads(out)["problems"]), f"and says so: {out[-500:]}")
        bad.terminate()
        bad.wait(60)

        # Run the clock to UNTIL.
        deadline = time.time() + 200
        while True:
            code, out, _ = status(state, "--json")
            if code in (0, 1) and iso(json.loads(out)["time"]) >= iso(UNTIL):
                break
            check(time.time() < deadline, "the clock reached the end of the window")
            time.sleep(1)
        svc.terminate()
        _, err = svc.communicate(timeout=60)
        check(svc.returncode == 0, f"service exit {svc.returncode}: {err.decode()[-1500:]}")
        ev.wait(20)
        check(ev.returncode == 0, "trakbox events ends with 0 when the station stops")
        lines.join(5)
        events = [json.loads(line) for line in lines.lines]

        # The passes `trakbox passes` predicts over the window, for the tracking list.
        data = load_state(os.path.join(state, "trakbox-state.json"))
        names = {data["db"]["satellites"][i]["elements"]["name"] for i in data["db"]["selected"]}
        st = data["station"]
        hours = (iso(UNTIL) - iso(CLOCK)).total_seconds() / 3600
        code, out, err = sh(BIN, "passes", os.path.join(SOURCE, "data", "amateur.tle"), "--station",
                            f"{st['lat_deg']},{st['lon_deg']},{st['height_m']}", "--start", CLOCK, "--hours",
                            str(hours), "--json")
        check(code == 0, f"passes: {err}")
        expected, low = [], []
        for p in json.loads(out):
            if p["sat"] not in names:
                continue
            if p["max_el_deg"] < MIN_EL:
                low.append(p["sat"])
                continue
            expected.append(("aos", p["sat"], iso(p["aos_utc"])))
            if iso(p["los_utc"]) < iso(UNTIL) - datetime.timedelta(seconds=2):
                expected.append(("los", p["sat"], iso(p["los_utc"])))
        # Every AOS and LOS ran the file hook, with the event's time in its environment: those times
        # against the predictions. (The passes up at the start fire at the first tick, before any
        # `trakbox events` could connect: the stream is checked for the rest.)
        with open(hook_file) as f:
            rows = [line.split() for line in f if line.strip()]
        got = {(r[0], r[1]): iso(r[2]) for r in rows}
        check(len(rows) == len(got), f"the file hook ran once per event: {rows}")
        check(len(expected) >= 6, f"the window holds AOS and LOS to check: {expected}")
        worst = 0.0
        for kind, sat, t in expected:
            check((kind, sat) in got, f"{kind} of {sat} at {t} ran the hook: {sorted(got)}")
            late = (got[(kind, sat)] - t).total_seconds()
            check(-0.2 <= late <= TICK_S + 0.5, f"{kind} {sat}: event at {got[(kind, sat)]}, predicted {t}")
            worst = max(worst, late)
        check(len(got) == len(expected), f"no other AOS/LOS: {sorted(got)} vs {expected}")
        check("ISS" in low, f"ISS's low pass is in the window: {low}")
        for sat in low:
            check(("aos", sat) not in got and ("los", sat) not in got,
                  f"no event nor hook for {sat}, whose pass stays under {MIN_EL} deg: {sorted(got)}")
        streamed = {(e["event"], e["satellite"]): iso(e["time"]) for e in events if e["event"] in ("aos", "los")}
        later = {k: v for k, v in got.items() if v > iso(CLOCK) + datetime.timedelta(seconds=10)}
        check(len(later) >= 3 and all(streamed.get(k) == v for k, v in later.items()),
              f"trakbox events streamed the same events: {sorted(streamed)} vs {sorted(later)}")
        e0 = next(e for e in events if e["event"] in ("aos", "los"))
        for key in ("satellite", "catalog_number", "aos", "los", "tca", "max_el_deg", "downlink_hz"):
            check(key in e0, f"an AOS/LOS event has {key}: {e0}")

        # The hanging hook: killed at its limit, each time.
        log = open(os.path.join(state, "trakbox.log")).read()
        aos_count = sum(1 for k in got if k[0] == "aos")
        killed = log.count("still running after its limit of 2 s: killed")
        check(killed == aos_count, f"the hanging hook was killed at its limit for each AOS: {killed} of {aos_count}")
        check("killed at its limit; output: waiting for" in log, "its output is in the log")
        check("exit status 0" in log, "the file hook's exit status is in the log")
        print(f"{len(expected)} AOS/LOS events ({len(low)} low passes untold), latest {worst:.2f} s after the prediction; {killed} hooks killed")
    finally:
        reap(procs)
        for d in (state, other, scratch):
            shutil.rmtree(d, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
