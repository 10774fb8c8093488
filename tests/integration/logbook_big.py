"""A logbook of 100,000 QSOs on the real binary (issue 56, items 4 and 8): the station's loop keeps
answering (a rotctld `p` within 1.5 s, asked every 20 ms) and its memory stays bounded (VmRSS grows
under 64 MB) while
- `trakbox log import` takes the 100,000 QSOs (13 MB of ADIF) through the station's socket (the
  import runs on a worker thread; all or nothing, acknowledged after the commit);
- `GET /api/v1/log` answers a page (500 QSOs and the cursor of the next), not the whole log, and
  the pages joined are the whole log;
- `GET /api/v1/log.adi` streams the whole export (chunked, a page at a time), also to four clients
  that never read it;
- `trakbox log export` asks the station page by page.
The figures measured are printed (stall, RSS before/after, time)."""
import datetime
import http.client
import os
import shutil
import socket
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, check, free_port, read_log, run_test, sh, wait_listening  # noqa: E402
from _web import WebStation  # noqa: E402

N = 100_000
STALL_LIMIT = 1.5
RSS_LIMIT_KB = 64 * 1024


def rss_kb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def write_adif(path, n):
    """n satellite QSOs one second apart (no two alike), as a logger would export them."""
    start = datetime.datetime(2026, 1, 1, tzinfo=datetime.timezone.utc)
    with open(path, "w") as f:
        f.write("made by logbook_big.py <EOH>\n")
        for i in range(n):
            t = start + datetime.timedelta(seconds=i)
            call = f"N{i % 10}A{chr(65 + i // 10 % 26)}{chr(65 + i // 260 % 26)}"
            f.write(f"<CALL:{len(call)}>{call} <QSO_DATE:8>{t:%Y%m%d} <TIME_ON:6>{t:%H%M%S} <MODE:2>FM <BAND:2>2m "
                    f"<FREQ:10>145.990000 <PROP_MODE:3>SAT <SAT_NAME:5>ARISS <EOR>\n")


class Probe:
    """Asks rotctld `p` every 20 ms on one connection and keeps the longest wait for its answer, and
    the highest VmRSS seen, until stopped."""

    def __init__(self, port, pid):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=30)
        self.pid = pid
        self.worst = 0.0
        self.answers = 0
        self.peak_kb = 0
        self.running = True
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        while self.running:
            t0 = time.monotonic()
            self.sock.sendall(b"p\n")
            got = b""
            while got.count(b"\n") < 2:
                chunk = self.sock.recv(4096)
                if not chunk:
                    return
                got += chunk
            self.worst = max(self.worst, time.monotonic() - t0)
            self.answers += 1
            self.peak_kb = max(self.peak_kb, rss_kb(self.pid))
            time.sleep(0.02)

    def stop(self):
        self.running = False
        self.thread.join(40)
        self.sock.close()
        return self.worst


def settle(pid, seconds=1.5):
    time.sleep(seconds)
    return rss_kb(pid)


def measured(what, w, rot, action, peak_limit_kb=RSS_LIMIT_KB):
    """Runs action() under a probe; checks the longest stall, and the RSS growth at its peak and
    after (what it took given back). Its result."""
    before = settle(w.proc.pid, 0.5)
    probe = Probe(rot, w.proc.pid)
    t0 = time.monotonic()
    result = action()
    took = time.monotonic() - t0
    stall = probe.stop()
    after = settle(w.proc.pid)
    print(f"{what}: {took:.1f} s; longest rotctld wait {stall:.3f} s over {probe.answers} answers; "
          f"VmRSS {before // 1024} MB before, {probe.peak_kb // 1024} MB at most, {after // 1024} MB after "
          f"(+{(after - before) / 1024:.1f} MB)")
    check(probe.answers > 0, f"{what}: rotctld answered")
    check(stall < STALL_LIMIT, f"{what}: the loop stalled {stall:.2f} s (at most {STALL_LIMIT})")
    check(after - before < RSS_LIMIT_KB, f"{what}: VmRSS grew {(after - before) // 1024} MB and stayed")
    check(probe.peak_kb - before < peak_limit_kb, f"{what}: VmRSS rose {(probe.peak_kb - before) // 1024} MB")
    return result


