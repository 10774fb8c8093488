"""A receiver as the downlink radio (issue 48): `--radio gqrx:127.0.0.1:PORT` against a responder
with GQRX 2.15's remote-control answers, through a whole SO-50 pass (FM, 67.0 Hz tone) at
--clock-rate 40, then a second program taking GQRX's one client.

The responder answers what GQRX answers (`f`, `F hz`, `m`, `M mode passband`, `v`, `V VFOA`, `s`,
`\\dump_state`, `_`, `l`, `l STRENGTH`, `u ?`, `AOS`, `LOS`) and `RPRT 1` (positive, never a Hamlib code)
to everything else: `\\chk_vfo`, `\\get_vfo_list`, `\\get_powerstat`, `S`, `i`, `I`, `F VFOA hz`, `C`, `t`,
`T`. It keeps one client: a new connection closes the one before.

Checked: every `F` on SO-50's Doppler (the clock of each `F` fitted from the wall time at the clock
rate), the error printed and within one Doppler step (100 Hz for FM) plus one tick's change; no
command GQRX refuses is sent; no `link-lost` event; `status` healthy with the uplink "not sent", no
`sent_hz`, `failures` 0 and the limits "GQRX: no CTCSS, no uplink". Then a second client connects
and stays 3 s: trakbox's connection is closed by the responder; the log says once that another
program holds GQRX's remote control, trakbox does not knock the other program off while it holds it
(no reconnect within the hold-off), and it is back after it left.

Then SDR++'s rigctl server (one client at a time: the next is served only when the one before has
gone) held by another program when trakbox starts: the log says once that another program may hold
it, and trakbox is connected once the other program leaves.
"""
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
from datetime import datetime, timedelta

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (BIN, SOURCE, check, leave_and_read_log, poll, reap, run_test, satellite_track, sh,  # noqa: E402
                        socket_lines)

RATE = 40
SPOT = 436_795_000           # SO-50's downlink
STEP = 100                   # trakbox's factory Doppler step for FM
STATION = "27.391,128.657,50"


class Gqrx:
    """GQRX 2.15's remote control on a free loopback port: one client at a time (a new one closes the
    one before), its answers, every command line kept with its time."""

    # `u ?`: what `u` reads, as GQRX's remote_control.cpp lists it (trakbox asks at connect: the
    # recorder's capability, docs/radio.md "Recording a pass").
    ANSWERS = {"v": "VFOA", "s": "0\nVFOA", "_": "Gqrx 2.15", "l": "-62.3", "l STRENGTH": "-62.3",
               "u ?": "RECORD IQRECORD DSP RDS MUTE",
               "\\dump_state": "0\n2\n1\n0.000000 2000000000.000000 0x1ff -1 -1 0x10000003 0x0\n0 0 0 0 0 0 0\n0 0 0 0 0 0 0\n0x1ff 1\n0x1ff 0\n0 0\n0x1e 2400\n0x2 500\n0x1 8000\n0x1 2400\n0x20 15000\n0x20 8000\n0x40 200000\n0 0\n9990\n9990\n10000\n0\n10\n10 20 30\n0xffffffff\n0xffffffff\n0xf7ffffff\n0x83ffffff\n0xffffffff\n0xffffffbf"}

    def __init__(self):
        self.sock = socket.socket()
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(4)
        self.port = self.sock.getsockname()[1]
        self.lock = threading.Lock()
        self.hz, self.mode = 145_000_000, "FM"
        self.commands = []       # (wall time, line, connection number)
        self.client = None
        self.connections = 0
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self):
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            with self.lock:
                self.connections += 1
                n = self.connections
                self._admit(c)
            self._start(c, n)

    def _admit(self, c):
        """GQRX keeps one client: the one before goes."""
        if self.client:
            try:
                self.client.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            self.client.close()
        self.client = c

    def _start(self, c, n):
        threading.Thread(target=self._serve, args=(c, n), daemon=True).start()

    def answer(self, line):
        words = line.split()
        if line in self.ANSWERS:
            return self.ANSWERS[line]
        if line == "f":
            return str(self.hz)
        if line == "m":
            return f"{self.mode}\n10000"
        if len(words) == 2 and words[0] == "F":
            try:
                self.hz = int(float(words[1]))
            except ValueError:
                return "RPRT 1"
            return "RPRT 0"
        if words[:1] == ["M"] and len(words) in (2, 3) and words[1] in ("OFF", "RAW", "AM", "LSB", "USB", "CW", "FM", "WFM"):
            self.mode = words[1]
            return "RPRT 0"
        if line in ("V VFOA", "AOS", "LOS"):
            return "RPRT 0"
        return "RPRT 1"

    def _serve(self, c, n):
        try:
            for raw in socket_lines(c):
                line = raw.decode(errors="replace").strip()
                with self.lock:
                    self.commands.append((time.time(), line, n))
                    reply = self.answer(line)
                c.sendall(reply.encode() + b"\n")
        except OSError:
            pass

    def sent(self, pred):
        with self.lock:
            return [(t, line, n) for t, line, n in self.commands if pred(line)]

    def close(self):
        self.sock.close()
        with self.lock:
            if self.client:
                self.client.close()


