"""What a piece of code costs on a KDF11-A (PDP-11/23), from SIMH's CPU history.

SIMH records every executed instruction when `SET CPU HISTORY=n` is on, and
`SHOW CPU HISTORY` lists them (PDP11/pdp11_cpu.c, cpu_show_hist):

    PC     PSW     src    dst     IR
    001400 000340|       001400  INC @#2000

PC and PSW before the instruction, then the source and destination registers'
values (only for instructions that have them), then SIMH's disassembly. The
instruction words themselves are not listed, so they are read from memory at
the end of the run (the code must not change while it is measured; each
executed instruction's disassembly is checked against the word read).

A *span* is one execution of the code being measured: it starts when the
instruction at `entry` executes and ends with the RTI (or RTT) that returns from
it (end="rti"), or with the first execution of the instruction at a given
address (end=address, included). A span entered by an interrupt (the processor priority rose from the
instruction before, which did not change the PSW itself) is charged
kdf11.INTERRUPT_ENTRY for the entry sequence: an estimate, as DEC's tables give
no figure (IOT's trap sequence). A trap instruction (EMT, TRAP, IOT, BPT) is not
an interrupt entry: its own price includes its trap sequence. SOB is priced
taken or not from its register (the history's src column: taken unless it was 1).

    report = measure(setup_script, entry=0o1400, end="rti", instructions=300_000)
    print(report.format())

measure() runs build/pdp11: `setup` (SIMH lines) must leave the machine stopped
where measuring starts (e.g. after `break`/`go`, or deposits and `deposit pc`);
then it steps `instructions` instructions in chunks under history, and counts
the clock's ticks over them, so `per_tick_us` is the average cost per 60 Hz tick.
price_spans() does the pricing alone, on history text and memory words.
"""
import itertools
import re
from collections import Counter, defaultdict
from dataclasses import dataclass, field
from typing import NamedTuple

from harness.analysis import kdf11
from harness.machine import simh
from harness.machine.build import RATE

TICK_US = 1e6 / 60              # the 60 Hz line clock's period
CHUNK = 100_000                 # instructions per history chunk (SIMH allows 262144)
MEMORY_TOP = 0o157776           # last word below the I/O page (56 KB of RAM)

_STOP = re.compile(r"^(.+), PC: ([0-7]+)")
# Lines read in runs: history ("PPPPPP SSSSSS|", 15 register columns, the
# disassembly) and memory ("address:<tab>word"); a run ends at the newline
# before a line of another kind.
_HISTORY = r"[0-7]{6} [0-7]{6}\|.{15}"
_EXAMINE = r"[0-7]+:[^\S\n]+[0-7]+[^\S\n]*\n"
_HISTORY_LINE, _HISTORY_END = re.compile(_HISTORY), re.compile(rf"\n(?!{_HISTORY})")
_EXAMINE_LINE, _EXAMINE_END = re.compile(_EXAMINE), re.compile(rf"\n(?!{_EXAMINE})")
_HISTORY_HEADER = "PC     PSW     src    dst     IR"
# Instructions that change the PSW themselves: a priority rise after them is not an
# interrupt entry (a trap instruction's price already includes its trap sequence).
_OWN_PSW_CHANGE = ("MTPS", "RTI", "RTT", "EMT", "TRAP", "IOT", "BPT")


class TimingError(RuntimeError):
    """The measurement could not be made (bad address, code changed, no span)."""


@dataclass
class Span:
    """One execution of the measured code."""
    start_pc: int
    instructions: int = 0
    microseconds: float = 0.0
    interrupt_entry: bool = False


