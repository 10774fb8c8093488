"""A Yaesu FT-847 on a pseudo-terminal, written from Hamlib's ft847.c and the operating manual's CAT
table (docs/radio.md), or with ft817=True an FT-817/818 (Hamlib's ft817.c: its one VFO, no CAT on or
off, the tone as 4 BCD digits twice): a helper of the integration tests, not a test.

Five-byte commands, parameters first, the opcode last; nothing is acknowledged. 00 CAT on, 80 CAT
off, 4E / 8E satellite mode on / off. The opcode's high nibble is the VFO (0 main, 1 SAT RX, 2 SAT
TX), its low nibble the command: 1 frequency (4 BCD bytes of 10 Hz, most significant first), 7 mode
(LSB 00, USB 01, CW 02, FM 08), 3 read (answers the 4 BCD bytes and the mode), B the CTCSS tone
(the radio's code), A the encoder (4A on, 8A off). turn() moves a VFO as the knob would (the FT-847
says nothing unless asked).
"""
import time

from _ptyradio import PtyRadio

VFO = {0x00: "main", 0x10: "rx", 0x20: "tx"}


def bcd_be(value, n=4):
    digits = f"{value:0{2 * n}d}"
    return bytes(int(digits[2 * i]) << 4 | int(digits[2 * i + 1]) for i in range(n))


def from_bcd_be(b):
    return int("".join(f"{x >> 4}{x & 0x0F}" for x in b))


class FT847(PtyRadio):
    def __init__(self, path, ft817=False):
        self.cat = ft817          # the FT-817 takes CAT commands without being switched on
        self.satellite = False
        self.hz = {"main": 145_000_000, "rx": 435_000_000, "tx": 145_900_000}
        self.mode = {}
        self.tone = {}            # VFO -> the radio's tone code
        self.encoder = {}         # VFO -> on
        self.commands = []        # (time, bytes) of every command
        self.buf = b""
        super().__init__(path)

    def turn(self, vfo, delta):
        with self.lock:
            self.hz[vfo] += delta

    def handle(self, c):
        self.commands.append((time.time(), c))
        op = c[4]
        if op in (0x00, 0x80):
            self.cat = op == 0x00
            return
        if op in (0x4E, 0x8E):
            self.satellite = op == 0x4E
            return
        if op == 0xBB and self.cat:   # the FT-817 family's EEPROM read (Hamlib asks it): two bytes, zero
            self.write(b"\x00\x00")
            return
        if op in (0xE7, 0xF7) and self.cat:   # RX / TX status: nothing received, PTT off
            self.write(b"\x00" if op == 0xE7 else b"\x80")
            return
        vfo, cmd = VFO.get(op & 0xF0), op & 0x0F
        if vfo is None or not self.cat:
            return
        if cmd == 0x01:
            self.hz[vfo] = from_bcd_be(c[:4]) * 10
        elif cmd == 0x07:
            self.mode[vfo] = c[0]
        elif cmd == 0x03:
            self.write(bcd_be(self.hz[vfo] // 10) + bytes([self.mode.get(vfo, 0x01)]))
        elif cmd == 0x0B:
            self.tone[vfo] = c[0]
        elif cmd == 0x0A:
            self.encoder[vfo] = c[0] == 0x4A


    def feed(self, chunk):
        self.buf += chunk
        while len(self.buf) >= 5:
            c, self.buf = self.buf[:5], self.buf[5:]
            self.handle(c)

    def get(self, vfo):
        with self.lock:
            return self.hz[vfo]

    def sent(self, since=0.0):
        with self.lock:
            return [c.hex(" ").upper() for t, c in self.commands if t >= since]
