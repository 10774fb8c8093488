"""TLS in front, as docs/security.md recommends: nginx with packaging/nginx-trakbox.conf (its port,
certificate and upstream replaced by the test's own), a self-signed certificate made by openssl,
trakbox with a secret on loopback behind it. Through the proxy over HTTPS: the login sets a Secure
session cookie (X-Forwarded-Proto from the loopback proxy), the page loads with it, the API answers
the bearer, a change is taken only with the page's https Origin, and the WebSocket upgrades and
checks its Origin too."""
import http.client
import json
import os
import shutil
import ssl
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import SOURCE, check, free_port, reap, run_test, skip, wait_listening  # noqa: E402
from _web import WebSocket, WebStation  # noqa: E402

SECRET = "s3cret-for-the-tls-test"


def nginx_binary():
    return shutil.which("nginx") or next((p for p in ("/usr/sbin/nginx",) if os.access(p, os.X_OK)), None)


def proxy_config(d, proxy_port, upstream_port):
    with open(os.path.join(SOURCE, "packaging", "nginx-trakbox.conf")) as f:
        site = f.read()
    for old, new in (("listen 443 ssl;", f"listen 127.0.0.1:{proxy_port} ssl;"),
                     ("/etc/letsencrypt/live/station.example.org/fullchain.pem", os.path.join(d, "cert.pem")),
                     ("/etc/letsencrypt/live/station.example.org/privkey.pem", os.path.join(d, "key.pem")),
                     ("http://127.0.0.1:8073;", f"http://127.0.0.1:{upstream_port};")):
        check(old in site, f"packaging/nginx-trakbox.conf has '{old}'")
        site = site.replace(old, new)
    with open(os.path.join(d, "site.conf"), "w") as f:
        f.write(site)
    temps = "".join(f"    {k}_temp_path {d}/{k};\n" for k in ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
    with open(os.path.join(d, "nginx.conf"), "w") as f:
        f.write(("user root;\n" if os.geteuid() == 0 else "") +
                f"daemon off;\nmaster_process off;\npid {d}/nginx.pid;\nerror_log {d}/error.log;\nevents {{ worker_connections 64; }}\n"
                f"http {{\n    access_log off;\n{temps}    include {d}/site.conf;\n}}\n")


def https(port, tls, method, path, body=None, headers=None):
    c = http.client.HTTPSConnection("127.0.0.1", port, timeout=15, context=tls)
    try:
        c.request(method, path, body=body, headers={"Host": f"127.0.0.1:{port}", **(headers or {})})
        r = c.getresponse()
        return r.status, {k.lower(): v for k, v in r.getheaders()}, r.read()
    finally:
        c.close()


def through_proxy(pp, w, tls):
    origin = f"https://127.0.0.1:{pp}"
    bearer = {"Authorization": f"Bearer {SECRET}"}
    status, headers, _ = https(pp, tls, "POST", "/login", body=f"secret={SECRET}",
                               headers={"Origin": origin, "Content-Type": "application/x-www-form-urlencoded"})
    cookie = headers.get("set-cookie", "")
    check(status == 303 and "HttpOnly" in cookie and "Secure" in cookie and SECRET not in cookie,
          f"the login over HTTPS: {status} {cookie}")
    session = cookie.split(";")[0]
    status, headers, page = https(pp, tls, "GET", "/", headers={"Cookie": session})
    check(status == 200 and headers.get("content-type", "").startswith("text/html") and b"trakbox" in page,
          f"the page through the proxy: {status} {headers}")
    check("default-src 'self'" in headers.get("content-security-policy", ""), "the page's CSP passes the proxy")
    status, _, body = https(pp, tls, "GET", "/api/v1/status", headers=bearer)
    check(status == 200 and json.loads(body).get("schema") == 1, f"the status with the bearer: {status}")
    status, _, body = https(pp, tls, "GET", "/api/v1/status")
    check(status == 401, f"without the secret: {status} {body[:200]}")
    change = {"Content-Type": "application/json", "Cookie": session}
    status, _, body = https(pp, tls, "POST", "/api/v1/rotor", body=json.dumps({"control": True}),
                            headers={**change, "Origin": "https://evil.example"})
    check(status == 403 and w.status()["antenna"]["rotor_control"] is False, f"another site's Origin: {status} {body}")
    status, _, body = https(pp, tls, "POST", "/api/v1/rotor", body=json.dumps({"control": True}),
                            headers={**change, "Origin": origin})
    check(status == 200 and w.status()["antenna"]["rotor_control"] is True, f"the page's Origin: {status} {body}")
    ws = WebSocket(pp, origin=origin, headers={"Cookie": session}, tls=tls)
    try:
        check(ws.status == 101, f"the WebSocket upgrades through the proxy: {ws.head}")
        st = ws.state()
        check(st["status"]["antenna"]["rotor_control"] is True, f"the live state through the proxy: {st.keys()}")
    finally:
        ws.close()
    bad = WebSocket(pp, origin="https://evil.example", headers={"Cookie": session}, tls=tls)
    check(bad.status == 403, f"the WebSocket from another site: {bad.head}")
    bad.close()


def main():
    nginx = nginx_binary()
    if not nginx or not shutil.which("openssl"):
        skip("nginx or openssl is not installed")
    d = tempfile.mkdtemp(prefix="trakbox-tls-")
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2", "-subj", "/CN=127.0.0.1",
                    "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", os.path.join(d, "key.pem"),
                    "-out", os.path.join(d, "cert.pem")], check=True, capture_output=True, timeout=60)
    secret_file = os.path.join(d, "secret")
    with open(secret_file, "w") as f:
        f.write(SECRET + "\n")
    os.chmod(secret_file, 0o600)
    w = WebStation("--http-secret-file", secret_file)
    pp = free_port()
    proxy_config(d, pp, w.port)
    proxy = subprocess.Popen([nginx, "-p", d, "-e", os.path.join(d, "error.log"), "-c", os.path.join(d, "nginx.conf")],
                             stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        wait_listening(pp, "nginx", within=20, proc=proxy)
        tls = ssl.create_default_context(cafile=os.path.join(d, "cert.pem"))
        through_proxy(pp, w, tls)
        check(w.alive(), "trakbox still running")
    finally:
        if proxy.poll() is None:
            proxy.terminate()
            try:
                proxy.wait(10)
            except subprocess.TimeoutExpired:
                pass
        reap([proxy])
        w.stop()


run_test(main)
