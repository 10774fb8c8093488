"""Issue 56 item 10 on the real binary: a user and password written in --satnogs-url
(http://bob:PW@127.0.0.1:PORT) were shown in clear in status' and the live feed's satnogs.url and
sent as Basic auth on the jobs request that is meant to be anonymous (with the owner's token it is
the station's heartbeat). Now the jobs are asked with no Authorization header, satnogs.url shows the
URL without them (status --json, the status text, the WebSocket's state), the log and standard error
never hold the password, and a warning at the start says they are not used (docs/security.md)."""
import http.server
import json
import os
import sys
import threading

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import check, free_port, poll, read_log, run_test  # noqa: E402
from _web import WebSocket, WebStation  # noqa: E402

PASSWORD = "PW7satnogsSecret"
seen = []


class Jobs(http.server.BaseHTTPRequestHandler):
    def do_GET(self):
        seen.append((self.path, {k.lower(): v for k, v in self.headers.items()}))
        body = b"[]"
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *a):
        pass


def main():
    port = free_port()
    server = http.server.ThreadingHTTPServer(("127.0.0.1", port), Jobs)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    web = WebStation("--satnogs-station", "9", "--satnogs-url", f"http://bob:{PASSWORD}@127.0.0.1:{port}/")
    err = ""
    try:
        s = poll("the jobs read", lambda: (lambda s: s if s.get("satnogs", {}).get("last_poll") else None)(web.status()), 20)
        check(seen and seen[0][0] == "/api/jobs/?ground_station=9", f"the request: {seen}")
        check(all("authorization" not in h for _, h in seen), f"no Authorization header: {seen}")
        check(s["satnogs"]["url"] == f"http://127.0.0.1:{port}/api/jobs/?ground_station=9" and s["satnogs"]["error"] is None,
              f"satnogs in status: {s['satnogs']}")
        ws = WebSocket(web.port)
        live = ws.state()
        ws.close()
        check(live["status"]["satnogs"]["url"] == s["satnogs"]["url"], f"the live feed's satnogs: {live['status'].get('satnogs')}")
        for where, text in (("status --json", json.dumps(s)), ("status", web.status_text()), ("the live feed", json.dumps(live))):
            check(PASSWORD not in text, f"the password is in {where}")
    finally:
        err = web.stop()
        server.shutdown()
        server.server_close()
    log = read_log(web.state)
    check("--satnogs-url: the user and password in the URL are not used" in err, f"the warning: {err[-300:]!r}")
    for where, text in (("the log", log), ("standard error", err)):
        check(PASSWORD not in text, f"the password is in {where}")
    print(f"{len(seen)} jobs request(s), none with Authorization; satnogs.url {s['satnogs']['url']}")


if __name__ == "__main__":
    run_test(main)
