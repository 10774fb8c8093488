"""The web API (docs/web-api.md) on the real binary, endpoint by endpoint, bad input included: each
refusal is a 4xx with a JSON sentence and the station goes on tracking. Then the secret: without it
nothing changes, the login page's session works only from the page's own Origin, the bearer works
for scripts; and --http-port beyond loopback without --allow and a secret is refused at start."""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, free_port, poll, run_test  # noqa: E402
from _web import WebSocket, WebStation  # noqa: E402


def still_tracking(w, what):
    check(w.alive(), f"the station runs after {what}")
    st = w.status()
    check(st["tracking"]["followed"] == "ISS", f"still tracking ISS after {what}: {st['tracking']}")


def page_and_headers(w):
    first = 0
    for path in ("/", "/style.css", "/app.js"):
        status, headers, body = w.request("GET", path)
        check(status == 200, f"GET {path}: {status}")
        first += len(body)
        check("default-src 'self'" in headers.get("content-security-policy", ""), f"CSP on {path}: {headers}")
        check("frame-ancestors 'none'" in headers["content-security-policy"], "frame-ancestors 'none'")
        check(headers.get("x-content-type-options") == "nosniff", "nosniff")
    check(first <= 150 * 1024, f"first load {first} bytes")
    print(f"first load: {first} bytes")
    status, _, _ = w.request("GET", "/api/v1/status", host="evil.example:80")
    check(status == 403, f"a foreign Host (DNS rebinding) is refused: {status}")


def endpoints(w):
    status, doc = w.get_json("/api/v1/status")
    check(status == 200 and doc["schema"] == 1 and doc["running"], f"status: {status} {str(doc)[:200]}")
    check(set(w.status().keys()) <= set(doc.keys()), "the status document of `trakbox status --json`")
    status, sats = w.get_json("/api/v1/satellites")
    check(status == 200 and any(s["name"] == "ISS" for s in sats["satellites"]), "satellites lists ISS")
    status, p = w.get_json("/api/v1/passes?sat=ISS&hours=24")
    check(status == 200 and p["satellite"] == "ISS" and len(p["passes"]) >= 2, f"passes: {p}")
    # A repeated sat= is every one named, as sat=A,B (issue 60: only the first was used).
    status, both = w.get_json("/api/v1/passes?sat=ISS&sat=SO-50&hours=24")
    check(status == 200 and {x["satellite"] for x in both["passes"]} == {"ISS", "SO-50"}, f"sat twice: {status} {both}")
    status, e = w.get_json("/api/v1/passes?sat=RS44")
    check(status == 404 and e["error"] == "unknown satellite 'RS44'; did you mean RS-44?", f"did you mean: {status} {e}")
    for q, want in (("sat=ISS&hours=x", 400), ("hours=2&hours=3", 400), ("sat=ISS&hours=0", 400), ("sat=NOPE&hours=2", 404), ("sat=ISS&hours=73", 400),
                    ("min_el=-1", 400), ("with=XX99", 400)):
        status, e = w.get_json("/api/v1/passes?" + q)
        check(status == want and isinstance(e.get("error"), str), f"passes?{q}: {status} {e}")

    status, r = w.post("/api/v1/track", {"satellite": "ISS"})
    check(status == 200 and r["ok"], f"track ISS: {status} {r}")
    poll("ISS followed", lambda: w.status()["tracking"]["followed"] == "ISS", 10)
    status, r = w.post("/api/v1/rotor", {"control": True})
    check(status == 200, f"rotor control on: {status} {r}")
    check(w.status()["antenna"]["rotor_control"] is True, "rotor control on in trakbox status")
    status, r = w.post("/api/v1/radio", {"doppler": True})
    check(status == 200, f"Doppler on: {status} {r}")
    status, r = w.post("/api/v1/elements/refresh", {})
    check(status in (200, 409) and ("error" in r or r["ok"]), f"elements refresh: {status} {r}")


