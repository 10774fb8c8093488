"""The logger (--logger cloudlog:URL, docs/logbook.md) on the real binary, against a local HTTP
server that checks the fields as Cloudlog's application/controllers/Api.php does (the key must be
the key file's; api/radio needs `radio`; a JSON body; api/qso needs type adif, a string that parses
to a record with a CALL, and the station_profile_id) and answers as Cloudlog does (201 with
imported_count and messages; a record already there is a "Duplicate" message).
The station tracks ISS through a simulated pass: its radio posts carry prop_mode SAT and sat_name
ARISS while the ISS is up, and a post after the pass has prop_mode "". Three QSOs are logged (the
page's API and `trakbox log add`); the logger answers 500, then refuses connections: a problem in
`status --json`; the station is killed with SIGKILL and restarted, the logger comes back, and it
holds every QSO exactly once; a fourth QSO the logger stores but whose answer is lost is sent again,
answered "Duplicate", and counted done. The key is never in the station's log, its state file or
status.
Then the same stand-in answers as Wavelog 2.0.5 does (issue 60: 201 with adif_count and adif_errors,
messages [""]; a duplicate is 400 "abort" with "Duplicate for <call>"), splitting the ADIF string on
<eor> before anything else as Adif_parser.php does (issue 56 item 11): a first answer 401 quotes the key
(issue 56 item 9: redacted in status, the log and standard error), a note holding
"<eor><call:5>EVIL1" arrives as one record, a QSO whose answer is lost is counted done on the
400 duplicate, the queue drains to 0 with no problem, and after a SIGKILL and a restart nothing is
sent again."""
import datetime
import http.server
import json
import os
import re
import signal
import stat
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, SOURCE, Failure, check, free_port, poll, read_log, run_test, sh  # noqa: E402
from _web import WebStation  # noqa: E402

RATE = 20
KEY = "cl64f0a1b2c3d4e5KEY"
STATION = "27.391,128.657,50"
PROFILE = "7"


def iso(t):
    return datetime.datetime.fromisoformat(t.replace("Z", "+00:00"))


def zulu(t):
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


def adif_fields(text):
    """Cloudlog's Adif_parser in short: <NAME:LEN[:TYPE]>value, names lower-cased."""
    out, at = {}, 0
    while True:
        m = re.compile(r"<([A-Za-z0-9_]+):(\d+)(?::[A-Za-z])?>").search(text, at)
        if not m:
            return out
        n = int(m.group(2))
        out[m.group(1).lower()] = text[m.end():m.end() + n]
        at = m.end() + n


class Logger:
    """What the server has stored, and how it answers now: "ok", "500" (or closed: not running)."""

    def __init__(self):
        self.mode = "ok"
        self.flavour = "cloudlog"  # or "wavelog": how api/qso answers
        self.records_read = 0      # the records the Wavelog stand-in split the strings into
        self.radio = []      # the radio posts accepted, in order
        self.qsos = []       # the records stored
        self.qso_posts = 0   # every api/qso request that reached the server
        self.lock = threading.Lock()


LOG = Logger()


