"""The station's links going away and coming back, with real peers on loopback:

a. the remote rotator: Hamlib's `rotctld -m 1` (dummy rotator) as `--rotator rotctld:...`; trakbox
   is sent to a position through its Satrak port, then rotctld is killed (SIGKILL) and started again
   on the same port, twice;
b. the CAT port: a socat pty pair, trakbox's Kenwood driver on one end and a Kenwood peer (this
   script) on the other, recording the frequencies set; the pair is missing when trakbox starts
   and plugged in later; then socat is killed (the device disappears, its
   links are removed as udev removes a USB adapter's node) and started again with the same names,
   twice. Frequencies are set through trakbox's rigctld endpoint.

Each outage must be reported (trakbox.log, and the endpoints: Satrak STATUS?/ERRSTATUS?, rotctld
p, rigctld get_powerstat and set_freq), cost almost no CPU (no busy loop: utime + stime from
/proc/PID/stat), and end by itself when the peer returns: trakbox reconnects and drives the peer
again, without a restart. Every wait waits for a condition, with a bound. Skipped (exit 77)
without rotctld/socat.
"""
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import (BIN, CLOCK, Failure, Satrak, check, free_port, hamlib_dummy, poll, reap, run_test,  # noqa: E402
                        sh, skip, tcp_exchange)

# CPU trakbox may spend over an outage of OUTAGE_S seconds: its one-second tick and the polls of
# this script cost a few tens of milliseconds; a loop spinning on a dead link costs the whole time.
OUTAGE_S = 3.0
OUTAGE_CPU_S = 0.6


def wait_for(what, cond, timeout):
    return poll(what, cond, timeout, every=0.1)