@dataclass
class TimingReport:
    entry: int
    end: object                              # "rti" or an address
    spans: list = field(default_factory=list)
    by_mnemonic: dict = field(default_factory=dict)   # name -> [count, us]
    unpriced: Counter = field(default_factory=Counter)
    incomplete: int = 0                      # a span still running when the run ended
    instructions_run: int | None = None      # instructions stepped (whole run)
    ticks: int | None = None                 # clock ticks during the run
    rate: int | None = None                  # instructions per simulated second
    stopped: str | None = None               # why the run stopped early, if it did

    @property
    def count(self):
        return len(self.spans)

    @property
    def total_us(self):
        return sum(s.microseconds for s in self.spans)

    @property
    def total_instructions(self):
        return sum(s.instructions for s in self.spans)

    @property
    def interrupt_entries(self):
        return sum(s.interrupt_entry for s in self.spans)

    @property
    def mean_us(self):
        return self.total_us / self.count if self.spans else None

    @property
    def per_tick_us(self):
        return self.total_us / self.ticks if self.ticks else None

    @property
    def percent_of_tick(self):
        per = self.per_tick_us
        return None if per is None else 100 * per / TICK_US

    def format(self, name=None):
        what = name or f"code at {self.entry:06o}"
        end = "its RTI" if self.end == "rti" else f"the instruction at {self.end:06o}"
        lines = [f"{what}, from {self.entry:06o} through {end}: {self.count} executions"]
        if self.instructions_run is not None:
            secs = f", {self.instructions_run / self.rate:.3f} simulated s" if self.rate else ""
            lines[0] += f" in {self.instructions_run} instructions run{secs}"
            if self.ticks is not None:
                lines[0] += f", {self.ticks} clock ticks"
        if self.stopped:
            lines.append(f"the run stopped early: {self.stopped}")
        if self.spans:
            us = [s.microseconds for s in self.spans]
            n = [s.instructions for s in self.spans]
            lines.append(f"per execution: {self.mean_us:.3f} us mean (min {min(us):.3f}, "
                         f"max {max(us):.3f}); {self.total_instructions / self.count:.1f} "
                         f"instructions mean (min {min(n)}, max {max(n)})")
            lines.append(f"total: {self.total_us:.3f} us for {self.total_instructions} "
                         "instructions")
        if self.per_tick_us is not None:
            lines.append(f"per 60 Hz tick: {self.per_tick_us:.3f} us = "
                         f"{self.percent_of_tick:.2f} % of the {TICK_US:.0f} us tick")
        if self.interrupt_entries:
            lines.append(f"interrupt entries: {self.interrupt_entries} x "
                         f"{kdf11.INTERRUPT_ENTRY} us (an estimate: DEC's tables give no "
                         "figure; priced as IOT's trap sequence)")
        if self.incomplete:
            lines.append(f"not counted: {self.incomplete} execution still running "
                         "when the run ended")
        if self.by_mnemonic:
            lines.append(f"{'by instruction':20} {'count':>9} {'us':>11}  share")
            total = self.total_us or 1.0
            for name_, (count, us) in sorted(self.by_mnemonic.items(),
                                             key=lambda kv: (-kv[1][1], kv[0])):
                lines.append(f"  {name_:18} {count:9d} {us:11.3f} {100 * us / total:6.1f} %")
        if self.unpriced:
            lines.append("not priced (no figure in the tables): " + ", ".join(
                f"{k} x{v}" for k, v in sorted(self.unpriced.items())))
        lines.append("KDF11-A times, memory management off: DEC KDF11-B User's Guide "
                     "tables B-4..B-7, as in docs/kdf11-timing.md (harness/analysis/kdf11.py).")
        return "\n".join(lines)


def _same_instruction(text, priced):
    """Does SIMH's disassembly name the instruction kdf11 priced?"""
    token = text.split()[0]
    if priced.mnemonic == "CCOP":
        return bool(re.fullmatch(r"(CL|SE)[CVZN]+|CCC|SCC|NOP", token))
    return token == priced.mnemonic


def _source_register(line):
    """The src column's value, None when the instruction has no source."""
    registers = line[14:29].split()
    return int(registers[0], 8) if len(registers) == 2 else None


class _Cost(NamedTuple):
    """What one instruction (an address and its disassembly) costs in a span."""
    mnemonic: str
    microseconds: float | None
    returns: bool                   # RTI or RTT
    closes: bool                    # the span ends with it (unless in a nested interrupt)
    not_taken: "_Cost | None"       # SOB: its cost when R was 1 before the decrement


def price_spans(history, words, entry, end="rti", report=None):
    """Price the spans in `history`: pieces of SHOW CPU HISTORY text, each whole
    history lines ended by newlines, in execution order (the lines of one
    execution may be split between pieces). `words`: address -> instruction
    word (memory after the run)."""
    if end != "rti" and not isinstance(end, int):
        raise TimingError(f"end must be 'rti' or an address, not {end!r}")
    report = report or TimingReport(entry, end)
    spans = _Spans(words, entry, end, report)
    for piece in history:
        spans.read(piece)
    report.incomplete += spans.span is not None
    report.by_mnemonic = dict(spans.by_mnemonic)
    return report


