#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets (tests/fuzz/corpus/NAME/) from the shipped data, the
docs' examples and the reference files Debian ships. Run once from the source tree; the output is
committed. The state seeds need a built trakbox (build/trakbox): it writes a real state file.

    tests/fuzz/make_corpus.py [path/to/trakbox]
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "tests", "fuzz", "corpus")


def read(path):
    with open(path, "rb") as f:
        return f.read()


def put(target, name, data):
    d = os.path.join(OUT, target)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def lines(data, n, start=0):
    return b"\n".join(data.split(b"\n")[start:start + n]) + b"\n"


def main():
    tle = read(os.path.join(ROOT, "data", "amateur.tle"))
    freqmode = read(os.path.join(ROOT, "data", "freqmode.txt"))
    station = read(os.path.join(ROOT, "data", "station.txt"))

    # --- elements: first byte = parser (0 NASA, 1 AMSAT, 2 gpredict, 3 detect) and options.
    put("elements", "nasa_3le", b"\x00" + lines(tle, 9))
    put("elements", "nasa_2le_crlf", b"\x00" + lines(tle, 2, 1).replace(b"\n", b"\r\n"))
    put("elements", "detect_3le", b"\x03" + lines(tle, 6, 3) + b"\x1a")
    vallado = "/usr/lib/python3/dist-packages/sgp4/SGP4-VER.TLE"
    if os.path.exists(vallado):
        v = read(vallado).split(b"\n")
        put("elements", "vallado_near_earth", b"\x10" + b"\n".join(v[:12]) + b"\n")
        deep = [i for i, l in enumerate(v) if b"MOLNIYA" in l or b"deep" in l.lower()]
        if deep:
            put("elements", "vallado_deep", b"\x10" + b"\n".join(v[deep[0]:deep[0] + 9]) + b"\n")
    amsat = b"""Satellite: AO-07
Catalog number: 07530
Epoch time:      26141.31992461
Element set:     999
Inclination:       101.9910 deg
RA of node:        154.2858 deg
Eccentricity:     0.0012269
Arg of perigee:    180.6108 deg
Mean anomaly:      191.1977 deg
Mean motion:    12.53697584 rev/day
Decay rate:     -5.4e-07 rev/day^2
Epoch rev:          35715
Checksum:           313
"""
    put("elements", "amsat", b"\x01" + b"HR AMSAT ORBITAL ELEMENTS FOR THE AMATEUR SATELLITES\n\n" + amsat + b"\n/EX\n")
    put("elements", "amsat_detect", b"\x03" + amsat)
    gpredict = "/usr/share/gpredict/data/satdata/satellites.dat"
    if os.path.exists(gpredict):
        put("elements", "gpredict", b"\x02" + lines(read(gpredict), 22))
    put("elements", "gpredict_sat", b"\x02[Satellite]\nVERSION=1.1\nNAME=ISS\nNICKNAME=ISS\n" +
        b"TLE1=" + lines(tle, 1, 1) + b"TLE2=" + lines(tle, 1, 2))

    # --- freq/mode and station files.
    # --- omm: first byte = reader (0 JSON, 1 XML, 2 CSV, 3 KVN, 4 parse_elements); the files
    # python-sgp4 wrote (scripts/make-omm-fixtures.py), and what trakbox must refuse.
    omm = os.path.join(ROOT, "tests", "data", "omm")
    for i, (name, suffix) in enumerate([("celestrak", ".json"), ("xml", ".xml"), ("csv", ".csv"), ("kvn", ".kvn")]):
        put("omm", name, bytes([i]) + read(os.path.join(omm, "sources" + suffix)))
        put("omm", name + "_detect", b"\x04" + read(os.path.join(omm, "n800123456" + suffix)))
    put("omm", "spacetrack", b"\x00" + read(os.path.join(omm, "n100123-spacetrack.json")))
    kvn = read(os.path.join(omm, "sources.kvn"))
    put("omm", "sgp4_xp", b"\x03" + kvn.replace(b"THEORY = SGP4\n", b"THEORY = SGP4-XP\n", 1))
    put("omm", "gcrf_bad_epoch", b"\x03" + kvn.replace(b"= TEME", b"= GCRF", 1).replace(b"2026-05-21T05", b"2026-13-21T05"))
    put("omm", "broken_json", b"\x00[{\"OBJECT_NAME\": \"A\", \"NORAD_CAT_ID\": [1]}, 5, {\"EPOCH\": null}")
    put("omm", "not_text", b"\x04\x7fELF\x02\x01\x01\x00\x00\x00")
    put("horizon_mask", "hrz", b"# roof\n0 5\n200 5\n214\t25\n262 25 # trees\n280 5\n")
    put("horizon_mask", "csv", b"az,el\r\n0,2\r\n90, 12.5\r\n180,2\r\n")
    put("horizon_mask", "steps", b"0 5 214 25 262 5\n360\n")
    put("horizon_mask", "stored", b"0 5; 214 25; 262 25.5; 263 5")
    put("horizon_mask", "bad", b"0 5\n400 25\n")
    put("freqmode", "shipped", freqmode)
    put("freqmode", "upload", lines(freqmode, 3).replace(b"\n", b"\r") + b"\x1a")
    put("freqmode", "offsets", b"AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma\nRS-44 435.640 145.965 usb lsb cat no\n")
    # The later firmware's files (issue 12), written from the format description.
    firmware = os.path.join(ROOT, "tests", "data", "firmware")
    put("freqmode", "firmware", read(os.path.join(firmware, "FREQ.DAT")))
    put("freqmode", "firmware_bad", read(os.path.join(firmware, "FREQ_BAD.DAT")))
    put("station_file", "firmware", read(os.path.join(firmware, "STATION.DAT")))
    put("station_file", "firmware_bad", read(os.path.join(firmware, "STATION_BAD.DAT")))
    put("station_file", "firmware_icom", b"1 W1AW 41.714 -72.727 30 S\n2 0 1023 0 511 F\n3 3 1 0 0\n"
        b"4 ICOM FULL 2E 60 19200\n5 0 0 0 -2 -2 -2\n6 00 0 0 none none 3\n7 0 0 360 0 90\n")
    put("station_file", "shipped", station)
    put("station_file", "upload", station.replace(b"\n", b"\r\n") + b"\x1a")
    put("station_file", "north_kenwood", b"1 JA6FTL 33.5 130.4 10 N\n2 0 1023 0 1023\n3 2 2 -5 4\n4 KENWOOD F 00 00\n5 0 0 0 0 0 360 0 90\n")

    # --- Satrak: frames (first byte: line bound; second: read size), then unit sessions.
    def frame(p):
        c = 0
        for b in p.encode():
            c ^= b
        return "$%s*%02X\r\n" % (p, c)

    payloads = ["VERSION?", "STATUS?", "ERRSTATUS?", "TPOS?", "GOTO=,180,45", "MOVE=,2.5,-1", "STEP=,-10,5",
                "STOP=", "TIME=,15,55,40,22,12,2016", "DATETIMEG?=,2016,12,22,15,55,40,10",
                "START_STOP_TIME=,12,0,0,21,5,2026,12,30,0,21,5,2026", "TRACK_AUTO_ENABLE =,1",
                "SETTINGS=,0,1000,1.5,-0.5,30000,0,5,10,2,3,2", "ANGLE_SETTINGS=0,39049,180,36838,45",
                "GPS_SETTINGS=,0,41.02N,29.17E", "SATELLITE=,amateur.txt,ISS,1,1",
                "SATELLITE_HTTP=, https://celestrak.org/NORAD/elements/amateur.txt,1,1,1",
                "SATELLITE_FTP=,10.0.0.1,user,pass,21,amateur.txt,ISS,1,0", "LOAD_IMAGE=,image.json",
                "REDUCTION=,100,120", "TRACK=,1", "RTC_REUPDATE="]
    put("satrak_frame", "frames", b"\x7e\x05" + "".join(frame(p) for p in payloads).encode())
    put("satrak_frame", "noisy", b"\x7e\x03" + b"garbage$STATUS?*0a\r\n$GOTO=,1,2\n\r$STOP=*ff  \n" + b"x" * 600 + b"\n")
    put("satrak_frame", "reply", b"\xff\x40STATUS?0,299.49,45.00,0,0,0,0,1,1,0,0,0,0,299.49,45.00,1\n")
    put("satrak_unit", "session", "\n".join(payloads[:12]) + "\n")
    put("satrak_unit", "track_iss", "SATELLITE=,amateur.txt,ISS,1,1\nSETTINGS=,0,0,0,0,60000,0,0,0,2,2,0\nTRACK=,1\n~3600\nSTATUS?\nSATELLITE?\nTPOS?\n")
    put("satrak_unit", "window", "SATELLITE=,keps.txt,AO-07,0,1\nSTART_STOP_TIME=,12,0,30,21,5,2026,13,0,0,21,5,2026\nTRACK_AUTO_ENABLE=,1\n~1800\nSTATUS?\nERRSTATUS?\n~3600\nSTATUS?\n")
    put("satrak_unit", "frames", "".join(frame(p) for p in ["GOTO=,90,30", "STATUS?", "LOAD_IMAGE=,broken.json",
                                                             "LOAD_IMAGE?", "SATELLITE=,empty.txt,ISS,0,0"]).replace("\r\n", "\n"))
    put("satrak_unit", "web", "SATELLITE=,amateur.txt,ISS,1,1\nSATELLITE_HTTP=,https://example.invalid/a.txt,0.5,0,1\n~600\nERRSTATUS?\nSATELLITE_FTP?\n")

    # --- host mode: first byte: 0 interpreter, 1 TCP protocol; +2 rotor control off; +4 tracking.
    host = "AZ220 EL45\nFU14595000\nFD43590000\nMUFM\nMDUSB\n?A\nS\\xFE\\xFE\\x10\\xE0\\x03\\xFD\n?\nAZ400 EL10\nXY12\nQ\n"
    put("host", "session", b"\x00" + host.encode())
    put("host", "tcp", b"\x01" + host.replace("\n", "\r\n").encode())
    put("host", "tracking_off", b"\x06az 220.5 el 45\r\nAZ220_EL45\nSTX;\n?A\n")

    # --- rotctl / rigctl: first byte: +2 rotor control off, +4 tracking.
    put("rotctl", "session", b"\x00P 180 45\np\n\\get_pos\nM 16 50\nS\nK\n_\n\\dump_state\n1\n+P 90 10\n;\\get_pos\nq\n")
    put("rotctl", "refused", b"\x02P 600 45\nP 10\nK\n\\set_pos 10 100\n")
    put("rigctl", "session", b"\x00F 435800000\nf\nM FM 15000\nm\nV VFOB\nv\nS 1 VFOB\ns\nI 145990000\ni\nX USB 0\nx\nT 0\nt\n_\n\\chk_vfo\n\\dump_state\n1\nM ?\n\\get_powerstat\n\\get_lock_mode\n+\\get_freq\nq\n")
    put("rigctl", "tracking", b"\x04F 435800000\nV Sub\nF 145990000\n\\set_split_vfo 1 VFOB\n")

    # --- CAT: first byte & 3: 0 Icom (bits 2.. read size), 1 Kenwood, 2 Yaesu, 3 hex.
    put("cat", "icom", b"\x04" + bytes.fromhex("FEFE10E00500009545 01FD FEFEE010FBFD FEFEE010FAFD FC FEFE10E00605FD 00 FEFE".replace(" ", "")))
    put("cat", "kenwood", b"\x01FA00435123450;FB00145950000;MD2;FN0;SP1;UP;ID;FA001")
    put("cat", "yaesu", b"\x02" + bytes.fromhex("0000000000 4359000001 1459900 01E C129000 02E 080000 0017 8080808080".replace(" ", "")))
    put("cat", "hex", b"\x03FE FE 10 E0 05 00 00 95 45 01 FD")

    # --- menus: first byte: timed waits per key (0..3); then keys (CR = Enter, ^Z ends an upload).
    up_tle = lines(tle, 6).replace(b"\n", b"\r")
    put("menus", "upload_3_3", b"\x00" + b"3\r3\r" + up_tle + b"\x1a" + lines(freqmode, 2).replace(b"\n", b"\r") + b"\x1a" + b"Y\rQ\r")
    put("menus", "station_4", b"\x00" + b"4\rWA7GXD\r32.259\r-110.778\r842\rS\r\r")
    put("menus", "clock_5", b"\x00" + b"5\r\r93/07/17 03:03:15\r\r")
    put("menus", "realtime_1", b"\x01" + b"1\r\r\r\r\rQ\r")
    put("menus", "single_S", b"\x01" + b"S\r1\r\r\rQ")
    put("menus", "config_6", b"\x00" + b"6\r9\r" + station.replace(b"\n", b"\r") + b"\x1aQ\r")
    put("menus", "host_7", b"\x00" + b"7\rAZ220 EL45\r?A\rQ\r")
    put("menus", "antenna_8", b"\x00" + b"8\r180\r45\rQ\r")
    put("menus", "schedule_2", b"\x00" + b"2\r1\r\rQ\r")

    # --- command line: words separated by LF.
    put("cli", "ports", "--state\n/tmp/x\n--clock\n2026-05-21T12:00:00Z\n--clock-rate\n10\n--satrak-port\n4001\n--tick-ms\n500\n")
    put("cli", "devices", "--rotator\nrotctld:[::1]:4533\n--radio\nicom:/dev/ttyUSB0\n--baud\n9600\n--standalone\n3\n")
    put("cli", "specs", "satrak:localhost:4001\nrigctld:localhost:4532\nhamlib:603:/dev/ttyUSB0:9600\nsimulated\n-77.85,166.67,10\n[::1]:4001\n")

    # --- attach_frames: first byte = the size of each read; then what a client sends.
    put("attach_frames", "keys", b"\x05" + b"1\r4\rVK2XYZ\r\x1b[A\x1bOP\x7f\x14\x1d")
    put("attach_frames", "window_sizes", b"\x03" + b"ab\xffW\x00\x28\x00\x64cd\xff\xffe\xffW\xff\xff\x00\x00")
    put("attach_frames", "escape_cut", b"\x00" + b"\xffW\x00\x18\x00P\xff\xffx\xffQz\xff")

    # --- attach_hello: the text after "attach" (issue 38's repros, and what trakbox attach sends).
    for i, g in enumerate([b'{"rows":"x"}', b'{"term":5,"full_screen":true}', b'{"full_screen":"yes"}',
                           b'{"tty":[1]}', b'{"crlf":1}', b'{"cols":1.5}', b'{"term":"../../tmp/x"}', b'{',
                           b'[' * 200, b'{"tty":"/dev/pts/\\u001b[2J"}', b'',
                           b' {"full_screen":true,"crlf":false,"rows":40,"cols":132,"term":"xterm-256color",'
                           b'"tty":"/dev/pts/3"}', b'{"rows":-5,"cols":18446744073709551615,"term":null}']):
        put("attach_hello", f"greeting_{i}", g)

    # --- element_names: element files whose names are not printable UTF-8 (issue 38).
    iss = (b"1 25544U 98067A   26141.16510469  .00005835  00000-0  11282-3 0  9994\n"
           b"2 25544  51.6328  73.8715 0007529  81.3651 278.8190 15.49291753567565\n")
    put("element_names", "invalid_utf8", b"IS\xff\xfeS\n" + iss)
    put("element_names", "escapes", b"\x1b[2J\x1b[31m EVIL \x1b]0;pwn\x07\n" + iss)
    put("element_names", "c1_csi", b"A\xc2\x9b2J\n" + iss)
    put("element_names", "amsat", b"Satellite: IS\xff\x1bS\nCatalog number: 25544\nEpoch time: 26141.16510469\n"
        b"Element set: 999\nInclination: 51.6328 deg\nRA of node: 73.8715 deg\nEccentricity: 0.0007529\n"
        b"Arg of perigee: 81.3651 deg\nMean anomaly: 278.8190 deg\nMean motion: 15.49291753 rev/day\n"
        b"Decay rate: 5.835e-05 rev/day^2\nEpoch rev: 56756\nChecksum: 0\n")
    put("element_names", "omm_json", b'[{"OBJECT_NAME":"A\\u001bB","NORAD_CAT_ID":25544,"EPOCH":"2026-05-21T03:57:44",'
        b'"MEAN_MOTION":15.49291753,"ECCENTRICITY":0.0007529,"INCLINATION":51.6328,"RA_OF_ASC_NODE":73.8715,'
        b'"ARG_OF_PERICENTER":81.3651,"MEAN_ANOMALY":278.819,"BSTAR":0.00011282}]')

    # --- state: first byte even: JSON data; odd: a whole state file.
    trakbox = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "trakbox")
    if os.path.exists(trakbox):
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([trakbox, "host", "--state", d, "--clock", "2026-05-21T12:00:00Z"],
                           input=b"AZ10 EL10\nQ\n", stdout=subprocess.DEVNULL, timeout=60, check=False)
            path = os.path.join(d, "trakbox-state.json")
            if os.path.exists(path):
                doc = read(path)
                put("state", "state_file", b"\x01" + doc)
                import json
                data = json.loads(doc)["data"]
                data["db"]["satellites"] = data["db"]["satellites"][:2]
                data["db"]["selected"] = [0, 1]
                put("state", "data_small", b"\x00" + json.dumps(data, separators=(",", ":")).encode())
                data["satrak"] = {}
                put("state", "data_satrak_empty", b"\x00" + json.dumps(data, separators=(",", ":")).encode())
            else:
                print("trakbox wrote no state file; state seeds skipped", file=sys.stderr)
    put("state", "not_state", b"\x01{\"format\":\"trakbox-state\",\"version\":1,\"checksum\":\"00000000\",\"data\":{}}")


if __name__ == "__main__":
    main()
