"""The 1983 servo's cost per 60 Hz tick, in the two states make bench-robot prices
and `python -m harness timing --servo idle|move` reproduces in one command.

Each case boots the FORTH on a copy of build/robot.dsk, types its lines (at the
QUERY breakpoint, as a scripted run does: harness/machine/scripted_machine.py), leaves
the machine stopped at the prompt with the breakpoint removed, and prices every
execution of the code vector 100 holds (Interrupt.Servo after Set.Up.Robot) for
the case's simulated seconds (harness/analysis/timing.py)."""
import tempfile

from harness.analysis import timing
from harness.machine.build import KERNEL, RATE, fresh_disk
from harness.machine.kernel_layout import read_kernel_map
from harness.machine.scripted_machine import feed_commands

CASES = {
    "idle": ("idle, 5 s after a move (no command pending; the axes hunt)",
             ["1000 LOAD Set.Up.Robot", "1600 800 400 0 Abs.Move Move.Complete?"], 5),
    "move": ("during a move, its first 0.6 s (x 4000, y 3000, z 1500 counts)",
             ["1000 LOAD Set.Up.Robot", "4000 3000 1500 0 Abs.Move"], 0.6),
}


def setup_script(disk, lines):
    """Boot, stop at QUERY, give each line in turn; leave the machine stopped
    at QUERY after the last one, breakpoint removed."""
    sym = read_kernel_map()
    cmds = [f"attach rl0 {disk}", f"load {KERNEL}", f"break {sym['QUERY']:o}", "go"]
    for line in lines:
        # empty the ring at index 0, then type the line into it
        cmds += [f"deposit {sym['RXTAIL']:o} 0"] + feed_commands(sym, line, 0) + ["cont"]
    return "\n".join(cmds + [f"nobreak {sym['QUERY']:o}"]) + "\n"


def measure(case):
    """(label, TimingReport) of one case of CASES."""
    label, lines, seconds = CASES[case]
    with tempfile.TemporaryDirectory(prefix="servo-timing-") as tmp:
        disk = fresh_disk(tmp)
        report = timing.measure(setup_script(disk, lines), vector=0o100,
                                instructions=round(seconds * RATE))
    return label, report


def summary(label, report):
    """The one line make bench-robot prints per case."""
    per_tick = report.total_instructions / max(report.count, 1)
    return (f"  Interrupt.Servo, {label}: {report.count} ticks, "
            f"{per_tick:.1f} instructions and {report.mean_us:.0f} us per tick "
            f"= {100 * report.mean_us / timing.TICK_US:.2f} % of the 16.7 ms tick")
