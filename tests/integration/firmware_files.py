"""The later TrakBox firmware's files (v3.20d-3.50b; issue 12) on the real binary: STATION.DAT
through menu 6-9 (a broken file first: every problem by line and item, nothing applied), FREQ.DAT
through menu 3-3 (a file with broken lines: they are reported, the rest loads; then the whole file),
and FREQ.DAT as the freqmode.txt of a --data directory. The files are tests/data/firmware/, written
from the format description; the stored state is checked after each step.
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import BIN, CLOCK, SOURCE, check, load_state, run_test  # noqa: E402
from _tbui import SerialSession  # noqa: E402

FW = os.path.join(SOURCE, "tests", "data", "firmware")


def fw(name):
    return open(os.path.join(FW, name)).read()


def station_6_9(ui, state_file):
    ui.send("6\r")
    ui.prompt(w.UPDATE)
    w.start_6_9(ui)
    ui.upload(fw("STATION_BAD.DAT"))
    out = ui.prompt(w.UPDATE)
    w.must(out, r'line 2, item 7 \(COM baud\): found "38400", expected a speed in baud', "line 1's baud")
    w.must(out, r'line 3, item 6 \(flip mode\): found "X", expected F \(flip mode\) or nothing', "the F item")
    w.must(out, r'line 5, item 2 \(CAT rig\): found "YAESU_999", expected ICOM, KENWOOD, KENWOOD711', "the rig")
    w.must(out, r'line 6, item 2 \(antenna parking ON/OFF\): found "1x7"', "parking with digits")
    w.must(out, r'line 7, item 7 \(rotator error timeout\): found "0", expected seconds 1 to 600', "the timeout")
    w.must(out, r'line 8, item 4 \(azimuth maximum\): found "270"', "a limit range of no width")
    w.must(out, r"Station file not applied: every parameter is at its default\.", "nothing applied")
    data = load_state(state_file)
    check(data["station"]["callsign"] == "NOCALL", f"the broken file left the defaults: {data['station']}")

    w.start_6_9(ui)
    ui.upload(fw("STATION.DAT"))
    out = ui.prompt(w.UPDATE)
    w.must(out, r"Station file loaded\. Verify it with 6-0", "the seven-line file is taken")
    data = load_state(state_file)
    st, rot, rc = data["station"], data["rotator"], data["radio"]
    check((st["callsign"], st["lat_deg"], st["lon_deg"], st["height_m"], st["rotor_start"], st["com_baud"]) ==
          ("JA6FTL", 33.59, 130.4, 25.0, "north", 19200), f"line 1: {st}")
    check((rot["az_span"], rot["el_span"], rot["el_flip_allowed"]) == ([12, 1010], [8, 500], True), f"line 2: {rot}")
    check((rot["az_dead_band"], rot["el_dead_band"], rot["az_skew"], rot["el_skew"]) == (4, 2, -3, 5), "line 3")
    check((rc["rig"], rc["rig_model"], rc["ft736_wide_fm"], rc["cat_policy"], rc["cat_baud"]) ==
          ("yaesu", "yaesu_847", True, "full_orbit", 4800), f"line 4: {rc}")
    check((rot["parking_enabled"], rot["parking"]) == (True, [0.0, 10.0]), "line 5: parking")
    check((rc["mic_click"]["park_pulse_width_digit"], rc["mic_click"]["park_pulse_interval_digit"]) == (2, 5),
          f"line 5: mic-click digits {rc['mic_click']}")
    check(data["pass_events"] == {"rotor_start_el_deg": -1.5, "output_on_el_deg": 0.5, "output_off_el_deg": -0.5},
          f"line 5: elevations {data['pass_events']}")
    check(rc["parking"] == {"enabled": True, "rx_hz": 145_800_000, "tx_hz": 435_300_000, "rx_mode": "fm",
                            "tx_mode": "usb"}, f"line 6: radio parking {rc['parking']}")
    check((data["rotator_error_detection"], rot["stall_s"]) == (True, 45.0), "line 6: rotator error")
    check((rot["limits_enabled"], rot["az_limit_min"], rot["az_limit_max"], rot["el_limit_min"],
           rot["el_limit_max"]) == (True, 270.0, 90.0, 0.0, 80.0), f"line 7: limits through North {rot}")
    # Flip mode (v3.30a: the EL rotor calibrated at 0 and 180 degrees): the firmware's own example
    # line and a span like JA6FTL's (25-981, refused while the span was read as 0..90) apply.
    for name, el_span in (("STATION_FLIP.DAT", [2, 917]), ("STATION_JA6FTL.DAT", [25, 981])):
        w.start_6_9(ui)
        ui.upload(fw(name))
        out = ui.prompt(w.UPDATE)
        w.must(out, r"Station file loaded\. Verify it with 6-0", f"{name} is taken")
        rot = load_state(state_file)["rotator"]
        check((rot["el_span"], rot["el_flip_allowed"]) == (el_span, True), f"{name}: line 2 {rot}")
    ui.send("Q\r")
    ui.prompt(w.MAIN)


def upload_3_3(ui, freq_file):
    ui.send("3\r")
    ui.prompt(w.UPDATE)
    w.start_upload(ui, "N")
    ui.upload(open(os.path.join(w.DATA, "amateur.tle")).read())
    ui.prompt(r"Upload freq/mode data file\. \(EOF:ctrl\+Z\)", timeout=20)
    ui.upload(fw(freq_file))
    out = ui.prompt(w.UPDATE, timeout=20)
    ui.send("Q\r")
    ui.prompt(w.MAIN)
    return out


def radio_of(data, name):
    for s in data["db"]["satellites"]:
        if s["elements"]["name"] == name:
            return s["radio"]
    raise AssertionError(name)


def freq_3_3(ui, state_file):
    out = upload_3_3(ui, "FREQ_BAD.DAT")
    w.must(out, r"Satellite \(ISS\) updated and selected as # 1$", "a good line before the broken ones")
    w.must(out, r"Satellite \(AO-91\) updated and selected as # 2$", "a good line after them")
    w.must(out, r'Skipped line 3, field 3 \(uplink frequency\): found "145\.950,145\.960,145\.970,145\.980,145\.990", '
                r"expected a frequency in MHz such as 145\.900, up to 4", "five uplinks")
    w.must(out, r'Skipped line 5, field 8 \(reverse flag\): found "xr"', "a bad reverse flag")
    w.must(out, r'Skipped line 6, field 5 \(uplink mode\): found "am", expected usb, lsb, fm, cw or none', "a mode")
    w.must(out, r'Skipped line 8: found "9 fields"', "too many fields")
    w.must(out, r"2 satellite\(s\) updated and selected, 6 record\(s\) skipped\.", "the summary")

    out = upload_3_3(ui, "FREQ.DAT")
    w.must(out, r"8 satellite\(s\) updated and selected, 0 record\(s\) skipped\.", "every FREQ.DAT line taken")
    w.must(out, r"Satellite \(QO-100\) updated and selected as # 3$", "in the file's order")
    data = load_state(state_file)
    iss = radio_of(data, "ISS")
    check(iss["uplink_hz"] == 145_990_000 and iss["alternate_uplinks_hz"] == [145_825_000, 145_800_000, 437_800_000]
          and iss["reverse"] == "icom_main_sub", f"ISS: four uplinks, ir {iss}")
    fo29 = radio_of(data, "FO-29")
    check(fo29["reverse"] == "kenwood_vfo" and len(fo29["alternate_uplinks_hz"]) == 3, f"FO-29: kr {fo29}")
    qo = radio_of(data, "QO-100")
    check((qo["downlink_hz"], qo["downlink_offset_hz"], qo["uplink_hz"], qo["uplink_offset_hz"]) ==
          (10_489_550_000, -9_750_000_000, 2_400_050_000, -1_968_000_000), f"QO-100: offsets on both links {qo}")
    jo97 = radio_of(data, "JO-97")
    check((jo97["uplink_hz"], jo97["uplink_mode"]) == (0, "none"), f"JO-97: no uplink {jo97}")
    check(radio_of(data, "HO-113")["downlink_mode"] == "cw", "cw")
    check(data["station"]["callsign"] == "JA6FTL", "3-3 left the station of 6-9 alone")


def fresh_start(files):
    """A fresh start on a --data directory holding amateur.tle and `files` ({name in the
    directory: test file}); returns (the saved state, what trakbox printed)."""
    data_dir = tempfile.mkdtemp(prefix="trakbox-fwdata-")
    state_dir = tempfile.mkdtemp(prefix="trakbox-fwstate-")
    try:
        shutil.copy(os.path.join(w.DATA, "amateur.tle"), data_dir)
        for name, source in files.items():
            shutil.copy(os.path.join(FW, source), os.path.join(data_dir, name))
        r = subprocess.run([BIN, "--state", state_dir, "--data", data_dir, "--line", "--satrak-port", "0",
                            "--clock", CLOCK], stdin=subprocess.DEVNULL, capture_output=True, timeout=60)
        check(r.returncode == 0, f"trakbox --data: exit {r.returncode} {r.stderr[-500:]!r}")
        return load_state(os.path.join(state_dir, "trakbox-state.json")), (r.stdout + r.stderr).decode(errors="replace")
    finally:
        shutil.rmtree(data_dir, ignore_errors=True)
        shutil.rmtree(state_dir, ignore_errors=True)


def freq_data_dir():
    """FREQ.DAT as the freqmode.txt of a --data directory, on a fresh start."""
    data, _ = fresh_start({"freqmode.txt": "FREQ.DAT"})
    iss = radio_of(data, "ISS")
    check(iss["alternate_uplinks_hz"] == [145_825_000, 145_800_000, 437_800_000] and
          iss["reverse"] == "icom_main_sub", f"--data: ISS {iss}")
    ao91 = radio_of(data, "AO-91")
    check((ao91["uplink_hz"], ao91["alternate_uplinks_hz"], ao91["uplink_offset_hz"]) ==
          (1_268_100_000, [1_268_200_000], -1_124_000_000), f"--data: AO-91 {ao91}")
    names = [data["db"]["satellites"][i]["elements"]["name"] for i in data["db"]["selected"]]
    check(names[:3] == ["ISS", "FO-29", "QO-100"], f"--data: the tracking list in the file's order {names}")


def firmware_names_data_dir():
    """The firmware's own file names in a --data directory: FREQ.DAT (no freqmode.txt) and
    STATION.DAT, applied on a fresh start; a STATION.DAT with a problem is not used and said so."""
    data, _ = fresh_start({"FREQ.DAT": "FREQ.DAT", "STATION.DAT": "STATION.DAT"})
    check(radio_of(data, "ISS")["reverse"] == "icom_main_sub", "--data: FREQ.DAT read under its own name")
    st, rc = data["station"], data["radio"]
    check((st["callsign"], st["lat_deg"], st["rotor_start"], rc["rig_model"], rc["cat_baud"]) ==
          ("JA6FTL", 33.59, "north", "yaesu_847", 4800), f"--data: STATION.DAT applied {st} {rc}")
    check(data["pass_events"]["rotor_start_el_deg"] == -1.5, f"--data: line 5 {data['pass_events']}")
    bad, err = fresh_start({"STATION.DAT": "STATION_BAD.DAT"})
    check(bad["station"]["callsign"] != "JA6FTL" and bad["radio"]["cat_baud"] == 0,
          f"--data: a bad STATION.DAT changes nothing {bad['station']}")
    check("STATION.DAT: not used" in err, f"--data: the bad STATION.DAT is reported: {err[-800:]!r}")


def main():
    s = SerialSession()
    try:
        s.ui.prompt(w.MAIN, timeout=15)
        station_6_9(s.ui, s.state_file)
        freq_3_3(s.ui, s.state_file)
        check(s.stop() == 0, "SIGTERM: exit 0")
        data = load_state(s.state_file)
        check(radio_of(data, "ISS")["reverse"] == "icom_main_sub" and data["radio"]["cat_baud"] == 4800,
              "the state saved at SIGTERM keeps the new fields")
    finally:
        s.close()
    freq_data_dir()
    firmware_names_data_dir()


if __name__ == "__main__":
    run_test(main)
