"""The horizon mask set by the operator (issue 57, item 3) on the real binary running as a service:

1. Menu 6-4 over `trakbox attach --line` on a pty (the serial line's plain lines) parks the antenna
   at azimuth 200, elevation 0; menu 4 shows the mask (none), refuses a malformed one with the
   reader's sentence and asks again, takes the step list `0 0 190 25 230 0 360` (a roof 25 deg high
   from 190 to 230) and warns that parking now points into it. The status carries the mask and the
   parking problem; the log says it.
2. `trakbox settings set` answers with the same warning.
3. Tracking a satellite that is down, the station parks by itself: the log says it parks into the mask.
4. The page at phone size (390x844, headless Chromium): the Station card shows the mask; a bad mask
   typed there is refused (HTTP 400, the reader's sentence) and the stored mask stays; pairs one a
   line are taken, the sky's mask redraws, the parking problem follows the new mask's height; no
   horizontal scrolling (screenshots of the card and the sky kept in the test's temporary folder,
   its path printed, and copied to TRAKBOX_SCREENSHOT_DIR when set). Parking from the API says the warning, the log too. No mask
   clears the problem.
"""
import os
import pty
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, Terminal, check, poll, run_test  # noqa: E402
from _tbui import LineUI  # noqa: E402
from _walk_steps import MAIN, UPDATE  # noqa: E402
from _web import WebStation  # noqa: E402
from web_browser import CLOCK, browser, console_errors, no_horizontal_scroll, text  # noqa: E402

ROOF = "0 0 190 25 230 0 360"
ROOF_WARNING = "parking at azimuth 200.0, elevation 0.0 points into the horizon mask (25.0 there)"
# 0 0; 180 10; 270 30 interpolated: at 200, 10 + 20 * 20 / 90 = 14.4.
SLOPE_WARNING = "parking at azimuth 200.0, elevation 0.0 points into the horizon mask (14.4 there)"


def line_client(state):
    master, slave = pty.openpty()
    p = subprocess.Popen([BIN, "attach", "--state", state, "--line"], stdin=slave, stdout=slave, stderr=slave,
                         env=dict(os.environ, TERM="xterm"), start_new_session=True)
    os.close(slave)
    return p, Terminal(master), master


def log_text(state):
    with open(os.path.join(state, "trakbox.log"), errors="replace") as f:
        return f.read()


def menus(w):
    p, t, fd = line_client(w.state)
    ui = LineUI(t)
    try:
        ui.prompt(MAIN, 20)
        # 6-4: parking at 200/0, no limits.
        ui.send("6\r")
        ui.prompt(UPDATE)
        ui.send("4\r")
        ui.prompt(r"Set Antenna Parking position \? \[Y/N\] ")
        ui.send("Y\r")
        ui.prompt(r"Azimuth Parking value : 0\.0 ")
        ui.send("200\r")
        ui.prompt(r"Elevation Parking value : 0\.0 ")
        ui.send("0\r")
        ui.prompt(r"Set Antenna rotation limit \? \[Y/N\] ")
        ui.send("N\r")
        out = ui.prompt(UPDATE)
        check("WARNING" not in out, f"no mask yet, nothing to warn of:\n{out}")
        ui.send("Q\r")
        ui.prompt(MAIN)
        # Menu 4: Enter keeps the six values; the mask is none.
        ui.send("4\r")
        for label in ("Callsign", r"Latitude  \[deg\]", r"Longitude \[deg\]", r"Height    \[m\]", r"Rotor start \[N/S\]",
                      "COM port baud rate"):
            ui.prompt(label + r"\s*: \S+  ")
            ui.send("\r")
        out = ui.prompt(r"Horizon mask       : none  ")
        check("or none; Enter keeps it" in out, f"menu 4 says the forms it takes:\n{out}")
        ui.send("0 0; 190 25; 400 0\r")
        out = ui.prompt(r"Horizon mask       : none  ")
        check("horizon mask pair 3: azimuth 400 is outside 0..360; not changed" in out,
              f"a bad mask is refused with the reader's sentence and asked again:\n{out}")
        ui.send(ROOF + "\r")
        out = ui.prompt(MAIN)
        check("Horizon mask: stepped, 3 steps, 0.0..25.0 deg" in out, f"the mask stored, said:\n{out}")
        check("WARNING: " + ROOF_WARNING.replace(" mask (", " mask\n(") in out,
              f"menu 4 warns that parking points into the mask:\n{out}")
        for line in out.splitlines():
            check(len(line) <= 80, f"menu 4's lines fit 80 columns: {line!r}")
        ui.send("\x1d")  # detach
        p.wait(10)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
        os.close(fd)


