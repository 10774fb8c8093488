"""Rotator controllers on the far end of a pseudo-terminal, for connect_doc.py: a Yaesu GS-232B
(Hamlib 603: `C2` answered `AZ=aaa  EL=eee`, `Waaa eee` moves there, `S` stops, each line ending CR)
and a SPID Rot2Prog (Hamlib 901: 13-byte packets `W` + four azimuth digits + resolution + four
elevation digits + resolution + command + 0x20; 0x2F sets, any other (Hamlib's status 0x1F, stop 0x0F) is answered; the 12-byte
answer carries the angles plus 360 as digits in units of the resolution). The antenna moves to the
commanded angles at once; the angles commanded are kept (`commands`). Not a test."""
from _ptyradio import PtyRadio


class GS232B(PtyRadio):
    def __init__(self, path, az=0, el=0):
        self.az, self.el = az, el
        self.commands = []
        self.buf = b""
        super().__init__(path)

    def feed(self, chunk):
        self.buf += chunk
        while b"\r" in self.buf:
            line, self.buf = self.buf.split(b"\r", 1)
            cmd = line.strip().decode("ascii", "replace")
            self.commands.append(cmd)
            if cmd == "C2":
                self.write(f"AZ={round(self.az) % 1000:03d}  EL={round(self.el):03d}\r\n".encode())
            elif cmd.startswith("W") and len(cmd.split()) == 2:
                az, el = cmd[1:].split()
                self.az, self.el = float(az), float(el)
                self.write(b"\r\n")
            elif cmd == "S":
                self.write(b"\r\n")
            else:
                self.write(b"?>\r\n")


class Rot2Prog(PtyRadio):
    RESOLUTION = 10   # pulses a degree: 0.1 degree

    def __init__(self, path, az=0, el=0):
        self.az, self.el = az, el
        self.commands = []
        self.buf = b""
        super().__init__(path)

    def answer(self):
        def digits(deg):
            n = round((deg + 360) * self.RESOLUTION)
            return bytes([n // 1000 % 10, n // 100 % 10, n // 10 % 10, n % 10])
        # The answer: W, az+360 as hundreds/tens/units/tenths, PH, el likewise, PV, 0x20 (Hamlib's rot2prog).
        self.write(b"W" + digits(self.az) + bytes([self.RESOLUTION]) + digits(self.el) + bytes([self.RESOLUTION]) + b"\x20")

    def feed(self, chunk):
        self.buf += chunk
        while len(self.buf) >= 13:
            i = self.buf.find(b"W")
            if i < 0:
                self.buf = b""
                return
            packet, self.buf = self.buf[i:i + 13], self.buf[i + 13:]
            if len(packet) < 13:
                self.buf = packet
                return
            cmd = packet[11]
            self.commands.append(cmd)
            if cmd == 0x2F:
                az = int(packet[1:5].decode()) / packet[5] - 360
                el = int(packet[6:10].decode()) / packet[10] - 360
                self.az, self.el = az, el
            else:
                self.answer()