class _Spans:
    """price_spans()'s work. Between spans it looks for the entry's next line
    with str.find, without reading the lines between (most of a long run: an
    idle loop between interrupts); in a span it reads every line. An
    instruction's cost is worked out once per address and disassembly, the
    check against memory with it (the code does not change, or the
    disassembly does)."""

    def __init__(self, words, entry, end, report):
        self.words, self.entry, self.report = words, entry, report
        self.entry_line = f"{entry:06o} "
        self.end_pc = None if end == "rti" else f"{end:06o}"
        self.by_mnemonic = defaultdict(lambda: [0, 0.0], report.by_mnemonic)
        self.costs = {}                 # (pc, disassembly) -> _Cost
        self.span, self.depth = None, 0
        self.last = None                # the line before the piece being read

    def read(self, piece):
        pos = 0
        while pos < len(piece):
            if self.span is None:
                if not piece.startswith(self.entry_line, pos):
                    pos = piece.find("\n" + self.entry_line, pos) + 1
                    if pos == 0:
                        break
            pos = self._through_span(piece, pos)
        if piece:
            self.last = piece[piece.rfind("\n", 0, len(piece) - 1) + 1:-1]

    def _through_span(self, piece, pos):
        """Read from the line at `pos` (the entry's, if no span is under way)
        until the span ends or the piece does; where reading stopped. The
        loop runs for every instruction of every span, on local names."""
        prev = piece[piece.rfind("\n", 0, pos - 1) + 1:pos - 1] if pos else self.last
        prev_priority = 0o400 if prev is None else int(prev[7:13], 8) & 0o340
        span, depth, costs = self.span, self.depth, self.costs
        by_mnemonic, unpriced = self.by_mnemonic, self.report.unpriced
        if span is not None:
            count, micro = span.instructions, span.microseconds
        while pos < len(piece):
            nl = piece.index("\n", pos)
            line, pos = piece[pos:nl], nl + 1
            priority = int(line[7:13], 8) & 0o340
            interrupted = (priority > prev_priority
                           and prev[29:].split()[0] not in _OWN_PSW_CHANGE)
            prev, prev_priority = line, priority
            if span is None:
                span, count, micro = self._start(interrupted)
            elif interrupted:
                depth += 1                  # a nested interrupt: its cost counts too
            key = line[:6], line[29:]
            mnemonic, us, returns, closes, not_taken = costs.get(key) or self._cost(key)
            if not_taken and _source_register(line) == 1:
                mnemonic, us, returns, closes, _ = not_taken
            count += 1
            if us is None:
                unpriced[mnemonic] += 1
            else:
                micro += us
                tally = by_mnemonic[mnemonic]
                tally[0] += 1
                tally[1] += us
            if returns and depth:
                depth -= 1
            elif closes:
                span.instructions, span.microseconds = count, micro
                self.report.spans.append(span)
                span = None
                break
        if span is not None:
            span.instructions, span.microseconds = count, micro
        self.span, self.depth = span, depth
        return pos

    def _start(self, interrupted):
        """A new span, its instruction count and microseconds so far."""
        span = Span(self.entry, interrupt_entry=interrupted)
        if interrupted:
            span.microseconds += kdf11.INTERRUPT_ENTRY
            self.by_mnemonic["(interrupt entry)"][0] += 1
            self.by_mnemonic["(interrupt entry)"][1] += kdf11.INTERRUPT_ENTRY
        return span, span.instructions, span.microseconds

    def _cost(self, key):
        """The _Cost of the instruction at `key` = (pc, disassembly), checked
        against memory: SIMH's disassembly must name the word's instruction."""
        pc, text = int(key[0], 8), key[1].strip()
        if pc not in self.words:
            raise TimingError(f"no memory word read for the instruction at {pc:06o}")
        word = self.words[pc]
        taken = kdf11.price(word)
        if not _same_instruction(text, taken):
            raise TimingError(f"at {pc:06o} SIMH executed {text!r} but memory now "
                              f"holds {word:06o} ({taken.mnemonic}): the code changed "
                              "during the run")

        def cost(priced, not_taken=None):
            returns = priced.mnemonic in ("RTI", "RTT")
            closes = returns if self.end_pc is None else key[0] == self.end_pc
            return _Cost(priced.mnemonic, priced.microseconds, returns, closes, not_taken)
        not_taken = cost(kdf11.price(word, sob_taken=False)) if taken.mnemonic == "SOB" else None
        self.costs[key] = cost(taken, not_taken)
        return self.costs[key]


def _measure_script(setup, instructions, chunk):
    # memory first: the pricing streams through the history as it is printed
    lines = [setup.rstrip("\n"), f"examine 0-{MEMORY_TOP:o}", "examine clk rate",
             "examine clk ticks", f"set cpu history={chunk}"]
    left = instructions
    while left > 0:
        n = min(chunk, left)
        lines += [f"step {n}", f"show cpu history={n}", "set cpu history"]
        left -= n
    lines += ["examine clk ticks"]
    return "\n".join(lines) + "\n"


