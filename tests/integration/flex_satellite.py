"""A FlexRadio 6000/8000 over the SmartSDR TCP/IP API (issue 61): `--radio flex:127.0.0.1:PORT`
against a responder of our own speaking the API (FlexRadio's wiki, "SmartSDR TCPIP API", "TCPIP
slice", "SmartSDR Status Responses"): `V1.4.0.0` and `H<handle>` on connect, `R<seq>|<hex>|data`
replies, `S<handle>|slice N ...` status lines; its slices tune the bands it is given (HF and the
transverters it has) and refuse anything else with a non-zero status.

RS-44, its whole pass (AOS 10:46:57, LOS 11:08:48 on 2026-05-21) at --clock-rate 20, `:duplex`: the
radio has slice 0 (tx=1, 14.2 MHz), which carries the uplink; the downlink gets a slice of its own
(`slice create freq=... mode=USB`, the reply's data its index). The command lines are checked
exactly; every `slice tune` against RS-44's Doppler at the station time it was sent (the clock
fitted as in sdr_receivers.py); the operator turns the downlink slice 10 kHz up in SmartSDR (an
S line from another client's handle): trakbox follows (the uplink moves 10 kHz down, RS-44 being
inverting, and the downlink tracks the new spot). Mid-pass the status is healthy, no limits.
Then 8 s near culmination at the real rate: the worst tuning error of each link, sampled every
0.2 s (update lag included), comparable with the other rows of docs/radio.md.
SO-50 in FM: the 67.0 Hz tone on the transmit slice (`fm_tone_mode=CTCSS_TX fm_tone_value=67.0`).
After the connection closed mid-pass: the slices taken again, none created.
Then a radio with a 2 m transverter only: the downlink slice's `slice tune 0 435...` is refused
(R|50000004|...): a limit ("no 70 cm", in the log and the status's limits, said once, not sent
again), never a lost link; the uplink is tuned on slice 1 and marked `tx=1`.
"""
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import threading
import time
from datetime import datetime, timedelta, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _ptyradio import C, RS44_PASS, SO50_PASS, SPOTS  # noqa: E402
from _rigs2026 import worst_error  # noqa: E402
from _tbharness import (BIN, SOURCE, check, leave_and_read_log, poll, reap, run_test, satellite_track,  # noqa: E402
                        socket_lines)

RATE = 20
STATION = "27.391,128.657,50"
AOS = datetime(2026, 5, 21, 10, 46, 57, tzinfo=timezone.utc)
LOS = datetime(2026, 5, 21, 11, 8, 48, tzinfo=timezone.utc)
STEP = 20                  # trakbox's factory Doppler step for SSB
HF = (30_000, 54_000_000)
XVTR_2M = (144_000_000, 148_000_000)
XVTR_70CM = (420_000_000, 450_000_000)
GUI = "12AB34CD"           # the handle of SmartSDR's own window: the operator's knob
TUNE = re.compile(r"slice tune (\d+) (\d+\.\d{6})$")


