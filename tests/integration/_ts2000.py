"""A Kenwood TS-2000 on a pseudo-terminal, written from what its sources say (docs/radio.md,
"TS-2000 SA"): a helper of the integration tests, not a test.

ASCII commands ending in ';'. FA / FB set VFO A / B in 11 digits of Hz (in satellite mode A is
Main, the downlink, and B is Sub, the uplink); FA; / FB; answer them. SA; answers SA, the digits
P1..P7 and an 8-character name; SA<7 digits>; sets them (refused with ?; while VFO A is on a memory,
FR2). FR; answers the VFO select and is refused in satellite mode. MD, TN and TO go to the CTRL band
(P4: Main or Sub) in satellite mode; TO; answers the encoder. turn() moves a VFO as the knob would
(the TS-2000 says nothing unless asked: Auto Information is off).
"""
import time

from _ptyradio import PtyRadio


class TS2000(PtyRadio):
    def __init__(self, path, sa="0010000", refuse_tone=False):
        self.sa = sa
        self.fr = "0"
        self.refuse_tone = refuse_tone
        self.hz = {"A": 14_074_000, "B": 14_074_000}
        self.mode = {}            # band ("M"/"S" in satellite mode, "0"/"1" outside) -> MD digit
        self.tone = {}            # band -> TN number
        self.encoder = {}         # band -> TO on
        self.commands = []        # (time, command) of every command the controller sent
        self.text = ""
        super().__init__(path)

    def ctrl(self):
        if self.sa[0] == "1":
            return "S" if self.sa[3] == "1" else "M"
        return self.fr

    def turn(self, vfo, delta):
        with self.lock:
            self.hz[vfo] += delta

    def handle(self, c):
        self.commands.append((time.time(), c))
        if len(c) == 14 and c[0] == "F" and c[1] in "AB" and c[2:13].isdigit():
            self.hz[c[1]] = int(c[2:13])
        elif c in ("FA;", "FB;"):
            self.write(f"F{c[1]}{self.hz[c[1]]:011d};".encode())
        elif c == "SA;":
            self.write(f"SA{self.sa}ISS     ;".encode())
        elif len(c) == 10 and c.startswith("SA") and c[2:9].isdigit():
            if self.fr == "2":
                self.write(b"?;")
            else:
                self.sa = c[2:9]
        elif c == "FR;":
            self.write(b"?;" if self.sa[0] == "1" else f"FR{self.fr};".encode())
        elif len(c) == 4 and c.startswith("FR"):
            self.fr = c[2]
        elif len(c) == 4 and c.startswith("MD"):
            self.mode[self.ctrl()] = c[2]
        elif len(c) == 5 and c.startswith("TN"):
            if self.refuse_tone:
                self.write(b"?;")
            else:
                self.tone[self.ctrl()] = int(c[2:4])
        elif c in ("TO0;", "TO1;"):
            self.encoder[self.ctrl()] = c == "TO1;"
        elif c == "TO;":
            self.write(b"TO1;" if self.encoder.get(self.ctrl()) else b"TO0;")
        else:
            self.write(b"?;")

    def feed(self, chunk):
        self.text += chunk.decode("ascii", "replace")
        while ";" in self.text:
            c, self.text = self.text.split(";", 1)
            self.handle(c + ";")

    def get(self, vfo):
        with self.lock:
            return self.hz[vfo]

    def sent(self, since=0.0):
        with self.lock:
            return [c for t, c in self.commands if t >= since]
