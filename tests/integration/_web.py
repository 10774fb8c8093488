"""Helpers for the web endpoint's tests (web_api.py, web_browser.py): a service with --http-port,
HTTP requests with chosen headers, a minimal WebSocket client (standard library only), and
`trakbox status --json`."""
import base64
import http.client
import json
import os
import socket
import struct
import subprocess
import tempfile
import time

from _tbharness import BIN, CLOCK, check, free_port, wait_listening


class WebStation:
    """trakbox --service on a fresh state directory, serving the web page on a free port."""

    def __init__(self, *extra, port=None, state=None, clock=CLOCK, rate="1"):
        self.state = state or tempfile.mkdtemp(prefix="trakbox-web-")
        self.port = port or free_port()
        self.args = [BIN, "--service", "--state", self.state, "--satrak-port", "0", "--clock", clock,
                     "--clock-rate", rate, "--http-port", str(self.port)] + list(extra)
        self.start()

    def start(self):
        self.proc = subprocess.Popen(self.args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.PIPE)
        wait_listening(self.port, "the web server", within=20, proc=self.proc)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        return self.proc.stderr.read().decode(errors="replace")

    def alive(self):
        return self.proc.poll() is None

    def status(self):
        r = subprocess.run([BIN, "status", "--state", self.state, "--json"], capture_output=True, text=True,
                           timeout=20)
        return json.loads(r.stdout)

    def status_text(self):
        return subprocess.run([BIN, "status", "--state", self.state], capture_output=True, text=True,
                              timeout=20).stdout

    def request(self, method, path, body=None, headers=None, host=None):
        """(status, headers dict lower-cased, body bytes)."""
        c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=15)
        h = {"Host": host or f"127.0.0.1:{self.port}"}
        if body is not None and not isinstance(body, (bytes, str)):
            body = json.dumps(body)
            h["Content-Type"] = "application/json"
        h.update(headers or {})
        try:
            c.request(method, path, body=body, headers=h)
            r = c.getresponse()
            return r.status, {k.lower(): v for k, v in r.getheaders()}, r.read()
        finally:
            c.close()

    def get_json(self, path, **kw):
        status, _, body = self.request("GET", path, **kw)
        return status, json.loads(body)

    def post(self, path, body, **kw):
        status, _, got = self.request("POST", path, body=body, **kw)
        return status, json.loads(got) if got else None


def merge_patch(target, patch):
    """RFC 7386 section 2: the patch applied to the target (a new value; the target is not changed)."""
    if not isinstance(patch, dict):
        return patch
    out = dict(target) if isinstance(target, dict) else {}
    for k, v in patch.items():
        if v is None:
            out.pop(k, None)
        else:
            out[k] = merge_patch(out.get(k), v)
    return out


def as_list(v):
    """A list sent as an object of its entries by position, as a list again."""
    return [v[k] for k in sorted(v, key=int)] if isinstance(v, dict) else v


def as_drawn(doc):
    """The live state with its tracking list, radios and followed satellites, sent as objects by
    position, as lists again."""
    st = doc.get("status")
    if not isinstance(st, dict):
        return doc
    out = {**st, **{k: as_list(st[k]) for k in ("tracking_list", "radios") if k in st}}
    if isinstance(st.get("tracking"), dict) and "satellites" in st["tracking"]:
        out["tracking"] = {**st["tracking"], "satellites": as_list(st["tracking"].get("satellites"))}
    return {**doc, "status": out}


class WebSocket:
    """A client of /api/v1/live: text frames only, masked as RFC 6455 asks."""

    def __init__(self, port, origin=None, path="/api/v1/live", headers=None, tls=None):
        """tls: an ssl.SSLContext to speak through (a TLS proxy in front, web_tls.py)."""
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=15)
        if tls is not None:
            self.sock = tls.wrap_socket(self.sock, server_hostname="127.0.0.1")
        key = base64.b64encode(os.urandom(16)).decode()
        lines = [f"GET {path} HTTP/1.1", f"Host: 127.0.0.1:{port}", "Upgrade: websocket", "Connection: Upgrade",
                 f"Sec-WebSocket-Key: {key}", "Sec-WebSocket-Version: 13"]
        if origin:
            lines.append(f"Origin: {origin}")
        lines += [f"{k}: {v}" for k, v in (headers or {}).items()]
        self.sock.sendall(("\r\n".join(lines) + "\r\n\r\n").encode())
        self.buf = b""
        while b"\r\n\r\n" not in self.buf:
            chunk = self.sock.recv(4096)
            if not chunk:
                break
            self.buf += chunk
        head, _, self.buf = self.buf.partition(b"\r\n\r\n")
        self.status = int(head.split(b" ")[1]) if head else 0
        self.head = head.decode(errors="replace")

    def _read(self, n):
        while len(self.buf) < n:
            chunk = self.sock.recv(65536)
            if not chunk:
                raise ConnectionError("closed")
            self.buf += chunk
        out, self.buf = self.buf[:n], self.buf[n:]
        return out

    def message(self):
        """The next text message (its fragments joined), as JSON."""
        return json.loads(self.raw())

    def message_size(self):
        """The next message's bytes on the wire (its frames' headers and payloads)."""
        return len(self.raw(count=True)[1])

    def send(self, text):
        """One masked text frame (a client's frames are masked, RFC 6455 section 5.3)."""
        data = text.encode()
        head = bytes([0x81])
        n = len(data)
        head += bytes([0x80 | n]) if n < 126 else bytes([0x80 | 126]) + struct.pack(">H", n)
        mask = os.urandom(4)
        self.sock.sendall(head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data)))

    def raw(self, count=False):
        """The next text message's payload; with count, (payload, every byte read for it)."""
        parts, wire = [], b""
        while True:
            head = self._read(2)
            b0, b1 = head
            n = b1 & 0x7F
            if n == 126:
                ext = self._read(2)
                n = struct.unpack(">H", ext)[0]
                head += ext
            elif n == 127:
                ext = self._read(8)
                n = struct.unpack(">Q", ext)[0]
                head += ext
            payload = self._read(n)
            wire += head + payload
            op = b0 & 0x0F
            if op == 8:
                raise ConnectionError("closed by the server")
            if op in (0, 1):
                parts.append(payload)
                if b0 & 0x80:
                    return (b"".join(parts), wire) if count else b"".join(parts)

    def state(self, within=10):
        """The next live state, whole: a state message, or the last one with the next patch applied
        (the live feed sends the state whole once, then merge patches; the tracking list, sent by
        position, made a list again as the page's live.js does)."""
        deadline = time.time() + within
        while time.time() < deadline:
            m = self.message()
            if m.get("type") == "state":
                self.doc = m
            elif m.get("type") == "patch" and getattr(self, "doc", None) is not None:
                self.doc = merge_patch(self.doc, m["patch"])
            else:
                continue
            return as_drawn(self.doc)
        check(False, "a state message within %d s" % within)

    def close(self):
        self.sock.close()
