"""A Yaesu FT-991A or FTX-1 on a pseudo-terminal, written from the FT-991 CAT operation reference
(and the FTX-1's, the same family): a helper of the integration tests, not a test.

ASCII commands ending in ';', nothing acknowledged; a read answers its value, a command the radio
does not know answers ?;. FA / FB with nine digits of Hz set VFO-A / VFO-B (FA; / FB; read them);
MD0x / MD1x the mode of Main / Sub (1 LSB, 2 USB, 3 CW, 4 FM); AB copies VFO-A (frequency, mode,
tone) to VFO-B; LK1 / LK0 the dial lock; CN00nnn the CTCSS tone's number, CT02 the encoder, CT00
off; ID; answers ID0670; (FT-991A) or ID0840; (FTX-1). ST (split) is recorded: trakbox must never
send it (on the FTX-1 it puts the Sub VFO in TX state and freezes its frequency, Hamlib #1972).
With md1=False (the FT-991A) MD1 is refused: its MD reaches VFO-A only.
"""
import re
import time

from _ptyradio import PtyRadio


PROBES = {"AI;": "AI0;", "VS;": "VS0;", "FT;": "FT0;", "PS;": "PS1;", "EX032;": "EX0320;"}


class Newcat(PtyRadio):
    def __init__(self, path, ident="0670", md1=False, tones=True):
        self.ident = ident
        self.md1 = md1
        self.tones = tones
        self.hz = {"a": 14_250_000, "b": 14_250_000}
        self.mode = {"a": "2", "b": "2"}
        self.lock_on = False
        self.tone = {"a": None, "b": None}     # the CN number when CT02 is on
        self.pending_tone = None
        self.commands = []                     # (time, text) of every command
        self.buf = b""
        super().__init__(path)

    def say(self, text):
        self.write(text.encode())

    def handle(self, c):
        self.commands.append((time.time(), c))
        if m := re.fullmatch(r"F([AB])(\d{9});", c):
            self.hz[m[1].lower()] = int(m[2])
        elif m := re.fullmatch(r"F([AB]);", c):
            self.say(f"F{m[1]}{self.hz[m[1].lower()]:09d};")
        elif m := re.fullmatch(r"MD([01])([0-9A-E]);", c):
            if m[1] == "1" and not self.md1:
                self.say("?;")
            else:
                self.mode["a" if m[1] == "0" else "b"] = m[2]
        elif c == "AB;":
            for k in ("hz", "mode", "tone"):
                getattr(self, k)["b"] = getattr(self, k)["a"]
        elif m := re.fullmatch(r"LK([01]);", c):
            self.lock_on = m[1] == "1"
        elif (m := re.fullmatch(r"CN00(\d{3});", c)) and self.tones:
            self.pending_tone = int(m[1])
        elif (m := re.fullmatch(r"CT0([0-4]);", c)) and self.tones:
            self.tone["a"] = self.pending_tone if m[1] == "2" else None
        elif c == "ID;":
            self.say(f"ID{self.ident};")
        elif m := re.fullmatch(r"MD([01]);", c):
            self.say(f"MD{m[1]}{self.mode['a' if m[1] == '0' else 'b']};")
        elif c in PROBES:   # what Hamlib asks at open (AI, VS, FT, PS, EX032): plain answers
            self.say(PROBES[c])
        elif re.fullmatch(r"(AI|VS|FT)\d;|EX\d{4};", c):
            pass
        else:
            self.say("?;")

    def feed(self, chunk):
        self.buf += chunk
        while b";" in self.buf:
            c, self.buf = self.buf.split(b";", 1)
            self.handle(c.decode(errors="replace") + ";")

    def turn(self, vfo, delta):
        with self.lock:
            self.hz[vfo] += delta

    def get(self, vfo):
        with self.lock:
            return self.hz[vfo]

    def sent(self, since=0.0):
        with self.lock:
            return [c for t, c in self.commands if t >= since]
