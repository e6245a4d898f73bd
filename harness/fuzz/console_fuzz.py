"""Hammer the FORTH with random console lines, then drive the robot (issue 8).

    python -m harness.fuzz.console_fuzz --lines 10000 --seed 1983     # make fuzz

Lines come from harness/fuzz/lines.py (seeded) and go to the machine through
the lock-step driver (harness/machine/scripted_machine.py), so a run is deterministic.
Every line must end at the prompt, " ok" or a FORTH error. Counted as failures:
  halt    the simulator stopped (SIMH's sim>), so the machine is rebooted;
  hang    no prompt within the line limit; ^C is typed, and if even that does
          not bring the prompt back the machine is rebooted;
  reboot  the probe after every PROBE_EVERY lines found the FORTH broken: an
          error line resets it, then 7 DUP * . must print 49 and a word
          defined before the first line must still run.
The run ends by forgetting the words the lines defined (the MARKER FUZZ-START set
at boot: a long run fills the dictionary, as a class's would), then 1000 LOAD,
Set.Up.Robot and a move of x by +800 counts and y by -800, whose counters must
end within TOLERANCE counts of that two seconds later (the printed servo hunts
round its targets: docs/servo.md). The directions: with no servo running, x
drifts onto its lower end stop and y onto its upper one within about three
simulated minutes, and a long run takes more. Last, two simulators on one
image (harness/fuzz/two_writers.py): --writer-rounds seeded rounds of a second
simulator, read-write (refused) or read-only, beside the fuzz's machine. Exit
status 0 when all three counts are 0, the move works and no round failed, else 1.
"""
import argparse
import collections
import re
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from harness.fuzz import two_writers
from harness.fuzz.lines import EMPTIES_STACK, LineMaker
from harness.machine.build import fresh_disk
from harness.machine.scripted_machine import ScriptedMachine

LINE_LIMIT = 10.0          # simulated seconds; the slowest fuzz lines take well under 1
PROBE_EVERY = 25
START_MARKER = "MARKER FUZZ-START"   # the final move forgets the fuzz's words first
CHECK_WORD = ": FUZZ-CHECK 7 DUP * ;"
PROBE = "DECIMAL 7 DUP * . FUZZ-CHECK ."
TARGET = (800, -800)
MOVE = ["1000 LOAD", "Set.Up.Robot", f"{TARGET[0]} {TARGET[1]} 0 0 Abs.Move"]
COUNTERS = "0 Read.Counter . 1 Read.Counter ."
TOLERANCE = 100
WRITER_ROUNDS = 20         # second simulators tried beside the fuzz's machine


@dataclass
class Report:
    lines: int = 0
    ok: int = 0
    errors: collections.Counter = field(default_factory=collections.Counter)
    halts: list = field(default_factory=list)
    hangs: list = field(default_factory=list)
    reboots: list = field(default_factory=list)
    counters: tuple = ()
    move_failure: str = ""
    writer_rounds: int = 0
    two_writers: list = field(default_factory=list)     # failures, one line each
    seconds: float = 0.0

    @property
    def move_works(self):
        return len(self.counters) == 2 and all(abs(c - t) <= TOLERANCE
                                               for c, t in zip(self.counters, TARGET))

    @property
    def passed(self):
        return not (self.halts or self.hangs or self.reboots or self.two_writers) \
            and self.move_works

    def text(self):
        errors = sum(self.errors.values())
        rows = [f"fuzz: {self.lines} lines in {self.seconds:.1f} s of host time "
                f"({self.lines / max(self.seconds, 1e-9):.0f} lines/s)",
                f"  answered ok {self.ok}, with a FORTH error {errors}",
                f"  halts (sim> reached) {len(self.halts)}, hangs (line limit hit) "
                f"{len(self.hangs)}, lines needing a reboot {len(self.reboots)}"]
        for what, where in (("halt", self.halts), ("hang", self.hangs), ("reboot", self.reboots)):
            rows += [f"    {what} at line {n}: {line!r}: {why}" for n, line, why in where[:10]]
        rows.append("  most frequent errors: " + "; ".join(
            f"{msg} x{k}" for msg, k in self.errors.most_common(8)))
        rows.append(f"  then {' '.join(MOVE)}, 2 s later the x y "
                    f"counters read {' '.join(map(str, self.counters)) or 'nothing'}: "
                    f"{'the move works' if self.move_works else 'THE MOVE FAILED'}"
                    + (f" ({self.move_failure})" if self.move_failure else ""))
        rows.append(f"  two simulators on one image: {self.writer_rounds} rounds, "
                    f"{len(self.two_writers)} failed")
        rows += [f"    {failure}" for failure in self.two_writers[:10]]
        return "\n".join(rows)