class Sdrpp(Gqrx):
    """SDR++'s rigctl server: one client at a time (the next is served only when the one before has
    gone), `M` wants its passband, `v` is "VFO"."""

    def _admit(self, c):
        pass

    def _start(self, c, n):
        self._serve(c, n)   # here, in the accepting thread: nobody else is served meanwhile
        c.close()

    def answer(self, line):
        words = line.split()
        if line == "v":
            return "VFO"
        if line == "\\chk_vfo":
            return "CHKVFO 0"
        if words[:1] == ["M"]:
            if len(words) != 3:
                return "RPRT 1"
            self.mode = words[1]
            return "RPRT 0"
        if line in ("V VFOA", "l", "l STRENGTH", "\\get_powerstat"):
            return "RPRT 1"
        return super().answer(line)


def sdrpp_held_by_another():
    """SDR++ held by another program when trakbox starts: one line saying so, then tuned once the
    other program leaves."""
    rig = Sdrpp()
    other = socket.create_connection(("127.0.0.1", rig.port))
    other.sendall(b"f\n")
    other.recv(64)
    state = tempfile.mkdtemp(prefix="trakbox-sdrpp-")
    procs = []
    try:
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--radio", f"sdrpp:127.0.0.1:{rig.port}",
                               "--elements-url", "file://" + os.path.join(SOURCE, "data", "amateur.tle")],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        log_path = os.path.join(state, "trakbox.log")
        poll("the log to say another program may hold SDR++", lambda: os.path.exists(log_path) and
             "another program may hold SDR++'s remote control" in open(log_path).read(), 15)
        time.sleep(4)
        other.close()
        poll("trakbox served by SDR++", lambda: any(n > 1 for _, _, n in rig.sent(lambda line: line == "f")), 20)
        # Its answer read and said before trakbox is told to leave (the reply may still be on its way).
        poll("trakbox to say SDR++ answers", lambda: "radio SDR++ at 127.0.0.1:" in open(log_path).read() and
             ": connected" in open(log_path).read(), 10)
        log = leave_and_read_log(tb, state, procs)
        said = log.count("another program may hold SDR++'s remote control")
        check(said == 1, f"said once while held ({said})")
        check("radio SDR++ at 127.0.0.1:" in log and ": connected" in log, "connected once served")
        print(f"sdr_receivers SDR++: held by another program: {said} log line, "
              f"{log.count('event: link-lost')} link-lost; connected once it left")
    finally:
        reap(procs)
        rig.close()
        shutil.rmtree(state, ignore_errors=True)


def so50_pass():
    """SO-50's pass over the factory station around 2026-05-21 14:10 UTC: (AOS, LOS) as datetimes."""
    code, out, err = sh(BIN, "passes", os.path.join(SOURCE, "data", "amateur.tle"), "--sat", "SO-50",
                        "--station", STATION, "--start", "2026-05-21T13:40:00Z", "--hours", "1", "--json")
    check(code == 0, f"passes: {err}")
    p = json.loads(out)[0]
    iso = lambda s: datetime.fromisoformat(s.replace("Z", "+00:00"))  # noqa: E731
    return iso(p["aos_utc"]), iso(p["los_utc"])


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=30)
    return r.returncode, json.loads(r.stdout) if r.stdout.strip().startswith("{") else {}


