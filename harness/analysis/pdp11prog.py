"""Small hand-assembled PDP-11 programs (device tests, benchmark).

Each instruction is written twice: its machine words (hand-assembled) and its
text exactly as SIMH's `EXAMINE -M` disassembles them; check_listing() runs
SIMH's disassembler over a program and says where they differ
(tests/devices/test_assembly.py does so for every test program, the benchmark
before it measures), so a wrong word cannot pass unnoticed.

Conventions: programs start at 1000; results go to 2000 upwards; interrupt
handlers live at 1400 and up; the stack starts at 700; every vector not given
a handler points to a HALT at 600, so a stray interrupt or trap stops the run.
"""
from harness.machine import simh

ORIGIN = 0o1000
RESULTS = 0o2000
STRAY_HALT = 0o600
STACK = 0o700


class Program:
    def __init__(self, origin=ORIGIN):
        self.origin = origin
        self.words = []
        self.listing = []          # (address, SIMH disassembly)
        self.vectors = {}          # vector -> handler address
        self.data = {}             # address -> word

    @property
    def here(self):
        return self.origin + 2 * len(self.words)

    def op(self, text, *words):
        self.listing.append((self.here, text))
        self.words.extend(words)
        return self

    def org(self, address):
        """Continue assembling at `address` (a new segment)."""
        seg = Program(address)
        seg.vectors, seg.data = self.vectors, self.data
        self._segments = getattr(self, "_segments", []) + [seg]
        return seg

    # common instructions (absolute addressing, as the 1983 code uses)
    def mov_imm(self, value, addr):
        return self.op(f"MOV #{value:o},@#{addr:o}", 0o012737, value, addr)

    def movb_imm(self, value, addr):
        return self.op(f"MOVB #{value:o},@#{addr:o}", 0o112737, value, addr)

    def mov_abs(self, src, dst):
        return self.op(f"MOV @#{src:o},@#{dst:o}", 0o013737, src, dst)

    def clr_abs(self, addr):
        return self.op(f"CLR @#{addr:o}", 0o005037, addr)

    def inc_abs(self, addr):
        return self.op(f"INC @#{addr:o}", 0o005237, addr)

    def mov_imm_reg(self, value, reg):
        return self.op(f"MOV #{value:o},R{reg}", 0o012700 | reg, value)

    def sob_self(self, reg):
        """SOB Rn back to itself: a delay of the register's count, one instruction each."""
        return self.op(f"SOB R{reg},{self.here:o}", 0o077001 | (reg << 6))

    def delay(self, instructions):
        """Burn about `instructions` instructions with R0/R1 (nested SOB loops)."""
        outer = max(1, instructions // 60000)
        self.mov_imm_reg(outer, 1)
        top = self.here
        self.mov_imm_reg(60000, 0)
        self.sob_self(0)
        off = (self.here + 2 - top) // 2
        return self.op(f"SOB R1,{top:o}", 0o077100 | off)

    def reset(self):
        return self.op("RESET", 0o000005)

    def halt(self):
        return self.op("HALT", 0o000000)

    def loop_forever(self):
        return self.op(f"BR {self.here:o}", 0o000777)

    def rti(self):
        return self.op("RTI", 0o000002)

    def handler(self, vector, address, body):
        """Install an interrupt handler at `address` for `vector`: body(seg) then RTI."""
        seg = self.org(address)
        body(seg)
        seg.rti()
        self.vectors[vector] = address
        return self

    def segments(self):
        return [self] + getattr(self, "_segments", [])

    def all_listing(self):
        return [line for seg in self.segments() for line in seg.listing]

    def script(self, psw=0, start=True):
        """SIMH lines: vectors, program, stack, PSW, and `go` unless start=False."""
        lines = [simh.deposit(STRAY_HALT, [0])]
        for v in range(4, 0o400, 4):
            handler = self.vectors.get(v, STRAY_HALT)
            lines.append(simh.deposit(v, [handler, 0o340]))
        for seg in self.segments():
            lines.append(simh.deposit(seg.origin, seg.words))
        for addr, word in self.data.items():
            lines.append(simh.deposit(addr, [word]))
        lines.append(f"deposit sp {STACK:o}\ndeposit psw {psw:o}\ndeposit pc {self.origin:o}\n")
        if start:
            lines.append(f"go {self.origin:o}\n")
        return "".join(lines)


def check_listing(prog, simulator=simh.PDP11):
    """Mismatches between a program's texts and SIMH's disassembly of its words:
    a list of (address, written, disassembled); empty when all agree."""
    listing = prog.all_listing()
    out = simh.run(prog.script(start=False) + "".join(f"examine -m {a:o}\n" for a, _ in listing),
                   simulator=simulator)
    got = {}
    for line in out.splitlines():
        addr, sep, text = line.partition(":\t")
        if sep and addr.isdigit():
            got[int(addr, 8)] = text.strip()
    return [(a, t, got.get(a)) for a, t in listing if got.get(a) != t]
