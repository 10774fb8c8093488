"""An Icom IC-9700 on a pseudo-terminal, written from Icom's IC-9700 CI-V reference guide and
docs/radio.md: a helper of the integration tests, not a test. With sat_answer="data" it answers
16 5A as Hamlib's simulators/simic9700.c does (a data frame with the value, not FB); power(False)
switches it off (no echo, no answer) until power(True).

Frames FE FE <to> <from> <cmd> [data] FD; the radio is at A2h, the controller E0h. It answers
FB (OK) / FA (NG); 07 D0 / D1 select Main / Sub; 05 / 06 set the selected band's frequency / mode;
03 answers the selected band's frequency (5 BCD bytes, least significant first), 1C 03 the transmit
frequency (Sub in satellite mode); 16 5A 01 / 00
satellite mode; 1B 00 <3 BCD> the tone, 16 42 01 / 00 TONE; 04 the mode, 25 / 26 00|01 the selected
or unselected VFO's frequency / mode and 0F split (off), as Hamlib asks newer rigs. With echo (a CI-V bus) each frame comes
back first; without (USB, Echo Back OFF) only the answer. turn() moves a dial as the knob would and
sends the transceive frame FE FE 00 A2 00 <freq> FD, which does not say which band moved.
"""
import time

from _ptyradio import PtyRadio

ADDR, CTRL = 0xA2, 0xE0


def bcd_le(hz, n=5):
    out = []
    for _ in range(n):
        lo = hz % 10
        hz //= 10
        hi = hz % 10
        hz //= 10
        out.append(hi << 4 | lo)
    return bytes(out)


def width(hz):
    """CI-V frequency bytes: 6 on the IC-905's 10 GHz band (12 digits), 5 below."""
    return 6 if hz >= 10_000_000_000 else 5


def from_bcd_le(b):
    v = 0
    for x in reversed(b):
        v = v * 100 + (x >> 4) * 10 + (x & 0x0F)
    return v


class IC9700(PtyRadio):
    def __init__(self, path, echo=False, refuse_tone=False, sat_answer="fb", addr=None, xvtr=True):
        self.echo = echo
        # Another CI-V radio with the same commands (IC-905 ACh, IC-7300 94h, IC-7100 88h,
        # IC-706MKIIG 58h); xvtr=False: an IC-905 without its transverter refuses (FA) 10 GHz.
        self.own_addr = addr
        self.xvtr = xvtr
        self.refuse_tone = refuse_tone
        # 16 5A answered FB, or as Hamlib's simic9700 does: "data" (the value echoed, not taken)
        self.sat_answer = sat_answer
        self.off = False          # switched off: no echo, no answer
        self.hz = {"main": 145_000_000, "sub": 435_000_000}
        self.mode = {"main": None, "sub": None}
        self.selected = "main"
        self.satellite = False
        self.tone = None          # tenths of Hz when TONE is on
        self.frames = []          # (time, bytes) of every frame the controller sent
        self.buf = b""
        super().__init__(path)

    @property
    def addr(self):
        """The given address, else the module's ADDR as it is at the time (connect_doc.py sets it)."""
        return ADDR if self.own_addr is None else self.own_addr

    def answer(self, ok):
        self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0xFB if ok else 0xFA, 0xFD]))

    def turn(self, band, delta):
        with self.lock:
            self.hz[band] += delta
            self.write(bytes([0xFE, 0xFE, 0x00, self.addr, 0x00]) + bcd_le(self.hz[band], width(self.hz[band])) + b"\xfd")

    def power(self, on):
        """Switched off, then on again: a radio switched on comes up out of satellite mode."""
        with self.lock:
            if on and self.off:
                self.satellite = False
            self.off = not on

    def handle(self, f):
        self.frames.append((time.time(), f))
        if self.off:
            return
        if self.echo:
            self.write(f)
        if len(f) < 6 or f[2] != self.addr:
            return
        cmd, d = f[4], f[5:-1]
        band = self.selected
        if cmd == 0x05 and len(d) in (5, 6):
            hz = from_bcd_le(d)
            ok = len(d) == width(hz) and (self.xvtr or hz < 10_000_000_000)
            if ok:
                self.hz[band] = hz
            self.answer(ok)
        elif cmd == 0x06 and d:
            self.mode[band] = d[0]
            self.answer(True)
        elif cmd == 0x07 and len(d) == 1 and d[0] in (0xD0, 0xD1):
            self.selected = "main" if d[0] == 0xD0 else "sub"
            self.answer(True)
        elif cmd == 0x03 and not d:
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x03]) + bcd_le(self.hz[band], width(self.hz[band])) + b"\xfd")
        elif cmd == 0x04 and not d:   # the selected band's mode and filter (Hamlib asks it before a set)
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x04, self.mode[band] or 0x01, 0x01, 0xFD]))
        elif cmd in (0x25, 0x26) and d and d[0] in (0, 1):   # newer rigs' selected (00) / unselected VFO
            other = band if d[0] == 0 else ("sub" if band == "main" else "main")
            if len(d) == 1:
                value = bcd_le(self.hz[other], width(self.hz[other])) if cmd == 0x25 else bytes([self.mode[other] or 1, 0, 1])
                self.write(bytes([0xFE, 0xFE, CTRL, self.addr, cmd, d[0]]) + value + b"\xfd")
            else:
                if cmd == 0x25:
                    self.hz[other] = from_bcd_le(d[1:])
                else:
                    self.mode[other] = d[1]
                self.answer(True)
        elif cmd == 0x1A and d == b"\x06":   # data mode: off
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x1A, 0x06, 0x00, 0x00, 0xFD]))
        elif cmd == 0x0F and not d:   # split: off
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x0F, 0x00, 0xFD]))
        elif cmd == 0x1C and d == b"\x03":   # the transmit frequency: Sub in satellite mode
            tx = "sub" if self.satellite else band
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x1C, 0x03]) + bcd_le(self.hz[tx], width(self.hz[tx])) + b"\xfd")
        elif cmd == 0x16 and len(d) == 2 and d[0] == 0x5A and self.sat_answer == "data":
            self.write(bytes([0xFE, 0xFE, CTRL, self.addr, 0x16, 0x5A, 0x00, 0xFD]))
        elif cmd == 0x16 and len(d) == 2 and d[0] == 0x5A:
            self.satellite = d[1] == 1
            self.answer(True)
        elif cmd == 0x1B and len(d) == 4 and d[0] == 0x00:
            if not self.refuse_tone:
                self.pending_tone = int(d[1:].hex())
            self.answer(not self.refuse_tone)
        elif cmd == 0x16 and len(d) == 2 and d[0] == 0x42:
            if not self.refuse_tone:
                self.tone = getattr(self, "pending_tone", None) if d[1] == 1 else None
            self.answer(not self.refuse_tone)
        else:
            self.answer(False)

    def feed(self, chunk):
        self.buf += chunk
        while True:
            start = self.buf.find(b"\xfe\xfe")
            if start < 0:
                self.buf = b""
                return
            end = self.buf.find(b"\xfd", start)
            if end < 0:
                self.buf = self.buf[start:]
                return
            f, self.buf = self.buf[start:end + 1], self.buf[end + 1:]
            self.handle(f)

    def get(self, band):
        with self.lock:
            return self.hz[band]

    def count(self, cmd, since=0.0):
        with self.lock:
            return sum(1 for t, f in self.frames if t >= since and len(f) > 4 and f[3] == CTRL and f[4] == cmd)