class Handler(http.server.BaseHTTPRequestHandler):
    def reply(self, code, obj):
        body = json.dumps(obj).encode()
        self.send_response(code)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def do_POST(self):
        raw = self.rfile.read(int(self.headers.get("Content-Length", "0")))
        if LOG.mode == "500":
            if self.path.endswith("/api/qso"):
                LOG.qso_posts += 1
            body = b"<html><body>Internal Server Error</body></html>"
            self.send_response(500)
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)
            return
        try:
            obj = json.loads(raw)
        except ValueError:
            return self.reply(200, {"status": "failed", "reason": "wrong JSON"})
        if self.headers.get("Content-Type") != "application/json" or not isinstance(obj, dict):
            return self.reply(200, {"status": "failed", "reason": "wrong JSON"})
        if obj.get("key") != KEY:
            return self.reply(401, {"status": "failed", "reason": "missing api key"})
        with LOG.lock:
            if self.path == "/index.php/api/radio":
                if "radio" not in obj:
                    return self.reply(404, {"status": "failed", "reason": "missing radio element in payload"})
                LOG.radio.append(obj)
                return self.reply(200, {"status": "success"})
            if self.path != "/index.php/api/qso":
                return self.reply(404, {"status": "failed", "reason": "no such endpoint"})
            LOG.qso_posts += 1
            if obj.get("station_profile_id") != PROFILE:
                return self.reply(401, {"status": "failed", "reason": "station id does not belong to the API key owner."})
            if obj.get("type") != "adif" or not obj.get("string"):
                return self.reply(200, {"status": "failed", "reason": "not adif"})
            if LOG.flavour == "wavelog":
                return self.wavelog_qso(obj)
            rec = adif_fields(obj["string"])
            if not rec.get("call", "").strip():
                return self.reply(401, {"status": "failed", "reason": "QSO Call is empty."})
            same = [q for q in LOG.qsos if (q["call"], q["qso_date"], q["time_on"], q["band"]) ==
                    (rec["call"], rec.get("qso_date"), rec.get("time_on"), rec.get("band"))]
            if same:
                msg = f"Date/Time: {rec.get('qso_date')} {rec.get('time_on')} Callsign: {rec['call']} Band: " \
                      f"{rec.get('band')}  Duplicate<br>"
                return self.reply(201, {"status": "created", "type": "adif", "string": obj["string"],
                                        "imported_count": 0, "messages": [msg]})
            LOG.qsos.append(rec)
            if LOG.mode == "lose-reply":  # stored, and the answer lost on the way back
                LOG.mode = "ok"
                self.send_response(502)
                self.send_header("Content-Length", "0")
                self.end_headers()
                return
            return self.reply(201, {"status": "created", "type": "adif", "string": obj["string"],
                                    "imported_count": 1, "messages": []})

    def wavelog_qso(self, obj):
        """Wavelog 2.0.5's Api.php qso(): the string split on <eor> (any case) into records first,
        each stored with import_bulk; 201 with adif_count/adif_errors, or 400 "abort" naming each
        refusal (a duplicate: same call, minute of TIME_ON, band and mode)."""
        if LOG.mode == "quote-key":
            return self.reply(401, {"status": "failed", "reason": f"the key '{KEY}' is not valid for this station"})
        parts = [p for p in re.split(r"(?i)<eor>", obj["string"]) if p.strip()]
        records = [adif_fields(p) for p in parts]
        LOG.records_read += len(records)
        msgs, stored = [""], 0
        for rec in records:
            same = [q for q in LOG.qsos if (q["call"], q["qso_date"], q["time_on"][:4], q["band"], q["mode"]) ==
                    (rec.get("call"), rec.get("qso_date"), rec.get("time_on", "")[:4], rec.get("band"), rec.get("mode"))]
            if same:
                msgs.append(f"Date/Time: {rec.get('qso_date')} {rec.get('time_on')} Callsign: {rec.get('call')} "
                            f"Band: {rec.get('band')} Duplicate for WA7GXD<br>")
                continue
            LOG.qsos.append(rec)
            stored += 1
        if LOG.mode == "lose-reply" and stored:
            LOG.mode = "ok"
            self.send_response(502)
            self.send_header("Content-Length", "0")
            self.end_headers()
            return
        errors = len(msgs) - 1
        if errors:
            return self.reply(400, {"status": "abort", "type": "adif", "string": "", "adif_count": len(records),
                                    "adif_errors": errors, "messages": msgs})
        return self.reply(201, {"status": "created", "type": "adif", "string": "", "adif_count": len(records),
                                "adif_errors": 0, "messages": [""]})

    def log_message(self, *a):
        pass


def serve(port):
    srv = http.server.ThreadingHTTPServer(("127.0.0.1", port), Handler)
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    return srv


def first_pass():
    """The first ISS pass above 10 degrees after CLOCK, from `trakbox passes`."""
    code, out, err = sh(BIN, "passes", os.path.join(SOURCE, "data", "amateur.tle"), "--station", STATION,
                        "--start", CLOCK, "--hours", "24", "--json")
    check(code == 0, f"passes: {err}")
    for p in json.loads(out):
        if p["sat"] == "ISS" and p["max_el_deg"] >= 10:
            return iso(p["aos_utc"]), iso(p["los_utc"])
    raise Failure("no ISS pass within a day of the clock")


