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
price_spans() does the pricing alone, on history lines and memory words.
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
_EXAMINE = re.compile(r"^([0-7]+):\s+([0-7]+)\s*$")
_HISTORY_HEADER = "PC     PSW     src    dst     IR"
# Instructions that change the PSW themselves: a priority rise after them is not an
# interrupt entry (a trap instruction's price already includes its trap sequence).
_OWN_PSW_CHANGE = ("MTPS", "RTI", "RTT", "EMT", "TRAP", "IOT", "BPT")


class TimingError(RuntimeError):
    """The measurement could not be made (bad address, code changed, no span)."""


class Executed(NamedTuple):
    """One line of SHOW CPU HISTORY (register columns kept as text: the only
    one needed, SOB's source register, is read when asked for)."""
    pc: int
    psw: int
    registers: str          # the 15 columns "src    dst    ", blank where none
    text: str               # SIMH's disassembly

    @property
    def priority(self):
        return (self.psw >> 5) & 7

    @property
    def src(self):
        regs = self.registers.split()
        return int(regs[0], 8) if len(regs) == 2 else None

    @property
    def dst(self):
        regs = self.registers.split()
        return int(regs[-1], 8) if regs else None


def parse_history_line(line):
    """An Executed for a history line ("PPPPPP SSSSSS|" + 15 columns + text);
    None for any other line. Fixed columns: this runs for every instruction."""
    if len(line) < 30 or line[13] != "|" or line[6] != " ":
        return None
    try:
        return Executed(int(line[:6], 8), int(line[7:13], 8), line[14:29],
                        line[29:].strip())
    except ValueError:
        return None


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


def _price(executed, word):
    sob_taken = executed.src != 1          # SOB: R before the decrement
    priced = kdf11.price(word, sob_taken=sob_taken)
    if not _same_instruction(executed.text, priced):
        raise TimingError(f"at {executed.pc:06o} SIMH executed {executed.text!r} but "
                          f"memory now holds {word:06o} ({priced.mnemonic}): the code "
                          "changed during the run")
    return priced


def price_spans(history, words, entry, end="rti", report=None):
    """Price the spans in `history` (Executed records, in execution order).
    `words`: address -> instruction word (memory after the run)."""
    if end != "rti" and not isinstance(end, int):
        raise TimingError(f"end must be 'rti' or an address, not {end!r}")
    report = report or TimingReport(entry, end)
    by_mnemonic = defaultdict(lambda: [0, 0.0], report.by_mnemonic)
    span, depth, prev = None, 0, None
    for ex in history:
        interrupted = (prev is not None and (ex.psw & 0o340) > (prev.psw & 0o340)
                       and prev.text.split()[0] not in _OWN_PSW_CHANGE)
        if span is None and ex.pc == entry:
            span = Span(ex.pc, interrupt_entry=interrupted)
            if interrupted:
                span.microseconds += kdf11.INTERRUPT_ENTRY
                by_mnemonic["(interrupt entry)"][0] += 1
                by_mnemonic["(interrupt entry)"][1] += kdf11.INTERRUPT_ENTRY
        elif span is not None and interrupted:
            depth += 1                      # a nested interrupt: its cost counts too
        prev = ex
        if span is None:
            continue
        if ex.pc not in words:
            raise TimingError(f"no memory word read for the instruction at {ex.pc:06o}")
        priced = _price(ex, words[ex.pc])
        span.instructions += 1
        if priced.microseconds is None:
            report.unpriced[priced.mnemonic] += 1
        else:
            span.microseconds += priced.microseconds
            by_mnemonic[priced.mnemonic][0] += 1
            by_mnemonic[priced.mnemonic][1] += priced.microseconds
        returning = priced.mnemonic in ("RTI", "RTT")
        if returning and depth:
            depth -= 1
        elif (end == "rti" and returning) or (end != "rti" and ex.pc == end):
            report.spans.append(span)
            span = None
    report.incomplete += span is not None
    report.by_mnemonic = dict(by_mnemonic)
    return report


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
    into attributes, history records yielded as they come."""

    def __init__(self):
        self.words, self.registers, self.stopped = {}, [], None
        self._blocks, self._last_block = 0, None

    def records(self, lines):
        for line in lines:
            if line.startswith(_HISTORY_HEADER):
                self._blocks += 1
                continue
            rec = parse_history_line(line)
            if rec is not None:
                if self._blocks and (self._last_block is None
                                     or self._blocks <= self._last_block):
                    yield rec
                continue
            m = _EXAMINE.match(line)
            if m:
                self.words[int(m.group(1), 8)] = int(m.group(2), 8)
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
        records = reader.records(out)
        first = next(records, None)         # memory has been read by now
        if vector is not None:
            if vector not in reader.words:
                raise TimingError(f"vector {vector:o}: no such memory word")
            entry = reader.words[vector]
        report = TimingReport(entry, end, instructions_run=instructions)
        if first is not None:
            price_spans(itertools.chain([first], records), reader.words, entry, end, report)
        for _ in records:                   # whatever follows the last history
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