def error_class(message):
    """The message without the word and the trap details: what kind of error."""
    return re.sub(r" \(vector.*", "", message.rsplit(": ", 1)[0]) if message else ""


class Fuzzer:
    def __init__(self, workdir, line_limit=LINE_LIMIT):
        self.workdir = Path(workdir)
        self.line_limit = line_limit
        self.machine = None
        self.boots = 0

    def boot(self):
        if self.machine:
            self.machine.close()
        self.boots += 1
        self.disk = fresh_disk(self.workdir, f"fuzz-{self.boots}.dsk").name
        self.machine = ScriptedMachine(self.disk, cwd=self.workdir, line_limit=self.line_limit)
        if not (self.machine.line(START_MARKER).ok and self.machine.line(CHECK_WORD).ok):
            raise RuntimeError("the fuzz's check word does not compile on a fresh boot")

    def send(self, n, line, report):
        """One line; returns False when the machine had to be rebooted."""
        answer = self.machine.line(line)
        if answer.stopped and "no prompt within" in answer.stopped:
            answer = self.machine.interrupt()
            report.hangs.append((n, line, "^C " + ("brought the prompt back" if not answer.stopped
                                                   else "did not help: rebooted")))
        if answer.stopped:
            if not report.hangs or report.hangs[-1][0] != n:
                report.halts.append((n, line, answer.stopped))
            self.boot()
            return False
        if answer.error:
            report.errors[error_class(answer.error)] += 1
        else:
            report.ok += 1
        return True

    def probe(self, n, report):
        """Reset whatever the lines left open, then check the FORTH still works."""
        reset = self.machine.line(EMPTIES_STACK)
        answer = self.machine.line(PROBE)
        out = answer.output.replace("\r\n", " ")
        if reset.stopped or answer.stopped or answer.error or "49 49" not in out:
            report.reboots.append((n, PROBE, (reset.stopped or answer.stopped or answer.error
                                              or out.strip())[:120]))
            self.boot()

    def robot_move(self, report):
        """As a class would between exercises: forget the words the lines defined
        (a long run fills the dictionary), then load the blocks and move."""
        self.probe(report.lines, report)
        for line in ["FUZZ-START", *MOVE]:
            answer = self.machine.line(line)
            if not answer.ok:
                return f"{line}: {answer.error or answer.stopped}"
        self.machine.wait(2.0)
        found = re.findall(r"-?\d+", self.machine.line(COUNTERS).output[len(COUNTERS):])
        report.counters = tuple(int(x) for x in found[:2])
        return ""

    def close(self):
        if self.machine:
            self.machine.close()


def fuzz(lines, seed, line_limit=LINE_LIMIT, progress=None, writer_rounds=WRITER_ROUNDS):
    """Run `lines` random lines from `seed`, the move, then `writer_rounds` rounds of
    two simulators on one image; the Report."""
    report, maker = Report(), LineMaker(seed)
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        fuzzer = Fuzzer(tmp, line_limit)
        try:
            fuzzer.boot()
            for n in range(1, lines + 1):
                line = maker.line()
                report.lines = n
                if fuzzer.send(n, line, report) and n % PROBE_EVERY == 0:
                    fuzzer.probe(n, report)
                if progress and n % 1000 == 0:
                    progress(f"  {n} lines ...")
            failure = fuzzer.robot_move(report)
            if failure:
                report.counters, report.move_failure = (), failure
            report.writer_rounds = writer_rounds
            report.two_writers = two_writers.check(fuzzer.machine, Path(tmp), fuzzer.disk,
                                                   writer_rounds, seed)
        finally:
            fuzzer.close()
    report.seconds = time.monotonic() - start
    return report


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lines", type=int, default=10000, help="random lines (default 10000)")
    parser.add_argument("--seed", type=int, default=1983, help="the generator's seed")
    parser.add_argument("--writer-rounds", type=int, default=WRITER_ROUNDS,
                        help=f"second simulators on the image (default {WRITER_ROUNDS})")
    args = parser.parse_args(argv)
    if args.lines < 1 or args.writer_rounds < 0:
        parser.error("--lines must be at least 1, --writer-rounds at least 0")
    report = fuzz(args.lines, args.seed, progress=lambda s: print(s, flush=True),
                  writer_rounds=args.writer_rounds)
    print(report.text())
    return 0 if report.passed else 1


if __name__ == "__main__":
    sys.exit(main())