def bad_input(w):
    cases = [
        ("/api/v1/track", {"satellite": 42}, 400),
        ("/api/v1/track", {"satellite": "ISSS"}, 409),
        ("/api/v1/track", {"list": ["ISS"]}, 409),
        ("/api/v1/track", {"list": "ISS"}, 400),
        ("/api/v1/track", [1, 2], 400),
        ("/api/v1/rotor", {"control": "yes"}, 400),
        ("/api/v1/rotor", {"action": "dance"}, 400),
        ("/api/v1/rotor", {"goto": {"az": "north", "el": 3}}, 400),
        ("/api/v1/radio", {"doppler": "off"}, 400),
        ("/api/v1/nothing", {}, 404),
    ]
    for path, body, want in cases:
        status, e = w.post(path, body)
        check(status == want and isinstance(e.get("error"), str), f"POST {path} {body}: {status} {e}")
        still_tracking(w, f"POST {path} {body}")
    status, e = w.post("/api/v1/track", {"satellite": "ISSS"})
    check(e["error"] == "unknown satellite 'ISSS'; did you mean ISS?", f"the sentence: {e}")
    status, _, _ = w.request("POST", "/api/v1/track", body="{" * 10, headers={"Content-Type": "application/json"})
    check(status == 400, f"malformed JSON: {status}")
    status, _, _ = w.request("POST", "/api/v1/track", body='{"satellite":"ISS"}', headers={"Content-Type": "text/plain"})
    check(status == 415, f"not JSON: {status}")
    try:
        status, _, _ = w.request("POST", "/api/v1/track", body=b"x" * (1 << 20),
                                 headers={"Content-Type": "application/json"})
        check(status == 413, f"1 MB body: {status}")
    except (ConnectionError, OSError):
        pass  # the server may close before the client has sent it all: refused either way
    still_tracking(w, "a 1 MB body")
    status, e = w.post("/api/v1/rotor", {"control": False}, headers={"Origin": "http://evil.example"})
    check(status == 403, f"a cross-site POST: {status} {e}")
    check(w.status()["antenna"]["rotor_control"] is True, "the cross-site POST changed nothing")
    status, _, _ = w.request("POST", "/api/v1/rotor", body='{"control":false}', headers={
        "Content-Type": "application/json", "X-Pad": "y" * 10000})
    check(status == 431, f"headers over 8 kB: {status}")
    still_tracking(w, "bad input")


def live(w):
    ws = WebSocket(w.port, origin=f"http://127.0.0.1:{w.port}")
    check(ws.status == 101, f"the WebSocket opens: {ws.head}")
    m = ws.state()
    st = w.status()
    a, b = m["status"]["antenna"]["position"], st["antenna"]["position"]
    check(abs(a["az_deg"] - b["az_deg"]) < 5 and abs(a["el_deg"] - b["el_deg"]) < 5, f"live antenna {a} vs {b}")
    check(m["sky"]["satellite"]["name"] == "ISS", f"the sky follows ISS: {m['sky']['satellite']}")
    ws.state()  # and the next tick's
    ws.close()
    bad = WebSocket(w.port, origin="http://evil.example")
    check(bad.status == 403, f"a WebSocket from another site: {bad.status}")
    bad.close()


def connection_bounds(w):
    """Eight connections per address: the ninth is answered 503 with Retry-After at once and closed
    (issue 46: it was a reset); the eight still work."""
    import socket
    held = [socket.create_connection(("127.0.0.1", w.port), timeout=5) for _ in range(8)]
    try:
        ninth = socket.create_connection(("127.0.0.1", w.port), timeout=5)
        ninth.sendall(f"GET /api/v1/status HTTP/1.1\r\nHost: 127.0.0.1:{w.port}\r\n\r\n".encode())
        try:
            got = ninth.recv(100)
        except ConnectionResetError:
            got = b""
        check(got.startswith(b"HTTP/1.1 503") and b"Retry-After: 10" in got,
              f"a ninth connection from one address is answered 503: {got!r}")
        ninth.close()
        held[0].sendall(f"GET /api/v1/status HTTP/1.1\r\nHost: 127.0.0.1:{w.port}\r\n\r\n".encode())
        check(held[0].recv(12).startswith(b"HTTP/1.1 200"), "the eight held ones are served")
    finally:
        for s in held:
            s.close()
    still_tracking(w, "nine connections")

    def served():
        try:
            return w.get_json("/api/v1/status")[0] == 200
        except (ConnectionError, OSError, ValueError):
            return False
    poll("served again once they closed", served, 10)