class Flex:
    """A FlexRadio's SmartSDR API on a free loopback port: slices (frequency, mode, tx), the bands its
    slices tune, every command line kept with its time."""

    MODES = ("USB", "LSB", "CW", "FM", "NFM", "AM", "DIGU", "DIGL")

    def __init__(self, slices, bands, duplex=True, handle="6F4EC23D"):
        self.slices = {n: dict(s) for n, s in slices.items()}
        self.bands, self.duplex, self.handle = bands, duplex, handle
        self.lock = threading.Lock()
        self.lines = []        # (wall time, "C<seq>|command", connection number)
        self.client = None
        self.connections = 0
        self.sock = socket.socket()
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(2)
        self.port = self.sock.getsockname()[1]
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self):
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            with self.lock:
                self.client = c
                self.connections += 1
                n = self.connections
                self._send(f"V1.4.0.0\nH{self.handle}\nS{self.handle}|radio slices=4 full_duplex_enabled=0")
            threading.Thread(target=self._serve, args=(c, n), daemon=True).start()

    def _send(self, text):
        try:
            self.client.sendall(text.encode() + b"\n")
        except OSError:
            pass

    def _status(self, n, who=None, *keys):
        s = self.slices[n]
        fields = {"RF_frequency": f"{s['hz'] / 1e6:.6f}", "mode": s["mode"], "tx": str(s["tx"]), "in_use": "1"}
        return f"S{who or self.handle}|slice {n} " + " ".join(f"{k}={fields[k]}" for k in (keys or fields))

    def tunes(self, hz):
        return any(lo <= hz <= hi for lo, hi in self.bands)

    def _serve(self, c, conn):
        for raw in socket_lines(c):
            line = raw.decode(errors="replace").strip()
            m = re.match(r"C(\d+)\|(.*)$", line)
            with self.lock:
                self.lines.append((time.time(), line, conn))
                if not m:
                    continue
                before, status, data, after = self.answer(m.group(2))
                self._send("\n".join(before + [f"R{m.group(1)}|{status}|{data}"] + after))

    def answer(self, cmd):
        """(status lines before the reply, the reply's hex status, its data, status lines after)."""
        w = cmd.split()
        if cmd == "sub slice all":
            return [self._status(n) for n in sorted(self.slices)], "0", "", []
        if cmd == "slice list":
            return [], "0", " ".join(str(n) for n in sorted(self.slices)), []
        if cmd == "ping":
            return [], "0", "", []
        if cmd.startswith("radio set full_duplex_enabled="):
            return ([], "0", "", []) if self.duplex else ([], "50000016", "Malformed Command", [])
        if w[:2] == ["slice", "create"]:
            kv = dict(x.split("=", 1) for x in w[2:])
            hz = round(float(kv.get("freq", "14.1")) * 1e6)
            if not self.tunes(hz):
                return [], "50000004", "Slice parameter error", []
            n = min(set(range(8)) - set(self.slices))
            self.slices[n] = {"hz": hz, "mode": kv.get("mode", "USB").upper(), "tx": 0}
            return [], "0", f"{n}|OK Slice receiver {n} created", [self._status(n)]
        if w[:2] == ["slice", "tune"] and len(w) == 4:
            n, hz = int(w[2]), round(float(w[3]) * 1e6)
            if n not in self.slices:
                return [], "5000000D", "Incorrect slice receiver", []
            if not self.tunes(hz):
                return [], "50000004", "Slice parameter error", []
            self.slices[n]["hz"] = hz
            return [], "0", "", [self._status(n, None, "RF_frequency")]
        if w[:2] == ["slice", "set"] and len(w) >= 4 and int(w[2]) in self.slices:
            n = int(w[2])
            after = []
            for k, v in (x.split("=", 1) for x in w[3:]):
                if k == "mode" and v.upper() not in self.MODES:
                    return [], "50000032", "Bad Mode", []
                if k == "mode":
                    self.slices[n]["mode"] = v.upper()
                if k == "tx" and v == "1":
                    for o in self.slices:
                        self.slices[o]["tx"] = int(o == n)
                        after.append(self._status(o, None, "tx"))
            return [], "0", "", after + [self._status(n)]
        return [], "50000016", "Malformed Command", []

    def turn(self, n, by):
        """The operator turns slice n's knob by `by` Hz in SmartSDR (another client's handle)."""
        with self.lock:
            self.slices[n]["hz"] += by
            self._send(self._status(n, GUI, "RF_frequency"))

    def hz(self, n):
        with self.lock:
            return self.slices.get(n, {}).get("hz", 0)

    def sent(self, conn=None):
        with self.lock:
            return [(t, line) for t, line, c in self.lines if conn in (None, c)]

    def drop(self):
        """The radio closes trakbox's connection (restarted, the network gone)."""
        with self.lock:
            self.client.shutdown(socket.SHUT_RDWR)
            self.client.close()

    def close(self):
        self.sock.close()
        with self.lock:
            if self.client:
                self.client.close()