def page(w, scratch):
    d = browser(390, 844)
    try:
        d.get(f"http://127.0.0.1:{w.port}/")
        poll("the page live", lambda: text(d, "link") == "live", 20)
        # (A fresh station's card opens by itself: NOCALL is still to be set.)
        d.execute_script("document.getElementById('station-card').open = true")
        poll("the card shows the mask", lambda: text(d, "st-mask-now") == "stepped, 3 steps, 0.0..25.0 deg", 10)
        area = d.find_element("id", "st-mask")
        check(area.get_attribute("value") == ROOF, f"the mask's points to edit: {area.get_attribute('value')!r}")
        check(text(d, "problems").find(ROOF_WARNING) >= 0, f"the page's problems: {text(d, 'problems')}")
        drawn = d.find_element("id", "mask").get_attribute("points")
        # A bad mask typed in the card: refused with the reader's sentence, nothing changes.
        area.click()  # from then on the station's refreshes leave the field to the operator
        area.clear()
        area.send_keys("0 0\n180 10\n270 95")
        d.find_element("id", "btn-station").click()
        poll("the refusal shown", lambda: "line 3: elevation 95 is outside -90..90" in text(d, "station-reply"), 10)
        check(w.status()["station"]["horizon_mask"]["text"] == ROOF, "a refused mask keeps the stored one")
        # Pairs one a line: taken, the sky redrawn, the problem follows the new height.
        area.clear()
        area.send_keys("0 0\n180 10\n270 30")
        d.find_element("id", "btn-station").click()
        poll("the new mask stored", lambda: w.status()["station"]["horizon_mask"]["text"] == "0 0; 180 10; 270 30", 10)
        poll("the sky redrawn", lambda: d.find_element("id", "mask").get_attribute("points") != drawn, 10)
        poll("the card's answer", lambda: "WARNING: " + SLOPE_WARNING in text(d, "station-reply"), 10)
        poll("the problem follows", lambda: SLOPE_WARNING in text(d, "problems"), 10)
        check(w.status()["problems"].count(SLOPE_WARNING) == 1, f"status problems: {w.status()['problems']}")
        no_horizontal_scroll(d, "the Station card with the mask on a phone")
        shot = os.path.join(scratch, "web-mask-edit.png")
        d.find_element("id", "station-card").screenshot(shot)
        sky = os.path.join(scratch, "web-mask-edit-sky.png")
        d.find_element("id", "sky").screenshot(sky)
        check(os.path.getsize(shot) > 1000 and os.path.getsize(sky) > 1000, "screenshots of the card and the sky")
        if os.environ.get("TRAKBOX_SCREENSHOT_DIR"):
            for f in (shot, sky):
                shutil.copy(f, os.path.join(os.environ["TRAKBOX_SCREENSHOT_DIR"], os.path.basename(f)))
        # Parking now: said in the answer and in the log.
        code, r = w.post("/api/v1/rotor", {"action": "park"})
        check(code == 200 and "WARNING: " + SLOPE_WARNING in r["note"], f"park says it: {code} {r}")
        poll("the log says it", lambda: "antenna: parks into the horizon mask: " + SLOPE_WARNING in log_text(w.state), 10)
        # No mask: the problem goes.
        d.find_element("id", "btn-mask-none").click()
        poll("the mask cleared", lambda: "horizon_mask" not in w.status()["station"], 10)
        poll("the card says none", lambda: text(d, "st-mask-now") == "none", 10)
        check(not any("horizon mask" in p for p in w.status()["problems"]), f"{w.status()['problems']}")
        # (The refused mask's 400 is the browser's one network error, as it should be.)
        errors = [e for e in console_errors(d) if "/api/v1/station" not in e["message"] or "status of 400" not in e["message"]]
        check(not errors, f"console errors: {errors}")
    finally:
        d.quit()


def main():
    scratch = tempfile.mkdtemp(prefix="trakbox-mask-edit-")
    w = WebStation(clock=CLOCK)
    try:
        menus(w)
        s = w.status()
        check(s["station"]["horizon_mask"]["text"] == ROOF, f"stored from menu 4: {s['station']}")
        check(ROOF_WARNING in s["problems"] and not s["healthy"], f"a status problem: {s['problems']}")
        check("  PROBLEM   " + ROOF_WARNING in w.status_text(), "trakbox status says it")
        check("antenna: " + ROOF_WARNING in log_text(w.state), "the log says it when menu 4 made it so")
        # A bad mask through the API: 400 and the reader's sentence, nothing changed.
        code, r = w.post("/api/v1/station", {"horizon_mask": "0 0; 190 x"})
        check(code == 400 and r["error"] == "station: horizon mask pair 2: 'x' is not a number", f"{code} {r}")
        check(w.status()["station"]["horizon_mask"]["text"] == ROOF, "the refused mask changed nothing")
        # trakbox settings set: the same warning in its answer.
        r = subprocess.run([BIN, "settings", "set", "station.horizon_mask", ROOF, "--state", w.state],
                           capture_output=True, text=True, timeout=20)
        check(r.returncode == 0 and "WARNING: " + ROOF_WARNING in r.stdout, f"settings set warns: {r.stdout} {r.stderr}")
        # Tracking a satellite that is down (AO-07 at 13:47): the station parks by itself, and says so.
        check(w.post("/api/v1/rotor", {"control": True})[0] == 200, "rotor control on")
        check(w.post("/api/v1/track", {"satellite": "AO-07"})[0] == 200, "tracking AO-07")
        poll("the antenna parks", lambda: w.status()["antenna"]["action"] == "park", 10)
        poll("the log says it parks into the mask",
             lambda: "antenna: parks into the horizon mask: " + ROOF_WARNING in log_text(w.state), 10)
        page(w, scratch)
        print(f"menu 4, settings and the page set the mask; parking warned: {ROOF_WARNING}; {SLOPE_WARNING}; "
              f"the card at 390x844: {os.path.join(scratch, 'web-mask-edit.png')}")
    finally:
        w.stop()
        shutil.rmtree(w.state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