def tuning_error(fs, start, aos, los):
    """Each F against SO-50's Doppler: the clock of an F is start + RATE * (its wall time - w0), w0
    fitted (the median over the pass); returns the worst error in Hz and the worst allowed (one
    Doppler step plus the change over one tick of the clock at that point)."""
    track = satellite_track(aos, int((los - aos).total_seconds()) + 1, sat="SO-50", station=STATION, freq=SPOT)
    want = [SPOT + row["doppler_hz"] for row in track]          # one a second from AOS

    def at(sec):   # the expected frequency at `sec` seconds after AOS (linear between rows)
        i = max(0, min(len(want) - 2, int(sec)))
        return want[i] + (want[i + 1] - want[i]) * (sec - i)

    def when(hz):  # the second after AOS at which the Doppler is hz (it falls through the pass)
        for i in range(len(want) - 1):
            if want[i] >= hz >= want[i + 1]:
                return i + (want[i] - hz) / (want[i] - want[i + 1])
        return None

    offset = (aos - start).total_seconds()
    fits = sorted(when(hz) - (offset + RATE * (t - fs[0][0])) for t, hz in fs if when(hz) is not None)
    w0 = fits[len(fits) // 2]
    worst, allowed = 0.0, 0.0
    for t, hz in fs:
        sec = offset + RATE * (t - fs[0][0]) + w0
        if not 5 <= sec <= len(want) - 5:
            continue
        err = hz - at(sec)
        tick = abs(at(sec + 1) - at(sec))
        if abs(err) > abs(worst):
            worst = err
        allowed = max(allowed, STEP + tick)
        check(abs(err) <= STEP + tick + 60, f"F {hz} at {sec:.0f} s after AOS: {err:+.0f} Hz off SO-50's Doppler "
                                             f"(step {STEP} Hz, a tick {tick:.0f} Hz)")
    return worst, allowed


def main():
    aos, los = so50_pass()
    start = aos - timedelta(seconds=40)
    rig = Gqrx()
    state = tempfile.mkdtemp(prefix="trakbox-gqrx-")
    procs = []
    try:
        t0 = time.time()
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock",
                               start.strftime("%Y-%m-%dT%H:%M:%SZ"), "--clock-rate", str(RATE),
                               "--radio", f"gqrx:127.0.0.1:{rig.port}",
                               "--elements-url", "file://" + os.path.join(SOURCE, "data", "amateur.tle")],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        tb.stdin.write(b"S\r5\r")   # single tracking of the shipped list's #5, SO-50
        tb.stdin.flush()
        poll("SO-50's downlink on GQRX", lambda: abs(rig.hz - SPOT) < 12_000, 20)
        # Mid-pass: healthy, the uplink not sent, no failure, the receiver's limits.
        poll("the status to show the receiver's limits",
             lambda: "no uplink" in (status(state)[1].get("radios") or [{}])[0].get("limits", ""), 15)
        code, s = status(state)
        radio = s["radios"][0]
        up = radio["links"]["uplink"]
        check(code == 0 and s["healthy"], f"status healthy mid-pass: {code} {s.get('problems')}")
        check(up["state"] == "not sent" and up["sent_hz"] is None and "--uplink-radio" in up["message"],
              f"the uplink is not sent and points to --uplink-radio: {up}")
        check(radio["failures"] == 0 and not radio["fault"], f"no failure, no fault: {radio}")
        check(radio["limits"] in ("GQRX: no CTCSS, no uplink", "GQRX: no uplink, no CTCSS"), f"limits: {radio['limits']}")
        # The rest of the pass, to LOS.
        poll("the clock past LOS", lambda: datetime.fromisoformat(status(state)[1].get("time", "2000-01-01T00:00:00Z")
                                                                   .replace("Z", "+00:00")) > los, 60, every=0.5)
        fs = [(t, int(line.split()[1])) for t, line, _ in rig.sent(lambda line: line.startswith("F "))]
        check(len(fs) >= 20, f"Doppler updates through the pass: {len(fs)}")
        worst, allowed = tuning_error(fs, start, aos, los)
        refused = rig.sent(lambda line: rig.answer(line) == "RPRT 1" and not line.startswith("F "))
        check(not refused, f"nothing GQRX refuses was sent: {refused[:5]}")
        code, s = status(state)
        check(code == 0 and s["radios"][0]["failures"] == 0, f"failures 0 after the pass: {s.get('radios')}")
        pass_s = time.time() - t0

        # A second program takes GQRX's one client; it stays 3 s.
        before = rig.connections
        other = socket.create_connection(("127.0.0.1", rig.port))
        other.sendall(b"f\n")
        other.recv(64)
        time.sleep(3)
        check(rig.connections == before + 1, f"trakbox did not knock the other program off: {rig.connections - before} connections")
        other.close()
        poll("trakbox back on GQRX", lambda: rig.connections >= before + 2, 15)
        log = leave_and_read_log(tb, state, procs)
        held = log.count("another program holds GQRX's remote control")
        check(held == 1, f"the log says once that another program holds GQRX ({held})")
        pass_log = log.split("another program holds")[0]
        check("event: link-lost" not in pass_log, "no link-lost event through the pass")
        check(log.count("event: link-lost") <= 1 and log.count("event: link-back") <= 1,
              "at most one link-lost / link-back pair for the takeover")
        print(f"sdr_receivers GQRX: SO-50 pass at x{RATE}: {len(fs)} F commands, worst tuning error {worst:+.0f} Hz "
              f"(allowed {allowed:.0f}: step {STEP} Hz + a tick), 0 failures, 0 link-lost, uplink not sent, "
              f"limits \"{radio['limits']}\"; {pass_s:.1f} s; takeover: {held} log line, "
              f"{log.count('event: link-lost')} link-lost")
    finally:
        reap(procs)
        rig.close()
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(lambda: (main(), sdrpp_held_by_another()))
