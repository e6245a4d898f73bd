"""make bench-timed: SET CLK TIMED against `python -m harness timing`, on the
BYTE Sieve, and the FORTH's figures in 11/23 seconds.

One pass of the Sieve (8190 flags), run between two CODE words MARK and
END-MARK at processor priority 6 (no interrupt comes in between):
  timed   a scripted run with SET CLK TIMED: SIMH's time (75 ns units) at MARK
          and at END-MARK (breakpoints, for this measurement only)
  priced  the same lines on the same disk, untimed, under SIMH's CPU history,
          every instruction from MARK through END-MARK priced by
          harness/analysis/timing.py (kdf11.py's table, SOB taken or not)
They use the one table (harness/analysis/kdf11.py; the simulator's C table is
generated from it) and should agree within 1 %: the difference is SOB priced
taken in the simulator's table. Then the ten-pass Sieve and 1000 LOAD in both
time bases (instruction counts / 300 000, and timed), and
docs/servo.md's moves on x with Move.Complete?."""
import re
import tempfile

from harness.analysis import timing
from harness.analysis.servo_timing import setup_script
from harness.machine.build import DISK_NAME, PDP11, PDP11_TIMED, fresh_disk
from harness.machine.kernel_layout import read_kernel_map
from harness.machine.scripted_machine import ScriptedMachine, feed_commands

DEFINITIONS = [
    "CODE MARK NEXT, END-CODE",
    "CODE END-MARK NEXT, END-CODE",
    "8190 CONSTANT SIZE  CREATE FLAGS SIZE ALLOT",
    ": PRIMES ( -- n ) FLAGS SIZE 1 FILL  0 SIZE 0 DO FLAGS I + C@ IF I 2* 3 + DUP I + "
    "BEGIN DUP SIZE < WHILE 0 OVER FLAGS + C! OVER + REPEAT 2DROP 1+ THEN LOOP ;",
    ": SIEVE ( -- n ) 0 10 0 DO DROP PRIMES LOOP ;",
    ": B-PASS ( -- ) 6 PRIORITY! MARK PRIMES DROP END-MARK 0 PRIORITY! ;",
]
UNIT_S = 75e-9
MOVE_TARGETS = (4000, 4150, 4190)


def machine(tmp, timed):
    """A scripted run on a copy of the disk in `tmp`: timed (build/pdp11-timed,
    SET CLK TIMED) or by the count (build/pdp11)."""
    if timed:
        return ScriptedMachine(DISK_NAME, cwd=tmp, simulator=PDP11_TIMED,
                               settings=("set clk timed",))
    return ScriptedMachine(DISK_NAME, cwd=tmp, simulator=PDP11)


def show_time(m):
    return int(re.search(r"Time:\s*(\d+)", m.simh("show time")).group(1))


def clock_seconds(m):
    return float(re.search(r"time=([\d.]+)s", m.simh("show clk")).group(1))


def addresses(m):
    out = m.line("OCTAL ' MARK U. ' END-MARK U. DECIMAL").output
    mark, end = re.findall(r"\b([0-7]{3,6})\b", out.split("DECIMAL", 1)[1])[:2]
    return int(mark, 8), int(end, 8)


def timed_pass(tmp, definitions=DEFINITIONS):
    """(MARK, END-MARK, seconds of one timed B-PASS: MARK to END-MARK)."""
    with machine(tmp, True) as m:
        for line in definitions:
            m.line(line)
        mark, end = addresses(m)
        m.simh(f"break {mark:o}")
        m.line("B-PASS")                         # stops at MARK
        at_mark = show_time(m)
        m.simh(f"nobreak {mark:o}")
        m.run_to(end, limit=60)
        return mark, end, (show_time(m) - at_mark) * UNIT_S


def priced_pass(tmp, mark, end, definitions=DEFINITIONS, instructions=1_000_000):
    """(seconds, instructions) of B-PASS untimed, priced from SIMH's history."""
    disk = fresh_disk(tmp, "priced.dsk")
    sym = read_kernel_map()
    lines = definitions + ["OCTAL ' MARK U. ' END-MARK U. DECIMAL"]
    setup = (setup_script(disk, lines) + f"deposit {sym['RXTAIL']:o} 0\n"
             + "\n".join(feed_commands(sym, "B-PASS", 0)) + "\n")
    report = timing.measure(setup, entry=mark, end=end, instructions=instructions)
    return report.spans[0].microseconds * 1e-6, report.spans[0].instructions


def seconds_of(line, timed, before=()):
    """Simulated seconds `line` takes (SHOW CLK), timed or by the count."""
    with tempfile.TemporaryDirectory() as tmp:
        fresh_disk(tmp)
        with machine(tmp, timed) as m:
            for b in before:
                m.line(b, limit=600)
            t0 = clock_seconds(m)
            m.line(line, limit=600)
            return clock_seconds(m) - t0


def move_seconds(timed):
    """Simulated seconds of docs/servo.md's moves on x (harness/bench/servo_runs.py's:
    4000 counts out, then 150 and 40 more), each line with Move.Complete?."""
    with tempfile.TemporaryDirectory() as tmp:
        fresh_disk(tmp)
        with machine(tmp, timed) as m:
            m.line("1000 LOAD")
            m.line("Set.Up.Robot")
            found = []
            for x in MOVE_TARGETS:
                t0 = clock_seconds(m)
                answer = m.line(f"{x} 0 0 0 Abs.Move Move.Complete?")
                found.append(clock_seconds(m) - t0 if answer.ok else None)
            return found


def main():
    with tempfile.TemporaryDirectory() as tmp:
        fresh_disk(tmp)
        mark, end, timed = timed_pass(tmp)
        priced, instructions = priced_pass(tmp, mark, end)
    print("SET CLK TIMED against python -m harness timing: one Sieve pass (8190 flags)")
    print(f"  {instructions:,} instructions: {instructions / 300000:.4f} s by the count "
          f"(1/300 000 s each)")
    print(f"  timed run {timed:.4f} s, priced {priced:.4f} s: "
          f"{100 * (timed - priced) / priced:+.3f} % (goal: within 1 %)")
    print("The same work in both time bases (simulated seconds: by the count, timed):")
    for label, line, before in [
            ("BYTE Sieve, 10 passes", "SIEVE .", DEFINITIONS[2:5]),
            ("1000 LOAD", "1000 LOAD", ())]:
        count, real = seconds_of(line, False, before), seconds_of(line, True, before)
        print(f"  {label:32s} {count:9.3f} {real:9.3f}  ({real / count:.3f})")
    print("docs/servo.md's moves on x, each line with Move.Complete? (seconds: by the "
          "count, timed)")
    for x, count, real in zip(MOVE_TARGETS, move_seconds(False), move_seconds(True)):
        shown = [f"{v:9.3f}" if v is not None else "  (error)" for v in (count, real)]
        print(f"  to x = {x:<5d}{'':22s} {shown[0]} {shown[1]}")
    per_instruction = timed / instructions
    print(f"  the tick: 1/60 s = 16.667 ms timed; by the count 5000 instructions, "
          f"{5000 * per_instruction * 1e3:.2f} ms of the Sieve's instructions on a real 11/23")


if __name__ == "__main__":
    main()
