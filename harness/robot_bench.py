"""make bench (mk/robot.mk): what the 1983 servo costs the 11/23, and how long
`1000 LOAD` takes.

- Interrupt.Servo per 60 Hz tick: every instruction it executes, from the
  interrupt entry to its RTI, priced with the KDF11-A tables (harness/kdf11.py,
  from shared/kdf11-timing.md: basic + source + destination time per
  instruction, DEC's KDF11-A timing tables), through harness/timing.measure
  on SIMH's CPU history; idle (no command pending, the axes hunting around
  their targets) and during a move.
- 1000 LOAD: simulated 11/23 seconds (instructions / 300 000) and host time.
"""
import shutil
import sys
import tempfile
import time
from pathlib import Path

from harness import timing
from harness.robot import KERNEL, RATE, Robot
from harness.scripted_machine import feed_commands, read_kernel_map

ROOT = Path(__file__).resolve().parent.parent
DISK = ROOT / "build" / "robot.dsk"


def setup_script(disk, lines):
    """Boot, stop at QUERY, give each line in turn; leave the machine stopped
    at QUERY after the last one, breakpoint removed."""
    sym = read_kernel_map()
    cmds = [f"attach rl0 {disk}", f"load {KERNEL}", f"break {sym['QUERY']:o}", "go"]
    for line in lines:
        # empty the ring at index 0, then type the line into it
        cmds += [f"deposit {sym['RXTAIL']:o} 0"] + feed_commands(sym, line, 0) + ["cont"]
    return "\n".join(cmds + [f"nobreak {sym['QUERY']:o}"]) + "\n"


def servo_cost(disk, label, lines, seconds):
    report = timing.measure(setup_script(disk, lines), vector=0o100,
                            instructions=round(seconds * RATE))
    print(report.format("Interrupt.Servo")) if "-v" in sys.argv else None
    per_tick = report.total_instructions / max(report.count, 1)
    print(f"  Interrupt.Servo, {label}: {report.count} ticks, "
          f"{per_tick:.1f} instructions and {report.mean_us:.0f} us per tick "
          f"= {100 * report.mean_us / timing.TICK_US:.2f} % of the 16.7 ms tick")


def load_time(disk):
    with Robot(disk=disk) as r:
        t0, s0 = time.perf_counter(), r.time()
        r.send("1000 LOAD")
        host = time.perf_counter() - t0
        print(f"  1000 LOAD: {r.time() - s0:.2f} s simulated 11/23 time "
              f"({(r.time() - s0) * RATE:,.0f} instructions at {RATE:,}/s), "
              f"{1000 * host:.0f} ms host time")


def main():
    print("==> robot servo benchmark (KDF11-A prices: shared/kdf11-timing.md)")
    with tempfile.TemporaryDirectory() as tmp:
        for k, (label, lines, seconds) in enumerate([
                ("idle, 5 s after a move (no command pending; the axes hunt)",
                 ["1000 LOAD Set.Up.Robot", "1600 800 400 0 Abs.Move Move.Complete?"], 5),
                ("during a move, its first 0.6 s (x 4000, y 3000, z 1500 counts)",
                 ["1000 LOAD Set.Up.Robot", "4000 3000 1500 0 Abs.Move"], 0.6)]):
            disk = Path(tmp) / f"bench{k}.dsk"
            shutil.copy(DISK, disk)
            servo_cost(disk, label, lines, seconds)
        disk = Path(tmp) / "load.dsk"
        shutil.copy(DISK, disk)
        load_time(disk)
    return 0


if __name__ == "__main__":
    sys.exit(main())
