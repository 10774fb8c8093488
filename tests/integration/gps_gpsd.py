#!/usr/bin/env python3
"""The GPS receiver through a real gpsd fed by gpsfake on a loopback port (docs/gps.md).

gpsfake (Debian's gpsd-clients) starts its own gpsd on a free port and plays an NMEA log from
tests/data/gps/ (written by make_logs.py from the NMEA 0183 GGA, GSA and RMC formats). It runs with
-i: it sends one sentence each time the test writes a line to it, so what gpsd has seen is what
the test has fed, however loaded the machine is. trakbox runs as a service with its Satrak server
on another free port and a --clock far from the wall clock; nothing here reads the wall clock for a
result. Exits 77 (skipped) when gpsfake is missing, unless CI is set (then it fails).
"""
import contextlib
import json
import math
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _tbharness import BIN, SOURCE, Failure, check, free_port, run_test, sh, skip  # noqa: E402

LOGS = os.path.join(SOURCE, "tests", "data", "gps")
CLOCK = "2017-10-19T06:00:00Z"   # the logs' own date (the Satrak document's GPS_DATA? example)
LEAD = 8                         # make_logs.py: lead-in cycles before a log's first second
LINES_PER_CYCLE = 3              # GGA, GSA, RMC


def frame(payload):
    p = payload.encode("ascii")
    x = 0
    for b in p:
        x ^= b
    return b"$" + p + b"*%02X\r\n" % x


