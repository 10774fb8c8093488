"""One radio through rigctld, the Gpredict-style set-up (issue 28): `--radio rigctld:HOST:PORT` alone.

Hamlib's dummy rig (`rigctld -m 1`) plays the radio; trakbox reaches it through a small rigctld-
protocol relay of this test's own, which counts the bytes each way and can play a radio that misbehaves:
  - RS-44 (an SSB linear transponder): both links are read back; the operator turns the downlink dial
    +10 kHz with a second client (`rigctl -m 2 ... F`, straight to rigctld): the downlink is kept and
    the uplink moves -10 kHz once the knob has rested (1 s), within 2 s after the rest. The bytes per
    second on the line during the pass at one update a second are measured.
  - SO-50 (FM, 67.0 Hz tone) with a radio that does not answer the tone (the relay answers `C` with
    RPRT -5, what rigctld says when the radio timed out): the refusal is logged once and Doppler goes
    on; the link never reconnects.
  - RS-44 with a radio that puts the split frequency on its receive VFO (the relay turns `I`/`i` into
    `F`/`f`): the uplink is refused once with a clear message, the downlink is put back and tuned.
  - RS-44 through `rigctld --vfo`: satellite mode switched on before the first frequency, the downlink
    on Sub and the uplink on Main; a turn of the Sub dial moves Main after the rest.
Every wait polls for its condition with a deadline; the clock is fixed with --clock.
"""
import contextlib
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
from datetime import datetime, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (BIN, Failure, check, free_port, hamlib_dummy, need, poll, reap, run_test, sh,  # noqa: E402
                        socket_lines, wait_listening)



class Relay:
    """A rigctld-protocol relay on a free loopback port in front of a real rigctld. `tone_rprt`: answer
    CTCSS commands with this RPRT instead of forwarding them; `one_vfo`: a radio that carries the split
    frequency on its receive VFO (I/i/X become F/f/M)."""

    def __init__(self, upstream_port, tone_rprt=None, one_vfo=False):
        self.upstream_port, self.tone_rprt, self.one_vfo = upstream_port, tone_rprt, one_vfo
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(4)
        self.port = self.sock.getsockname()[1]
        self.traffic = []          # (time, bytes to the radio, bytes from the radio)
        self.commands = []         # (time, command line) as trakbox sent it
        self.lock = threading.Lock()
        self.closing = False
        threading.Thread(target=self._accept, daemon=True).start()

    def close(self):
        self.closing = True
        self.sock.close()

    def _accept(self):
        while not self.closing:
            try:
                client, _ = self.sock.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(client,), daemon=True).start()

    def _serve(self, client):
        up = socket.create_connection(("127.0.0.1", self.upstream_port))

        def back():  # replies from rigctld to trakbox
            try:
                while True:
                    data = up.recv(4096)
                    if not data:
                        break
                    with self.lock:
                        self.traffic.append((time.time(), 0, len(data)))
                    client.sendall(data)
            except OSError:
                pass
            client.close()

        threading.Thread(target=back, daemon=True).start()
        try:
            for line in socket_lines(client):
                text = line.decode(errors="replace")
                with self.lock:
                    self.traffic.append((time.time(), len(line) + 1, 0))
                    self.commands.append((time.time(), text))
                word = text.split(" ")[0]
                if self.tone_rprt is not None and word in ("C", "\\set_ctcss_tone"):
                    reply = f"RPRT {self.tone_rprt}\n".encode()
                    with self.lock:
                        self.traffic.append((time.time(), 0, len(reply)))
                    client.sendall(reply)
                    continue
                if self.one_vfo and word in ("I", "i", "X"):
                    text = {"I": "F", "i": "f", "X": "M"}[word] + text[1:]
                up.sendall(text.encode() + b"\n")
        except OSError:
            pass
        up.close()

    def rate(self, since, until):
        """Bytes per second both ways on the line between two times."""
        with self.lock:
            n = sum(a + b for t, a, b in self.traffic if since <= t < until)
        return n / (until - since)

    def sent(self, prefix):
        with self.lock:
            return [c for _, c in self.commands if c.startswith(prefix)]


