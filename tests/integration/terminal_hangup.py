"""A terminal that goes away ends trakbox's terminal front end, which saves and leaves as Ctrl-C
does, instead of living on, spinning on an input that is always readable (found 2026-12-02: six
orphans of closed tmux windows at 20-28 % of a core each, the tick and SIGHUP starved).

Two ways a terminal goes: tmux kill-session (the kernel hangs up the pane's terminal and sends its
process group SIGHUP), and a pseudo-terminal whose other end closes with no signal at all (the
terminal is not the process's controlling one: a front end started by another program).
"""
import fcntl
import os
import struct
import subprocess
import sys
import tempfile
import termios
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, poll, read_log, run_test, skip  # noqa: E402


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def pid_of(state):
    r = subprocess.run(["pgrep", "-f", f"^{BIN} --state {state} "], capture_output=True, text=True)
    pids = [int(p) for p in r.stdout.split()]
    return pids[0] if pids else None


def tmux_window_closed():
    if subprocess.run(["which", "tmux"], capture_output=True).returncode != 0:
        skip("tmux is not installed")
    state = tempfile.mkdtemp(prefix="trakbox-hup-")
    session = f"trakbox-hup-{os.getpid()}"
    cmd = f"{BIN} --state {state} --clock {CLOCK} --satrak-port 0"
    r = subprocess.run(["tmux", "new-session", "-d", "-s", session, "-x", "100", "-y", "34", "env", "TERM=xterm",
                        "sh", "-c", cmd], capture_output=True, text=True, timeout=10)
    check(r.returncode == 0, f"tmux: {r.stderr}")
    pid = poll("the trakbox of the tmux window", lambda: pid_of(state), 10)
    poll("the menus on the screen", lambda: "Select [1-8,S,M]:" in subprocess.run(
        ["tmux", "capture-pane", "-t", session, "-p"], capture_output=True, text=True).stdout, 10)
    subprocess.run(["tmux", "kill-session", "-t", session], capture_output=True, timeout=10)
    try:
        poll("trakbox to leave after its window closed", lambda: not alive(pid), 10)
    finally:
        if alive(pid):
            os.kill(pid, 9)
    log = read_log(state)
    check("trakbox stopped" in log, f"the log does not say it stopped:\n{log[-1500:]}")
    check(os.path.exists(os.path.join(state, "trakbox-state.json")), "no state saved")


def pty_closed_without_signal():
    state = tempfile.mkdtemp(prefix="trakbox-hup-")
    master, slave = os.openpty()
    fcntl.ioctl(master, termios.TIOCSWINSZ, struct.pack("HHHH", 34, 100, 0, 0))
    env = dict(os.environ, TERM="xterm", LINES="34", COLUMNS="100")
    proc = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], stdin=slave,
                            stdout=slave, stderr=slave, env=env, close_fds=True)
    os.close(slave)
    try:
        seen = b""
        deadline = time.time() + 10
        while b"Select" not in seen and time.time() < deadline:
            try:
                seen += os.read(master, 65536)
            except OSError:
                break
        check(b"Select" in seen, f"the menus never came: {seen[-400:]!r}")
        before = cpu_seconds(proc.pid)
        os.close(master)  # the other end goes: no SIGHUP, the terminal is not trakbox's controlling one
        t0 = time.time()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            spent = cpu_seconds(proc.pid) - before
            raise AssertionError(f"trakbox still runs {time.time() - t0:.0f} s after its terminal closed, "
                                 f"{spent:.1f} CPU seconds spent meanwhile")
        check(proc.returncode == 0, f"exit status {proc.returncode}")
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    check(os.path.exists(os.path.join(state, "trakbox-state.json")), "no state saved")


def main():
    pty_closed_without_signal()
    tmux_window_closed()
    print("ok: a closed terminal ends the front end, with the state saved (tmux and a bare pty)")


if __name__ == "__main__":
    run_test(main)
