"""A first start asks for the station (issue 60, item 8): a fresh service runs as the factory's NOCALL
at 27.4 N 128.7 E and says so (status --json "setup", SETUP lines in `trakbox status`, the page's
Station card open by itself); the callsign and a locator typed in the card on a phone (390x844,
headless Chromium) go through POST /api/v1/station, the setup notes go, and a restart keeps them. A
refused callsign changes neither the callsign nor the place. A QSO logged before the callsign was
set is exported with a warning."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, poll, run_test, sh  # noqa: E402
from _web import WebStation  # noqa: E402
from web_browser import CLOCK, browser, console_errors, no_horizontal_scroll, text  # noqa: E402


def main():
    w = WebStation("--elements-url", "file://" + os.path.join(os.path.abspath(SOURCE), "data", "amateur.tle"),
                   clock=CLOCK)
    d = None
    try:
        s = w.status()
        check(s["station"]["callsign"] == "NOCALL" and len(s["setup"]) == 2 and s["healthy"],
              f"a fresh station says what to set, and still works: {s['setup']} healthy={s['healthy']}")
        check("callsign not set (NOCALL)" in s["setup"][0] and "station position not set" in s["setup"][1], f"{s['setup']}")
        shown = w.status_text()
        check("  SETUP     callsign not set (NOCALL)" in shown, f"the text status:\n{shown}")
        # A QSO before the callsign is set: exported without STATION_CALLSIGN, with a warning.
        status, r = w.post("/api/v1/track", {"satellite": "ISS"})
        status, r = w.post("/api/v1/log", {"call": "W1AW"})
        check(status == 200, f"a QSO as NOCALL: {status} {r}")
        code, out, err = sh(BIN, "log", "export", "--state", w.state)
        check(code == 0 and "no STATION_CALLSIGN (logged before the station's callsign was set)" in err and
              "STATION_CALLSIGN" not in out, f"the export warns: {code} {err}")
        # The whole request is checked first: a bad callsign with a good place changes nothing.
        status, r = w.post("/api/v1/station", {"callsign": "W1AW-TOO-LONG-X", "locator": "JN58td"})
        check(status == 409 and "station.callsign" in r.get("error", ""), f"a bad callsign refused: {status} {r}")
        s = w.status()
        check(s["station"]["callsign"] == "NOCALL" and abs(s["station"]["lat_deg"] - 27.391) < 0.01,
              f"nothing changed: {s['station']}")

        d = browser(390, 844)
        d.get(f"http://127.0.0.1:{w.port}/")
        poll("the page live", lambda: text(d, "link") == "live", 20)
        poll("the Station card open by itself", lambda: d.find_element("id", "station-card").get_attribute("open") is not None, 10)
        check("callsign not set" in text(d, "station-setup"), f"the card says what to set: {text(d, 'station-setup')}")
        no_horizontal_scroll(d, "the Station card on a phone")
        d.find_element("id", "st-call").send_keys("dl1abc")
        d.find_element("id", "st-place").send_keys("JN58td")
        d.find_element("id", "st-height").send_keys("520")
        d.find_element("id", "btn-station").click()
        s = poll("the station set", lambda: (lambda s: s if s["station"]["callsign"] == "DL1ABC" else None)(w.status()), 10)
        check(s["station"]["locator"].startswith("JN58td") and s["station"]["height_m"] == 520 and s["setup"] == [],
              f"set from the page, nothing left to set: {s['station']} {s['setup']}")
        poll("the card's notes gone", lambda: text(d, "station-setup") == "", 10)
        check(text(d, "station-now").startswith("DL1ABC JN58td"), f"the card's summary: {text(d, 'station-now')}")
        errors = console_errors(d)
        check(not errors, f"console errors: {errors}")
        w.stop()
        w.start()
        s = w.status()
        check(s["station"]["callsign"] == "DL1ABC" and s["setup"] == [], f"kept across a restart: {s['station']}")
        print(f"station set from the page: {s['station']['callsign']} {s['station']['locator']} "
              f"{s['station']['height_m']} m; setup notes before: 2, after: 0")
    finally:
        if d:
            d.quit()
        w.stop()


if __name__ == "__main__":
    run_test(main)
