"""`tick`: walk the 1983 servo one 60 Hz tick at a time (harness/analysis/tick_view.py)."""
import argparse
import sys
import tempfile

from harness.analysis.tick_view import SETUP, WATCH, open_view
from harness.commands.argtypes import count
from harness.machine.machine import ForthError, MachineHalted
from harness.machine.build import fresh_disk
from harness.machine.scripted_machine import ScriptError

ERRORS = (ForthError, MachineHalted, ScriptError, RuntimeError)

DESCRIPTION = f"""\
Boot the FORTH on a fresh copy of build/robot.dsk, type the set-up lines
(default: {' / '.join(SETUP)}), then the lines to watch (default:
{' / '.join(WATCH)}), and stop at each 60 Hz tick as the servo is entered
(vector 100). Each stop prints, per axis, Desire.Pos, the counter, Velocity,
0-Vel, State, Command.Status and the DAC code: exactly one tick of simulated
time lies between two tables, and time (and the plant) stands still between
them. On a terminal, Enter shows the next tick and q ends; with --ticks N (or
when the input is not a terminal) N tables are printed.

Example:
  python -m harness tick --ticks 20
  python -m harness tick --line "0 800 400 0 Abs.Move" """


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--setup", action="append", metavar="LINE",
                        help="a FORTH line before the arrays are read; repeatable "
                        f"(default: {' / '.join(SETUP)})")
    parser.add_argument("--line", action="append", metavar="LINE",
                        help=f"a FORTH line to watch; repeatable (default: {WATCH[0]})")
    parser.add_argument("--ticks", type=count, metavar="N",
                        help="print N ticks and end (default: step with Enter on a "
                        "terminal, else 1)")
    parser.set_defaults(run=run)


def run(args):
    interactive = args.ticks is None and sys.stdin.isatty()
    with tempfile.TemporaryDirectory(prefix="tick-") as tmp:
        disk = fresh_disk(tmp)
        robot, view = open_view(disk, args.setup or SETUP, args.line or WATCH)
        with robot:
            for n in range(args.ticks or (1 if not interactive else 10**9)):
                print(view.step(), flush=True)
                if interactive and input("Enter: next tick, q: quit > ").strip().lower() == "q":
                    break
    return 0