def ask(port, command, tries=3):
    """One command straight to rigctld (its own protocol): the first reply line as a number, or None
    when none came in `tries` attempts (a loaded machine may let one connection time out)."""
    for _ in range(tries):
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=2) as s:
                s.sendall(command.encode() + b"\n")
                data = b""
                while b"\n" not in data:
                    chunk = s.recv(256)
                    if not chunk:
                        break
                    data += chunk
                line = data.split(b"\n")[0].decode()
                if re.fullmatch(r"\d+", line):
                    return int(line)
        except OSError:
            pass
        time.sleep(0.1)
    return None


def turn_knob(rig_port, read_cmd, turned, turn):
    """The operator turns a dial to `turned` (turn() does it); returns when the turn was made.
    CAT has no compare-and-set: a turn that lands between trakbox's read of the dial and its write
    right after (a few ms on loopback) is overwritten, on a real radio as here. The operator then
    sees the dial jump back and turns again; so does this test (at most 3 times), and says so."""
    for attempt in range(3):
        turn()
        made = time.time()
        time.sleep(0.3)
        f = ask(rig_port, read_cmd)
        if f is not None and abs(f - turned) < 400:
            return made
        print(f"rigctld_one_radio: the turn to {turned} fell between a read and a write of trakbox's "
              f"(the dial shows {f}); turned again")
    raise Failure(f"the dial never kept the turn to {turned}")


def near(port, command, target, within):
    f = ask(port, command)
    return f if f is not None and abs(f - target) < within else None


def start_trakbox(state, relay_port, clock, sat_no, extra=()):
    tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock", clock,
                           "--radio", f"rigctld:127.0.0.1:{relay_port}", *extra],
                          stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    tb.stdin.write(f"S\r{sat_no}\r".encode())   # single tracking of the shipped list's #sat_no
    tb.stdin.flush()
    return tb


@contextlib.contextmanager
def session(procs, rig_port, start, sat_no, **relay_options):
    """A relay in front of rigctld and trakbox tracking the shipped list's #sat_no from `start`
    (--clock); yields (trakbox, relay, state directory) and cleans up."""
    relay = Relay(rig_port, **relay_options)
    state = tempfile.mkdtemp(prefix="trakbox-rigctld-one-")
    try:
        tb = start_trakbox(state, relay.port, start.strftime("%Y-%m-%dT%H:%M:%SZ"), sat_no)
        procs.append(tb)
        yield tb, relay, state
    finally:
        relay.close()
        shutil.rmtree(state, ignore_errors=True)


def finish(tb, state):
    tb.stdin.close()
    check(tb.wait(20) == 0, "trakbox leaves cleanly when input ends")
    with open(os.path.join(state, "trakbox.log")) as f:
        return f.read()


