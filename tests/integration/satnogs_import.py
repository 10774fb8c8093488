"""Menu 3-5's S on the real binary (line mode on a pipe): the SatNOGS transmitter list fetched from
a loopback HTTP server is merged (answer Y: the list's values over the freq/mode file's) into the
modes: RS-44's SSB takes the list's wider passbands (an inverting linear transponder, its spot the
centre), the ISS's FM agrees with the shipped one; the state file holds them after Q. Keeping the
operator's own values (answer N) is checked in tests/unit/menus/test_menu_3_5.cpp, and every
importer in radio_import.py.
"""
import http.server
import json
import os
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Terminal, check, run_test  # noqa: E402

LIST = [
    {"description": "Mode U/V linear", "alive": True, "status": "active", "type": "Transponder",
     "uplink_low": 145925000, "uplink_high": 146005000, "downlink_low": 435600000, "downlink_high": 435680000,
     "mode": "SSB", "invert": True, "norad_cat_id": 44909},
    {"description": "FM voice", "alive": True, "status": "active", "type": "Transceiver",
     "uplink_low": 145990000, "downlink_low": 437800000, "mode": "FM", "invert": False, "norad_cat_id": 25544},
]


def main():
    body = json.dumps(LIST).encode()

    class Handler(http.server.BaseHTTPRequestHandler):
        def log_message(self, *args):
            pass

        def do_GET(self):
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    url = "http://127.0.0.1:%d/api/transmitters/?format=json" % httpd.server_address[1]
    state = tempfile.mkdtemp(prefix="trakbox-satnogs-")
    p = subprocess.Popen([BIN, "--line", "--state", state, "--clock", CLOCK, "--satrak-port", "0"],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        t = Terminal(p.stdout.fileno())
        send = lambda s: (p.stdin.write(s.encode()), p.stdin.flush())  # noqa: E731
        t.expect(r"Select \[1-8,S,M\]:")
        send("3\r")
        t.expect(r"5\. REFRESH")
        send("5\r")
        t.expect(r"S\. Frequencies from the SatNOGS DB")
        send("S\r")
        t.expect(r"file or URL")
        send(url + "\r")
        t.expect(r"Replace the records you entered yourself too")
        send("Y\r")
        m = t.expect(r"(\d+) added, (\d+) updated, (\d+) conflicts? \(yours kept\), (\d+) unchanged", timeout=20)
        check(m.groups() == ("0", "1", "0", "1"), "RS-44's passbands updated, the ISS's FM unchanged: " + m.group(0))
        check("RS-44 SSB passbands: 435.600-435.680 / 145.925-146.005 MHz from satnogs (was 435.610-435.670 / "
              "145.935-145.995 MHz, freq/mode file)" in t.transcript, "the update names the old value and its source")
        send("Q\rQ\r")
        t.expect(r"Select \[1-8,S,M\]:")
        p.stdin.close()
        p.wait(timeout=15)
        with open(os.path.join(state, "trakbox-state.json")) as f:
            db = json.load(f)["data"]["db"]["satellites"]
        radio = {s["elements"]["name"]: s["radio"] for s in db}
        print("satnogs_import: RS-44", radio["RS-44"])
        check(radio["RS-44"]["downlink_hz"] == 435640000 and radio["RS-44"]["uplink_hz"] == 145965000,
              "RS-44's spot the passband centres")
        check(radio["RS-44"]["passbands_hz"]["downlink"] == [435600000, 435680000], "RS-44's passbands the list's")
        check(radio["ISS"]["downlink_hz"] == 437800000 and radio["ISS"]["uplink_hz"] == 145990000, "ISS FM voice")
        print("satnogs_import: ok")
    finally:
        if p.poll() is None:
            p.kill()
        httpd.shutdown()


if __name__ == "__main__":
    run_test(main)