class _Output:
    """Reads measure()'s simulator output: memory words and clock registers
    into attributes, runs of history lines yielded (as text) as they come.
    Runs of history and of memory lines are found and read in bulk: a
    measurement prints a line per instruction and one per memory word."""

    def __init__(self):
        self.words, self.registers, self.stopped = {}, [], None
        self._blocks, self._last_block = 0, None

    def history(self, out):
        for text in _whole_lines(out):
            pos = 0
            while pos < len(text):
                if _HISTORY_LINE.match(text, pos):
                    end = _HISTORY_END.search(text, pos).end()
                    if self._blocks and (self._last_block is None
                                         or self._blocks <= self._last_block):
                        yield text[pos:end]
                elif _EXAMINE_LINE.match(text, pos):
                    end = _EXAMINE_END.search(text, pos).end()
                    self._memory(text[pos:end])
                else:
                    end = text.index("\n", pos) + 1
                    self._line(text[pos:end])
                pos = end

    def _memory(self, lines):
        numbers = iter(lines.replace(":", " ").split())     # address, word, ...
        self.words.update({int(a, 8): int(w, 8) for a, w in zip(numbers, numbers)})

    def _line(self, line):
        if line.startswith(_HISTORY_HEADER):
            self._blocks += 1
        elif line.startswith(("RATE:", "TICKS:")):
            self.registers.append(int(line.split()[1]))
        else:
            m = _STOP.match(line)
            # stops before RATE and TICKS were read belong to the setup
            # (breakpoints that bring the machine to where measuring starts)
            if m and not m.group(1).strip().startswith("Step expired") \
                    and self.stopped is None and len(self.registers) >= 2:
                # the chunk that stopped is still shown; later ones are not
                self.stopped = f"{m.group(1).strip()} at PC {m.group(2)}"
                self._last_block = self._blocks + 1


def _whole_lines(out, size=1 << 18):
    """The text read from `out`, in pieces of whole lines."""
    rest = ""
    while piece := out.read(size):
        cut = piece.rfind("\n") + 1
        if cut:
            yield rest + piece[:cut]
            rest = piece[cut:]
        else:
            rest += piece
    if rest:
        yield rest + "\n"


def measure(setup, entry=None, end="rti", instructions=RATE, chunk=CHUNK,
            keyboard="", simulator=simh.PDP11, machine=True, timeout=600, vector=None):
    """Run `setup`, then `instructions` more instructions under CPU history, and
    price every execution of the code at `entry` (see the module's docstring).
    Instead of `entry`, `vector` names an interrupt vector: the code is the one
    whose address the vector holds once `setup` has run (Interrupt.Servo's, at
    100, after Set.Up.Robot)."""
    if (entry is None) == (vector is None):
        raise TimingError("give the code's entry address or its vector, one of them")
    if not 64 <= chunk <= 262144:
        raise TimingError(f"chunk must be 64..262144 instructions (SIMH's history), "
                          f"not {chunk}")
    if instructions < 1:
        raise TimingError("instructions must be at least 1")
    reader = _Output()
    with simh.stream(_measure_script(setup, instructions, chunk), machine, simulator,
                     timeout, keyboard=keyboard) as out:
        history = reader.history(out)
        first = next(history, None)         # memory has been read by now
        if vector is not None:
            if vector not in reader.words:
                raise TimingError(f"vector {vector:o}: no such memory word")
            entry = reader.words[vector]
        report = TimingReport(entry, end, instructions_run=instructions)
        if first is not None:
            price_spans(itertools.chain([first], history), reader.words, entry, end, report)
        for _ in history:                   # whatever follows the last history
            pass
    if len(reader.registers) != 3:
        raise TimingError("the simulator did not report the clock's RATE and TICKS "
                          "(is this build/pdp11 with the project's clock?)")
    report.rate = reader.registers[0]
    report.ticks = reader.registers[2] - reader.registers[1]
    report.stopped = reader.stopped
    if first is None:
        raise TimingError("no instruction ran: did the setup leave the machine "
                          "ready to run?" + (f" ({reader.stopped})" if reader.stopped else ""))
    if not report.spans:
        where = "its RTI" if end == "rti" else f"{end:06o}"
        raise TimingError(f"the code at {entry:06o} never ran through {where} in "
                          f"{instructions} instructions"
                          + (f" (the run stopped: {reader.stopped})" if reader.stopped else ""))
    return report
