"""make bench (mk/robot.mk): what the 1983 servo costs the 11/23, and how long
`1000 LOAD` takes.

- Interrupt.Servo per 60 Hz tick: every instruction it executes, from the
  interrupt entry to its RTI, priced with the KDF11-A tables (harness/analysis/kdf11.py,
  from docs/kdf11-timing.md: basic + source + destination time per
  instruction, DEC's KDF11-A timing tables), through harness/timing.measure
  on SIMH's CPU history; idle (no command pending, the axes hunting around
  their targets) and during a move.
- 1000 LOAD: simulated 11/23 seconds (instructions / 300 000) and host time.
"""
import sys
import tempfile
import time

from harness.analysis import servo_timing
from harness.bench.protection_cost import cost
from harness.machine.build import RATE, fresh_disk
from harness.machine.robot import Robot



def load_time(disk):
    with Robot(disk=disk) as r:
        t0, s0 = time.perf_counter(), r.time()
        r.send("1000 LOAD")
        host = time.perf_counter() - t0
        instructions = round((r.time() - s0) * RATE)
        print(f"  1000 LOAD: {r.time() - s0:.2f} s simulated 11/23 time "
              f"({instructions:,} instructions at {RATE:,}/s), "
              f"{1000 * host:.0f} ms host time")
        print(cost("load", instructions))


def main():
    print("==> robot servo benchmark (KDF11-A prices: docs/kdf11-timing.md)")
    for case in servo_timing.CASES:
        label, report = servo_timing.measure(case)
        if "-v" in sys.argv:
            print(report.format("Interrupt.Servo"))
        print(servo_timing.summary(label, report))
        print(cost("servo idle" if "idle" in label else "servo move",
                   round(report.total_instructions / max(report.count, 1), 1),
                   "instructions per tick"))
    with tempfile.TemporaryDirectory() as tmp:
        disk = fresh_disk(tmp, "load.dsk")
        load_time(disk)
    return 0


if __name__ == "__main__":
    sys.exit(main())
