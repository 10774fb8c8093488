"""Issue 30, item 12: the log says the Satrak server listens once, and "trakbox stopped" is its
last line (the drivers' workers and the servers used to write after it). trakbox host on a fresh
state with Hamlib's dummy rotator (model 1) and the Satrak server on a free loopback port; the
element refresh to CelesTrak fails on the closed proxy, as everywhere in the suite."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, free_port, run_test  # noqa: E402

NO_NET = {k: "socks5h://127.0.0.1:9" for k in ("all_proxy", "ALL_PROXY", "http_proxy", "https_proxy", "HTTPS_PROXY")}


def main():
    state = tempfile.mkdtemp(prefix="trakbox-log-")
    try:
        r = subprocess.run([BIN, "host", "--state", state, "--clock", CLOCK, "--rotator", "hamlib:1:/dev/null",
                            "--satrak-port", str(free_port())], input="?A\n", capture_output=True, text=True,
                           timeout=30, env=dict(os.environ, **NO_NET))
        check(r.returncode == 0, f"trakbox host: {r.returncode} {r.stderr}")
        with open(os.path.join(state, "trakbox.log")) as f:
            lines = [ln.rstrip("\n") for ln in f if ln.strip()]
        listening = [ln for ln in lines if "listening on" in ln or "Satrak server on" in ln]
        check(len(listening) == 1, f"the Satrak server's start is logged {len(listening)} times: {listening}")
        check(lines[-1].endswith("trakbox stopped"), "lines after 'trakbox stopped':\n" + "\n".join(lines[-4:]))
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
