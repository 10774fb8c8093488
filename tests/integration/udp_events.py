"""--udp-events HOST:PORT on the real binary: the service sends each event as one JSON datagram with
the fields of `trakbox events` (here the AOS and LOS of the ISS pass at 13:44-13:55 UTC over the
factory station, on a clock ten times fast), to two listeners at once; a malformed destination is
refused at start."""
import json
import os
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, run_test  # noqa: E402


def listener():
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind(("127.0.0.1", 0))
    s.settimeout(1.0)
    return s


def main():
    a, b = listener(), listener()
    state = tempfile.mkdtemp(prefix="trakbox-udp-")
    p = subprocess.Popen([BIN, "--service", "--state", state, "--satrak-port", "0", "--clock", "2026-05-21T13:43:30Z",
                          "--clock-rate", "20", "--udp-events", f"127.0.0.1:{a.getsockname()[1]}",
                          "--udp-events", f"localhost:{b.getsockname()[1]}"],
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        got = {}
        deadline = time.time() + 60
        while time.time() < deadline and not ("los" in got.get("a", {}) and "los" in got.get("b", {})):
            for name, s in (("a", a), ("b", b)):
                try:
                    data = s.recv(65536)
                except socket.timeout:
                    continue
                e = json.loads(data)
                if e.get("satellite") == "ISS":
                    got.setdefault(name, {})[e["event"]] = e
        for name in ("a", "b"):
            check("aos" in got.get(name, {}) and "los" in got.get(name, {}), f"ISS AOS and LOS to listener {name}: {got}")
        aos = got["a"]["aos"]
        # trakbox's AOS is at -2.0 deg (the manual's rule): 13:44:31, before Skyfield's 0-deg 13:45:12.
        check(aos["time"].startswith("2026-05-21T13:44") and aos["aos"].startswith(aos["time"][:19]),
              f"the AOS datagram's time: {aos}")
        check(got["a"]["los"]["time"].startswith("2026-05-21T13:55"), f"the LOS datagram: {got['a']['los']}")
        check(got["a"]["aos"] == got["b"]["aos"], "both listeners get the same datagram")
    finally:
        p.terminate()
        p.wait(30)
    r = subprocess.run([BIN, "--service", "--state", state, "--satrak-port", "0", "--udp-events", "nohost"],
                       stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=20)
    check(r.returncode == 2 and "--udp-events: 'nohost': expected HOST:PORT" in r.stderr, f"refused: {r.stderr}")


run_test(main)
