"""Each pass recorded on the receiver trakbox drives (issue 59, item 4): `--radio gqrx:127.0.0.1:PORT
--record audio` through SO-50's pass at --clock-rate 40, against a GQRX stand-in that answers its
recorder commands as GQRX's remote_control.cpp does:

  `u ?` lists what `u` reads (RECORD IQRECORD DSP RDS MUTE); `u RECORD`, `u IQRECORD`, `u DSP` read
  0 or 1; `AOS` answers RPRT 0 and starts the audio recorder only while the DSP runs and a
  demodulator is chosen; `LOS` answers RPRT 0 and stops it; `U RECORD 1|0` answers RPRT 1 (refused)
  when the DSP is off or the demodulator is OFF, `U IQRECORD 1|0` when the DSP is off.

Checked, DSP on: the stand-in sees `AOS` once, at the pass's AOS (the `recording` event's start
within a few seconds of the AOS `trakbox passes` gives, the command's wall time next to the AOS
event's), `u RECORD` read back as 1 and said so (event `started`, read back, with the file name
GQRX gives: gqrx_yyyyMMdd_hhmmss_<Hz>.wav from the start in UTC and the frequency then), "REC" in
the status line, the status document's radios[0].recording and `trakbox status`; `LOS` once, at
LOS; one connection all through (GQRX keeps one client) with `F` frames before, between and after
the recorder's commands; no failure, no link-lost.
DSP off: `AOS`, `u RECORD` 0, `U RECORD 1` refused, `u DSP` 0: the event `not started` says "DSP
off" (and trakbox leaving mid-pass sends `LOS`), the status's limits say "GQRX: ... not recording: DSP off", the station stays healthy
(failures 0, no fault) and the Doppler `F` frames keep coming.
`--record iq`: `U IQRECORD 1` read back with `u IQRECORD` (no AOS: that starts the audio recorder),
`iq` in the status, stopped with `U IQRECORD 0` when trakbox leaves mid-pass.
"""
import json
import re
import os
import shutil
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timedelta, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, leave_and_read_log, poll, reap, run_test  # noqa: E402
from sdr_receivers import Gqrx, so50_pass, status  # noqa: E402

RATE = 40


class RecordingGqrx(Gqrx):
    """GQRX's remote control with its recorders: the DSP running or not, the demodulator as `M` set
    it (FM after trakbox's first `M FM 0`)."""

    def __init__(self, dsp=True):
        super().__init__()
        self.dsp = dsp
        self.recording = False
        self.iq = False

    def answer(self, line):
        words = line.split()
        if line == "u ?":
            return "RECORD IQRECORD DSP RDS MUTE"
        if words[:1] == ["u"] and len(words) == 2 and words[1] in ("RECORD", "IQRECORD", "DSP"):
            return str(int({"RECORD": self.recording, "IQRECORD": self.iq, "DSP": self.dsp}[words[1]]))
        if line == "AOS":
            if self.dsp and self.mode != "OFF":
                self.recording = True
            return "RPRT 0"
        if line == "LOS":
            self.recording = False
            return "RPRT 0"
        if words[:1] == ["U"] and len(words) == 3 and words[1] in ("RECORD", "IQRECORD") and words[2] in ("0", "1"):
            if not self.dsp or (words[1] == "RECORD" and self.mode == "OFF"):
                return "RPRT 1"
            setattr(self, "recording" if words[1] == "RECORD" else "iq", words[2] == "1")
            return "RPRT 0"
        return super().answer(line)


def iso(s):
    return datetime.fromisoformat(s.replace("Z", "+00:00"))


