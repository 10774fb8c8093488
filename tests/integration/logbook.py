"""The logbook on the real binary (docs/logbook.md): three QSOs logged while the simulated station
tracks, one from each of the page's API, host mode over TCP and `trakbox log add`; the station is
killed with SIGKILL right after the third acknowledgement, restarted, and all three are there.
The ADIF export gives TQSL's names (<SAT_NAME:5>RS-44, <SAT_NAME:5>ARISS) with the uplink in
BAND/FREQ, and a malformed file is refused whole, naming the record and the field."""
import os
import re
import shutil
import signal
import socket
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Failure, check, free_port, poll, run_test, sh, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402


def host_log(port, line):
    with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
        data = b""
        end = time.time() + 10
        while data.count(b"TrakBox>>") < 1:
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
        return data.decode(errors="replace")


def track(w, sat):
    status, r = w.post("/api/v1/track", {"satellite": sat})
    check(status == 200 and r["ok"], f"track {sat}: {status} {r}")
    poll(f"{sat} followed", lambda: w.status()["tracking"]["followed"] == sat, 10)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-logbook-")
    host_port = free_port()
    w = WebStation("--host-port", str(host_port), state=state)
    try:
        wait_listening(host_port, "host mode", within=20, proc=w.proc)
        track(w, "RS-44")
        # 1. the page's API: a refusal names the field and stores nothing; then a QSO.
        status, r = w.post("/api/v1/log", {"call": "W1 AW"})
        check(status == 409 and r["error"].startswith("call: 'W1 AW' is not a callsign"), f"bad call: {status} {r}")
        status, r = w.post("/api/v1/log", {"call": "W1AW", "grid": "FN31zz"})
        check(status == 409 and r["error"].startswith("grid: 'FN31zz'"), f"bad grid: {status} {r}")
        status, r = w.post("/api/v1/log", {"call": "W1AW", "cal": "x"})
        check(status == 400 and "'cal'" in r["error"], f"unknown key: {status} {r}")
        status, r = w.post("/api/v1/log", {"call": "w1aw", "grid": "fn31", "rst_sent": "59"})
        check(status == 200 and r["ok"], f"web QSO: {status} {r}")
        q = r["qso"]
        check(q["call"] == "W1AW" and q["sat_name"] == "RS-44" and q["lotw_name"] == "RS-44" and q["norad"] == 44909,
              f"the satellite filled in: {q}")
        check(q["mode"] == "SSB" and q["band"] == "2m" and q["band_rx"] == "70cm" and q["source"] == "web",
              f"mode and bands: {q}")
        check(q["uplink_hz"] == 145965000 and q["downlink_hz"] == 435640000, f"the transponder's spot: {q}")
        check(q["time_on"].startswith(CLOCK[:10]), f"time on from the station's clock: {q['time_on']}")
        # 2. host mode
        reply = host_log(host_port, "LOG K1JT FN20 57")
        check(re.search(r"LOGGED 2 K1JT RS-44 \d{4}-\d\d-\d\d \d\d:\d\d:\d\d", reply), f"host LOG: {reply!r}")
        reply = host_log(host_port, "LOG K1JT FN2")
        check("ERROR LOG: grid: 'FN2'" in reply, f"host LOG refusal: {reply!r}")
        # 3. the command line, on ISS
        track(w, "ISS")
        code, out, err = sh(BIN, "log", "add", "G4XYZ", "IO91", "--state", state, "--note", "hello")
        check(code == 0 and re.match(r"logged 3 G4XYZ ISS FM ", out), f"trakbox log add: {code} {out!r} {err!r}")
        # acknowledged: on disk. SIGKILL now, nothing may be lost.
        w.proc.send_signal(signal.SIGKILL)
        w.proc.wait(10)
        w.start()
        status, r = w.get_json("/api/v1/log")
        check(status == 200, f"GET /api/v1/log: {status} {r}")
        calls = [(x["id"], x["call"], x["source"]) for x in r["qsos"]]
        check(calls == [(1, "W1AW", "web"), (2, "K1JT", "host"), (3, "G4XYZ", "cli")], f"after SIGKILL: {calls}")
        st = w.status()
        check(st["log"]["count"] == 3 and st["log"]["last"]["call"] == "G4XYZ", f"status log: {st['log']}")
        check("log       3 QSO(s)" in w.status_text(), "trakbox status says the log")
        # ADIF: TQSL's names, the uplink in BAND/FREQ.
        status, headers, adif = w.request("GET", "/api/v1/log.adi")
        adif = adif.decode()
        check(status == 200 and "<ADIF_VER:5>3.1.4" in adif and "<PROGRAMID:7>trakbox" in adif, f"ADIF header: {adif[:200]}")
        records = adif.split("<EOH>")[1].split("<EOR>")
        check("<SAT_NAME:5>RS-44" in records[0] and "<BAND:2>2m <FREQ:10>145.965000" in records[0] and
              "<FREQ_RX:10>435.640000" in records[0] and "<PROP_MODE:3>SAT" in records[0], f"RS-44 record: {records[0]}")
        check("<SAT_NAME:5>ARISS" in records[2] and "<FREQ:10>145.990000" in records[2] and "<MODE:2>FM" in records[2],
              f"ISS record: {records[2]}")
        # edit keeps a version, delete is a mark
        status, r = w.post("/api/v1/log/edit", {"id": 2, "grid": "FN42"})
        check(status == 200 and r["qso"]["grid"] == "FN42" and r["qso"]["version"] == 2, f"edit: {status} {r}")
        status, r = w.post("/api/v1/log/delete", {"id": 1})
        check(status == 200, f"delete: {status} {r}")
        status, r = w.get_json("/api/v1/log")
        check([x["id"] for x in r["qsos"]] == [2, 3], f"after delete: {r['qsos']}")
        # The CLI's export and import through the socket: the same records are duplicates; a bad file
        # is refused naming the record and the field, and nothing is stored.
        out_file = os.path.join(state, "out.adi")
        code, out, err = sh(BIN, "log", "export", "--state", state, "--adif", out_file)
        check(code == 0 and os.path.getsize(out_file) > 0, f"export: {code} {err}")
        code, out, err = sh(BIN, "log", "import", out_file, "--state", state)
        check(code == 0 and "imported 0 QSOs, 2 already in the log" in out, f"import of the export: {code} {out} {err}")
        # A general logger's export (issue 60, item 6): its HF records are skipped and named, the
        # satellite one is imported.
        mixed = os.path.join(state, "mixed.adi")
        with open(mixed, "w") as f:
            f.write("exported by a general logger <EOH>\n"
                    "<CALL:5>DL1AB <QSO_DATE:8>20261201 <TIME_ON:4>1200 <BAND:3>20m <FREQ:6>14.074 <MODE:3>FT8 <EOR>\n"
                    "<CALL:4>N0HF <QSO_DATE:8>20261201 <TIME_ON:4>1210 <PROP_MODE:2>F2 <MODE:2>CW <EOR>\n"
                    "<CALL:4>N0SO <QSO_DATE:8>20261201 <TIME_ON:4>2205 <MODE:2>FM <PROP_MODE:3>SAT <SAT_NAME:5>SO-50 <EOR>\n")
        code, out, err = sh(BIN, "log", "import", mixed, "--state", state)
        check(code == 0 and "imported 1 QSOs, 0 already in the log, 2 records skipped (not satellite QSOs)" in out
              and "skipped record 1 DL1AB: neither PROP_MODE SAT nor SAT_NAME" in out
              and "skipped record 2 N0HF: PROP_MODE F2, not SAT" in out, f"mixed import: {code} {out} {err}")
        status, r = w.get_json("/api/v1/log")
        check(len(r["qsos"]) == 3 and any(q["call"] == "N0SO" for q in r["qsos"]), f"the SO-50 QSO stored: {r['qsos']}")
        bad = os.path.join(state, "bad.adi")
        with open(bad, "w") as f:
            f.write("<CALL:4>N0AA <QSO_DATE:8>20261201 <TIME_ON:4>2200 <PROP_MODE:3>SAT <EOR>\n"
                    "<CALL:4>N0BB <QSO_DATE:8>20261201 <TIME_ON:4>2590 <PROP_MODE:3>SAT <EOR>\n")
        code, out, err = sh(BIN, "log", "import", bad, "--state", state)
        check(code != 0 and "record 2: TIME_ON: '2590'" in err and "nothing was stored" in err, f"bad import: {code} {err}")
        status, r = w.get_json("/api/v1/log")
        check(len(r["qsos"]) == 3, f"nothing stored from the bad file: {r['qsos']}")
        # A file past the socket's first 1 MiB goes through (4200 QSOs of 540 bytes); one past its 16 MiB is
        # refused by the client, naming the size and the limit.
        note = "x" * 400
        big = os.path.join(state, "big.adi")
        with open(big, "w") as f:
            for i in range(4200):
                t = f"{i // 60 % 24:02d}{i % 60:02d}00"
                f.write(f"<CALL:4>N0AA <QSO_DATE:8>202612{1 + i // 1440:02d} <TIME_ON:6>{t} "
                        f"<MODE:2>FM <BAND:2>2m <FREQ:10>145.990000 <PROP_MODE:3>SAT <SAT_NAME:5>ARISS "
                        f"<COMMENT:{len(note)}>{note} <EOR>\n")
        check(os.path.getsize(big) > 2 << 20, "the big file is over 2 MiB")
        code, out, err = sh(BIN, "log", "import", big, "--state", state, timeout=60)
        check(code == 0 and "imported 4200 QSOs, 0 already in the log" in out, f"import of 2 MiB: {code} {out} {err}")
        huge = os.path.join(state, "huge.adi")
        with open(huge, "w") as f:
            f.write("<CALL:4>N0AA <EOR>\n" * ((17 << 20) // 19 + 1))
        code, out, err = sh(BIN, "log", "import", huge, "--state", state, timeout=60)
        check(code != 0 and re.search(r"makes a request of \d+ bytes, more than the 16777216 \(16 MiB\)", err),
              f"a file over 16 MiB: {code} {err}")
    finally:
        w.stop()
    # No station: export opens the logbook itself.
    code, out, err = sh(BIN, "log", "export", "--state", state)
    check(code == 0 and "<SAT_NAME:5>ARISS" in out, f"export without a station: {code} {err}")
    shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