def rs44_dial_follow(procs, rig_port):
    """RS-44, one radio: read back, the operator's turn kept, the uplink after the rest; bytes/s."""
    start = datetime(2026, 5, 21, 10, 57, 0, tzinfo=timezone.utc)
    with session(procs, rig_port, start, 12) as (tb, relay, state):
        t0 = time.time()
        d0 = poll("the downlink on 435.640 MHz", lambda: near(rig_port, "f", 435_640_000, 12_000), 30)
        poll("the uplink (split) on 145.965 MHz", lambda: near(rig_port, "i", 145_965_000, 5_000), 30)
        # One radio in split: trakbox reads both links back (f and i), as the log says.
        poll("a read-back of both links", lambda: relay.sent("f") and relay.sent("i"), 10)
        # Bytes on the line over 8 s of the pass, one update a second (reads included).
        time.sleep(1.0)
        m0 = time.time()
        time.sleep(8.0)
        bytes_per_s = relay.rate(m0, time.time())

        # The operator turns the downlink dial up 10 kHz; the knob then rests.
        d_now = ask(rig_port, "f")
        u_before = ask(rig_port, "i")
        turned = d_now + 10_000
        def rigctl_turn():
            code, _, err = sh("rigctl", "-m", "2", "-r", f"127.0.0.1:{rig_port}", "F", str(turned))
            check(code == 0, f"rigctl F {turned}: {err}")
        t_turn = turn_knob(rig_port, "f", turned, rigctl_turn)
        u1 = poll("the uplink to move down 10 kHz",
                  lambda: near(rig_port, "i", u_before - 10_000, 300), 10, every=0.02)
        delay = time.time() - t_turn
        check(delay >= 0.95, f"the uplink moved {delay:.2f} s after the turn, before the knob had rested 1 s")
        check(delay <= 1.0 + 2.0, f"the uplink moved {delay:.2f} s after the turn: more than 2 s after the 1 s rest")
        # The downlink stays where the operator put it (with its Doppler), never back near the old spot.
        samples = []
        for _ in range(3):
            time.sleep(1.0)
            samples.append(ask(rig_port, "f"))
        for f in samples:
            check(f is not None and abs(f - turned) < 400, f"downlink {f} after the turn, expected near {turned}")
        log = finish(tb, state)
        procs.remove(tb)
        check("downlink dial turned" in log and "the knob rested" in log,
              "the log names the turn and the rest")
        check("reconnected" not in log, "the link never reconnected")
        print(f"rigctld_one_radio RS-44: downlink {d0} -> {turned} by the operator, then {samples}; uplink "
              f"{u_before} -> {u1} ({u1 - u_before:+d} Hz) {delay:.2f} s after the turn (rest 1.0 s: "
              f"{delay - 1.0:.2f} s after the rest); {bytes_per_s:.0f} bytes/s on the line at one update a "
              f"second; {time.time() - t0:.1f} s")


def so50_tone_refused(procs, rig_port):
    """SO-50 through a radio that does not answer the tone: Doppler goes on, no reconnect."""
    start = datetime(2026, 5, 21, 14, 11, 30, tzinfo=timezone.utc)
    with session(procs, rig_port, start, 5, tone_rprt=-5) as (tb, relay, state):
        poll("the CTCSS tone sent", lambda: relay.sent("C "), 30)
        d1 = poll("the downlink on 436.795 MHz", lambda: near(rig_port, "f", 436_795_000, 12_000), 30)
        u1 = poll("the uplink on 145.850 MHz", lambda: near(rig_port, "i", 145_850_000, 5_000), 30)
        # Doppler goes on: new downlink frequencies keep arriving (FM step 100 Hz; near culmination the
        # Doppler moves faster than that each second).
        seen = {d1}
        deadline = time.time() + 10
        while len(seen) < 3 and time.time() < deadline:
            f = ask(rig_port, "f")
            if f:
                seen.add(f)
            time.sleep(0.2)
        check(len(seen) >= 3, f"Doppler updates after the refused tone: only {sorted(seen)}")
        log = finish(tb, state)
        procs.remove(tb)
        refusals = log.count("CTCSS tone 67.0 Hz refused")
        check(refusals == 1, f"the refused tone is logged once ({refusals} times):\n{log}")
        check("Doppler tuning goes on" in log, "the log says Doppler goes on")
        check("reconnected" not in log, f"a refused tone must not reconnect the link:\n{log}")
        print(f"rigctld_one_radio SO-50: tone refused (RPRT -5) once, downlink {sorted(seen)}, uplink {u1}")