def run(dsp, aos, los, until, kind="audio"):
    """trakbox single-tracking SO-50 (the shipped list's #5) on the stand-in from 40 s before AOS to
    `until` (station time); returns (stand-in, events as (wall time, JSON), status documents
    sampled mid-pass, `trakbox status` text then, trakbox.log)."""
    rig = RecordingGqrx(dsp=dsp)
    state = tempfile.mkdtemp(prefix="trakbox-gqrx-record-")
    hooks = os.path.join(state, "events.txt")
    procs = []
    start = aos - timedelta(seconds=40)
    try:
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--clock",
                               start.strftime("%Y-%m-%dT%H:%M:%SZ"), "--clock-rate", str(RATE),
                               "--radio", f"gqrx:127.0.0.1:{rig.port}", "--record", kind,
                               "--elements-url", "file://" + os.path.join(SOURCE, "data", "amateur.tle"),
                               "--on-event", f"aos,los,recording,link-lost=echo \"$(date +%s.%N) $TRAKBOX_EVENT_JSON\" >> {hooks}"],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        tb.stdin.write(b"S\r5\r")   # single tracking of SO-50
        tb.stdin.flush()
        mid = aos + (los - aos) / 2
        clock = lambda: iso(status(state)[1].get("time", "2000-01-01T00:00:00Z"))  # noqa: E731
        poll("the clock past mid-pass", lambda: clock() > mid, 60, every=0.3)
        code, doc = status(state)
        text = subprocess.run([BIN, "status", "--state", state], capture_output=True, text=True, timeout=30).stdout
        poll("the clock at the end", lambda: clock() > until, 60, every=0.3)
        time.sleep(0.5)   # the last hook's line written
        log = leave_and_read_log(tb, state, procs)
        events = []
        with open(hooks) as f:
            for row in f:
                wall, _, js = row.strip().partition(" ")
                events.append((float(wall), json.loads(js)))
        return rig, events, (code, doc), text, log
    finally:
        reap(procs)
        rig.close()
        shutil.rmtree(state, ignore_errors=True)


def dsp_on(aos, los):
    rig, events, (code, doc), text, log = run(True, aos, los, los + timedelta(seconds=30))
    kinds = [e["event"] for _, e in events]
    rec = [(w, e) for w, e in events if e["event"] == "recording"]
    check([e["recording"]["state"] for _, e in rec] == ["started", "stopped"], f"recording events: {kinds}")
    (w_start, started), (w_stop, stopped) = rec
    r = started["recording"]
    start = iso(r["start"])
    check(abs((start - aos).total_seconds()) <= 5, f"recording started at {r['start']}, SO-50's AOS {aos}")
    check(abs((iso(stopped["time"]) - los).total_seconds()) <= 5, f"recording stopped at {stopped['time']}, LOS {los}")
    check(r["read_back"] and r["kind"] == "audio" and started["satellite"] == "SO-50", f"started event: {started}")
    # The stand-in names the file from its own reading of the station clock when RECORD came: at
    # --clock-rate 40 that may be a second or two after the recording's start, never more.
    named = re.fullmatch(r"gqrx_(\d{8}_\d{6})_(\d+)\.wav", r["file"] or "")
    check(named and named.group(2) == str(r["frequency_hz"]), f"file {r['file']}: gqrx_yyyyMMdd_hhmmss_<Hz>.wav")
    named_at = datetime.strptime(named.group(1), "%Y%m%d_%H%M%S").replace(tzinfo=timezone.utc)
    check(-1 <= (named_at - start.replace(microsecond=0)).total_seconds() <= 2,
          f"file {r['file']}: named at the recording's start {r['start']}")
    want_file = r["file"]
    check(abs(r["frequency_hz"] - 436_795_000) < 12_000, f"the frequency at the start: {r['frequency_hz']}")
    # The stand-in: AOS and LOS once each, next to the events' wall times; u RECORD read back 1.
    aos_cmd = rig.sent(lambda line: line == "AOS")
    los_cmd = rig.sent(lambda line: line == "LOS")
    check(len(aos_cmd) == 1 and len(los_cmd) == 1, f"AOS {len(aos_cmd)}, LOS {len(los_cmd)} sent")
    check(abs(aos_cmd[0][0] - w_start) < 1.0 and abs(los_cmd[0][0] - w_stop) < 1.0,
          f"AOS/LOS commands at the events' wall times: {aos_cmd[0][0] - w_start:+.2f} s, {los_cmd[0][0] - w_stop:+.2f} s")
    after_aos = [line for t, line, _ in rig.commands if t >= aos_cmd[0][0]][:3]
    check(after_aos[:2] == ["AOS", "u RECORD"], f"AOS then u RECORD read back: {after_aos}")
    check(not rig.sent(lambda line: line == "U RECORD 1"), "no U RECORD 1 needed: AOS started the recorder")
    check(not rig.recording, "the recorder is off after LOS")
    # One connection all through; F frames before, between and after the recorder's commands.
    check(rig.connections == 1, f"one connection to GQRX: {rig.connections}")
    t_aos, t_los = aos_cmd[0][0], los_cmd[0][0]
    fs = rig.sent(lambda line: line.startswith("F "))
    before = sum(1 for t, _, _ in fs if t < t_aos)
    during = sum(1 for t, _, _ in fs if t_aos < t < t_los)
    check(before >= 1 and during >= 10, f"F frames before AOS {before}, during the pass {during}")
    check("link-lost" not in kinds and "event: link-lost" not in log, "no link-lost")
    # Mid-pass: REC in the status line, the document and `trakbox status`.
    radio = doc["radios"][0]
    rj = radio["recording"]
    check(code == 0 and doc["healthy"] and radio["failures"] == 0, f"healthy mid-pass: {doc.get('problems')} {radio}")
    check(rj["state"] == "audio" and rj["read_back"] and rj["records"] == "audio, iq" and rj["file"] == want_file,
          f"radios[0].recording mid-pass: {rj}")
    check("| REC" in doc["status_line"], f"REC in the status line: {doc['status_line']}")
    check(f"REC audio SO-50 since {r['start']}, {want_file}" in text, f"trakbox status: {text}")
    said = [line for line in log.splitlines() if "recording" in line and "GQRX" in line]
    print(f"gqrx_record DSP on: AOS sent at station {r['start']} (pass AOS {aos:%H:%M:%S}), LOS at {stopped['time']} "
          f"(pass LOS {los:%H:%M:%S}); {r['file']}; {during} F frames during the pass, 1 connection")
    for line in said:
        print("  log:", line.split("] ", 1)[-1] if "] " in line else line)


