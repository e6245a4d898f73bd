"""`timing SETUP`: the KDF11-A-priced cost of code, from SIMH's CPU history."""
import argparse
from pathlib import Path

from harness.analysis import servo_timing
from harness.analysis.timing import CHUNK, TimingError, measure
from harness.commands.argtypes import count
from harness.machine import simh
from harness.machine.build import RATE

ERRORS = (TimingError, simh.SimhError)

DESCRIPTION = """\
Run build/pdp11 on SETUP (a SIMH script, run after pdp11-devices/machine.ini,
that leaves the machine stopped where measuring starts: deposits and
`deposit pc`, or a `break` and `go`), then step INSTRUCTIONS more instructions
with SIMH's CPU history on, and price every execution of the code at --entry
(or at the address held by --vector) through its RTI, or through the first
execution of the instruction at --end. Prints executions, microseconds per execution and per
60 Hz tick (with the tick's percentage), and a per-instruction breakdown.

Times: DEC KDF11-B User's Guide tables B-4..B-7 (memory management off), as
in docs/kdf11-timing.md; an interrupt entry is charged 9.375 us, an estimate
(IOT's trap sequence), as the tables give none.

Example: the code that vector 100 (the 60 Hz clock) runs, over 2 simulated s:
  python -m harness timing setup.ini --vector 100 --instructions 600000

The 1983 servo, as make bench-robot prices it, in one command (no SETUP):
  python -m harness timing --servo idle    1000 LOAD Set.Up.Robot, a move, then
                                           5 s at rest (the axes hunting)
  python -m harness timing --servo move    the first 0.6 s of a long move"""


def octal(text):
    try:
        value = int(text, 8)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected an octal address") from None
    if not 0 <= value <= 0o177776 or value % 2:
        raise argparse.ArgumentTypeError(f"{text!r}: expected an even address 0..177776")
    return value


def end_condition(text):
    return "rti" if text.lower() == "rti" else octal(text)


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("setup", metavar="SETUP", nargs="?",
                        help="SIMH script that prepares the run")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--servo", choices=sorted(servo_timing.CASES),
                       help="the 1983 servo (Interrupt.Servo) as make bench-robot measures "
                       "it: idle or during a move; no SETUP")
    where.add_argument("--entry", type=octal, metavar="ADDR",
                       help="octal address of the code's first instruction")
    where.add_argument("--vector", type=octal, metavar="VEC",
                       help="octal interrupt vector whose handler is the code")
    parser.add_argument("--end", type=end_condition, default="rti", metavar="rti|ADDR",
                        help="an execution ends with its RTI (default) or with the first "
                        "execution of the instruction at this octal address")
    parser.add_argument("--instructions", type=count, default=RATE, metavar="N",
                        help=f"instructions to run after SETUP (default {RATE}: one "
                        "simulated second at the default RATE)")
    parser.add_argument("--keyboard", metavar="FILE",
                        help="text the console keyboard receives (default none)")
    parser.add_argument("--name", help="what to call the code in the report")
    parser.add_argument("--chunk", type=count, default=CHUNK, metavar="N",
                        help=f"history chunk, 64..262144 (default {CHUNK})")
    parser.set_defaults(run=run, parser=parser)


def _read(path, what):
    try:
        return Path(path).read_text()
    except FileNotFoundError:
        raise TimingError(f"{path}: no such {what} file") from None
    except (OSError, UnicodeDecodeError) as err:
        raise TimingError(f"{path}: cannot read the {what} file: {err}") from None


def run(args):
    if args.servo:
        if args.setup or args.keyboard:
            args.parser.error("--servo prepares its own run: no SETUP or --keyboard")
        label, report = servo_timing.measure(args.servo)
        print(report.format("Interrupt.Servo"))
        print(servo_timing.summary(label, report))
        return 0
    if not args.setup or (args.entry is None and args.vector is None):
        args.parser.error("give SETUP and one of --entry, --vector (or --servo)")
    setup = _read(args.setup, "setup")
    keyboard = _read(args.keyboard, "keyboard") if args.keyboard else ""
    report = measure(setup, entry=args.entry, vector=args.vector, end=args.end,
                     instructions=args.instructions, chunk=args.chunk, keyboard=keyboard)
    print(report.format(args.name))
    return 0