def rs44_one_vfo_radio(procs, rig_port):
    """A radio that puts the split frequency on its receive VFO: the uplink is refused, clearly, once."""
    start = datetime(2026, 5, 21, 10, 57, 0, tzinfo=timezone.utc)
    with session(procs, rig_port, start, 12, one_vfo=True) as (tb, relay, state):
        poll("the uplink sent once", lambda: relay.sent("I "), 30)
        # After the check the downlink is put back and tuned with its Doppler; the uplink never again.
        time.sleep(3.0)
        d = poll("the downlink on 435.640 MHz", lambda: near(rig_port, "f", 435_640_000, 12_000), 10)
        uplinks = relay.sent("I ")
        log = finish(tb, state)
        procs.remove(tb)
        check(len(uplinks) == 1, f"the uplink is sent once and then refused, not {len(uplinks)} times")
        said = log.count("does not carry the uplink on its own VFO")
        check(said == 1, f"the refusal is logged once ({said}):\n{log}")
        check("--vfo" in log and "--uplink-radio" in log, "the log says what to do")
        print(f"rigctld_one_radio one-VFO radio: uplink refused after one try, downlink {d}")


def rs44_satellite_mode(procs, rig_port):
    """rigctld --vfo: satellite mode on, downlink on Sub and uplink on Main, a turn of the Sub dial."""
    start = datetime(2026, 5, 21, 10, 57, 0, tzinfo=timezone.utc)
    with session(procs, rig_port, start, 12) as (tb, relay, state):
        d0 = poll("the downlink on Sub", lambda: near(rig_port, "f Sub", 435_640_000, 12_000), 30)
        poll("the uplink on Main", lambda: near(rig_port, "f Main", 145_965_000, 5_000), 30)
        poll("satellite mode on", lambda: ask(rig_port, "u Main SATMODE") == 1, 10)
        sat_on = relay.sent("U Main SATMODE 1")
        first_freq = next(i for i, c in enumerate(relay.sent("")) if c.startswith("F "))
        check(sat_on and relay.sent("").index(sat_on[0]) < first_freq, "satellite mode before the first frequency")
        u_before = ask(rig_port, "f Main")
        turned = ask(rig_port, "f Sub") + 10_000
        def sub_knob():
            with socket.create_connection(("127.0.0.1", rig_port), timeout=2) as s:
                s.sendall(f"F Sub {turned}\n".encode())
                s.recv(64)
        t_turn = turn_knob(rig_port, "f Sub", turned, sub_knob)
        u1 = poll("the uplink on Main to move down 10 kHz",
                  lambda: near(rig_port, "f Main", u_before - 10_000, 300), 10, every=0.02)
        delay = time.time() - t_turn
        check(0.95 <= delay <= 3.0, f"the uplink moved {delay:.2f} s after the turn (rest 1 s, then within 2 s)")
        time.sleep(1.5)
        d1 = ask(rig_port, "f Sub")
        check(d1 is not None and abs(d1 - turned) < 400, f"downlink {d1} after the turn, expected near {turned}")
        log = finish(tb, state)
        procs.remove(tb)
        check("satellite mode, downlink on Sub, uplink on Main" in log, "the log says how the links are carried")
        print(f"rigctld_one_radio --vfo: satellite mode on, downlink {d0} -> {turned} on Sub, uplink {u_before} -> "
              f"{u1} on Main {delay:.2f} s after the turn")


def main():
    need("rigctld", "rigctl")
    procs = []
    try:
        for case in (rs44_dial_follow, so50_tone_refused, rs44_one_vfo_radio, rs44_satellite_mode):
            port = free_port()
            if case is rs44_satellite_mode:   # rigctld addressing VFOs: Main and Sub
                rig = subprocess.Popen(["rigctld", "-m", "1", "-T", "127.0.0.1", "-t", str(port), "--vfo"],
                                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                wait_listening(port, "rigctld --vfo", 10, rig)
            else:
                rig = hamlib_dummy("rigctld", port)
            procs.append(rig)
            case(procs, port)
            reap([rig])
            procs.remove(rig)
    finally:
        reap(procs)


if __name__ == "__main__":
    run_test(main)
