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

    def name_at(self, address):
        return self.by_address.get(address)

    def containing(self, address):
        """The word whose code field is the nearest at or below `address`."""
        i = bisect.bisect_right(self._sorted, address) - 1
        return self.by_address[self._sorted[i]] if i >= 0 else None


def panel(fields, index):
    """A panel for the page from an R row's fields, or None when unreadable."""
    try:
        time, numbers = float(fields[0]), [int(f, 8) for f in fields[1:]]
    except (ValueError, IndexError):
        return None
    if len(numbers) < 17:
        return None
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
