"""A satellite's modes on the real binary (issue 59): RS-44 with SSB, CW and FT4 (a --data freq/mode
file with three mode= lines). Choosing a mode from the page's API, from host mode (MODE NAME) and
from `trakbox track SAT --mode NAME` moves the simulated radio's dials to that mode's spot with
Doppler (the dial the radio reports is the spot plus the Doppler the station reports, and the two
links' Doppler are one range rate: down/f_down = -up/f_up); each mode keeps its own RX offset across
a restart; a QSO logged in FT4 is exported as MODE MFSK, SUBMODE FT4 with its frequencies."""
import os
import re
import shutil
import socket
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, Failure, check, free_port, poll, run_test, sh, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

RS44_CLOCK = "2026-05-21T10:57:00Z"   # a minute before RS-44's culmination over the factory station

# The spots: SSB the passband's centre (data/freqmode.txt), FT4 as issue 59 gives it, CW the test's
# own (both inside the passband; the uplink paired by the inverting rule).
SPOTS = {"SSB": (435640000, 145965000), "CW": (435613500, 145991500), "FT4": (435611000, 145993610)}
RS44 = ("RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=SSB\n"
        "RS-44 435.6135 145.9915 cw cw cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=CW\n"
        "RS-44 435.611 145.99361 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=FT4\n")


def data_dir():
    d = tempfile.mkdtemp(prefix="trakbox-modes-data-")
    shutil.copy(os.path.join(SOURCE, "data", "amateur.tle"), d)
    with open(os.path.join(SOURCE, "data", "freqmode.txt")) as f:
        others = [line for line in f if not line.startswith("RS-44 ")]
    with open(os.path.join(d, "freqmode.txt"), "w") as f:
        f.write(RS44 + "".join(others))
    return d


def host(port, line):
    """One host-mode command over TCP: its reply lines (the prompts left out)."""
    with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
        data, end = b"", time.time() + 10
        while b"TrakBox>>" not in data:
            if time.time() > end:
                raise Failure(f"host mode: no prompt in {data!r}")
            data += c.recv(4096)
        c.sendall(line.encode() + b"\r\n")
        data = b""
        while b"TrakBox>>" not in data:
            if time.time() > end:
                raise Failure(f"host mode: no reply to {line!r}: {data!r}")
            chunk = c.recv(4096)
            if not chunk:
                break
            data += chunk
        return [l.strip() for l in data.decode(errors="replace").replace("TrakBox>>", "").splitlines() if l.strip()]


def at_mode(w, mode, rx=0):
    """The tuning once the radio is on `mode`'s spot (moved by the mode's RX offset `rx`, which on a
    followed transponder moves the spot) and the simulated radio reports a dial for it."""
    down, _ = SPOTS[mode]

    def got():
        st = w.status()
        r = st["radios"][0]
        t = r.get("tuning")
        if not t or t["satellite"] != "RS-44" or t["mode"] != mode or t["downlink_spot_hz"] != down + rx:
            return None
        if not r.get("downlink_hz") or not r.get("uplink_hz") or t["downlink_dial_hz"] != r["downlink_hz"]:
            return None
        return t, r
    return poll(f"the radio on RS-44 {mode}", got, 15)


