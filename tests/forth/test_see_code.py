"""SEE of a CODE word (issue 18): the octal and the block to load without the
disassembler; with blocks 1090-1097 loaded, PDP-11 mnemonics. The reference is
independent of both the kernel's assembler and the blocks: SIMH's own EXAMINE -M
disassembles the same addresses in the same running machine, for every CODE
word of the kernel, the 1983 servo's Interrupt.Servo (block 1008) and a table of
instructions neither uses (MUL, SOB, EMT, the condition codes ...)."""
import re
import tempfile

import pytest

from harness.machine.build import fresh_disk
from harness.machine.machine import Machine

LINE = re.compile(r"^([0-7]+): (.*?)((?: \\ \S+)*)\s*$")   # text, then \ NAME notes
SIMH_LINE = re.compile(r"^([0-7]+):\t(.*?)\s*$", re.M)

# words of instructions the kernel and the 1983 blocks do not assemble (octal),
# and what a PDP-11 programmer reads in them (DEC's mnemonics, SIMH's syntax)
EXTRA = [
    ([0o070203], "MUL R3,R2"), ([0o071027, 0o12], "DIV #12,R0"),
    ([0o072102], "ASH R2,R1"), ([0o073027, 0o177776], "ASHC #177776,R0"),
    ([0o074265, 0o4], "XOR R2,4(R5)"), ([0o077102], None),  # SOB R1,.-2
    ([0o104017], "EMT 17"), ([0o104417], "TRAP 17"), ([0o006403], "MARK 3"),
    ([0o000241], "CLC"), ([0o000277], "SCC"), ([0o000257], "CCC"), ([0o000264], "SEZ"),
    ([0o000240], "NOP"), ([0o006737, 0o1000], "SXT @#1000"), ([0o106427, 0o340], "MTPS #340"),
    ([0o106767, 0o2], None),                                 # MFPS relative
    ([0o105075, 0o6], "CLRB @6(R5)"), ([0o000003], "BPT"), ([0o000002], "RTI"),
    ([0o000234], "SPL 4"), ([0o000007], "MFPT"), ([0o000210], None),   # no instruction
    ([0o103777], None), ([0o100001], None),                  # BCS back, BPL forward
]


def see_lines(text):
    """(address, instruction text, name note) for each disassembled line."""
    rows = []
    for line in text.replace("\r", "").split("\n"):
        m = LINE.match(line.strip())
        if m:
            rows.append((int(m.group(1), 8), m.group(2).rstrip(),
                         m.group(3).replace("\\", "").split()))
    return rows


def simh_disassembly(m, spans):
    """SIMH's EXAMINE -M text by address over each (first, last) address span,
    from the sim> prompt (SIMH steps by its own instruction lengths)."""
    m.to_sim()
    found = {}
    ranges = [f"{first:o}-{last:o}" for first, last in spans]
    for i in range(0, len(ranges), 50):             # an address list: 50 spans a command
        found.update((int(a, 8), t)
                     for a, t in SIMH_LINE.findall(m.simh("e -m " + ",".join(ranges[i:i + 50]))))
    m.cont()
    return found


@pytest.fixture
def forth():
    """The kernel alone on a blank disk, for the one test here that needs it and
    closed after it: tests/forth/conftest.py's, module-scoped, would stay booted
    beside the disassembly tests, idling at 100 times the 11/23's pace (about a
    sixth of a host core, harness/machine/machine.py) for nothing."""
    with Machine() as m:
        yield m


@pytest.fixture(scope="module")
def robot():
    """The robot's disk: 1000 LOAD (the servo), then the disassembler."""
    with tempfile.TemporaryDirectory() as tmp, Machine(disk=fresh_disk(tmp), timeout=60) as m:
        m.send("1000 LOAD")
        m.send("1090 LOAD")
        yield m


def test_without_the_disassembler_see_prints_octal_and_the_block(forth):
    out = forth.send("SEE DUP")
    assert "DUP is CODE at" in out and "1090 LOAD: SEE then disassembles" in out
    assert re.search(r": (\d{6} ){8}", out)


def test_every_code_word_disassembles_as_simh_does(robot):
    robot.send(": CODE? ( nt -- f )  NAME> @ DUP 4437O <> OVER 4237O <> AND "
               "SWAP 137O <> AND ;")
    robot.send(": .CODE-WORD ( nt -- true )  DUP CODE? IF CR DUP NAME> U. .NAME ELSE DROP "
               "THEN TRUE ;")
    words = robot.send("' .CODE-WORD FORTH-WORDLIST TRAVERSE-WORDLIST").split()
    xts = dict(zip(words[1::2], map(int, words[0::2])))   # a name defined twice: its newest
    assert "Interrupt.Servo" in xts and "DUP" in xts and len(xts) > 100
    ours, spans = {}, []
    for name, xt in xts.items():          # what SEE shows of each (by xt: EXIT is two words)
        rows = see_lines(robot.send(f"{xt} DISASSEMBLE-CODE", timeout=60))
        assert rows and rows[0][0] == xt, f"{name}: no instructions"
        ours.update((a, (name, text, note)) for a, text, note in rows)
        spans.append((rows[0][0], rows[-1][0]))
    assert see_lines(robot.send("SEE DUP")) == [(a, t, n) for a, (name, t, n) in
                                                sorted(ours.items()) if name == "DUP"]
    theirs = simh_disassembly(robot, spans)
    differ = [f"{name} {a:o}: ours {text!r}, SIMH {theirs.get(a)!r}"
              for a, (name, text, note) in sorted(ours.items()) if theirs.get(a) != text]
    assert not differ, "\n".join(differ[:20])
    # the servo's variables are named, as python -m harness listing names them
    notes = {n for _, _, ns in ours.values() for n in ns}
    assert {"Desire.Pos+4", "Velocity+4", "Delay.Left+4"} <= notes
    both = [ns for name, text, ns in ours.values()    # @#a,X(R1): the source's word,
            if name == "Interrupt.Servo" and re.search(r"@#\d+,\d+\(R1\)", text)]  # then the destination's
    assert both and all(len(ns) >= 2 for ns in both), both
    # an I/O address is named by the block's constant for it (block 1000's CON)
    assert {"CntOut", "CntIn", "VelOut"} <= notes


def test_instructions_neither_uses(robot):
    words = [w for ws, _ in EXTRA for w in ws]
    robot.send("CREATE SAMPLES")
    for i in range(0, len(words), 12):
        robot.send(" ".join(f"{w:o}O ," for w in words[i:i + 12]))
    start = int(robot.send("SAMPLES U.").split()[0])
    rows = see_lines(robot.send(f"SAMPLES DUP {2 * len(words)} + DISASSEMBLE"))
    assert [a for a, _, _ in rows][:1] == [start] and len(rows) == len(EXTRA)
    theirs = simh_disassembly(robot, [(rows[0][0], rows[-1][0])])
    for (a, text, _), (_, expected) in zip(rows, EXTRA):
        assert text == theirs[a]
        if expected:
            assert text == expected
    assert rows[5][1] == f"SOB R1,{rows[5][0] + 2 - 4:o}"
