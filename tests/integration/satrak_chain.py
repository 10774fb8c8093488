"""One trakbox driving another as its Satrak ACU, both the real program: trakbox A is the antenna
control unit (simulated rotator, Satrak server on a free loopback port); trakbox B runs the menus
with `--rotator satrak:127.0.0.1:PORT` and tracks the ISS pass of 2026-05-21 05:33-05:45 UTC (seen
from the factory station) with menu S, from 05:39:45. A's antenna follows the satellite; when A goes away, B
reports the lost link and stops; when A comes back on the same port, B reconnects and A's antenna
follows again. B's host mode on TCP reads B's view of the antenna meanwhile.
"""
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timedelta, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (BIN, Failure, check, free_port, pointing_error, reap, run_test,  # noqa: E402
                        satellite_track, sh)

# Past culmination (az 93, el 38 and falling): the resting antennas (North) reach it in seconds.
START = datetime(2026, 5, 21, 5, 39, 45, tzinfo=timezone.utc)
CLOCK = START.strftime("%Y-%m-%dT%H:%M:%SZ")


# Menu 4: Enter keeps callsign, latitude, longitude and height; rotor start North; Enter keeps the
# baud rate. The pass runs 210 -> 180 -> 48 deg: through South, clear of a North-start rotor's stop,
# so neither trakbox has to swing round or flip over the top.
NORTH_START = b"4\r\r\r\r\rN\r\r\r"


def start_acu(state, port):
    p = subprocess.Popen([BIN, "--state", state, "--line", "--clock", CLOCK, "--satrak-port", str(port)],
                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    p.stdin.write(NORTH_START)
    p.stdin.flush()
    return p


def acu_position(port):
    """A's antenna as A's own Satrak server reports it (STATUS? X2, X3: true az/el)."""
    code, out, _ = sh(BIN, "satrak", f"127.0.0.1:{port}", "--timeout", "2", "STATUS?", timeout=10)
    if code != 0:
        return None
    f = out.strip().split(",")
    return float(f[2]), float(f[3])


def wait_for_acu(port, limit=15):
    deadline = time.time() + limit
    while acu_position(port) is None:
        if time.time() > deadline:
            raise Failure(f"trakbox A never answered on {port}")
        time.sleep(0.3)


def follows(port, t0, samples_needed, limit):
    """Samples A's antenna until it has sat on the ISS track `samples_needed` times."""
    good, worst, last = 0, 0.0, None
    deadline = time.time() + limit
    while time.time() < deadline and good < samples_needed:
        time.sleep(1.5)
        pos = acu_position(port)
        if pos is None:
            continue
        now = START + timedelta(seconds=time.time() - t0)
        # On the track as it was within the last eight seconds: B's 1 s ticks, its 250 ms STATUS?
        # polls, A's own tick and the simulated slew make the chain lag a few seconds; the dead
        # band (1.06 deg az, 0.18 deg el) and a count of each axis bound the rest.
        rows = satellite_track(now - timedelta(seconds=8), 9)
        err = min(pointing_error(pos[0], pos[1], r["az_deg"], r["el_deg"]) for r in rows)
        last = (pos, (rows[-1]["az_deg"], rows[-1]["el_deg"]), round(err, 2))
        print(f"  {time.time() - t0:5.1f}s antenna {pos} err {err:.2f}") if os.environ.get("VERBOSE") else None
        if err < 2.5:
            good += 1
            worst = max(worst, err)
    return good, worst, last


class HostClient:
    """B's host mode on TCP."""

    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.until(b"TrakBox>>")

    def until(self, marker):
        data = b""
        while marker not in data:
            chunk = self.sock.recv(4096)
            if not chunk:
                break
            data += chunk
        return data

    def ask(self, line):
        self.sock.sendall(line.encode() + b"\r")
        return self.until(b"TrakBox>>").decode()

    def close(self):
        self.sock.close()


def main():
    acu_port, host_port = free_port(), free_port()
    state_a = tempfile.mkdtemp(prefix="trakbox-acu-")
    state_b = tempfile.mkdtemp(prefix="trakbox-driver-")
    procs = []
    try:
        a = start_acu(state_a, acu_port)
        procs.append(a)
        wait_for_acu(acu_port)
        b = subprocess.Popen([BIN, "--state", state_b, "--line", "--clock", CLOCK, "--satrak-port", "0",
                              "--rotator", f"satrak:127.0.0.1:{acu_port}", "--host-port", str(host_port)],
                             stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(b)
        t0 = time.time()
        # Menu S on B: single tracking with rotor control on; the ISS is #4 of the shipped list.
        b.stdin.write(NORTH_START + b"S\r4\r")
        b.stdin.flush()

        good, worst, last = follows(acu_port, t0, 6, 60)
        check(good >= 6, f"A's antenna never followed the ISS for B; last antenna/expected/error {last}")
        print(f"satrak_chain: A followed the ISS for B in {good} samples (worst {worst:.2f} deg)")

        # B's own view of the antenna (host mode ?A) is A's reading.
        deadline = time.time() + 15
        while True:
            host = HostClient(host_port)
            m = re.match(r"AZ([\d.]+) EL([\d.]+)", host.ask("?A"))
            host.close()
            pos = acu_position(acu_port)
            if m and pos and pointing_error(float(m.group(1)), float(m.group(2)), *pos) < 2.0:
                break
            if time.time() > deadline:
                raise Failure(f"B's ?A {m and m.group(0)} does not match A's antenna {pos}")
            time.sleep(0.5)

        # A goes away: B says so (its log names the link), and its ?A refuses or reports the fault.
        a.send_signal(signal.SIGKILL)
        a.wait(10)
        log_b = os.path.join(state_b, "trakbox.log")
        deadline = time.time() + 15
        while True:
            with open(log_b, encoding="utf-8", errors="replace") as f:
                log = f.read()
            if re.search(r"(?i)satrak.*(lost|refused|fault|not answering|connect)", log):
                break
            if time.time() > deadline:
                raise Failure(f"B did not report losing A; log tail:\n{log[-1500:]}")
            time.sleep(0.3)
        check(b.poll() is None, "B keeps running without its ACU")

        # A comes back on the same port: B reconnects (backoff at most 8 s) and A follows again (the
        # restarted simulated antenna starts from its rest position: allow for the slew).
        a = start_acu(state_a, acu_port)
        procs.append(a)
        wait_for_acu(acu_port)
        good, worst, last = follows(acu_port, t0, 3, 60)
        check(good >= 3, f"after A restarted, its antenna did not follow the ISS again; last {last}")
        print(f"satrak_chain: after A restarted, A followed again in {good} samples (worst {worst:.2f} deg)")

        b.stdin.close()
        check(b.wait(20) == 0, "B leaves cleanly when its input ends")
        a.stdin.close()
        check(a.wait(20) == 0, "A leaves cleanly when its input ends")
    finally:
        reap(procs)
        shutil.rmtree(state_a, ignore_errors=True)
        shutil.rmtree(state_b, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