def cpu_seconds(pid):
    """utime + stime of a process, seconds (fields 14 and 15 of /proc/PID/stat)."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class Log:
    """trakbox.log, read again on every question."""

    def __init__(self, state):
        self.path = os.path.join(state, "trakbox.log")

    def text(self):
        try:
            with open(self.path, encoding="utf-8", errors="replace") as f:
                return f.read()
        except FileNotFoundError:
            return ""

    def count(self, pattern):
        return len(re.findall(pattern, self.text(), re.M))


# ---------------------------------------------------------------------------------------------
# a. The rotator.

class Rotctld:
    """Hamlib's dummy rotator daemon on a fixed loopback port."""

    def __init__(self, port):
        self.port = port
        self.proc = None

    def start(self):
        self.proc = hamlib_dummy("rotctld", self.port)

    def kill(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(10)

    def position(self):
        """(az, el) as Hamlib's own client reads it, or None."""
        code, out, _ = sh("rotctl", "-m", "2", "-r", f"127.0.0.1:{self.port}", "p", timeout=10)
        nums = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", out)]
        return (nums[0], nums[1]) if code == 0 and len(nums) >= 2 else None


def satrak_fields(port, query):
    """The fields of a Satrak reply to `query` (e.g. STATUS?), through trakbox's Satrak server."""
    c = Satrak(port)
    try:
        body = c.ask(query)
    finally:
        c.close()
    check(body.startswith(query + ","), f"{query} reply: {body!r}")
    return body.split(",")[1:]


def rotator_faults(tb, log, satrak_port, rotctld, endpoint):
    target = (40.0, 20.0)
    wait_for("trakbox to connect to rotctld", lambda: log.count(r"rotator: connected to rotctld") >= 1, 15)
    c = Satrak(satrak_port)
    try:
        reply = c.ask("GOTO=,%.0f,%.0f" % target)
    finally:
        c.close()
    check(reply == "GOTO=,OK", f"GOTO accepted: {reply!r}")

    for rnd in (1, 2):
        # The dummy rotator starts at 0/0 every time: it must be driven towards the target.
        def moving():
            p = rotctld.position()
            return p if p and p[0] > 5.0 and p[1] > 2.0 else None
        wait_for(f"round {rnd}: the dummy rotator to move towards {target}", moving, 20)
        status = satrak_fields(satrak_port, "ERRSTATUS?")
        check(status[0] == "0", f"round {rnd}: no link fault while rotctld answers: ERRSTATUS? {status}")

        lost_before = log.count(r"rotator: lost rotctld 127\.0\.0\.1:%d" % rotctld.port)
        rotctld.kill()
        t_kill = time.time()
        wait_for(f"round {rnd}: the loss in trakbox.log",
                 lambda: log.count(r"rotator: lost rotctld 127\.0\.0\.1:%d: .*motion stopped, reconnecting"
                                   % rotctld.port) > lost_before, 10)
        def link_error():
            fields = satrak_fields(satrak_port, "ERRSTATUS?")
            return fields if fields[0] == "1" else None
        err = wait_for(f"round {rnd}: ERRSTATUS? X1 (communication error) = 1", link_error, 5)
        check(err[9] == "2" and err[10] == "2", f"round {rnd}: no position: X/Y sensor connection error: {err}")
        st = satrak_fields(satrak_port, "STATUS?")
        check(st[0] == "1", f"round {rnd}: STATUS? X1 reports the fault: {st}")
        check(st[11] == "0" and st[12] == "0", f"round {rnd}: STATUS? shows no motion while the link is down: {st}")
        got = tcp_exchange(endpoint, b"p\n", b"\n")
        check(got == b"RPRT -6\n", f"round {rnd}: trakbox's rotctld endpoint: p -> I/O error: {got!r}")
        check(tb.poll() is None, f"round {rnd}: trakbox is still running after the loss")

        # The outage: trakbox retries with backoff, not in a spin.
        cpu0, t0 = cpu_seconds(tb.pid), time.time()
        while time.time() - t0 < OUTAGE_S:  # the outage itself is the condition: it has to last
            check(tb.poll() is None, f"round {rnd}: trakbox exited during the outage")
            time.sleep(0.2)
        used = cpu_seconds(tb.pid) - cpu0
        print(f"link_faults: rotator round {rnd}: {used:.2f} s CPU over a {time.time() - t0:.1f} s outage")
        check(used < OUTAGE_CPU_S, f"round {rnd}: trakbox used {used:.2f} s CPU in {OUTAGE_S} s of outage")

        connects = log.count(r"rotator: connected to rotctld")
        rotctld.start()
        wait_for(f"round {rnd}: trakbox to reconnect by itself",
                 lambda: log.count(r"rotator: connected to rotctld") > connects, 15)
        print(f"link_faults: rotator round {rnd}: reconnected {time.time() - t_kill:.1f} s after the kill")
        wait_for(f"round {rnd}: ERRSTATUS? X1 = 0 again",
                 lambda: satrak_fields(satrak_port, "ERRSTATUS?")[0] == "0", 10)

    # After the second return the antenna gets where it was sent.
    def there():
        p = rotctld.position()
        return p if p and abs(p[0] - target[0]) < 1.5 and abs(p[1] - target[1]) < 1.0 else None
    wait_for(f"the dummy rotator to reach {target}", there, 20)


# ---------------------------------------------------------------------------------------------
# b. The CAT port.

class KenwoodPeer:
    """The radio's end of the pty: reads Kenwood commands (`FA00145950000;`, `MD2;`, ...) and keeps
    the frequencies set, as (VFO letter, Hz). The TS-790 answers nothing to set commands."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        self.freqs = []
        self.lock = threading.Lock()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self):
        buf = b""
        while True:
            try:
                data = os.read(self.fd, 256)
            except OSError:
                break
            if not data:
                break
            buf += data
            while b";" in buf:
                cmd, buf = buf.split(b";", 1)
                m = re.fullmatch(rb"F([AB])(\d{11})", cmd)
                if m:
                    with self.lock:
                        self.freqs.append((m.group(1).decode(), int(m.group(2))))

    def seen(self, vfo, hz):
        with self.lock:
            return (vfo, hz) in self.freqs

    def close(self):
        try:
            os.close(self.fd)
        except OSError:
            pass
        self.thread.join(5)


class CatCable:
    """socat's pty pair with fixed link names in `folder`: radio (trakbox's end) and peer."""

    def __init__(self, folder):
        self.radio = os.path.join(folder, "radio")
        self.peer_path = os.path.join(folder, "peer")
        self.proc = None
        self.peer = None

    def plug(self):
        self.proc = subprocess.Popen(["socat", "-d", "-d", f"pty,raw,echo=0,link={self.radio}",
                                      f"pty,raw,echo=0,link={self.peer_path}"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        # Both ptys exist once socat says it is transferring data.
        deadline = time.time() + 10
        while True:
            line = self.proc.stderr.readline()
            if "starting data transfer loop" in line:
                break
            if not line or time.time() > deadline:
                raise Failure(f"socat did not start: {line!r}")
        self.peer = KenwoodPeer(self.peer_path)

    def pull(self):
        """The adapter is pulled: socat dies at once, its device nodes go away."""
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(10)
        self.proc.stderr.close()
        for path in (self.radio, self.peer_path):
            try:
                os.unlink(path)
            except FileNotFoundError:
                pass
        self.peer.close()

    def close(self):
        if self.proc and self.proc.poll() is None:
            self.pull()


class Rigctl:
    """trakbox's rigctld endpoint, one connection, plain protocol lines."""

    def __init__(self, port):
        self.s = wait_for(f"trakbox's rigctld endpoint on {port}", lambda: self._connect(port), 15)
        self.buf = b""

    @staticmethod
    def _connect(port):
        try:
            return socket.create_connection(("127.0.0.1", port), timeout=10)
        except OSError:
            return None

    def ask(self, line, end=b"\n"):
        """Sends a command; returns the reply up to `end`."""
        self.s.sendall(line.encode() + b"\n")
        while end not in self.buf:
            chunk = self.s.recv(4096)
            if not chunk:
                raise Failure(f"rigctld endpoint closed after {line!r}")
            self.buf += chunk
        reply, self.buf = self.buf.split(end, 1)
        return reply.decode().strip()

    def set_freq(self, hz):
        return self.ask(f"F {hz}")

    def powerstat(self):
        return self.ask("\\get_powerstat")

    def close(self):
        self.s.close()