def main():
    aos, los = first_pass()
    keydir = tempfile.mkdtemp(prefix="trakbox-logger-key-")
    keyfile = os.path.join(keydir, "cloudlog.key")
    with open(keyfile, "w") as f:
        f.write(KEY + "\n")
    os.chmod(keyfile, stat.S_IRUSR | stat.S_IWUSR)
    port = free_port()
    srv = serve(port)
    w = WebStation("--station", STATION, "--logger", f"cloudlog:http://127.0.0.1:{port}/", "--logger-key-file",
                   keyfile, "--logger-station-id", PROFILE, clock=zulu(aos - datetime.timedelta(seconds=40)),
                   rate=str(RATE))
    try:
        status, r = w.post("/api/v1/track", {"satellite": "ISS"})
        check(status == 200 and r["ok"], f"track ISS: {status} {r}")
        # While the ISS is up: the satellite's fields, TQSL's name.
        sat = poll("a radio post with prop_mode SAT", lambda: [p for p in LOG.radio if p["prop_mode"] == "SAT"],
                       60)[0]
        check(sat["sat_name"] == "ARISS" and sat["radio"] == "trakbox" and sat["mode"] == "FM" and
              abs(int(sat["frequency"]) - 145990000) < 5000 and abs(int(sat["frequency_rx"]) - 437800000) < 15000,
              f"the radio state while tracking: {sat}")
        check(not [p for p in LOG.radio if p["prop_mode"] == "SAT" and p is not sat and p["sat_name"] != "ARISS"],
              f"every SAT post names ARISS: {LOG.radio}")
        status, r = w.post("/api/v1/log", {"call": "W1AW", "grid": "FN31"})
        check(status == 200 and r["ok"], f"QSO 1: {status} {r}")
        poll("QSO 1 at the logger", lambda: len(LOG.qsos) == 1, 30)
        q1 = LOG.qsos[0]
        check(q1["call"] == "W1AW" and q1["prop_mode"] == "SAT" and q1["sat_name"] == "ARISS" and
              q1["band"] == "2m" and q1["gridsquare"] == "FN31", f"QSO 1 as the logger has it: {q1}")
        st = w.status()["log"]["logger"]
        check(st["kind"] == "cloudlog" and st["url"] == f"http://127.0.0.1:{port}" and st["queue"] == 0 and
              st["last_upload"] and st["last_radio_post"] and st["problem"] is None, f"status log.logger: {st}")
        # After the pass: one post without the satellite's fields.
        poll("a radio post after the pass with prop_mode ''",
                 lambda: LOG.radio[-1]["prop_mode"] == "" and LOG.radio[-1]["sat_name"] == "", (los - aos).seconds / RATE + 60)
        posts = len(LOG.radio)
        # The logger answers 500: the QSO stays queued, a problem in status.
        LOG.mode = "500"
        code, out, err = sh(BIN, "log", "add", "K1JT", "FN20", "--state", w.state)
        check(code == 0 and out.startswith("logged 2 K1JT"), f"QSO 2: {code} {out!r} {err!r}")
        st = poll("a problem in status while the logger fails",
                      lambda: (lambda s: s if [p for p in s["problems"] if p.startswith("logger: QSO 2")] else None)(w.status()),
                      30)
        problem = [p for p in st["problems"] if p.startswith("logger: QSO 2")][0]
        check("HTTP 500" in problem and "next try in 30 s" in problem and st["log"]["logger"]["queue"] == 1,
              f"the problem: {problem}; {st['log']}")
        # The logger is gone (connections refused); a third QSO.
        srv.shutdown()
        srv.server_close()
        status, r = w.post("/api/v1/log", {"call": "G4XYZ", "grid": "IO91"})
        check(status == 200 and r["ok"], f"QSO 3: {status} {r}")
        poll("QSO 3 tried against a closed port",
                 lambda: [p for p in w.status()["problems"] if p.startswith("logger: QSO 3")], 30)
        check(w.status()["log"]["logger"]["queue"] == 2, "two QSOs wait")
        status_text = w.status_text()
        status_json = json.dumps(w.status())
        # SIGKILL, the logger back, a restart an hour later on the station's clock.
        w.proc.send_signal(signal.SIGKILL)
        w.proc.wait(10)
        LOG.mode = "ok"
        srv = serve(port)
        later = zulu(los + datetime.timedelta(hours=1))
        w.args[w.args.index("--clock") + 1] = later
        w.start()
        poll("every QSO at the logger", lambda: len(LOG.qsos) == 3, 60)
        st = poll("the queue empty and the problem gone",
                      lambda: (lambda s: s if s["log"]["logger"]["queue"] == 0 and s["log"]["logger"]["problem"] is None
                               else None)(w.status()), 30)
        check(not [p for p in st["problems"] if p.startswith("logger:")], f"no logger problem: {st['problems']}")
        calls = sorted(q["call"] for q in LOG.qsos)
        check(calls == ["G4XYZ", "K1JT", "W1AW"], f"every QSO exactly once: {calls}")
        check(len(LOG.radio) == posts or all(p["prop_mode"] == "" for p in LOG.radio[posts:]),
              f"nothing but idle posts after the pass: {LOG.radio[posts:]}")
        # Stored by the logger but its answer lost: the retry meets Cloudlog's "Duplicate", which is
        # done, and the logger holds it once. The satellite is named: an hour after the pass, at 20
        # times real time, whether the ISS is followed at this moment depends on how long the polls
        # above took (CI under load met a moment when it was not).
        LOG.mode = "lose-reply"
        status, r = w.post("/api/v1/log", {"call": "JA1XYZ", "grid": "PM95", "sat": "ISS"})
        check(status == 200 and r["ok"], f"QSO 4: {status} {r}")
        poll("QSO 4 done after its lost answer", lambda: "logger: QSO 4 (JA1XYZ) uploaded (the logger had it already)"
             in read_log(w.state), 60)
        check(sorted(q["call"] for q in LOG.qsos) == ["G4XYZ", "JA1XYZ", "K1JT", "W1AW"], f"QSO 4 once: {LOG.qsos}")
        check(w.status()["log"]["logger"]["queue"] == 0, "nothing waits")
        status_text += w.status_text()
        status_json += json.dumps(w.status())
        # The key file gone since it was stored: the station starts and tracks all the same, the
        # logger's problem in status, and what is logged meanwhile waits in the queue.
        w.stop()
        os.remove(keyfile)
        for opt in ("--logger", "--logger-key-file", "--logger-station-id"):  # stored, not given again
            i = w.args.index(opt)
            del w.args[i:i + 2]
        w.start()
        st = w.status()
        problem = [p for p in st["problems"] if p.startswith("logger: the logger did not start")]
        check(problem and keyfile in problem[0] and "kept queued" in problem[0], f"the stored logger's problem: {st['problems']}")
        status, r = w.post("/api/v1/log", {"call": "VK3ABC", "grid": "QF22"})
        check(status == 200 and r["ok"], f"QSO 5 with the logger not started: {status} {r}")
        check(w.status()["log"]["logger"]["queue"] == 1, f"QSO 5 waits: {w.status()['log']}")
    finally:
        w.stop()
        srv.shutdown()
        srv.server_close()
    log = read_log(w.state)
    with open(os.path.join(w.state, "trakbox-state.json")) as f:
        state = f.read()
    for where, text in (("the log", log), ("the state file", state), ("status", status_text),
                        ("status --json", status_json)):
        check(KEY not in text, f"the key is in {where}")
    check(keyfile in state, "the key file's path is stored")
    check("logger: QSO 2 (K1JT) uploaded" in log and "logger: QSO 1 (W1AW) uploaded" in log, "uploads are logged")
    print(f"{len(LOG.radio)} radio posts, {LOG.qso_posts} QSO posts for 4 QSOs")
    wavelog(keyfile_again())