def dsp_off(aos, los):
    rig, events, (code, doc), text, log = run(False, aos, los, aos + (los - aos) * 0.6)
    rec = [e for _, e in events if e["event"] == "recording"]
    check(len(rec) == 1 and rec[0]["recording"]["state"] == "not started" and
          rec[0]["recording"]["why"] == "not recording: DSP off", f"recording events with the DSP off: {rec}")
    # The start: read first, AOS, read back, U RECORD 1 refused, read back, why; trakbox leaving
    # mid-pass then stops the recorder (LOS).
    sent = [line for _, line, _ in rig.commands if line in ("AOS", "LOS", "u RECORD", "U RECORD 1", "u DSP")]
    check(sent == ["u RECORD", "AOS", "u RECORD", "U RECORD 1", "u RECORD", "u DSP", "LOS", "u RECORD"],
          f"the start and its read back, the stop when trakbox leaves: {sent}")
    radio = doc["radios"][0]
    check(code == 0 and doc["healthy"] and not radio["fault"] and radio["failures"] == 0,
          f"a refusal is a limit, not a fault: {doc.get('problems')} {radio}")
    check("not recording: DSP off" in radio["limits"] and radio["limits"].startswith("GQRX:"), f"limits: {radio['limits']}")
    check(radio["recording"]["state"] == "off" and radio["recording"]["refused"] == "not recording: DSP off",
          f"radios[0].recording: {radio['recording']}")
    check("| REC" not in doc["status_line"], "no REC while nothing records")
    t_refused = rig.sent(lambda line: line == "U RECORD 1")[0][0]
    later = sum(1 for t, _, _ in rig.sent(lambda line: line.startswith("F ")) if t > t_refused)
    check(later >= 5 and rig.connections == 1, f"F frames after the refusal: {later}; connections {rig.connections}")
    print(f"gqrx_record DSP off: AOS, u RECORD 0, U RECORD 1 refused, u DSP 0: \"{radio['limits']}\", healthy, "
          f"failures 0, {later} F frames after the refusal on 1 connection")


def iq(aos, los):
    rig, events, (code, doc), text, log = run(True, aos, los, aos + (los - aos) * 0.6, kind="iq")
    rec = [e for _, e in events if e["event"] == "recording"]
    check(len(rec) == 1 and rec[0]["recording"]["state"] == "started" and rec[0]["recording"]["kind"] == "iq" and
          rec[0]["recording"]["read_back"] and rec[0]["recording"]["file"] is None, f"recording events, iq: {rec}")
    sent = [line for _, line, _ in rig.commands if "RECORD" in line or line in ("AOS", "LOS")]
    # Read, start, read back; at the leave, stop and read back. No AOS: that starts the audio recorder.
    check(sent == ["u IQRECORD", "U IQRECORD 1", "u IQRECORD", "U IQRECORD 0", "u IQRECORD"],
          f"the IQ recorder's start, read back and stop: {sent}")
    rj = doc["radios"][0]["recording"]
    check(code == 0 and doc["healthy"] and rj["state"] == "iq" and rj["read_back"], f"radios[0].recording, iq: {rj}")
    check(not rig.iq, "the IQ recorder is off after trakbox left")
    print(f"gqrx_record iq: {', '.join(sent)}")


def main():
    aos, los = so50_pass()
    dsp_on(aos, los)
    dsp_off(aos, los)
    iq(aos, los)


if __name__ == "__main__":
    run_test(main)