def read_export(port):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    c.request("GET", "/api/v1/log.adi", headers={"Host": f"127.0.0.1:{port}"})
    r = c.getresponse()
    records, size, tail = 0, 0, b""
    while True:
        chunk = r.read(1 << 16)
        if not chunk:
            break
        size += len(chunk)
        records += (tail + chunk).count(b"<EOR>")
        tail = chunk[-4:]
    c.close()
    return r.status, r.getheader("Transfer-Encoding"), records, size


def main():
    state = tempfile.mkdtemp(prefix="trakbox-logbig-")
    rot = free_port()
    adif = os.path.join(state, "big.adi")
    write_adif(adif, N)
    print(f"the file: {os.path.getsize(adif) / 1e6:.1f} MB, {N} QSOs")
    w = WebStation("--rotctld-port", str(rot), state=state)
    try:
        wait_listening(rot, "rotctld", within=20, proc=w.proc)
        # Item 8: the import, through the station's socket. While it runs the file is held (its 16 MiB
        # request, the records parsed): bounded by the socket's 16 MiB, given back when it is done.
        code, out, err = measured("import of 100,000 QSOs", w, rot,
                                  lambda: sh(BIN, "log", "import", adif, "--state", state, timeout=120),
                                  peak_limit_kb=256 * 1024)
        check(code == 0 and f"imported {N} QSOs, 0 already in the log" in out, f"import: {code} {out} {err}")
        check(f"{N} QSOs imported (0 already in the log, 0 records not satellite QSOs skipped) by trakbox log import" in read_log(state),
              "trakbox.log says the import and who asked")
        # Item 4: a page, not the whole log; the pages joined are the log.
        status, r = measured("GET /api/v1/log", w, rot, lambda: w.get_json("/api/v1/log"))
        check(status == 200 and len(r["qsos"]) == 500 and r["summary"]["count"] == N and r["next"],
              f"GET /api/v1/log: {status} {len(r.get('qsos', []))} QSOs, next {r.get('next')}")

        def all_pages():
            seen, after = 0, ""
            while True:
                status, page = w.get_json("/api/v1/log?limit=1000" + (f"&after={after}" if after else ""))
                check(status == 200, f"a page: {status} {page}")
                seen += len(page["qsos"])
                if not page["next"]:
                    return seen
                after = page["next"]
        check(measured("every page of GET /api/v1/log?limit=1000", w, rot, all_pages) == N, "the pages are the log")
        status, coding, records, size = measured("GET /api/v1/log.adi (whole)", w, rot, lambda: read_export(w.port))
        print(f"the ADIF export: {size / 1e6:.1f} MB")
        check(status == 200 and coding == "chunked" and records == N, f"log.adi: {status} {coding} {records} records")

        def never_read():
            idle = []
            for _ in range(4):
                s = socket.create_connection(("127.0.0.1", w.port), timeout=10)
                s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
                s.sendall(f"GET /api/v1/log.adi HTTP/1.1\r\nHost: 127.0.0.1:{w.port}\r\n\r\n".encode())
                idle.append(s)
            time.sleep(3)
            for s in idle:
                s.close()
        measured("four GET /api/v1/log.adi that never read", w, rot, never_read)
        out_file = os.path.join(state, "out.adi")
        code, out, err = measured("trakbox log export", w, rot,
                                  lambda: sh(BIN, "log", "export", "--state", state, "--adif", out_file, timeout=120))
        check(code == 0, f"export: {code} {err}")
        with open(out_file, "rb") as f:
            exported = f.read()
        check(exported.count(b"<EOR>") == N and exported.count(b"<EOH>") == 1, "trakbox log export wrote the whole log")
        check(w.alive(), "the station runs on")
    finally:
        w.stop()
    shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