def keyfile_again():
    keydir = tempfile.mkdtemp(prefix="trakbox-logger-key-")
    keyfile = os.path.join(keydir, "wavelog.key")
    with open(keyfile, "w") as f:
        f.write(KEY + "\n")
    os.chmod(keyfile, stat.S_IRUSR | stat.S_IWUSR)
    return keyfile


def logger_state(w):
    return w.status()["log"]["logger"]


def wavelog(keyfile):
    """Issue 60 item 1 and issue 56 items 9 and 11 against the Wavelog stand-in."""
    LOG.__init__()
    LOG.flavour = "wavelog"
    LOG.mode = "quote-key"
    port = free_port()
    srv = serve(port)
    w = WebStation("--station", STATION, "--logger", f"wavelog:http://127.0.0.1:{port}", "--logger-key-file",
                   keyfile, "--logger-station-id", PROFILE, rate=str(RATE))
    stderr = ""
    try:
        status, r = w.post("/api/v1/log", {"call": "DL1ABC", "grid": "JN58", "sat": "ISS",
                                           "note": "hi <eor><call:5>EVIL1 <eor>"})
        check(status == 200 and r["ok"], f"Wavelog QSO 1: {status} {r}")
        st = poll("the 401 quoting the key as a problem", lambda: (lambda s: s if s["log"]["logger"]["problem"] else None)(
            w.status()), 30)
        problem = st["log"]["logger"]["problem"]
        check("HTTP 401: the key '<redacted>' is not valid" in problem and KEY not in json.dumps(st),
              f"the key redacted in status: {problem}")
        # A mode that is not ADIF's is refused at entry, naming the field.
        status, r = w.post("/api/v1/log", {"call": "G0ABC", "sat": "ISS", "mode": "FM<eor>"})
        check(status != 200 and "mode: " in json.dumps(r), f"a mode outside ADIF's: {status} {r}")
        LOG.mode = "ok"
        poll("Wavelog QSO 1 stored and the queue empty",
             lambda: len(LOG.qsos) == 1 and logger_state(w)["queue"] == 0 and logger_state(w)["problem"] is None, 60)
        rec = LOG.qsos[0]
        check(LOG.records_read == 1 and rec["call"] == "DL1ABC" and "EVIL1" not in [q["call"] for q in LOG.qsos] and
              rec.get("comment") == "hi (eor)(call:5)EVIL1 (eor)", f"one record, the note's '<' sent as '(': {LOG.qsos}")
        # Stored, the answer lost: the retry meets the 400 duplicate, which is done.
        LOG.mode = "lose-reply"
        status, r = w.post("/api/v1/log", {"call": "OK1XYZ", "grid": "JN79", "sat": "ISS"})
        check(status == 200 and r["ok"], f"Wavelog QSO 3: {status} {r}")
        poll("the duplicate counted done", lambda: "(OK1XYZ) uploaded (the logger had it already)" in read_log(w.state), 60)
        st = logger_state(w)
        check(st["kind"] == "wavelog" and st["queue"] == 0 and st["problem"] is None and
              not [p for p in w.status()["problems"] if p.startswith("logger:")], f"drained, no problem: {st}")
        check(sorted(q["call"] for q in LOG.qsos) == ["DL1ABC", "OK1XYZ"], f"each once: {LOG.qsos}")
        # SIGKILL and a restart: nothing is sent again.
        posts = LOG.qso_posts
        w.proc.send_signal(signal.SIGKILL)
        w.proc.wait(10)
        stderr += w.proc.stderr.read().decode(errors="replace")
        w.start()
        poll("the restarted station's logger", lambda: w.status()["log"].get("logger"), 20)
        time.sleep(3)  # a minute of the station's clock: its queue looked at 60 times
        check(LOG.qso_posts == posts and len(LOG.qsos) == 2 and logger_state(w)["queue"] == 0,
              f"nothing sent after the restart: {LOG.qso_posts - posts} posts, {LOG.qsos}")
    finally:
        stderr += w.stop()
        srv.shutdown()
        srv.server_close()
    log = read_log(w.state)
    check("the key '<redacted>' is not valid" in log, "the 401 is logged, redacted")
    for where, text in (("the log", log), ("standard error", stderr)):
        check(KEY not in text, f"the key is in {where}")
    print(f"wavelog: {LOG.qso_posts} QSO posts, {len(LOG.qsos)} stored, {LOG.records_read} records read")


if __name__ == "__main__":
    run_test(main)
