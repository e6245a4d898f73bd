"""Which memory words the lab watches: the 1983 servo's variables, found by name
in the running FORTH's dictionary (pure logic: commands out, memory rows in);
and, once blocks 1070-1078 are loaded, the ASN's trial, steps, payoff and late
moves (watched each tick) and its 72 weights (dumped with each probe: they
change once a step, and the LAB device watches at most 64 words).

Every probe the lab asks the LAB device for the FORTH vocabulary's chain
heads and DP (HERE). When they change (a LOAD, a FORGET) it dumps the dictionary,
finds the servo's words (block 1000's arrays and Dir, defined above the kernel's FENCE) and watches their cells.
"""
from harness.lab.dictionary import Memory, find_bodies
from harness.machine.kernel_layout import BODY, CHAINS
from harness.machine.plant_rows import AXES

ORIGIN = 0o2000                      # the kernel and the dictionary start here
PER_AXIS = ("Desire.Pos", "State", "Velocity", "0-Vel", "Command.Status", "MaxVel")
SINGLE = ("Dir", "Trial.No", "Steps", "Z.Was", "Late")
DUMPED = {"Weights": 72}             # the ASN's 4 x 18 weights (docs/learning.md)


def signed(word):
    return word - 0o200000 if word & 0o100000 else word


class ServoWatch:
    def __init__(self, symbols):
        self.vocabulary = symbols["FORTH"] + BODY    # its chain heads
        self.dp = symbols["DP"] + BODY
        self.fence = symbols["FENCE"] + BODY      # the kernel ends here: its STATE is not block 1000's
        self.memory = Memory()
        self.seen = None               # chain heads and HERE at the last dictionary dump
        self.dump_end = None           # last address of the dump under way
        self.layout = []               # (name, axis or None) per watched word
        self.pending = ([], [])        # addresses asked for, and their layout
        self.found = {}
        self.probes = self.answered = 0    # probes asked for; their HERE rows come in order
        self.awaiting = False              # a watch list sent, its A row not yet back
        self.last = None                   # (words, the table values() made of them)

    def probe(self):
        """The commands that read the chain heads and HERE, and the dumped arrays."""
        self.probes += 1
        return [f"dump {self.vocabulary:o} {CHAINS}", f"dump {self.fence:o} 1",
                f"dump {self.dp:o} 1"] + [f"dump {self.found[name]:o} {n}"
                                          for name, n in DUMPED.items() if name in self.found]

    def _state(self):
        return tuple(self.memory.word(self.vocabulary + 2 * i) for i in range(CHAINS)) + (
            self.memory.word(self.fence), self.memory.word(self.dp))

    def on_memory(self, address, words):
        """A dump row arrived; the commands it calls for (a dictionary dump, a new
        watch list), in order."""
        self.memory.store(address, words)
        self.last = None                       # a dumped array may have changed
        last = address + 2 * len(words) - 2
        if address == self.dp and len(words) == 1:
            self.answered += 1                 # a probe's last row (before its arrays)
        if address == self.dp and self.dump_end is None:
            state = self._state()
            if state != self.seen and None not in state:
                self.seen = state
                # to HERE's last byte: HERE is odd while a header's name or a
                # string is compiled, and a dump that ended a byte short would
                # never bring the row of dump_end (the watch stuck for good)
                words = (state[-1] - ORIGIN + 1) // 2
                self.dump_end = ORIGIN + 2 * (words - 1)
                return [f"dump {ORIGIN:o} {words}"]
        elif self.dump_end is not None and address <= self.dump_end <= last:
            self.dump_end = None
            return [self._watch_command()]
        return []

    def _watch_command(self):
        fence = self.memory.word(self.fence)
        self.found = {name: body for name, body in
                      find_bodies(self.memory, self.vocabulary,
                                  PER_AXIS + SINGLE + tuple(DUMPED)).items()
                      if body > fence}
        layout, addresses = [], []
        for name in PER_AXIS:
            if name in self.found:
                for axis in range(len(AXES)):
                    layout.append((name, axis))
                    addresses.append(self.found[name] + 2 * axis)
        for name in SINGLE:
            if name in self.found:
                layout.append((name, None))
                addresses.append(self.found[name])
        self.pending = (addresses, layout)
        self.awaiting = True
        return "watch " + " ".join(f"{a:o}" for a in addresses)

    def settled(self):
        """Every probe asked for is answered, and a dictionary that changed is read
        (dumped, and its watch list confirmed): the names are the FORTH's own now."""
        return self.answered >= self.probes and self.dump_end is None and not self.awaiting

    def on_addresses(self, addresses):
        """The device's A row: from now on W rows carry these addresses."""
        wanted, layout = self.pending
        self.layout = layout if addresses == wanted else []
        self.last = None
        self.awaiting = False

    def values(self, words):
        """{name: [x, y, z, t]} or {name: value} from a W row's words (signed);
        a dumped array, once its dump arrived, as {name: [values]}. The same table
        (object) again while the words, the layout and the memory stand still, as
        they do tick after tick while the FORTH waits at its prompt."""
        if self.last is not None and self.last[0] == words:
            return self.last[1]
        table = {}
        for (name, axis), word in zip(self.layout, words):
            if axis is None:
                table[name] = signed(word)
            else:
                table.setdefault(name, [None] * 4)[axis] = signed(word)
        for name, n in DUMPED.items():
            if name in self.found:
                cells = [self.memory.word(self.found[name] + 2 * i) for i in range(n)]
                if None not in cells:
                    table[name] = [signed(w) for w in cells]
        self.last = (words, table)
        return table