def start(flex, at, rate=None, duplex=True, sat=RS44_PASS[1]):
    state = tempfile.mkdtemp(prefix="trakbox-flex-")
    spec = f"flex:127.0.0.1:{flex.port}" + (":duplex" if duplex else "")
    args = [BIN, "--state", state, "--line", "--satrak-port", "0", "--clock", at.strftime("%Y-%m-%dT%H:%M:%SZ"),
            "--radio", spec, "--elements-url", "file://" + os.path.join(SOURCE, "data", "amateur.tle")] + (["--clock-rate", str(rate)] if rate else [])
    tb = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    tb.stdin.write(b"S\r" + sat + b"\r")   # single tracking of the shipped list's RS-44 (12) or SO-50 (5)
    tb.stdin.flush()
    return tb, state


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=30)
    return json.loads(r.stdout) if r.stdout.strip().startswith("{") else {}


def station_time(state):
    t = status(state).get("time", "2000-01-01T00:00:00Z")
    return datetime.fromisoformat(t.replace("Z", "+00:00"))


class Doppler:
    """RS-44's downlink and uplink over the pass, one row a second from AOS (trakbox schedule), for
    the spots (down, up) and those spots moved by a turn of the dial."""

    def __init__(self):
        down = SPOTS["RS-44"][0]
        rows = satellite_track(AOS, int((LOS - AOS).total_seconds()) + 1, sat="RS-44", station=STATION, freq=down)
        self.rr = [-r["doppler_hz"] * C / down for r in rows]     # km/s, one a second from AOS

    def at(self, sec, link, spot):
        i = max(0, min(len(self.rr) - 2, int(sec)))
        rr = self.rr[i] + (self.rr[i + 1] - self.rr[i]) * (sec - i)
        return spot * (1 - rr / C) if link == "down" else spot / (1 - rr / C)

    def spot(self, cmds, link, clock):
        """The transponder spot a link's commands keep (the median of each one's spot)."""
        est = sorted(hz / self.at(clock(t), link, 1.0) for t, hz in cmds)
        return est[len(est) // 2]

    def when(self, hz, spot):
        """The second after AOS at which the downlink of `spot` is hz (it falls through the pass)."""
        for i in range(len(self.rr) - 1):
            a, b = self.at(i, "down", spot), self.at(i + 1, "down", spot)
            if a >= hz >= b:
                return i + (a - hz) / (a - b)
        return None


def tunes(flex, slice_no):
    return [(t, round(float(m.group(2)) * 1e6)) for t, line in flex.sent()
            if (m := TUNE.search(line)) and int(m.group(1)) == slice_no]


def errors(dop, cmds, link, spot, clock):
    """Each command's error against the Doppler at the station time it was sent (clock(t): seconds
    after AOS); returns (worst error, worst allowed: one Doppler step plus the change over one tick)."""
    worst, allowed = 0.0, 0.0
    for t, hz in cmds:
        sec = clock(t)
        if not 2 <= sec <= len(dop.rr) - 3:
            continue
        err = hz - dop.at(sec, link, spot)
        tick = abs(dop.at(sec + RATE, link, spot) - dop.at(sec, link, spot))
        worst = err if abs(err) > abs(worst) else worst
        allowed = max(allowed, STEP + tick)
        check(abs(err) <= STEP + tick + 60, f"{link} {hz} at {sec:.0f} s after AOS: {err:+.0f} Hz off RS-44's Doppler "
                                            f"(a tick {tick:.0f} Hz)")
    return worst, allowed


def first_lines(flex):
    """The command lines, checked exactly: the prologue, then the downlink's slice created with its
    mode, the uplink's mode and tune on slice 0 (already tx=1: no tx command); the pings that fence
    a read of the dial aside."""
    lines = [line for _, line in flex.sent()]
    check(lines[:3] == ["C1|sub slice all", "C2|slice list", "C3|radio set full_duplex_enabled=1"], f"prologue {lines[:3]}")
    core = [line[line.index("|") + 1:] for line in lines[3:] if not line.endswith("|ping")]
    check(re.fullmatch(r"slice create freq=435\.6\d{5} mode=USB", core[0]), f"the downlink's slice: {core[0]}")
    check(core[1] == "slice set 0 mode=LSB", f"the uplink's mode: {core[1]}")
    check(re.fullmatch(r"slice tune 0 145\.9\d{5}", core[2]), f"the uplink's tune: {core[2]}")
    odd = [c for c in core[3:] if not re.fullmatch(r"slice tune [01] \d+\.\d{6}|slice set 1 mode=USB|slice set 0 mode=LSB", c)]
    check(not odd, f"nothing but tunes of slices 0 and 1, their modes again and pings after: {odd[:5]}")
    check(not any("tx=" in line for line in lines), "slice 0 was already the transmit slice")
    seqs = [int(line[1:line.index("|")]) for line in lines]
    check(seqs == list(range(1, len(seqs) + 1)), "sequence numbers 1, 2, 3 ... in order")
    return lines[:3] + core[:3]


def turn_dial(flex, by):
    """Turns slice 1 up `by` Hz; trakbox must keep it (not write it back). A turn between trakbox's
    read and its write is overwritten (no compare-and-set, as on CAT): turned again, at most twice."""
    for attempt in range(3):
        before = flex.hz(1)
        flex.turn(1, by)
        turned = time.time()
        time.sleep(1.5)
        if abs(flex.hz(1) - (before + by)) < 3000:
            return turned, attempt
    check(False, "the downlink dial turn was kept")


def whole_pass():
    dop = Doppler()
    d_spot, u_spot = SPOTS["RS-44"]
    flex = Flex({0: {"hz": 14_200_000, "mode": "USB", "tx": 1}}, [HF, XVTR_2M, XVTR_70CM])
    start_at = AOS - timedelta(seconds=20)
    procs = []
    try:
        tb, state = start(flex, start_at, RATE)
        procs.append(tb)
        poll("RS-44's downlink on a slice of its own", lambda: abs(flex.hz(1) - d_spot) < 12_000, 30, every=0.05)
        poll("RS-44's uplink on slice 0", lambda: abs(flex.hz(0) - u_spot) < 5_000, 30, every=0.05)
        s = status(state)
        radio = s["radios"][0]
        check(s.get("healthy") and not radio["fault"] and not radio["limits"], f"healthy, no limits: {radio}")
        # Past TCA (10:58:18) the operator turns the downlink's knob 10 kHz up.
        poll("the clock past TCA", lambda: station_time(state) > datetime(2026, 5, 21, 10, 59, tzinfo=timezone.utc),
             60, every=0.25)
        turned_at, again = turn_dial(flex, 10_000)
        poll("the clock past LOS", lambda: station_time(state) > LOS, 90, every=0.5)
        log = leave_and_read_log(tb, state, procs)
        lines = first_lines(flex)
        down, up = tunes(flex, 1), tunes(flex, 0)
        check(len(down) >= 30 and len(up) >= 30, f"Doppler through the pass: {len(down)} / {len(up)} tunes")
        # The station clock at a command: start + RATE * (wall - w) + offset; fitted on the downlink's
        # commands before the turn (the median), as sdr_receivers.py does.
        t_ref = down[0][0]
        offset = (start_at - AOS).total_seconds()
        fits = sorted(w - (offset + RATE * (t - t_ref)) for t, hz in down if t < turned_at
                      and (w := dop.when(hz, d_spot)) is not None)
        w0 = fits[len(fits) // 2]
        clock = lambda t: offset + RATE * (t - t_ref) + w0  # noqa: E731
        settle = turned_at + 3
        worst_d, allow_d = errors(dop, [c for c in down if c[0] < turned_at], "down", d_spot, clock)
        worst_u, allow_u = errors(dop, [c for c in up if c[0] < turned_at], "up", u_spot, clock)
        # The spot the turn moved to: the radio's frequency at the turn (on the last tick's Doppler,
        # up to a tick behind at x20) plus 10 kHz, in the satellite's frame; fitted (the median).
        later_d, later_u = [c for c in down if c[0] > settle], [c for c in up if c[0] > settle]
        new_d, new_u = dop.spot(later_d, "down", clock), dop.spot(later_u, "up", clock)
        check(abs(new_d - d_spot - 10_000) < 1_500, f"the downlink's spot moved by the turn: {new_d - d_spot:+.0f} Hz")
        check(abs((new_u - u_spot) + (new_d - d_spot)) < 50, f"the uplink moved the other way: {new_u - u_spot:+.0f} Hz")
        after_d, _ = errors(dop, later_d, "down", new_d, clock)
        after_u, _ = errors(dop, later_u, "up", new_u, clock)
        check("event: link-lost" not in log, "no link-lost")
        print(f"flex_satellite RS-44 at x{RATE}, AOS to LOS: {len(flex.sent())} command lines, {len(down)} tunes of slice 1 "
              f"(down, created), {len(up)} of slice 0 (up); worst error per command {worst_d:+.0f} Hz down, "
              f"{worst_u:+.0f} Hz up (allowed a step + a tick: {allow_d:.0f} / {allow_u:.0f}); the dial turned "
              f"+10 kHz after TCA (turned {again + 1}x) followed: the spots moved {new_d - d_spot:+.0f} Hz down, "
              f"{new_u - u_spot:+.0f} Hz up, worst {after_d:+.0f} / {after_u:+.0f} Hz on them; first lines {lines}")
    finally:
        reap(procs)
        flex.close()


def near_culmination():
    """8 s at the real rate from RS44_PASS's start: the worst error sampled every 0.2 s (lag included)."""
    d_spot, u_spot = SPOTS["RS-44"]
    flex = Flex({0: {"hz": 14_200_000, "mode": "USB", "tx": 1}}, [HF, XVTR_2M, XVTR_70CM])
    procs = []
    try:
        t0 = time.time()
        tb, state = start(flex, RS44_PASS[0])
        procs.append(tb)
        clock_now = lambda: RS44_PASS[0] + timedelta(seconds=time.time() - t0)  # noqa: E731
        poll("RS-44's downlink on a slice of its own", lambda: abs(flex.hz(1) - d_spot) < 12_000, 30, every=0.05)
        poll("RS-44's uplink on slice 0", lambda: abs(flex.hz(0) - u_spot) < 5_000, 30, every=0.05)
        worst = worst_error("RS-44", SPOTS["RS-44"], lambda: flex.hz(1), lambda: flex.hz(0), clock_now, 8)
        check(worst[0] < 400 and worst[1] < 400, f"RS-44 worst {worst}")
        leave_and_read_log(tb, state, procs)
        print(f"flex_satellite RS-44 near culmination (x1, 8 s): worst tuning error {worst[0]:.0f} Hz down (slice 1), "
              f"{worst[1]:.0f} Hz up (slice 0)")
    finally:
        reap(procs)
        flex.close()


def reconnect():
    """The connection closed mid-pass: trakbox reconnects and takes the slices it had (slice 0 the
    uplink, tx=1; slice 1, which it created, the downlink): no new slice, both tuned again."""
    d_spot, u_spot = SPOTS["RS-44"]
    flex = Flex({0: {"hz": 14_200_000, "mode": "USB", "tx": 1}}, [HF, XVTR_2M, XVTR_70CM])
    procs = []
    try:
        tb, state = start(flex, RS44_PASS[0], RATE)
        procs.append(tb)
        poll("RS-44's downlink on a slice of its own", lambda: abs(flex.hz(1) - d_spot) < 12_000, 30, every=0.05)
        flex.drop()
        poll("trakbox back on the radio", lambda: any(TUNE.search(line) for _, line in flex.sent(2)), 20, every=0.05)
        poll("both slices tuned again", lambda: {int(TUNE.search(line).group(1)) for _, line in flex.sent(2)
                                                 if TUNE.search(line)} == {0, 1}, 20, every=0.05)
        again = [line[line.index("|") + 1:] for _, line in flex.sent(2)]
        log = leave_and_read_log(tb, state, procs)
        check(again[:2] == ["sub slice all", "slice list"], f"the prologue again: {again[:3]}")
        check(not any(c.startswith("slice create") for c in again), f"no new slice: {again[:6]}")
        check(sorted(flex.slices) == [0, 1], f"two slices on the radio: {sorted(flex.slices)}")
        check(abs(flex.hz(0) - u_spot) < 5_000, "the uplink on slice 0")
        lost = [ln for ln in log.splitlines() if "the connection was closed" in ln]
        check(lost and "reconnected" in log, f"the loss and the reconnect in the log: {lost}")
        print(f"flex_satellite reconnect: after the radio closed the connection, {again[:2]}, slices 0 and 1 "
              f"taken again, no slice created; log: {lost[0].strip()[:160]}")
    finally:
        reap(procs)
        flex.close()


def so50_tone():
    """SO-50 in FM: both slices FM, the 67.0 Hz tone on the transmit slice."""
    d_spot, u_spot = SPOTS["SO-50"]
    flex = Flex({0: {"hz": 14_200_000, "mode": "USB", "tx": 0}, 1: {"hz": 14_250_000, "mode": "USB", "tx": 1}},
                [HF, XVTR_2M, XVTR_70CM])
    procs = []
    try:
        tb, state = start(flex, SO50_PASS[0], sat=SO50_PASS[1])
        procs.append(tb)
        poll("SO-50's downlink on slice 0", lambda: abs(flex.hz(0) - d_spot) < 12_000, 30, every=0.05)
        poll("SO-50's uplink on slice 1", lambda: abs(flex.hz(1) - u_spot) < 5_000, 30, every=0.05)
        tone = "slice set 1 fm_tone_mode=CTCSS_TX fm_tone_value=67.0"
        poll("the 67.0 Hz tone on the transmit slice", lambda: any(line.endswith("|" + tone) for _, line in flex.sent()), 10)
        lines = [line[line.index("|") + 1:] for _, line in flex.sent()]
        leave_and_read_log(tb, state, procs)
        check("slice set 0 mode=FM" in lines and "slice set 1 mode=FM" in lines, f"FM on both slices: {lines[:8]}")
        check(not any("fm_tone" in c and not c.startswith("slice set 1 ") for c in lines), "the tone on slice 1 only")
        print(f"flex_satellite SO-50: {[c for c in lines if 'mode=' in c or 'fm_tone' in c][:3]}")
    finally:
        reap(procs)
        flex.close()


def no_70cm():
    """A radio with a 2 m transverter only: the downlink's tune refused, a limit; the uplink tuned."""
    d_spot, u_spot = SPOTS["RS-44"]
    flex = Flex({0: {"hz": 14_200_000, "mode": "USB", "tx": 0}, 1: {"hz": 14_250_000, "mode": "USB", "tx": 0}},
                [HF, XVTR_2M], duplex=False)
    procs = []
    try:
        tb, state = start(flex, RS44_PASS[0], RATE, duplex=False)
        procs.append(tb)
        poll("RS-44's uplink on slice 1", lambda: abs(flex.hz(1) - u_spot) < 5_000, 30, every=0.05)
        poll("the status to show the limit", lambda: "no 70 cm" in (status(state).get("radios") or [{}])[0].get("limits", ""), 15)
        s = status(state)
        radio = s["radios"][0]
        check(s.get("healthy") and radio["connected"] and not radio["fault"] and radio["failures"] == 0,
              f"healthy and connected, no failure: {radio}")
        check(radio["limits"] == "FlexRadio: no 70 cm", f"limits: {radio['limits']}")
        time.sleep(3)   # a minute of the pass more
        log = leave_and_read_log(tb, state, procs)
        lines = [line for _, line in flex.sent()]
        refused = [line for line in lines if re.search(r"slice tune 0 435\.", line)]
        check(len(refused) == 1, f"the refused band sent once: {refused}")
        check(flex.hz(0) == 14_200_000, "slice 0 left where it was")
        check(any(line.endswith("|slice set 1 tx=1") for line in lines), "slice 1 marked for transmit")
        said = [ln for ln in log.splitlines() if "no 70 cm" in ln or "refused (50000004" in ln]
        check(len(said) == 1, f"said once: {said}")
        check("event: link-lost" not in log and "reconnect" not in log, "never a lost link")
        print(f"flex_satellite no 70 cm: {refused[0]} answered R|50000004|, limits \"{radio['limits']}\", "
              f"{len(tunes(flex, 1))} uplink tunes on slice 1; log: {said[0].strip()[:300]}")
    finally:
        reap(procs)
        flex.close()


def main():
    whole_pass()
    near_culmination()
    reconnect()
    so50_tone()
    no_70cm()


if __name__ == "__main__":
    run_test(main)
