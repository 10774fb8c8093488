"""Menus 2 and 3 (3-1 edit, 3-2 select, 3-4 multi track, 3-3 NASA and AMSAT uploads ending in
Ctrl-Z with the freq/mode file, and uploads that fail) on the real binary over a serial line:
trakbox --tty on one end of a socat pty pair at 9600 bps, this script the operator's terminal.
The stored state is checked after each step that changes it and after SIGTERM.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import SerialSession, check, load_state, run_test  # noqa: E402


def main():
    s = SerialSession()
    try:
        ui = s.ui
        ui.prompt(w.MAIN, timeout=15)
        names = [n for n, _, _ in w.read_tle(os.path.join(w.DATA, "amateur.tle"))]

        w.walk_menu_2(ui, page_rows=22)  # line mode: 80x24, a screenful is 22 rows

        w.walk_menu_3_1(ui)
        data = load_state(s.state_file)  # saved after the change, before the next prompt
        ao73 = data["db"]["satellites"][6]
        check(ao73["elements"]["name"] == "AO-73", f"#7 is AO-73: {ao73['elements']['name']}")
        check(ao73["elements"]["revolution"] == 67560 and ao73["elements"]["inclination_deg"] == 97.83,
              f"3-1 stored K0 and I0: {ao73['elements']}")
        check(ao73["elements"]["eccentricity"] == 0.0034836, "the refused eccentricity left the stored one")
        check(ao73["radio"]["downlink_hz"] == 145_987_000 and ao73["radio"]["uplink_hz"] == 435_016_000,
              f"3-1 stored F1 and F2 exactly: {ao73['radio']}")
        check((ao73["radio"]["downlink_mode"], ao73["radio"]["uplink_mode"]) == ("fm", "fm"), "modes")
        check(ao73["radio"]["doppler"] != "cat" and ao73["radio"]["lcd_ma_display"] is True,
              f"Mic-click and LCD MA: {ao73['radio']}")

        w.walk_menu_3_2(ui, [4, 2, 3, 7], names)
        data = load_state(s.state_file)
        check(data["db"]["selected"] == [3, 1, 2, 6], f"the tracking list in the order chosen: {data['db']}")
        check(data["db"]["marked"] == 0, "the '*' goes to #1 when the marked satellite left the list")

        w.walk_menu_3_4(ui, 3, 4)
        before_uploads = load_state(s.state_file)
        check(before_uploads["db"]["multi_count"] == 3, "3-4 stored")

        w.walk_upload_nasa(ui)
        data = load_state(s.state_file)
        sats = data["db"]["satellites"]
        check([x["elements"]["name"] for x in sats] == names, "the uploaded NASA file is the database")
        check(all(x["elements"]["source"] == "nasa" for x in sats), "NASA sets")
        check(sats[6]["elements"]["revolution"] == 67551, "AO-73's elements are the uploaded ones again")
        check(sats[6]["radio"]["downlink_hz"] == 145_987_000, "AO-73's radio entry (3-1) kept by name")
        check(data["db"]["selected"] == [3, 1, 9, 0], f"the list in the freq/mode file's order: {data['db']}")
        qo100 = sats[9]["radio"]
        check(qo100["downlink_hz"] == 10_489_550_000 and qo100["downlink_offset_hz"] == -9_750_000_000,
              f"QO-100's converter offset: {qo100}")

        stored = open(s.state_file, "rb").read()
        w.walk_upload_failures(ui)
        check(open(s.state_file, "rb").read() == stored, "failed uploads leave the state file byte for byte")

        w.walk_upload_amsat(ui)
        ui.send("Q\r")
        ui.prompt(w.MAIN)

        check("\x1b" not in s.term.transcript, "no escape codes on a serial line")
        code = s.tb.stop()
        check(code == 0, f"exit status {code} after SIGTERM")
        w.check_state_after_3(load_state(s.state_file), before_uploads)
    finally:
        s.close()


if __name__ == "__main__":
    run_test(main)
