"""Secrets stay secret (issue 20) and the Satrak FTP settings read back cleanly (issue 19, item 1):
after a --log-level debug session that set every credential the Satrak protocol carries, neither
the FTP password nor the password inside an element-download URL is in trakbox.log, and
SATELLITE_FTP? answers a well-formed frame whose password field is "?" (written back, it keeps the
stored password). Frames are built and checked here with their own checksum code.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Satrak, check, free_port, read_log, run_test  # noqa: E402

FTP_SECRET = "Sup3rS3cretFtp"
HTTP_SECRET = "Sup3rS3cretHttp"


def main():
    state = tempfile.mkdtemp(prefix="trakbox-secrets-")
    port = free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", str(port), "--line",
                          "--log-level", "debug"], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE)
    try:
        acu = Satrak(port)
        dead = free_port()  # nothing listens there: the downloads fail at once, on loopback
        check(acu.ask(f"SATELLITE_FTP=,127.0.0.1,tracker,{FTP_SECRET},{dead},sats.txt,ISS,1,1")
              == "SATELLITE_FTP=,OK", "FTP settings accepted")
        got = acu.ask("SATELLITE_FTP?")
        check("*" not in got and "$" not in got, f"no framing character inside the payload: {got!r}")
        check(got == f"SATELLITE_FTP?,127.0.0.1,tracker,?,{dead},sats.txt,ISS,1,1", f"reply {got!r}")
        # Written back unchanged, the settings keep the stored password.
        check(acu.ask(got.replace("SATELLITE_FTP?", "SATELLITE_FTP=")) == "SATELLITE_FTP=,OK", "written back")
        check(acu.ask(f"SATELLITE_HTTP=,http://tracker:{HTTP_SECRET}@127.0.0.1:{dead}/sats.txt,1,1")
              .startswith("SATELLITE_HTTP=,"), "HTTP settings answered")
        acu.close()
    finally:
        p.terminate()
        p.wait(20)
    try:
        with open(os.path.join(state, "trakbox-state.json")) as f:
            doc = json.load(f)
        check(doc["data"]["satrak"]["ftp"]["password"] == FTP_SECRET, "the stored password survived the write-back")
        log = read_log(state)
        check("SATELLITE_FTP=" in log, "the debug log records the Satrak commands")
        check("<redacted>" in log, "and shows where a secret was")
        check(FTP_SECRET not in log, "the FTP password is not in the log")
        check(HTTP_SECRET not in log, "the URL password is not in the log")
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