def distance_m(lat1, lon1, lat2, lon2):
    r = 6371008.8
    p1, p2 = math.radians(lat1), math.radians(lat2)
    a = math.sin((p2 - p1) / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(math.radians(lon2 - lon1) / 2) ** 2
    return 2 * r * math.asin(math.sqrt(a))


class Gpsfake:
    """gpsfake -i on a free port playing one log, a sentence per step."""

    def __init__(self, log, port=None):
        self.lines = [l for l in open(os.path.join(LOGS, log)) if l.startswith("$")]
        self.fed = 0
        # Under a loaded machine (ctest -j2 beside other tests) gpsfake's gpsd can lose the race for
        # a free port or start slowly: a start that does not list its device is tried again, on a
        # new port unless the test named one.
        for attempt in range(3):
            self.port = port or free_port()
            if self._start(log, last=attempt == 2):
                return

    def _start(self, log, last):
        self.err = tempfile.TemporaryFile()
        self.proc = subprocess.Popen(["gpsfake", "-i", "-n", "-1", "-q", "-P", str(self.port), os.path.join(LOGS, log)],
                                     stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=self.err,
                                     text=True, start_new_session=True)
        # Fed before gpsd has opened the pseudo-terminal, sentences would be lost: wait until gpsd
        # lists the device (with -n it opens it at once).
        deadline = time.time() + 20
        while True:
            try:
                with socket.create_connection(("127.0.0.1", self.port), timeout=2) as c:
                    c.sendall(b"?DEVICES;\n")
                    got = b""
                    while b'"class":"DEVICES"' not in got or not got.endswith(b"\n"):
                        chunk = c.recv(4096)
                        if not chunk:
                            break
                        got += chunk
                    if re.search(rb'"class":"DEVICES","devices":\[\{', got):
                        break
            except OSError:
                pass
            if time.time() > deadline or self.proc.poll() is not None:
                self.kill()
                if not last:
                    return False
                self.err.seek(0)
                said = self.err.read().decode("latin-1", "replace")[-300:]
                raise Failure(f"gpsfake's gpsd did not list its device on {self.port} (three tries): {said!r}")
            time.sleep(0.1)
        return True

    def feed(self, lines, pace=0.03):
        for _ in range(lines):
            self.proc.stdin.write("\n")
            self.proc.stdin.flush()
            self.fed += 1
            time.sleep(pace)

    def feed_to(self, second, pace=0.03):
        """Feeds through the RMC (the cycle's end) of the log's second `second` (0 = 06:00:00)."""
        self.feed((LEAD + second + 1) * LINES_PER_CYCLE - self.fed, pace)

    def feed_all(self, pace=0.03):
        """All but the log's tail (make_logs.py): gpsfake and its gpsd stay up."""
        self.feed(len(self.lines) - LINES_PER_CYCLE - self.fed, pace)

    def kill(self):
        """gpsfake and its gpsd, as a machine losing gpsd."""
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self.proc.wait()


class Station:
    """trakbox --service on its own state, its GPS on `gps_port`, its Satrak server on a free port."""

    def __init__(self, gps_port, extra=(), clock=CLOCK, state=None):
        self.state = state or tempfile.mkdtemp(prefix="trakbox-gps-")
        self.port = free_port()
        self.proc = subprocess.Popen([BIN, "--state", self.state, "--service", "--clock", clock, "--satrak-port",
                                      str(self.port), "--gps", f"gpsd:127.0.0.1:{gps_port}"] + list(extra),
                                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.sock = None
        self.buf = b""

    def log(self):
        try:
            with open(os.path.join(self.state, "trakbox.log")) as f:
                return f.read()
        except OSError:
            return ""

    def wait_log(self, pattern, within=20, count=1):
        deadline = time.time() + within
        while time.time() < deadline:
            if len(re.findall(pattern, self.log())) >= count:
                return
            if self.proc.poll() is not None:
                raise Failure(f"trakbox exited ({self.proc.returncode}) waiting for {pattern!r}")
            time.sleep(0.05)
        raise Failure(f"not in the log within {within} s: {pattern!r}\n{self.log()}")

    def ask(self, payload):
        if self.sock is None:
            deadline = time.time() + 15
            while self.sock is None:
                try:
                    self.sock = socket.create_connection(("127.0.0.1", self.port), timeout=10)
                except OSError:
                    if time.time() > deadline:
                        raise Failure("no Satrak server")
                    time.sleep(0.05)
        self.sock.sendall(frame(payload))
        while b"\r\n" not in self.buf:
            chunk = self.sock.recv(4096)
            check(chunk, f"connection closed after {payload}")
            self.buf += chunk
        line, self.buf = self.buf.split(b"\r\n", 1)
        return line + b"\r\n"

    def wait_reply(self, payload, reply, within=15):
        """Asks until the reply is exactly frame(reply); fails showing the last one otherwise."""
        deadline = time.time() + within
        got = b""
        while time.time() < deadline:
            got = self.ask(payload)
            if got == frame(reply):
                return got
            time.sleep(0.05)
        raise Failure(f"{payload}: expected {frame(reply)!r}, last {got!r}")

    def wait_reply_like(self, payload, pattern, within=15):
        """Asks until the reply matches the bytes pattern; fails showing the last one otherwise."""
        deadline = time.time() + within
        got = b""
        while time.time() < deadline:
            got = self.ask(payload)
            if re.match(pattern, got):
                return got
            time.sleep(0.02)
        raise Failure(f"{payload}: expected {pattern!r}, last {got!r}")

    def status(self):
        """`trakbox status --json`: (exit status, the document)."""
        code, out, err = sh(BIN, "status", "--state", self.state, "--json")
        check(out.strip(), f"trakbox status printed nothing ({code}): {err}")
        return code, json.loads(out)

    def stop(self):
        if self.sock:
            self.sock.close()
        self.proc.send_signal(signal.SIGTERM)
        self.proc.wait(20)
        with open(os.path.join(self.state, "trakbox-state.json")) as f:
            return json.load(f)["data"]

    def cleanup(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        shutil.rmtree(self.state, ignore_errors=True)


@contextlib.contextmanager
def replayed(log, extra=("--gps-follow", "yes"), pace=0.03):
    """A station on a gpsd that has been fed the whole of `log`."""
    fake = Gpsfake(log)
    st = Station(fake.port, list(extra))
    try:
        st.wait_log(r"GPS: connected")
        fake.feed_all(pace)
        yield st
    finally:
        st.cleanup()
        fake.kill()


def moves(log):
    """The station's moves to GPS positions, as (lat, lon, height)."""
    return [tuple(map(float, m)) for m in re.findall(r"GPS: the station is now at (\S+) (\S+) (\S+) m", log)]


def passes(station):
    code, out, err = sh(BIN, "passes", os.path.join(SOURCE, "data", "amateur.tle"), "--station", station,
                        "--start", "2026-05-21T12:00:00Z", "--hours", "24", "--json", timeout=120)
    check(code == 0, f"passes: {err}")
    return json.loads(out)


def fixed_station():
    """A fixed station: the position taken once (jitter under the threshold), the passes as typed;
    GPS_DATA? with the exact bytes of the document's example; GPS time against the clock."""
    fake = Gpsfake("fixed.nmea")
    st = Station(fake.port, ["--gps-follow", "yes"], clock="2017-10-19T07:00:00Z")  # an hour ahead of GPS
    try:
        st.wait_log(r"GPS: connected to gpsd at 127\.0\.0\.1")
        fake.feed_to(2)
        got = st.wait_reply("GPS_DATA?", "GPS_DATA?,41.0100N,29.1700E,1,6,0,2,19,10,17")
        print("GPS_DATA? after the log's 06:00:02:", got)
        st.wait_log(r"GPS: the station is now at 41\.010000 29\.170000 120\.0 m \(fix of 2017-10-19T0[56]:")
        st.wait_log(r"GPS: the clock is 3\d\d\d\.\d{3} s ahead of GPS time")
        check(st.ask("STATUS?").split(b",")[10:12] == [b"0", b"0"], "STATUS X10 before RTC_REUPDATE")
        fake.feed_all()
        st.wait_reply("GPS_DATA?", "GPS_DATA?,41.0100N,29.1700E,1,6,0,11,19,10,17")
        check(st.ask("ERRSTATUS?") == frame("ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,0"), "ERRSTATUS with a receiver")
        check(st.ask("RTC_REUPDATE=") == frame("RTC_REUPDATE=,OK"), "RTC_REUPDATE=")
        t = st.ask("TIME?").decode()
        check(re.fullmatch(r"\$TIME\?,6,0,(1[1-9]|[2-5]\d),19,10,2017,\d+\*[0-9A-F]{2}\r\n", t), f"TIME? after: {t!r}")
        check(st.ask("STATUS?").split(b",")[10] == b"1", "STATUS X10 after RTC_REUPDATE")
        # trakbox status: the receiver, its fix and position, and the clock an hour ahead of GPS time.
        code, doc = st.status()
        g = doc["gps"]
        check(g["link"] == "receiving" and g["fix"] and g["follow"], f"status gps: {g}")
        check(distance_m(g["position"]["lat_deg"], g["position"]["lon_deg"], 41.01, 29.17) < 5 and g["position"]["mode"] == 3,
              f"status gps position (the receiver's latest, jitter and all): {g['position']}")
        check(-3700 < g["clock_error_s"] < -3500 and g["clock_warned"], f"status gps clock: {g}")
        check(code == 1 and any(p.startswith("GPS: GPS TIME -3") for p in doc["problems"]),
              f"a clock an hour off GPS time is a problem: {code} {doc['problems']}")
        print("trakbox status:", g["text"], "| problems:", doc["problems"])
        log = st.log()
        check(len(moves(log)) == 1, f"jitter moved the station: {moves(log)}")
        check(log.count("the clock is") == 1, "the clock warned about more than once")
        data = st.stop()
        s = data["station"]
        check((s["lat_deg"], s["lon_deg"], s["height_m"]) == (41.01, 29.17, 120.0), f"stored station {s}")
        check(data["gps"]["position_from_gps"] and data["gps"]["follow"], f"gps state {data['gps']}")
        check(data["gps"]["source"] == f"gpsd:127.0.0.1:{fake.port}", f"gps source {data['gps']}")
        from_gps = passes("%.9f,%.9f,%.3f" % (s["lat_deg"], s["lon_deg"], s["height_m"]))
        typed = passes("41.01,29.17,120")
        check(len(typed) > 10 and from_gps == typed, "passes from the GPS position differ from the typed one")
        print(f"passes from GPS = passes typed in: {len(typed)} passes; e.g. {typed[1]['sat']} "
              f"AOS {typed[1]['aos_utc']} TCA {typed[1]['tca_utc']} LOS {typed[1]['los_utc']} "
              f"max {typed[1]['max_el_deg']} deg")
    finally:
        st.cleanup()
        fake.kill()


def rover():
    """A rover driving 10 km east at 250 m a report; threshold 900 m: the station follows in steps of
    1000 m (every fourth report: 750 m is within the threshold) and ends where the rover stopped."""
    fake = Gpsfake("rover.nmea")
    st = Station(fake.port, ["--gps-follow", "yes", "--gps-threshold", "900"])
    try:
        st.wait_log(r"GPS: connected")
        # Cycle by cycle: once GPS_DATA? shows the cycle's second, GPS_SETTINGS? shows where the
        # station is (the log keeps only so many lines of one kind a minute: it is not counted on).
        where = []
        for second in range(0, 46):
            fake.feed_to(second, pace=0.01)
            st.wait_reply_like("GPS_DATA?", rb"\$GPS_DATA\?,41\.0100N,29\.\d{4}E,1,6,0,%d,19,10,17\*" % second)
            lat, lon = st.ask("GPS_SETTINGS?").decode().split("*")[0].split(",")[2:4]
            where.append((float(lat[:-1]), float(lon[:-1])))
        m = [w for i, w in enumerate(where) if i == 0 or w != where[i - 1]]
        check(len(m) == 11, f"{len(m)} positions for 10 km at a 900 m threshold (the start and ten of 1000 m): {m}")
        for a, b in zip(m, m[1:]):
            check(abs(distance_m(a[0], a[1], b[0], b[1]) - 1000.0) < 10.0, f"a move of other than 1000 m: {a} -> {b}")
        data = st.stop()
        end = (data["station"]["lat_deg"], data["station"]["lon_deg"])
        check(abs(distance_m(41.01, 29.17, end[0], end[1]) - 10000.0) < 1.0, f"the station ended at {end}")
        print(f"rover: the station took {len(m)} positions, the last {distance_m(41.01, 29.17, *end):.1f} m east")
    finally:
        st.cleanup()
        fake.kill()


def fix_lost_and_2d():
    """A fix, lost for 5 s (said once, the position kept), regained 2 km north; then a 2D fix keeps the
    stored height."""
    fake = Gpsfake("fix_lost.nmea")
    st = Station(fake.port, ["--gps-follow", "yes"])
    try:
        st.wait_log(r"GPS: connected")
        fake.feed_to(6)
        st.wait_log(r"GPS: fix lost; the station keeps 41\.0100N 29\.1700E 120\.0 m")
        deadline = time.time() + 10  # no fix: the last position, valid 0 (the time is the RTC's)
        while not st.ask("GPS_DATA?").startswith(b"$GPS_DATA?,41.0100N,29.1700E,0,"):
            check(time.time() < deadline, "GPS_DATA? did not say the fix was lost")
            time.sleep(0.05)
        fake.feed_all()
        st.wait_log(r"GPS: the station is now at 41\.0279\d+ 29\.170000 120\.0 m")
        log = st.log()
        check(log.count("fix lost") == 1, "fix lost said more than once")
        check(log.count("GPS: fix confirmed") == 2, "fix confirmed: once at first, once when regained")
        check(len(moves(log)) == 2, f"moves: {moves(log)}")
        st.stop()
    finally:
        st.cleanup()
        fake.kill()
    with replayed("fix_2d.nmea") as st:
        st.wait_log(r"GPS: the station is now at 41\.010000 29\.170000 50\.0 m")  # the factory height kept
        st.stop()


def gpsd_killed_and_restarted():
    """No gpsd at first (said once although retried), gpsd comes, goes (killed) and comes back on the
    same port: each said once, ERRSTATUS X12 follows, the position is kept throughout."""
    port = free_port()
    st = Station(port, ["--gps-follow", "yes"])
    fake = None
    try:
        st.wait_log(r"GPS: no gpsd at 127\.0\.0\.1:%d" % port)
        check(st.ask("ERRSTATUS?") == frame("ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,1"), "X12 without gpsd")
        st.wait_reply("GPS_DATA?", "GPS_DATA?,27.3910N,128.6570E,0,6,0,%s,19,10,17" % st.ask("TIME?").split(b",")[3].decode(), 2)
        time.sleep(4.5)  # two more tries
        check(st.log().count("GPS: no gpsd") == 1, "no gpsd said more than once")
        fake = Gpsfake("fixed.nmea", port)
        st.wait_log(r"GPS: connected to gpsd", within=20)
        fake.feed_to(3)
        st.wait_log(r"GPS: the station is now at 41\.01")
        check(st.ask("ERRSTATUS?") == frame("ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,0"), "X12 with gpsd")
        fake.kill()
        st.wait_log(r"GPS: gpsd at 127\.0\.0\.1:%d went away" % port)
        check(st.ask("ERRSTATUS?") == frame("ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,1"), "X12 after gpsd went")
        code, doc = st.status()
        check(code == 1 and "GPS: GPSD LOST" in doc["problems"] and round(doc["gps"]["position"]["lat_deg"], 3) == 41.01,
              f"status with gpsd gone: {code} {doc['problems']} {doc['gps']}")
        check(st.ask("GPS_DATA?").startswith(b"$GPS_DATA?,41.0100N,29.1700E,0,"), "the last position kept")
        time.sleep(4.5)
        log = st.log()
        check(log.count("went away") == 1 and log.count("GPS: no gpsd") == 1, "gpsd's absence said more than once")
        fake = Gpsfake("fixed.nmea", port)
        st.wait_log(r"GPS: connected to gpsd", within=20, count=2)
        fake.feed_to(3)
        st.wait_log(r"GPS: fix confirmed", count=2)
        check(st.ask("ERRSTATUS?") == frame("ERRSTATUS?,0,0,0,0,0,0,0,0,0,0,0,0"), "X12 with gpsd back")
        check(len(moves(st.log())) == 1, "the station moved again for the same position")
        st.stop()
    finally:
        st.cleanup()
        if fake:
            fake.kill()


def jump_and_nonsense():
    """One report 100 km away and two with latitude 95: each said once, the station stays put."""
    with replayed("jump_nonsense.nmea") as st:
        st.wait_reply("GPS_DATA?", "GPS_DATA?,41.0100N,29.1700E,1,6,0,13,19,10,17")
        log = st.log()
        check(log.count("GPS: position jumped 100.0 km in 1.0 s") == 1, f"jump:\n{log}")
        # gpsd itself leaves out a latitude of 95 degrees: a 3D fix without one.
        check(log.count("GPS: report ignored: a 3D fix without a latitude") == 1, f"nonsense:\n{log}")
        check(len(moves(log)) == 1 and moves(log)[0][:2] == (41.01, 29.17), f"moves: {moves(log)}")
        data = st.stop()
        check((data["station"]["lat_deg"], data["station"]["lon_deg"]) == (41.01, 29.17), "stored station")


def no_fix():
    """A receiver without a fix: said once; GPS_DATA? valid 0; the station does not move."""
    with replayed("no_fix.nmea") as st:
        st.wait_log(r"GPS: no fix yet")
        time.sleep(0.5)
        check(st.log().count("GPS: no fix yet") == 1, "no fix said more than once")
        check(st.ask("GPS_DATA?").startswith(b"$GPS_DATA?,27.3910N,128.6570E,0,"), "GPS_DATA? without a fix")
        check(st.ask("RTC_REUPDATE=") == frame("RTC_REUPDATE=,ERR,8,NO GPS FIX"), "RTC_REUPDATE= without a fix")
        check(not moves(st.log()), "moved without a fix")
        st.stop()


def main():
    if shutil.which("gpsfake") is None:
        if os.environ.get("CI"):
            raise Failure("gpsfake is missing (Debian's gpsd-clients; scripts/install-deps.sh)")
        skip("gpsfake is missing (Debian's gpsd-clients): skipped")
    fixed_station()
    rover()
    fix_lost_and_2d()
    gpsd_killed_and_restarted()
    jump_and_nonsense()
    no_fix()


if __name__ == "__main__":
    run_test(main)
