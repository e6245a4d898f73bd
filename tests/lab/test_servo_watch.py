"""Finding the servo's words by name in a copy of memory (harness/lab/dictionary.py,
servo_watch.py), on headers laid out as forth/README.md describes them."""
from harness.lab.dictionary import Memory, find_bodies
from harness.lab.servo_watch import ORIGIN, ServoWatch, signed
from harness.machine.kernel_layout import CHAINS, chain_of

VOCABULARY = 0o20470


class Dictionary:
    """Builds headers into a Memory the way the kernel's HEADER, does."""

    def __init__(self, start=0o50000):
        self.memory = Memory()
        self.here = start
        self.heads = [0] * CHAINS

    def byte(self, address, value):
        word = self.memory.word(address) or 0
        shift = 8 * (address & 1)
        self.memory.store(address & ~1, [(word & ~(0o377 << shift)) | (value << shift)])

    def header(self, name, flags=0, body_words=4):
        chain = chain_of(name)
        lfa = self.here
        self.memory.store(lfa, [self.heads[chain]])
        self.byte(lfa + 2, len(name) | flags)
        for i, c in enumerate(name.encode()):
            self.byte(lfa + 3 + i, c)
        cfa = (lfa + 3 + len(name) + 1) & ~1
        self.memory.store(cfa, [0o4737, 0o2026] + [0] * body_words)
        self.heads[chain] = lfa
        self.here = cfa + 4 + 2 * body_words
        self.memory.store(VOCABULARY, self.heads)
        return cfa + 4


def test_find_bodies_newest_first_case_ignored_smudged_skipped():
    d = Dictionary()
    old = d.header("Velocity")
    new = d.header("VELOCITY")
    d.header("State", flags=0o40)                         # smudged: being defined
    state = d.header("Dir")
    assert find_bodies(d.memory, VOCABULARY, ["Velocity", "State", "Dir", "Missing"]) == {
        "Velocity": new, "Dir": state}
    assert old != new


def test_a_broken_chain_ends_the_walk():
    d = Dictionary()
    d.header("Dir")
    d.memory.store(VOCABULARY + 2 * chain_of("Dir"), [0o77776])          # into memory never dumped
    assert find_bodies(d.memory, VOCABULARY, ["Dir"]) == {}


def symbols():
    return {"FORTH": VOCABULARY - 4, "DP": 0o6340, "FENCE": 0o6456}


def test_servo_watch_dumps_the_dictionary_when_it_changes_and_watches_by_name():
    d = Dictionary()
    kernel_state = d.header("STATE", body_words=1)         # the kernel's: below FENCE
    fence = d.here
    desire = d.header("Desire.Pos")
    d.header("State")
    direction = d.header("Dir", body_words=1)
    watch = ServoWatch(symbols())
    assert watch.probe() == [f"dump 20470 {CHAINS}", "dump 6462 1", "dump 6344 1"]
    assert watch.on_memory(VOCABULARY, d.heads) == []
    assert watch.on_memory(0o6462, [fence]) == []
    command = watch.on_memory(0o6344, [d.here])
    assert command == [f"dump {ORIGIN:o} {(d.here - ORIGIN) // 2}"]
    d.memory.store(0o6344, [d.here])                       # the kernel's DP and FENCE, dumped too
    d.memory.store(0o6462, [fence])
    words = [d.memory.word(a) or 0 for a in range(ORIGIN, d.here, 2)]
    assert watch.on_memory(ORIGIN, words[:64]) == []       # the dump comes in rows
    watch_command = watch.on_memory(ORIGIN + 128, words[64:])
    state_body = watch.found["State"]
    assert state_body != kernel_state
    expected = [desire + 2 * i for i in range(4)] + [state_body + 2 * i for i in range(4)] + [
        direction]
    assert watch_command == ["watch " + " ".join(f"{a:o}" for a in expected)]
    # W rows are read with the new layout once the device confirms the addresses
    assert watch.values([1] * 9) == {}
    watch.on_addresses(expected)
    assert watch.values([800, 800, 400, 0, 1, 1, 0, 0, 0o177777]) == {
        "Desire.Pos": [800, 800, 400, 0], "State": [1, 1, 0, 0], "Dir": -1}
    # nothing changed: the next probe dumps nothing
    assert watch.on_memory(0o6344, [d.here]) == []


