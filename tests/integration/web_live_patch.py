"""The live WebSocket sends what changed (issue 49): after the whole document ({"type":"state",
"seq":N}), numbered JSON merge patches (RFC 7386) of what changed; the patches applied in order
(RFC 7386 section 2, _web.py's, not trakbox's) give exactly the document the service sends whole
to a viewer that asks ({"type":"full"}); during an ISS pass a viewer receives at most 1.5 kB a
second, where the whole document every second weighs several times that (both printed)."""
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import SOURCE, check, poll, run_test  # noqa: E402
from _web import WebSocket, WebStation, merge_patch  # noqa: E402

# During the ISS pass of 13:45-13:55 UTC over the factory station (web_browser.py's clock).
CLOCK = "2026-05-21T13:47:00Z"
WINDOW = 8.0  # seconds of steady state measured


def without_seq(doc):
    return {k: v for k, v in doc.items() if k != "seq"}


def main():
    # The element refresh from the shipped file, not the network.
    station = WebStation("--elements-url", "file://" + os.path.join(os.path.abspath(SOURCE), "data", "amateur.tle"),
                         clock=CLOCK)
    try:
        # ISS is known once the first refresh has read the shipped file.
        poll("ISS tracked", lambda: station.post("/api/v1/track", {"satellite": "ISS"})[0] == 200, 15, every=0.5)
        status, reply = station.post("/api/v1/rotor", {"control": True})
        check(status == 200, f"rotor control on: {status} {reply}")
        ws = WebSocket(station.port)
        check(ws.status == 101, f"the WebSocket upgrade: {ws.head}")
        ws.state()
        first = ws.doc  # as sent: the tracking list by position
        check(isinstance(first.get("seq"), int), f"the whole document has a number: {list(first)}")
        full_bytes = len(json.dumps(first, separators=(",", ":")))
        doc, seq = without_seq(first), first["seq"]
        check(doc["status"]["tracking"]["followed"] == "ISS", f"the station tracks ISS: {doc['status']['tracking']}")
        check(doc["sky"]["pass"] and doc["sky"]["satellite"], f"ISS is up: {doc['sky'].get('satellite')}")

        # Steady state: every message a patch (or an event), numbered one after the other.
        patches, wire, t0 = 0, 0, time.monotonic()
        while time.monotonic() - t0 < WINDOW:
            raw, frame = ws.raw(count=True)
            m = json.loads(raw)
            if m.get("type") == "event":
                continue
            check(m.get("type") == "patch", f"after the whole document, patches: {m.get('type')}")
            check(m.get("seq") == seq + 1, f"patch {m.get('seq')} follows {seq}")
            seq = m["seq"]
            doc = merge_patch(doc, m["patch"])
            patches += 1
            wire += len(frame)
        elapsed = time.monotonic() - t0
        check(patches >= WINDOW - 2, f"a patch about every second: {patches} in {elapsed:.1f} s")
        per_second = wire / elapsed
        print(f"a viewer receives {per_second:.0f} bytes a second ({patches} patches in {elapsed:.1f} s); "
              f"the whole document, which went every second before, is {full_bytes} bytes "
              f"({per_second / full_bytes:.2f} of it)")
        check(per_second <= 1500, f"at most 1.5 kB a second at steady state during a pass: {per_second:.0f}")

        # A viewer that missed one asks for the whole document: it is the one the patches made.
        ws.send('{"type":"full"}')
        while True:
            m = ws.message()
            if m.get("type") == "patch":
                check(m["seq"] == seq + 1, f"patch {m['seq']} follows {seq}")
                seq, doc = m["seq"], merge_patch(doc, m["patch"])
            elif m.get("type") == "state":
                break
        check(m["seq"] == seq, f"the whole document is the last one sent: {m['seq']} after patch {seq}")
        check(without_seq(m) == doc, "the patches applied in order give the whole document")
        # Nonsense from a viewer is ignored: the feed goes on.
        ws.send('{"type":')
        ws.send("[" * 300)
        m = ws.message()
        while m.get("type") == "event":
            m = ws.message()
        check(m.get("type") == "patch" and m["seq"] == seq + 1, f"the feed goes on: {m.get('type')} {m.get('seq')}")
        ws.close()
        check(station.alive(), "the service runs on")
    finally:
        station.stop()


if __name__ == "__main__":
    run_test(main)
