"""The endpoints' shared secrets (issue 20): with --rotctld-secret-file and --host-secret-file, a
client must give the secret first. On rotctld (Hamlib's way): before \\password only \\dump_state,
\\chk_vfo and q work, anything else is RPRT -19; a wrong secret is RPRT -1, three wrong ones close
the connection; the right one is RPRT 0 and then every command works. Host mode: PASS SECRET. A
client that gives nothing is closed after --auth-timeout. The secret never reaches the log, even at
--log-level debug. Without a secret (rigctld here) clients work as before."""
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, free_port, run_test, stop_and_read_log, wait_listening  # noqa: E402

SECRET = "Tr4kB0x-s3cret"


class Client:
    def __init__(self, port):
        self.s = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.buf = b""

    def send(self, data):
        self.s.sendall(data)

    def until(self, marker, timeout=10):
        end = time.time() + timeout
        while marker not in self.buf:
            self.s.settimeout(max(0.05, end - time.time()))
            try:
                chunk = self.s.recv(4096)
            except socket.timeout:
                break
            if not chunk:
                break
            self.buf += chunk
        i = self.buf.find(marker)
        if i < 0:
            got, self.buf = self.buf, b""
            return got
        got, self.buf = self.buf[:i + len(marker)], self.buf[i + len(marker):]
        return got

    def ask(self, line, marker=b"\n"):
        self.send(line)
        return self.until(marker)

    def closed(self, timeout=10):
        """True when the server has closed the connection (EOF) within timeout."""
        end = time.time() + timeout
        while time.time() < end:
            self.s.settimeout(max(0.05, end - time.time()))
            try:
                chunk = self.s.recv(4096)
            except socket.timeout:
                return False
            except OSError:
                return True
            if not chunk:
                return True
            self.buf += chunk
        return False

    def close(self):
        self.s.close()


def main():
    state = tempfile.mkdtemp(prefix="trakbox-secret-")
    try:
        secret_file = os.path.join(state, "rotctld.secret")
        with open(secret_file, "w") as f:
            f.write(SECRET + "\n")
        os.chmod(secret_file, 0o600)
        rot, rig, host = free_port(), free_port(), free_port()
        p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", "0",
                              "--rotctld-port", str(rot), "--rigctld-port", str(rig), "--host-port", str(host),
                              "--rotctld-secret-file", secret_file, "--host-secret-file", secret_file,
                              "--auth-timeout", "2", "--log-level", "debug"],
                             stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        try:
            for port in (rot, rig, host):
                wait_listening(port, "trakbox", 15, p)
            # rotctld: missing, handshake, wrong, right.
            c = Client(rot)
            check(c.ask(b"p\n") == b"RPRT -19\n", "a command before the secret: RPRT -19")
            got = c.ask(b"\\dump_state\n", b"\n")
            check(not got.startswith(b"RPRT -19"), f"\\dump_state works before the secret: {got!r}")
            c.until(b"(the rest of the dump)", 1)  # drain the rest of the dump
            c.buf = b""
            check(c.ask(b"\\password wrong\n") == b"RPRT -1\n", "a wrong secret: RPRT -1")
            check(c.ask(b"\\password\n") == b"RPRT -1\n", "a missing secret: RPRT -1")
            check(c.ask(("\\password " + SECRET + "\n").encode()) == b"RPRT 0\n", "the right secret: RPRT 0")
            got = c.ask(b"p\n", b"\n")
            got += c.until(b"\n")
            check(not got.startswith(b"RPRT"), f"after the secret, p answers the position: {got!r}")
            c.close()

            # Three wrong secrets close the connection.
            c = Client(rot)
            for _ in range(3):
                check(c.ask(b"\\password nope\n") == b"RPRT -1\n", "a wrong secret: RPRT -1")
            check(c.closed(), "three wrong secrets close the connection")
            c.close()

            # Nothing given: closed after --auth-timeout (2 s).
            c = Client(rot)
            t0 = time.time()
            check(c.closed(8), "a silent client is closed after the auth timeout")
            check(1.5 <= time.time() - t0 <= 6, f"closed after about 2 s ({time.time() - t0:.1f} s)")
            c.close()

            # Host mode: PASS.
            c = Client(host)
            c.until(b"TrakBox>>")
            got = c.ask(b"?A\r\n", b"TrakBox>>")
            check(b"ERROR this port wants its secret first: PASS <secret>" in got, f"host mode before PASS: {got!r}")
            got = c.ask(b"PASS wrong\r\n", b"TrakBox>>")
            check(b"ERROR wrong secret" in got, f"host mode, wrong secret: {got!r}")
            got = c.ask(("PASS " + SECRET + "\r\n").encode(), b"TrakBox>>")
            check(b"OK authenticated" in got, f"host mode, right secret: {got!r}")
            got = c.ask(b"?A\r\n", b"TrakBox>>")
            check(b"AZ" in got and b"ERROR" not in got, f"host mode after PASS: {got!r}")
            c.close()

            # No secret on rigctld: served at once, as Gpredict expects.
            c = Client(rig)
            got = c.ask(b"f\n")
            check(got.strip().isdigit(), f"rigctld without a secret answers at once: {got!r}")
            c.close()
        finally:
            log = stop_and_read_log(p, state)
        check(SECRET not in log, "the secret never reaches the log")
        check("gave a wrong secret 3 times; closed" in log, "too many attempts are logged")
        check("did not give the secret within 2 s; closed" in log, "the deadline is logged")
        check("authenticated" in log, "authentication is logged")

        # A secret for a server that is off, and an unreadable file, are refused before anything starts.
        q = subprocess.run([BIN, "--state", state, "--satrak-port", "0", "--rotctld-secret-file", secret_file],
                           input=b"", capture_output=True, timeout=30)
        check(q.returncode == 2 and "--rotctld-secret-file" in q.stderr.decode(), f"no server: {q.stderr!r}")
        q = subprocess.run([BIN, "--state", state, "--satrak-port", "0", "--rotctld-port", str(free_port()),
                            "--rotctld-secret-file", os.path.join(state, "none")], input=b"", capture_output=True,
                           timeout=30)
        check(q.returncode == 2 and "cannot be read" in q.stderr.decode(), f"unreadable file: {q.stderr!r}")
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
