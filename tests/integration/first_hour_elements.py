"""Issue 30, item 2: a fresh state refreshes from CelesTrak's amateur group (OMM JSON) by default,
and with no network says so on the status line instead of leaving the database silently stale;
started again soon after, it says when the next attempt comes.

The network is closed here as in the whole suite (a SOCKS proxy on a closed loopback port, set
again below so that the test never reaches the Internet when run by hand). The clock is 190 days
after the shipped elements' epochs, as on the day the issue was filed.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, in_temp_dir, load_state, run_test  # noqa: E402
from _tbui import ScreenUI  # noqa: E402

NO_NET = {k: "socks5h://127.0.0.1:9" for k in ("all_proxy", "ALL_PROXY", "http_proxy", "https_proxy", "HTTPS_PROXY")}
URL = "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=json"


def main():
    in_temp_dir("trakbox-first-hour-", walk)


def walk(state):
    ui = ScreenUI([BIN, "--state", state, "--clock", "2026-11-27T11:55:00Z", "--satrak-port", "0"], cols=120, env=NO_NET)
    try:
        ui.prompt(r"Select \[1-8,S,M(,[A-Z])?\]:")
        status = ui.wait(r"ELEMENTS \d+ DAYS OLD, REFRESH FAILED, SEE MENU 3-5", timeout=20).split("\n")[-1]
        check("REFRESH FAILED" in status, f"status line: {status!r}")
        ui.send("3")
        ui.prompt(r"Select:")
        ui.send("5")
        screen = ui.prompt(r"Select:")
        check(URL in screen, f"3-5 does not list CelesTrak's amateur group:\n{screen}")
        check("Last refresh: FAILED" in screen and "Without a network" in screen,
              f"3-5 does not say the refresh failed and what to do:\n{screen}")
        ui.send("Q")
    finally:
        ui.close()
    refresh = load_state(os.path.join(state, "trakbox-state.json"))["refresh"]
    urls = [s["url"] for s in refresh["sources"]]
    check(urls == [URL], f"the stored refresh sources are {urls}")
    check(refresh["last_attempt_failed"] is True, f"the failed attempt is remembered: {refresh}")

    # Started again soon after (still offline): no second download yet, and the status line says
    # when the next comes -- half an hour after a failed one, not the 12 h interval.
    ui = ScreenUI([BIN, "--state", state, "--clock", "2026-11-27T11:55:00Z", "--satrak-port", "0"], cols=120, env=NO_NET)
    try:
        ui.prompt(r"Select \[1-8,S,M(,[A-Z])?\]:")
        status = ui.wait(r"ELEMENTS \d+ DAYS OLD, NEXT REFRESH IN (2\d|30) MIN, SEE MENU 3-5", timeout=20).split("\n")[-1]
        check("REFRESH FAILED" not in status, f"status line after the restart: {status!r}")
        ui.send("Q")
    finally:
        ui.close()


if __name__ == "__main__":
    run_test(main)
