"""The 11/23's front panel from the LAB device's R rows (pure logic).

An R row (pdp11-devices/lab/lab.c) holds, in octal: R0-R7, the PSW, the word the
FORTH's IP (R4) points at, the KW11-L's LKS, the DRV11's CSR and OUTBUF, the
AAV11-A's four DACs, then the words at the panel's addresses (BLK and >IN: the
block and the place in it being loaded). The FORTH's words are named from the
dictionary (the copy the servo watch keeps, harness/lab/servo_watch.py) and the
kernel's map: PC names the code running, IP the colon definition whose thread
runs, (IP) the word it calls next.
"""
import bisect
from collections import deque

from harness.lab.dictionary import headers
from harness.machine.kernel_layout import LENGTH, SMUDGE, code_field
from harness.machine.plant_rows import AXES

# the kernel's register map (forth/README.md, "Registers and threading")
ROLES = ("R0", "T", "W", "R3", "IP", "S (data stack)", "RP = SP", "PC")
PANEL_WORDS = ("BLK", ">IN")         # kernel variables the row carries, in this order
BLOCK_LINE = 64                      # characters a block line


def decode_psw(psw):
    """The PSW's fields: current mode, priority (the servo runs at 6 inside the
    clock's interrupt), the T bit and the condition codes."""
    return {"mode": "kernel" if psw >> 14 == 0 else "user" if psw >> 14 == 3 else "?",
            "priority": (psw >> 5) & 7, "T": (psw >> 4) & 1,
            "N": (psw >> 3) & 1, "Z": (psw >> 2) & 1, "V": (psw >> 1) & 1, "C": psw & 1}


class WordIndex:
    """Code-field address -> name, for every header of the dictionary's chains and
    every symbol of the kernel's map; which word an address lies in."""

    def __init__(self, kernel_names=None):
        self.by_address = dict(kernel_names or {})
        self._sorted = sorted(self.by_address)

    def learn(self, memory, vocabulary_body):
        """Add the headers of the vocabulary's chains, from `memory`."""
        for lfa, name, count in headers(memory, vocabulary_body):
            if not count & SMUDGE:
                self.by_address.setdefault(code_field(lfa, count & LENGTH), name)
        self._sorted = sorted(self.by_address)

    def address_of(self, name):
        """The code field of the newest word called `name` (case ignored), or None."""
        found = [a for a, n in self.by_address.items() if n.upper() == name.upper()]
        return max(found) if found else None

    def neighbours(self, name, count=3):
        """The names defined just before the newest `name` (nearest first) and just
        after it, `count` each: ([...], [...])."""
        address = self.address_of(name)
        if address is None:
            return [], []
        i = self._sorted.index(address)
        before = self._sorted[max(0, i - count):i][::-1]
        return ([self.by_address[a] for a in before],
                [self.by_address[a] for a in self._sorted[i + 1:i + 1 + count]])

    def name_at(self, address):
        return self.by_address.get(address)

    def containing(self, address):
        """The word whose code field is the nearest at or below `address`."""
        i = bisect.bisect_right(self._sorted, address) - 1
        return self.by_address[self._sorted[i]] if i >= 0 else None


def panel_numbers(fields):
    """An R row's fields -> (time, [numbers]), or None when unreadable."""
    try:
        time, numbers = float(fields[0]), [int(f, 8) for f in fields[1:]]
    except (ValueError, IndexError):
        return None
    return (time, numbers) if len(numbers) >= 17 else None


def panel(fields, index):
    """A panel for the page from an R row's fields, or None when unreadable."""
    read = panel_numbers(fields)
    if read is None:
        return None
    time, numbers = read
    regs, psw, at_ip = numbers[:8], numbers[8], numbers[9]
    lks, csr, outbuf = numbers[10:13]
    dacs, extra = numbers[13:17], numbers[17:]
    loading = dict(zip(PANEL_WORDS, extra))
    block = loading.get("BLK", 0)
    return {
        "time": time,
        "registers": [{"name": f"R{i}", "role": ROLES[i], "value": f"{v:06o}"}
                      for i, v in enumerate(regs)],
        "psw": f"{psw:06o}", "psw_fields": decode_psw(psw),
        "pc_in": index.containing(regs[7]),
        "ip_in": index.containing(regs[4] - 2),      # the thread IP runs through
        "next": index.name_at(at_ip),               # the word it calls next
        "loading": ({"block": block, "line": loading.get(">IN", 0) // BLOCK_LINE}
                    if block else None),
        "devices": [
            {"device": "KW11-L", "register": "LKS", "address": "177546", "value": f"{lks:06o}"},
            {"device": "DRV11", "register": "CSR", "address": "167770", "value": f"{csr:06o}"},
            {"device": "DRV11", "register": "OUT", "address": "167772", "value": f"{outbuf:06o}"},
        ] + [{"device": "AAV11-A", "register": f"DAC {axis}", "address": f"{0o170440 + 2 * i:o}",
              "value": f"{code:04o}"} for i, (axis, code) in enumerate(zip(AXES, dacs))],
    }


# The vectors the robot's machine uses (forth/README.md, pdp11-devices/): named on the
# panel, shown even while none is taken. Others appear once the CPU takes them.
VECTORS = {0o60: "DL11 in", 0o64: "DL11 out", 0o100: "KW11-L", 0o160: "RL11",
           0o300: "DRV11 A", 0o304: "DRV11 B"}
RATE_WINDOW_S = 1.0                  # interrupts per second over the last simulated second


def interrupt_counts(fields):
    """An I row's fields (time, then vector=count, octal vector): (time, {vector: count}),
    or None when unreadable."""
    try:
        counts = {int(v, 8): int(n) for v, n in (f.split("=") for f in fields[1:] if f)}
        return float(fields[0]), counts
    except (ValueError, IndexError):
        return None


class InterruptRates:
    """Interrupts per simulated second per vector, from the device's running counts
    (pdp11-devices/simh/interrupt_count.c): the counts' growth since the newest
    sample at least RATE_WINDOW_S simulated seconds old (or the oldest kept)."""

    def __init__(self):
        self.samples = deque()

    def add(self, time, counts):
        """A sample: the counts at simulated `time`."""
        if self.samples and time < self.samples[-1][0]:
            self.samples.clear()             # a new machine (or a reset): start again
        self.samples.append((time, counts))
        while len(self.samples) > 2 and self.samples[1][0] <= time - RATE_WINDOW_S:
            self.samples.popleft()

    def rates(self):
        """The panel's list at the newest sample: [{vector, device, per_s, total}],
        known vectors first."""
        time, counts = self.samples[-1]
        then, before = self.samples[0]
        span = time - then
        vectors = list(VECTORS) + sorted(set(counts) - set(VECTORS))
        return [{"vector": f"{v:03o}", "device": VECTORS.get(v, "?"), "total": counts.get(v, 0),
                 "per_s": round((counts.get(v, 0) - before.get(v, 0)) / span, 1) if span > 0
                 else None} for v in vectors]