def radio_faults(tb, log, rig, cable):
    label = re.escape(f"radio Kenwood CAT on {cable.radio}")
    # trakbox started before the cable was there: said so at once, and keeps trying.
    wait_for("the missing CAT port reported at start",
             lambda: log.count(label + ": cannot open " + re.escape(cable.radio) + ": No such file or directory"), 10)
    check(rig.powerstat() == "0", "get_powerstat: 0 while the port is missing")
    cable.plug()
    wait_for("trakbox to open the port once it exists", lambda: log.count(label + r": connected$"), 15)
    hz = 145_950_000
    check(rig.set_freq(hz) == "RPRT 0", "F accepted while the radio is there")
    wait_for("the peer to receive FA00145950000;", lambda: cable.peer.seen("A", hz), 10)
    check(rig.powerstat() == "1", "get_powerstat: 1 while the port is open")

    for rnd in (1, 2):
        faults_before = log.count(label + r": (?!reconnected|working again)")
        cable.pull()
        t_pull = time.time()
        # Nothing is sent now: trakbox must notice the port went away by itself.
        wait_for(f"round {rnd}: the loss of the CAT port in trakbox.log",
                 lambda: log.count(label + r": (?!reconnected|working again)") > faults_before, 10)
        wait_for(f"round {rnd}: get_powerstat 0", lambda: rig.powerstat() == "0", 5)
        reply = rig.set_freq(hz + 10_000 * rnd)
        check(reply == "RPRT -6", f"round {rnd}: F refused (I/O error) while the port is gone: {reply!r}")
        check(tb.poll() is None, f"round {rnd}: trakbox is still running after the loss")

        cpu0, t0 = cpu_seconds(tb.pid), time.time()
        while time.time() - t0 < OUTAGE_S:
            check(tb.poll() is None, f"round {rnd}: trakbox exited during the outage")
            time.sleep(0.2)
        used = cpu_seconds(tb.pid) - cpu0
        print(f"link_faults: radio round {rnd}: {used:.2f} s CPU over a {time.time() - t0:.1f} s outage")
        check(used < OUTAGE_CPU_S, f"round {rnd}: trakbox used {used:.2f} s CPU in {OUTAGE_S} s of outage")

        reconnects = log.count(label + r": reconnected")
        cable.plug()
        wait_for(f"round {rnd}: trakbox to reopen the port by itself",
                 lambda: log.count(label + r": reconnected") > reconnects, 15)
        print(f"link_faults: radio round {rnd}: reopened {time.time() - t_pull:.1f} s after the pull")
        # What the radio was last told is told again, and new frequencies go out.
        wait_for(f"round {rnd}: the last frequency sent again after the reopen", lambda: cable.peer.seen("A", hz), 10)
        wait_for(f"round {rnd}: get_powerstat 1 again", lambda: rig.powerstat() == "1", 5)
        hz = 145_900_000 + 1_000 * rnd
        check(rig.set_freq(hz) == "RPRT 0", f"round {rnd}: F accepted after the reopen")
        wait_for(f"round {rnd}: the peer to receive {hz}", lambda: cable.peer.seen("A", hz), 10)


def main():
    missing = [t for t in ("rotctld", "rotctl", "socat") if shutil.which(t) is None]
    if missing:
        skip(f"link_faults: skipped: {', '.join(missing)} not installed (Hamlib's utilities and socat)")
    state = tempfile.mkdtemp(prefix="trakbox-links-")
    folder = tempfile.mkdtemp(prefix="trakbox-cable-")
    satrak_port, rot_port, rig_port, rot_endpoint = free_port(), free_port(), free_port(), free_port()
    rotctld = Rotctld(rot_port)
    cable = CatCable(folder)
    procs = []
    rig = None
    try:
        rotctld.start()
        procs.append(rotctld.proc)
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--clock", CLOCK,
                               "--satrak-port", str(satrak_port), "--rigctld-port", str(rig_port),
                               "--rotctld-port", str(rot_endpoint),
                               "--rotator", f"rotctld:127.0.0.1:{rot_port}", "--radio", f"kenwood:{cable.radio}"],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        log = Log(state)
        t0 = time.time()
        rotator_faults(tb, log, satrak_port, rotctld, rot_endpoint)
        rig = Rigctl(rig_port)
        radio_faults(tb, log, rig, cable)
        rig.close()
        rig = None
        tb.stdin.close()
        check(tb.wait(20) == 0, "trakbox leaves cleanly when its input ends")
        print(f"link_faults: both links lost and recovered twice in {time.time() - t0:.1f} s")
    except Failure:
        print("trakbox.log, last 40 lines:\n" + "\n".join(Log(state).text().splitlines()[-40:]))
        raise
    finally:
        if rig:
            rig.close()
        cable.close()
        reap(procs + ([rotctld.proc] if rotctld.proc else []))
        shutil.rmtree(state, ignore_errors=True)
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