def device_dump(memory, command):
    """The M rows (address, words) the LAB device writes for `dump a n` (64 a row)."""
    _, address, n = command.split()
    address, n = int(address, 8), int(n)
    words = [memory.word(address + 2 * i) or 0 for i in range(n)]
    return [(address + 128 * r, words[64 * r:64 * r + 64]) for r in range(0, (n + 63) // 64)]


def test_a_probe_while_here_is_odd_still_ends_in_a_watch_list():
    """A probe can land while a LOAD compiles a header's name or a string: HERE is
    odd then. The dump must reach HERE's last byte, and its last row end the
    dump, or the watch never looks at the dictionary again (the servo table
    stayed empty for good, and the rack's hint never came)."""
    d = Dictionary()
    fence = d.here
    d.header("Dir", body_words=1)
    here = d.here + 3                                      # a name half laid down
    watch = ServoWatch(symbols())
    watch.probe()
    watch.on_memory(VOCABULARY, d.heads)
    watch.on_memory(0o6462, [fence])
    [dump] = watch.on_memory(0o6344, [here])
    d.memory.store(0o6344, [here])
    d.memory.store(0o6462, [fence])
    assert int(dump.split()[2]) * 2 + ORIGIN >= here       # HERE's last byte included
    out = [c for address, words in device_dump(d.memory, dump)
           for c in watch.on_memory(address, words)]
    assert out == [f"watch {watch.found['Dir']:o}"]
    watch.on_addresses([watch.found["Dir"]])
    assert watch.settled()


def test_signed():
    assert signed(0o177777) == -1 and signed(0o77777) == 32767 and signed(0) == 0


def test_the_asn_words_are_watched_and_its_weights_dumped_with_each_probe():
    d = Dictionary()
    fence = d.here
    trial = d.header("Trial.No", body_words=1)
    steps = d.header("Steps", body_words=1)
    weights = d.header("Weights", body_words=72)
    watch = ServoWatch(symbols())
    watch.on_memory(VOCABULARY, d.heads)
    watch.on_memory(0o6462, [fence])
    watch.on_memory(0o6344, [d.here])
    d.memory.store(0o6344, [d.here])
    d.memory.store(0o6462, [fence])
    words = [d.memory.word(a) or 0 for a in range(ORIGIN, d.here, 2)]
    command = watch.on_memory(ORIGIN, words)
    assert command == [f"watch {trial:o} {steps:o}"]
    assert watch.probe()[-1] == f"dump {weights:o} 72"     # 72 words: more than a watch holds
    watch.on_addresses([trial, steps])
    watch.on_memory(weights, [0o177776] + [5] * 71)
    shown = watch.values([3, 12])
    assert shown == {"Trial.No": 3, "Steps": 12, "Weights": [-2] + [5] * 71}
    # tick after tick the same words: the same table, not made again ...
    assert watch.values([3, 12]) is shown
    # ... until the words, a dumped array or the layout change
    assert watch.values([4, 12])["Trial.No"] == 4
    watch.on_memory(weights, [1] * 72)
    assert watch.values([4, 12])["Weights"] == [1] * 72
    watch.on_addresses([steps])
    assert watch.values([4, 12]) == {"Weights": [1] * 72}


def test_settled_once_every_probe_is_answered_and_a_changed_dictionary_read():
    """What a breakpoint on a word defined a moment ago waits for (server.read_dictionary)."""
    d = Dictionary()
    fence = d.here
    direction = d.header("Dir", body_words=1)
    watch = ServoWatch(symbols())
    watch.probe()
    assert not watch.settled()                             # asked, not answered
    watch.on_memory(VOCABULARY, d.heads)
    watch.on_memory(0o6462, [fence])
    watch.on_memory(0o6344, [d.here])                      # HERE moved: the dictionary is dumped
    assert not watch.settled()
    d.memory.store(0o6344, [d.here])
    d.memory.store(0o6462, [fence])
    watch.on_memory(ORIGIN, [d.memory.word(a) or 0 for a in range(ORIGIN, d.here, 2)])
    assert not watch.settled()                             # its watch list not yet confirmed
    watch.on_addresses([direction])
    assert watch.settled()
    watch.probe()
    watch.probe()
    watch.on_memory(0o6344, [d.here])                      # unchanged: nothing to dump
    assert not watch.settled()                             # the second probe's answer to come
    watch.on_memory(0o6344, [d.here])
    assert watch.settled()
