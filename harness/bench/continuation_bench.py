"""make bench-continuation: what the continuation's interrupt routine
(Interrupt.Path, block 1045: the path generator, the gripper stepping, then
the servo) costs the 11/23 per 60 Hz tick, priced with the KDF11-A tables
(harness/analysis/timing.py, as harness/bench/robot_bench.py prices Interrupt.Servo), with
the servo alone for comparison, no path running, along a path (a 4-inch square at 2400 counts/s, phase
changes included) and while the gripper steps; on the printed servo and on
the corrected one (block 1030).
"""
import sys
import tempfile

from harness.analysis import timing
from harness.analysis.servo_timing import setup_script
from harness.machine.build import RATE, fresh_disk

SQUARE = ("Path.Clear 3200 0 400 0 Via 3200 3200 400 0 Via 0 3200 400 0 Via "
          "0 0 400 0 Via 2400 Path.Run")
CASES = [  # label, lines after the set-up, seconds measured
    ("the servo alone (Interrupt.Servo, the same state)", ["' Interrupt.Servo 100O !"], 1.0),
    ("no path, gripper idle", [], 1.0),
    ("along a 4 in square at 2400 counts/s (5.6 s)", [SQUARE], 5.6),
    ("gripper stepping, 1 step a tick", ["150 -1 Grip.Move"], 1.0),
]


def cost(disk, label, lines, seconds):
    report = timing.measure(setup_script(disk, lines), vector=0o100,
                            instructions=round(seconds * RATE))
    if "-v" in sys.argv:
        print(report.format("Interrupt.Path"))
    us = [s.microseconds for s in report.spans]
    n = [s.instructions for s in report.spans]
    print(f"  {label}: {report.count} ticks, "
          f"{sum(n) / len(n):.1f} instructions (max {max(n)}) and {report.mean_us:.0f} us "
          f"(max {max(us):.0f}) per tick = {100 * report.mean_us / timing.TICK_US:.2f} % "
          "of the 16.7 ms tick")


def main():
    print("==> continuous path and gripper, Interrupt.Path's cost (KDF11-A prices)")
    with tempfile.TemporaryDirectory() as tmp:
        for servo, load in (("printed servo", "1000 LOAD 1040 LOAD"),
                            ("corrected servo, block 1030", "1000 LOAD 1030 LOAD 1040 LOAD")):
            print(f" {servo}")
            for k, (label, lines, seconds) in enumerate(CASES):
                disk = fresh_disk(tmp, f"bench{k}.dsk")
                cost(disk, label, [load, "Set.Up.Robot Path.Servo"] + lines, seconds)
    return 0


if __name__ == "__main__":
    sys.exit(main())
