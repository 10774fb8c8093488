"""The web endpoint's HTTP rules and the logbook's log lines on the real binary (issue 56, items 13,
14 and 15):
13. creating, editing and deleting a QSO over the web, and a refused one, are each a line of
    trakbox.log naming who (the address), the QSO (its number and call) and why; the refusals line
    carries the reason;
14. a method an endpoint does not take is 405 with that endpoint's Allow (POST /api/v1/log.adi is
    not "id expected"); a path that is no endpoint is 404 whatever the method;
15. an absolute-form target is served (its authority checked as the Host); `Expect: 100-continue`
    is answered with 100 Continue before the body is sent, another expectation with 417."""
import os
import shutil
import socket
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import check, poll, read_log, run_test  # noqa: E402
from _web import WebStation  # noqa: E402


def raw(port, data, wait_for=b"\r\n\r\n", timeout=5):
    """Sends bytes on a fresh connection; what came back until `wait_for` and the body's first bytes."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(data)
        got = b""
        while wait_for not in got:
            chunk = s.recv(4096)
            if not chunk:
                break
            got += chunk
        return got


def methods(w):
    for method, path, allow in [("POST", "/api/v1/log.adi", "GET, HEAD"), ("DELETE", "/api/v1/status", "GET, HEAD"),
                                ("PUT", "/api/v1/log", "GET, HEAD, POST"), ("GET", "/api/v1/track", "POST"),
                                ("GET", "/api/v1/log/delete", "POST"), ("PATCH", "/app.js", "GET, HEAD")]:
        status, headers, body = w.request(method, path, body=b"{}" if method != "GET" else None,
                                          headers={"Content-Type": "application/json"})
        check(status == 405 and headers.get("allow") == allow,
              f"{method} {path}: {status} Allow {headers.get('allow')!r} (expected 405 {allow!r}): {body[:120]!r}")
    status, _, _ = w.request("DELETE", "/api/v1/nothing")
    check(status == 404, f"DELETE /api/v1/nothing: {status}")


def absolute_and_expect(w):
    p = w.port
    got = raw(p, f"GET http://127.0.0.1:{p}/api/v1/status HTTP/1.1\r\nHost: 127.0.0.1:{p}\r\nConnection: close\r\n\r\n"
              .encode(), wait_for=b"schema")
    check(got.startswith(b"HTTP/1.1 200") and b'"schema"' in got, f"absolute-form target: {got[:200]!r}")
    got = raw(p, f"GET http://evil.example:{p}/api/v1/status HTTP/1.1\r\nHost: 127.0.0.1:{p}\r\nConnection: close\r\n\r\n"
              .encode())
    check(got.startswith(b"HTTP/1.1 403"), f"absolute-form with another authority: {got[:120]!r}")
    body = b'{"satellite":"ISS"}'
    with socket.create_connection(("127.0.0.1", p), timeout=5) as s:
        s.sendall(f"POST /api/v1/track HTTP/1.1\r\nHost: 127.0.0.1:{p}\r\nContent-Type: application/json\r\n"
                  f"Content-Length: {len(body)}\r\nExpect: 100-continue\r\nConnection: close\r\n\r\n".encode())
        t0 = time.monotonic()
        s.settimeout(0.8)
        got = s.recv(4096)
        waited = time.monotonic() - t0
        check(got.startswith(b"HTTP/1.1 100 Continue\r\n\r\n"), f"Expect: 100-continue: {got[:80]!r}")
        print(f"100 Continue after {waited * 1000:.0f} ms")
        s.settimeout(5)
        s.sendall(body)
        final = b""
        while b"\r\n\r\n" not in final:
            chunk = s.recv(4096)
            if not chunk:
                break
            final += chunk
        check(final.startswith(b"HTTP/1.1 200"), f"the POST after 100 Continue: {final[:120]!r}")
    got = raw(p, f"POST /api/v1/track HTTP/1.1\r\nHost: 127.0.0.1:{p}\r\nContent-Type: application/json\r\n"
                 f"Content-Length: 2\r\nExpect: 200-ok\r\n\r\n{{}}".encode())
    check(got.startswith(b"HTTP/1.1 417"), f"another expectation: {got[:120]!r}")


def log_lines(w):
    poll("ISS followed", lambda: w.status()["tracking"]["followed"] == "ISS", 10)
    status, r = w.post("/api/v1/log", {"call": "W1AW", "grid": "FN31"})
    check(status == 200, f"log: {status} {r}")
    qso = r["qso"]["id"]
    status, r = w.post("/api/v1/log/edit", {"id": qso, "grid": "FN42"})
    check(status == 200, f"edit: {status} {r}")
    status, r = w.post("/api/v1/log", {"call": "W1 AW"})
    check(status == 409, f"a refused QSO: {status} {r}")
    status, r = w.post("/api/v1/log/edit", {"id": 99, "grid": "FN42"})
    check(status == 404, f"an edit of no QSO: {status} {r}")
    status, r = w.post("/api/v1/log/delete", {"id": qso})
    check(status == 200, f"delete: {status} {r}")
    return qso


def main():
    state = tempfile.mkdtemp(prefix="trakbox-webrules-")
    w = WebStation(state=state)
    try:
        methods(w)
        absolute_and_expect(w)
        qso = log_lines(w)
    finally:
        w.stop()
    log = read_log(state)
    for line in [f"web: QSO {qso} W1AW ISS", "logged by web 127.0.0.1",
                 f"web: QSO {qso} W1AW edited by web 127.0.0.1 (now version 2",
                 f"web: QSO {qso} W1AW", "deleted by web 127.0.0.1",
                 "web: logging a QSO with W1 AW refused for web 127.0.0.1 (409): call: 'W1 AW' is not a callsign",
                 "web: editing QSO 99 refused for web 127.0.0.1 (404): id: no QSO 99 in the log",
                 "web: refused 127.0.0.1 (409): call: 'W1 AW'"]:
        check(line in log, f"trakbox.log has {line!r}:\n" + "\n".join(l for l in log.splitlines() if "web:" in l))
    check("web: refused 127.0.0.1 (409): \n" not in log, "no refusal logged without its reason")
    shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