def with_secret():
    secret_file = tempfile.mktemp(prefix="trakbox-web-secret-")
    with open(secret_file, "w") as f:
        f.write("s3cret-for-the-web-test\n")
    os.chmod(secret_file, 0o600)
    w = WebStation("--http-secret-file", secret_file)
    try:
        origin = {"Origin": f"http://127.0.0.1:{w.port}"}
        status, e = w.get_json("/api/v1/status")
        check(status == 401, f"no secret, no view: {status} {e}")
        status, e = w.post("/api/v1/rotor", {"control": True}, headers=origin)
        check(status == 401, f"no secret, no change: {status} {e}")
        status, _ = w.get_json("/api/v1/status", headers={"Authorization": "Bearer s3cret-for-the-web-test"})
        check(status == 200, f"the bearer views: {status}")
        status, _, _ = w.request("POST", "/login", body="secret=s3cret-for-the-web-test", headers={
            **origin, "Content-Type": "application/x-www-form-urlencoded"})
        check(status == 303, f"login: {status}")
        status, headers, _ = w.request("POST", "/login", body="secret=s3cret-for-the-web-test", headers={
            **origin, "Content-Type": "application/x-www-form-urlencoded"})
        cookie = headers.get("set-cookie", "")
        check("HttpOnly" in cookie and "SameSite=Strict" in cookie and "s3cret" not in cookie, f"cookie {cookie}")
        session = cookie.split(";")[0]
        status, e = w.post("/api/v1/rotor", {"control": True}, headers={"Cookie": session, "Origin": "http://evil.example"})
        check(status == 403, f"a cross-origin POST with the session: {status} {e}")
        check(w.status()["antenna"]["rotor_control"] is False, "it changed nothing")
        status, r = w.post("/api/v1/rotor", {"control": True}, headers={"Cookie": session, **origin})
        check(status == 200, f"the session from the page: {status} {r}")
        check(w.status()["antenna"]["rotor_control"] is True, "and it changed rotor control")
        status, e = w.post("/api/v1/rotor", {"control": False}, headers={"Authorization": "Bearer guess"})
        check(status == 401, f"a wrong bearer: {status}")
        status, e = w.post("/api/v1/rotor", {"control": False}, headers={"Authorization": "Bearer s3cret-for-the-web-test"})
        check(status == 429, f"the next guess at once is slowed: {status} {e}")
        log = open(os.path.join(w.state, "trakbox.log")).read()
        check("s3cret" not in log, "the secret is not in the log")
    finally:
        err = w.stop()
        os.unlink(secret_file)
    check("s3cret" not in err, "nor on standard error")
    r = subprocess.run([BIN, "--service", "--state", tempfile.mkdtemp(prefix="trakbox-web-"), "--satrak-port", "0",
                        "--clock", CLOCK, "--http-port", str(free_port()), "--listen", "0.0.0.0"],
                       stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=20)
    check(r.returncode == 2 and "--allow ranges and --http-secret-file" in r.stderr, f"open web refused: {r.stderr}")


def main():
    w = WebStation()
    try:
        log = poll("the URL in the log", lambda: "web: the station's page is at" in
                   open(os.path.join(w.state, "trakbox.log")).read(), 10)
        check(log, "start message")
        url = f"http://127.0.0.1:{w.port}/"
        check(url in w.status_text(), f"trakbox status prints {url}")
        page_and_headers(w)
        endpoints(w)
        bad_input(w)
        live(w)
        connection_bounds(w)
    finally:
        err = w.stop()
    check(f"the station's page: http://127.0.0.1:{w.port}/" in err, "the start message names the URL")
    with_secret()


run_test(main)