def check_dials(mode, t, r):
    """The radio's dials are the mode's spot plus the Doppler the station reports (to the 10 Hz the
    radios tune in), and both links' Doppler come from one range rate."""
    down, up = t["downlink_spot_hz"], t["uplink_spot_hz"]
    dd, du = t["downlink_doppler_hz"], t["uplink_doppler_hz"]
    check(abs(r["downlink_hz"] - (down + dd)) <= 10, f"{mode}: downlink dial {r['downlink_hz']} vs {down} {dd:+}")
    check(abs(r["uplink_hz"] - (up + du)) <= 10, f"{mode}: uplink dial {r['uplink_hz']} vs {up} {du:+}")
    check(abs(dd) > 1000 and abs(dd / down + du / up) < 2e-8,
          f"{mode}: one range rate: {dd:+} Hz at {down} Hz, {du:+} Hz at {up} Hz")
    print(f"RS-44 {mode}: spot {down}/{up} Hz, Doppler {dd:+}/{du:+} Hz, radio dials {r['downlink_hz']}/{r['uplink_hz']} Hz")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-modes-")
    hp = free_port()
    w = WebStation("--data", data_dir(), "--host-port", str(hp), state=state, clock=RS44_CLOCK)
    try:
        wait_listening(hp, "host mode", within=20, proc=w.proc)
        status, r = w.post("/api/v1/track", {"satellite": "RS-44"})
        check(status == 200, f"track RS-44: {status} {r}")
        t, r = at_mode(w, "SSB")
        check(t["modes"] == ["SSB", "CW", "FT4"], f"RS-44's modes, the first the default: {t['modes']}")
        check(t["uplink_spot_hz"] == SPOTS["SSB"][1], f"SSB's uplink: {t}")
        status, sats = w.get_json("/api/v1/satellites")
        rs = [s for s in sats["satellites"] if s["name"] == "RS-44"][0]
        check(rs["mode"] == "SSB" and [(m["name"], m["downlink_hz"], m["uplink_hz"]) for m in rs["modes"]] ==
              [(k, *SPOTS[k]) for k in ("SSB", "CW", "FT4")], f"GET /api/v1/satellites' RS-44: {rs}")
        check_dials("SSB", t, r)

        # The page's picker: FT4.
        status, r = w.post("/api/v1/radio", {"mode": "ft4"})
        check(status == 200 and r["note"] == "RS-44 FT4: 435611000 Hz down, 145993610 Hz up", f"mode FT4: {status} {r}")
        t, r = at_mode(w, "FT4")
        check(t["uplink_spot_hz"] == SPOTS["FT4"][1], f"FT4's uplink: {t}")
        check_dials("FT4", t, r)
        check(r["downlink_mode"] == "USB" and r["uplink_mode"] == "LSB", f"FT4's link modes pushed: {r}")
        status, r = w.post("/api/v1/radio", {"rx_offset_hz": 150})
        check(status == 200 and r["note"].endswith("(RS-44 FT4)"), f"FT4's offset kept for the mode: {status} {r}")
        at_mode(w, "FT4", 150)
        for body, want, sentence in [
            ({"mode": "PSK31"}, 409, "RS-44 has no mode 'PSK31': its modes are SSB, CW, FT4"),
            ({"mode": 7}, 400, None),
            ({"mode": "CW", "spot_hz": 1}, 400, None),
            ({"mode": "CW", "satellite": "NOSUCH"}, 409, "unknown satellite 'NOSUCH'"),
        ]:
            status, e = w.post("/api/v1/radio", body)
            check(status == want and (sentence is None or e["error"] == sentence), f"{body}: {status} {e}")

        # Host mode: the list, then CW, whose offset is its own.
        lines = host(hp, "MODE")
        check(lines[-1] == "MODES RS-44 SSB CW FT4*", f"host MODE: {lines}")
        lines = host(hp, "MODE cw")
        check(lines[-1] == "MODE RS-44 CW 435613500 145991500", f"host MODE cw: {lines}")
        t, r = at_mode(w, "CW")
        check(t["rx_offset_hz"] == 0, f"CW has no offset of its own yet: {t}")
        check_dials("CW", t, r)
        check(r["downlink_mode"] == "CW" and r["uplink_mode"] == "CW", f"CW's link modes pushed: {r}")
        lines = host(hp, "MODE RTTY")
        check(lines[-1] == "ERROR MODE: RS-44 has no mode 'RTTY': its modes are SSB, CW, FT4", f"host refusal: {lines}")
        status, r = w.post("/api/v1/radio", {"rx_offset_hz": -80})
        check(status == 200 and r["note"].endswith("(RS-44 CW)"), f"CW's offset: {status} {r}")
        at_mode(w, "CW", -80)
        host(hp, "MODE FT4")
        t, _ = at_mode(w, "FT4", 150)
        check(t["rx_offset_hz"] == 150, f"FT4's own offset again: {t}")

        # A restart: FT4 still chosen with its offset; CW keeps its own.
        w.stop()
        w.start()
        wait_listening(hp, "host mode", within=20, proc=w.proc)
        t, _ = at_mode(w, "FT4", 150)
        check(t["rx_offset_hz"] == 150, f"after the restart, FT4: {t}")
        # The command line: `trakbox track RS-44 --mode CW` through the station's socket.
        code, out, err = sh(BIN, "track", "RS-44", "--mode", "CW", "--state", state)
        check(code == 0 and out.startswith("ok:") and "RS-44 CW: 435613500 Hz down, 145991500 Hz up" in out,
              f"trakbox track --mode CW: {code} {out} {err}")
        t, r = at_mode(w, "CW", -80)
        check(t["rx_offset_hz"] == -80, f"after the restart, CW: {t}")
        check_dials("CW", t, r)
        code, out, err = sh(BIN, "track", "RS-44", "--mode", "AM", "--state", state)
        check(code == 1 and err.strip() == "refused: RS-44 has no mode 'AM': its modes are SSB, CW, FT4",
              f"trakbox track --mode AM: {code} {out} {err}")

        # An FT4 QSO: MFSK with SUBMODE FT4, at FT4's spot.
        status, r = w.post("/api/v1/radio", {"mode": "FT4", "satellite": "RS-44"})
        check(status == 200, f"back to FT4: {status} {r}")
        t, _ = at_mode(w, "FT4", 150)
        status, r = w.post("/api/v1/log", {"call": "W1AW", "grid": "FN31"})
        check(status == 200, f"log: {status} {r}")
        q = r["qso"]
        check(q["mode"] == "MFSK" and q["submode"] == "FT4", f"the FT4 QSO's mode: {q}")
        check(q["downlink_hz"] == t["downlink_spot_hz"] and q["uplink_hz"] == t["uplink_spot_hz"],
              f"the QSO at FT4's spot: {q} vs {t}")
        status, _, adif = w.request("GET", "/api/v1/log.adi")
        rec = adif.decode()
        check(status == 200 and "<MODE:4>MFSK" in rec and "<SUBMODE:3>FT4" in rec, f"the ADIF record: {rec}")
        freq = re.search(r"<FREQ:\d+>([\d.]+)", rec)
        check(freq and round(float(freq.group(1)) * 1e6) == q["uplink_hz"], f"its FREQ: {rec}")
        print(f"FT4 QSO: MODE MFSK SUBMODE FT4, FREQ {freq.group(1)} MHz")
    finally:
        w.stop()


run_test(main)
