"""measure()'s reading of the simulator's output in bulk (runs of history and
memory lines; between spans, the entry's next line found by str.find) against
a plain reading of the same real output: each line matched on its own, every
instruction priced, the spans summed at the end."""
import re
from collections import Counter

import pytest

from harness.analysis import kdf11, timing
from harness.machine import simh
from timing_programs import mixed_program

# SIMH's formats (PDP11/pdp11_cpu.c, cpu_show_hist): "%06o %06o|", then
# "%06o %06o  " or "       %06o  " or 15 blanks, then the disassembly
HISTORY = re.compile(r"(?P<pc>[0-7]{6}) (?P<psw>[0-7]{6})\|"
                     r"(?:(?P<src>[0-7]{6}) |       )(?:[0-7]{6}  |        )(?P<text>\S.*)")
WORD = re.compile(r"([0-7]+):\s+([0-7]+)\s*")             # EXAMINE's
STOP = re.compile(r"(.+), PC: ([0-7]+)")
OWN_PSW_CHANGE = {"MTPS", "RTI", "RTT", "EMT", "TRAP", "IOT", "BPT"}
# (entry, end): the clock's handler, the trap's, the loop's body with clock
# interrupts nested in it, the loop ended by the trap's RTI, one SOB, code
# that ran before measuring began
CASES = [(0o1400, "rti"), (0o1500, "rti"), (0o1012, 0o1022), (0o1012, "rti"),
         (0o1016, 0o1016), (0o1000, 0o1024)]


@pytest.fixture(scope="module")
def output():
    """A measurement's whole output: a breakpoint stop and an EXAMINE in the
    setup, chunks of 200 (spans cut between them), a HALT in the 13th of 15.
    The clock ticks every 400 instructions (RATE 24000): a short run has many."""
    setup = (mixed_program(passes=300).script(start=False)
             + "set clk rate=24000\nbreak 1012\ngo\nnobreak 1012\nexamine 2000\n")
    return simh.run(timing._measure_script(setup, 3000, 200))


@pytest.fixture(scope="module")
def plain(output):
    """plain_reading(output), and plain_prices() of each of CASES."""
    words, registers, stopped, history = plain_reading(output)
    executed = [HISTORY.fullmatch(line) for line in history]
    prices = {case: plain_prices(executed, words, *case) for case in CASES}
    return words, registers, stopped, history, prices


def plain_reading(output):
    """(words, registers, stopped, history lines measured): one line at a time."""
    words, registers, stopped, blocks, last_block, history = {}, [], None, 0, None, []
    for line in output.splitlines():
        if line.startswith("PC     PSW"):
            blocks += 1
        elif HISTORY.fullmatch(line):
            if blocks and (last_block is None or blocks <= last_block):
                history.append(line)
        elif m := WORD.fullmatch(line):
            words[int(m[1], 8)] = int(m[2], 8)
        elif line.split(":")[0] in ("RATE", "TICKS"):
            registers.append(int(line.split()[1]))
        elif (stop := STOP.match(line)) and stopped is None and len(registers) >= 2 \
                and not line.startswith("Step expired"):
            stopped, last_block = f"{stop[1]} at PC {stop[2]}", blocks + 1
    return words, registers, stopped, history


def priority(executed):
    return int(executed["psw"], 8) >> 5 & 7


def plain_prices(executed, words, entry, end):
    """(spans, by_mnemonic, unpriced, incomplete) by timing.py's rules, from
    the history lines' HISTORY matches."""
    spans, charges, unpriced = [], [], Counter()     # charges: [(span, mnemonic, us)]
    span, depth, prev = None, 0, None
    for ex in executed:
        pc = int(ex["pc"], 8)
        interrupted = (prev is not None and priority(ex) > priority(prev)
                       and prev["text"].split()[0] not in OWN_PSW_CHANGE)
        prev = ex
        if span is None and pc != entry:
            continue
        if span is None:
            span = timing.Span(pc, interrupt_entry=interrupted)
            spans.append(span)
            if interrupted:
                charges.append((span, "(interrupt entry)", kdf11.INTERRUPT_ENTRY))
        elif interrupted:
            depth += 1
        priced = kdf11.price(words[pc], sob_taken=ex["src"] is None or int(ex["src"], 8) != 1)
        assert ex["text"].split()[0] == priced.mnemonic or priced.mnemonic == "CCOP"
        span.instructions += 1
        if priced.microseconds is None:
            unpriced[priced.mnemonic] += 1
        else:
            charges.append((span, priced.mnemonic, priced.microseconds))
        if priced.mnemonic in ("RTI", "RTT") and depth:
            depth -= 1
        elif end == pc or (end == "rti" and priced.mnemonic in ("RTI", "RTT")):
            span = None
    by_mnemonic = {}
    for s, name, us in charges:             # summed in the order they were run
        s.microseconds += us
        count, total = by_mnemonic.get(name, (0, 0.0))
        by_mnemonic[name] = [count + 1, total + us]
    return spans[:len(spans) - (span is not None)], by_mnemonic, unpriced, int(span is not None)


class Trickle:
    """A stream that gives `size` characters a read, cut anywhere."""

    def __init__(self, text, size):
        self.text, self.pos, self.size = text, 0, size

    def read(self, n):
        piece = self.text[self.pos:self.pos + min(n, self.size)]
        self.pos += len(piece)
        return piece


def same_prices(pieces, words, prices):
    for entry, end in CASES:
        report = timing.price_spans(pieces, words, entry, end)
        got = (report.spans, report.by_mnemonic, report.unpriced, report.incomplete)
        assert got == prices[entry, end], (entry, end)


@pytest.mark.parametrize("size", [997, 1 << 20])
def test_bulk_reading_matches_the_plain_one(output, plain, size):
    """Read `size` characters at a time (cut anywhere, a run of lines too)."""
    words, registers, stopped, history, prices = plain
    assert stopped == "HALT instruction at PC 001026"     # not the setup's breakpoint
    assert len(history) > 2000 and len(words) > 28_000 and len(registers) == 3
    reader = timing._Output()
    runs = list(reader.history(Trickle(output, size)))
    assert (reader.words, reader.registers, reader.stopped) == (words, registers, stopped)
    assert "".join(runs).splitlines() == history
    same_prices(runs, reader.words, prices)


def test_pricing_a_line_a_piece(plain):
    """Every span starts a piece: the line before it is the last piece's."""
    words, _, _, history, prices = plain
    same_prices([line + "\n" for line in history], words, prices)


def test_every_kind_of_span_is_in_the_output(output, plain):
    """The cases above price what they are meant to: interrupt entries (and a
    clock interrupt taken as an RTI returns, not one), SOB taken and not,
    spans through nested interrupts, spans cut between chunks, code run
    before measuring began."""
    prices = plain[-1]
    assert re.search(r"^Step expired, PC: 0014(02|06) ", output, re.M)   # in the handler
    assert {s.interrupt_entry for s in prices[0o1400, "rti"][0]} == {True, False}
    assert {s.microseconds for s in prices[0o1016, 0o1016][0]} == {kdf11.SOB_TAKEN,
                                                                    kdf11.SOB_NOT_TAKEN}
    assert {s.instructions for s in prices[0o1012, 0o1022][0]} >= {8, 8 + 4}   # + the clock's
    assert prices[0o1000, 0o1024][0] == []
