"""POST /api/v1/radio's tuning (issue 47) on the simulated station: RS-44's passband moved +5 kHz
moves the downlink dial up and the uplink dial down by 5 kHz (an inverting transponder: up =
145.995 MHz - (down - 435.610 MHz), the shipped record); an FM satellite's RX and TX offsets move
each dial, are kept in the state and are in force again after a restart; the tone is set; every
malformed or refused body says what was wrong and changes nothing."""
import os
import socket
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import check, free_port, poll, read_log, run_test  # noqa: E402
from _web import WebStation  # noqa: E402

RS44_CLOCK = "2026-05-21T10:57:00Z"   # a minute before RS-44's culmination over the factory station
ISS_CLOCK = "2026-05-21T13:47:00Z"    # during the ISS pass of 13:45-13:55


def tuning(w, sat):
    def got():
        t = w.status()["radios"][0].get("tuning")
        return t if t and t["satellite"] == sat and t["downlink_dial_hz"] else None
    return poll(f"the radio tuned for {sat}", got, 10)


def rs44_passband():
    w = WebStation(clock=RS44_CLOCK)
    try:
        status, r = w.post("/api/v1/track", {"satellite": "RS-44"})
        check(status == 200, f"track RS-44: {status} {r}")
        t0 = tuning(w, "RS-44")
        check(t0["passband"] == {"downlink": [435610000, 435670000], "uplink": [145935000, 145995000],
                                 "inverting": True}, f"RS-44's passbands: {t0['passband']}")
        check(t0["downlink_spot_hz"] == 435640000 and t0["uplink_spot_hz"] == 145965000, f"the record's spot: {t0}")
        status, r = w.post("/api/v1/radio", {"spot_hz": t0["downlink_spot_hz"] + 5000})
        check(status == 200 and r["note"] == "spot 435645000 Hz down, 145960000 Hz up", f"+5 kHz: {status} {r}")
        t1 = poll("the dials moved", lambda: (lambda t: t if t["downlink_spot_hz"] == 435645000 else None)(
            tuning(w, "RS-44")), 10)
        # The dials: +5 kHz down, -5 kHz up, within the Doppler change of the seconds between readings.
        dd = t1["downlink_dial_hz"] - t0["downlink_dial_hz"]
        du = t1["uplink_dial_hz"] - t0["uplink_dial_hz"]
        check(abs(dd - 5000) < 500 and abs(du + 5000) < 200, f"dial changes {dd:+} Hz down, {du:+} Hz up")
        print(f"RS-44 +5 kHz: downlink dial {dd:+} Hz, uplink dial {du:+} Hz")
        for body, want, sentence in [
            ({"spot_hz": 435700000}, 409, "spot 435700000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz"),
            ({"spot_hz": "435.645"}, 400, None),
            ({"spot_hz": 435645000.5}, 400, None),
            ({"spot_hz": 435645000, "tone_hz": 67}, 400, None),
            ({"rx_offset_hz": 100, "doppler": True}, 400, None),
        ]:
            status, e = w.post("/api/v1/radio", body)
            check(status == want and isinstance(e.get("error"), str) and (sentence is None or e["error"] == sentence),
                  f"POST /api/v1/radio {body}: {status} {e}")
        check(tuning(w, "RS-44")["downlink_spot_hz"] == 435645000, "the refused bodies changed nothing")
        # Every change asked from the page is in the log at info, with the client and what came of it.
        log = read_log(w.state)
        check('web: /api/v1/radio {"spot_hz":435645000} from 127.0.0.1: 200 spot 435645000 Hz down' in log and
              "web: /api/v1/radio {\"spot_hz\":435700000} from 127.0.0.1: 409 spot 435700000 Hz is outside" in log,
              "the page's actions logged: " + "\n".join(l for l in log.splitlines() if "web: /api" in l))
    finally:
        w.stop()


def spot_survives_a_hold():
    """Issue 60, item 3: the operator's spot outlives a rigctld client's hold (one `F`, then the
    client's disconnect hands the radio back): tracking resumes on the chosen spot, not the record's."""
    rig = free_port()
    w = WebStation("--rigctld-port", str(rig), clock=RS44_CLOCK)
    try:
        w.post("/api/v1/track", {"satellite": "RS-44"})
        tuning(w, "RS-44")
        status, r = w.post("/api/v1/radio", {"spot_hz": 435650000})
        check(status == 200, f"spot 435.650: {status} {r}")
        poll("the spot at 435.650", lambda: tuning(w, "RS-44")["downlink_spot_hz"] == 435650000, 10)
        with socket.create_connection(("127.0.0.1", rig), timeout=10) as c:
            c.sendall(b"F 435658000\n")
            answer = c.recv(200).decode()
            check(answer.startswith("RPRT 0"), f"rigctld F: {answer!r}")
            poll("the radio held by rigctld", lambda: w.status()["control"]["radio"]["kind"] == "rigctld", 10)
        poll("the radio back to tracking", lambda: w.status()["control"]["radio"]["kind"] == "tracking", 10)
        t = poll("the spot kept", lambda: (lambda t: t if t["downlink_dial_hz"] and abs(
            t["downlink_dial_hz"] - 435650000) < 20000 else None)(tuning(w, "RS-44")), 10)
        check(t["downlink_spot_hz"] == 435650000 and t["uplink_spot_hz"] == 145955000,
              f"after the hold, the operator's spot (435.650 down, 145.955 up), not the record's: {t}")
        print(f"after a rigctld hold: spot {t['downlink_spot_hz']} down, {t['uplink_spot_hz']} up")
    finally:
        w.stop()


def iss_offsets():
    w = WebStation(clock=ISS_CLOCK)
    try:
        w.post("/api/v1/track", {"satellite": "ISS"})
        tuning(w, "ISS")
        status, r = w.post("/api/v1/radio", {"rx_offset_hz": 500, "tx_offset_hz": -300})
        check(status == 200 and r["note"] == "RX offset +500 Hz, TX offset -300 Hz (ISS FM)", f"offsets: {status} {r}")
        status, e = w.post("/api/v1/radio", {"rx_offset_hz": 250000})
        check(status == 409 and e["error"] == "RX offset 250000 Hz out of range: expected -100000 to 100000", f"{e}")
        status, e = w.post("/api/v1/radio", {"tone_hz": 67.05})
        check(status == 409 and e["error"].startswith("tone 67.05 Hz: expected a CTCSS tone"), f"{e}")
        status, r = w.post("/api/v1/radio", {"tone_hz": 88.5})
        check(status == 200 and r["note"] == "ISS tone 88.5 Hz", f"tone: {status} {r}")
        t = tuning(w, "ISS")
        check(t["rx_offset_hz"] == 500 and t["tx_offset_hz"] == -300 and t["tone_hz"] == 88.5, f"tuning: {t}")
        # A restart: the offsets kept for "ISS FM" and the tone are in force again.
        w.stop()
        w.start()
        t = tuning(w, "ISS")
        check(t["rx_offset_hz"] == 500 and t["tx_offset_hz"] == -300 and t["tone_hz"] == 88.5,
              f"after the restart: {t}")
        status, r = w.post("/api/v1/radio", {"rx_offset_hz": 0, "tx_offset_hz": 0})
        check(status == 200, f"reset: {r}")
        t = poll("the reset", lambda: (lambda t: t if t["rx_offset_hz"] == 0 and t["tx_offset_hz"] == 0 else None)(
            tuning(w, "ISS")), 10)
    finally:
        w.stop()


def main():
    rs44_passband()
    spot_survives_a_hold()
    iss_offsets()


run_test(main)
