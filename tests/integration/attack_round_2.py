"""The second attack round (issue 33), replayed on the real binary:

- a checksum-valid state file with 100,000 nested objects under "data" crashed trakbox at every
  start (SIGSEGV) and stayed in place: now it is kept aside, the manual's RAM-lost message is shown,
  and the station comes up on its defaults; a state file beyond the size bound likewise;
- credentials in every form: an HTTP URL with a password given to SATELLITE_HTTP= (lower and upper
  case scheme), an FTP host written as ftp://u:PW@host, a \\password and a PASS sent again after
  logging in: absent from the log at debug level and from every reply;
- a flood of connections refused by --allow: the log stays bounded (a line of each kind a few times,
  then a count of what was left out), and host mode says "not allowed", not "busy";
- a symbolic link in place of trakbox.log is moved aside; its target is not written.
"""
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import zlib

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Satrak, check, free_port, read_log, run_test, wait_listening  # noqa: E402

LOST = "Data in RAM was lost !! Set default parameter !"
SECRETS = ["HttpPass77", "FtpPw55", "RealSecret42", "WrongGuess31"]


def nested_state(state):
    levels = 100000
    data = '{"a":' * levels + "1" + "}" * levels
    crc = "%08x" % (zlib.crc32(data.encode()) & 0xFFFFFFFF)
    path = os.path.join(state, "trakbox-state.json")
    with open(path, "w") as f:
        f.write('{"checksum":"%s","data":%s,"format":"trakbox-state","version":1}' % (crc, data))
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], input=b"",
                       capture_output=True, timeout=60)
    out = p.stdout.decode("latin-1")
    check(p.returncode == 0, f"nested state: trakbox exits 0, not {p.returncode}: {p.stderr[-300:]!r}")
    check(LOST in out, "nested state: the manual's RAM-lost message")
    kept = [n for n in os.listdir(state) if n.startswith("trakbox-state.json.corrupt-")]
    check(len(kept) == 1, f"nested state: kept aside once ({kept})")
    log = read_log(state)
    check("nested more than 64 levels deep" in log, "nested state: the log says why")
    # The next start loads the defaults it saved.
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], input=b"",
                       capture_output=True, timeout=60)
    check(p.returncode == 0 and LOST not in p.stdout.decode("latin-1"), "nested state: the next start loads")

    # Beyond the size bound (sparse, so the test writes nothing large).
    with open(path, "w") as f:
        f.write('{"format":"trakbox-state","data":{"x":"')
    os.truncate(path, 64 * 1024 * 1024 + 1)
    t0 = time.monotonic()
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], input=b"",
                       capture_output=True, timeout=60)
    check(p.returncode == 0 and LOST in p.stdout.decode("latin-1"), "oversized state: RAM lost, station up")
    with open(os.path.join(state, "trakbox.log")) as f:
        check("more than a state document may have" in f.read(), "oversized state: the log says why")
    print(f"oversized state refused and station up in {time.monotonic() - t0:.2f} s")


def credentials(state):
    secret_file = os.path.join(state, "host.secret")
    with open(secret_file, "w") as f:
        f.write("RealSecret42\n")
    os.chmod(secret_file, 0o600)
    sat, rot, host = free_port(), free_port(), free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", str(sat),
                          "--rotctld-port", str(rot), "--host-port", str(host), "--rotctld-secret-file", secret_file,
                          "--host-secret-file", secret_file, "--log-level", "debug"],
                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    replies = []
    try:
        for port in (sat, rot, host):
            wait_listening(port, "trakbox", 15, p)
        s = Satrak(sat)
        for url in ("http://op:HttpPass77@127.0.0.1:1/x.txt", "HTTP://op:HttpPass77@127.0.0.1:1/x.txt"):
            replies.append(s.ask(f"SATELLITE_HTTP=,{url},1,1,1"))
            got = s.ask("SATELLITE_HTTP?")
            replies.append(got)
            check("op:<redacted>@127.0.0.1:1/x.txt" in got, f"SATELLITE_HTTP? redacts the password: {got!r}")
            # What it answered, written back, keeps the stored URL.
            replies.append(s.ask("SATELLITE_HTTP=," + got.split(",")[1] + ",1,1,1"))
        got = s.ask("SATELLITE_FTP=,ftp://u:FtpPw55@127.0.0.1,user,pw,21,1,1")
        replies.append(got)
        check(got.startswith("SATELLITE_FTP=,ERR"), f"a host with credentials in it is refused: {got!r}")
        replies.append(s.ask("SATELLITE_FTP?"))
        time.sleep(1.0)  # the failed downloads are logged
        for port, login, again in ((rot, b"\\password RealSecret42\n", b"\\password RealSecret42\n"),
                                   (host, b"PASS RealSecret42\r\n", b"pass WrongGuess31\r\n")):
            c = socket.create_connection(("127.0.0.1", port), timeout=10)
            c.sendall(login)
            time.sleep(0.3)
            c.sendall(again)
            time.sleep(1.0)
            c.settimeout(1)
            try:
                replies.append(c.recv(65536).decode("latin-1"))
            except socket.timeout:
                pass
            c.close()
    finally:
        p.terminate()
        p.wait(10)
    log = read_log(state)
    check("satrak: download failed: http://op:<redacted>@127.0.0.1:1/x.txt" in log
          or "download failed: HTTP://op:<redacted>@" in log, "the failed download is logged, redacted")
    for secret in SECRETS:
        check(secret not in log, f"{secret} is not in the log")
        for r in replies:
            check(secret not in r, f"{secret} is not in a reply: {r!r}")


def refusal_flood(state):
    host = free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", "0", "--host-port",
                          str(host), "--allow", "192.0.2.0/24"],
                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    n = 3000
    try:
        wait_listening(host, "trakbox", 15, p)
        log_path = os.path.join(state, "trakbox.log")
        before = os.path.getsize(log_path)
        first = b""
        for i in range(n):
            c = socket.create_connection(("127.0.0.1", host), timeout=5)
            if i == 0:
                c.settimeout(5)
                first = c.recv(200)
            c.close()
        time.sleep(0.5)
        grown = os.path.getsize(log_path) - before
    finally:
        p.terminate()
        p.wait(10)
    check(first.startswith(b"ERROR not allowed"), f"host mode names the refusal: {first!r}")
    print(f"{n} refused connections: the log grew {grown} bytes ({grown / n:.2f} bytes a connection)")
    check(grown < 4000, f"the log stays bounded under a refusal flood ({grown} bytes for {n} connections)")
    log = read_log(state)
    check("more lines like this left out of the log" in log, "the log says how many lines it left out")


def linked_log(state):
    victim = os.path.join(state, "victim.txt")
    with open(victim, "w") as f:
        f.write("precious\n")
    os.symlink(victim, os.path.join(state, "trakbox.log"))
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], input=b"",
                       capture_output=True, timeout=60)
    check(p.returncode == 0, "a linked trakbox.log: trakbox runs")
    with open(victim) as f:
        check(f.read() == "precious\n", "the link's target is not written")
    check(not os.path.islink(os.path.join(state, "trakbox.log")), "trakbox.log is a file of its own")
    check(b"was a symbolic link, not written through" in p.stderr, "standard error says so")


def main():
    for step in (nested_state, credentials, refusal_flood, linked_log):
        state = tempfile.mkdtemp(prefix="trakbox-attack2-")
        try:
            step(state)
        finally:
            shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
