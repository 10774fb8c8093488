"""At a terminal as with the service (issue 47): `--station JN58td` is stored (the next start has it
without the option), a satellite chosen from the page is tracked again after a restart of the menus
(the terminal says so), and the status line's end names the web page."""
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, free_port, poll, run_test, wait_listening  # noqa: E402

CLOCK = "2026-05-21T12:00:00Z"


def start(state, port, *extra):
    out = open(os.path.join(state, "terminal.out"), "ab")
    p = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock", CLOCK,
                          "--http-port", str(port), *extra], stdin=subprocess.PIPE, stdout=out, stderr=subprocess.PIPE)
    wait_listening(port, "the web server", within=20, proc=p)
    return p


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=20)
    return json.loads(r.stdout)


def stop(p):
    p.terminate()
    p.wait(20)


def post(port, path, body):
    import http.client
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    c.request("POST", path, body=json.dumps(body), headers={"Content-Type": "application/json",
                                                             "Host": f"127.0.0.1:{port}"})
    r = c.getresponse()
    return r.status, json.loads(r.read())


def main():
    state = tempfile.mkdtemp(prefix="trakbox-resume-")
    port = free_port()
    p = start(state, port, "--station", "JN58td")
    try:
        st = poll("the station", lambda: status(state), 10)
        loc = st["station"]
        check(abs(loc["lat_deg"] - 48.145833) < 1e-5 and abs(loc["lon_deg"] - 11.625) < 1e-5,
              f"--station JN58td: {loc}")
        code, r = post(port, "/api/v1/track", {"satellite": "SO-50"})
        check(code == 200, f"track SO-50: {r}")
        poll("SO-50 followed", lambda: status(state)["tracking"]["followed"] == "SO-50", 10)
    finally:
        stop(p)
    p = start(state, port)
    try:
        st = poll("SO-50 followed again at the terminal", lambda: (lambda s: s if s["tracking"]["followed"] == "SO-50"
                                                                   else None)(status(state)), 10)
        check(abs(st["station"]["lat_deg"] - 48.145833) < 1e-5, f"the stored station without --station: {st['station']}")
        # Menu 6-0 names the web page (the start message's URL is behind the full-screen menus).
        p.stdin.write(b"6\r0\r")
        p.stdin.flush()
        time.sleep(1.5)
        said = open(os.path.join(state, "terminal.out"), "rb").read().decode(errors="replace")
        check(f"Web page         http://127.0.0.1:{port}/" in said, f"6-0 shows the page: {said[-800:]}")
        check("Resumed: tracking SO-50, as last chosen" in said, f"the terminal says so: {said[-600:]}")
        print("terminal restart: SO-50 resumed; --station JN58td kept")
    finally:
        stop(p)


run_test(main)
