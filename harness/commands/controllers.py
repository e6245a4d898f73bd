"""`controllers`: the 11/23 and four LSI-11/03 axis controllers in lock-step on one
plant (issue 21, docs/controllers.md): the interactive launcher (`make run
CONTROLLERS=4`), an 11/03's console, and scripted runs of the five."""
import argparse
import os
import sys
import tempfile
import termios
import tty
from pathlib import Path

from harness.commands.argtypes import positive
from harness.commands.console import ConsoleError, working_disk
from harness.controllers import bridge
from harness.controllers.coordinator import CONTROLLERS, MEMBERS, CoordinatorError
from harness.controllers.launcher import STATUS, launch
from harness.lab.controllers_page import serve
from harness.controllers.scripted import run_five_file, split_joined
from harness.blocks.disk import write_atomic
from harness.machine.build import CONTROLLERS_DIR, KERNEL_1103, PRISTINE_DISK
from harness.machine.script_run import ERRORS as RUN_ERRORS

ERRORS = RUN_ERRORS + (ConsoleError, CoordinatorError)

LAUNCH = """\
Boot the five machines in lock-step on one plant: the robot's PDP-11/23, its
console in this terminal as `make run` gives it (on your working disk), and the
LSI-11/03s of axes x, y, z, t (each on a fresh copy of build/robot.dsk, its
kernel build/kernel-1103.lda), typed their boot lines (1080 LOAD, n Axis.Run)
when the disk holds block 1080. The 11/23 gets its link words with the boot line
harness/controllers/boot_lines.py names (docs/controllers.md, "Boot lines").

Each 11/03's console: in another terminal, `python -m harness controllers
console x` (y, z, t); ^] leaves it, ^E there gives that 11/03's sim> (while an
11/03 or the 11/23 stays at sim>, all five wait at their next 1 ms boundary:
simulated time is one). Leave with BYE at the 11/23: the session ends, the
11/03s QUIT. A killed 11/03 is reported at the 11/23's console."""

RUN = """\
A scripted, deterministic run of the five machines: the 11/23 runs SCRIPT (the
console script language of `run`: FORTH lines, #wait, #simh), the 11/03s boot,
are typed their boot lines when the disk holds block 1080, and run free. Writes
DIR/NAME.main.transcript, NAME.x.transcript ... (each console) and
NAME.trace.csv (the one plant's trace, the usual columns). The same script gives
the same bytes. Exit status 0 when every line was answered " ok"."""


def configure(parser):
    sub = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    p = sub.add_parser("launch", help="the five machines, the 11/23's console in front "
                       "(make run CONTROLLERS=4)", description=LAUNCH,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--disk", metavar="IMAGE", help="the 11/23's disk (default local/robot.dsk)")
    p.add_argument("--fast", action="store_true", help="full speed while the machines work")
    p.add_argument("--trace", metavar="FILE", help="record the plant trace (CSV)")
    p.add_argument("--no-boot-lines", action="store_true",
                   help="leave the 11/03s at their prompts")
    p.add_argument("--lab", action="store_true",
                   help="serve the lab's page of the five machines (127.0.0.1, its URL printed)")
    p.add_argument("--busy-wait", type=positive, help=argparse.SUPPRESS)
    # the session's directory (tests: not the user's local/controllers)
    p.add_argument("--session-dir", type=Path, default=CONTROLLERS_DIR, help=argparse.SUPPRESS)
    p.set_defaults(run=run_launch)

    c = sub.add_parser("console", help="join this terminal to an 11/03's console",
                       description="Join this terminal to the console of the 11/03 of "
                       "AXIS in the running `make run CONTROLLERS=4` session; ^] leaves "
                       "(the machine runs on), ^E gives its sim>.")
    c.add_argument("axis", choices=CONTROLLERS, metavar="AXIS", help="x, y, z or t")
    c.add_argument("--session-dir", type=Path, default=CONTROLLERS_DIR, help=argparse.SUPPRESS)
    c.set_defaults(run=run_console)

    r = sub.add_parser("run", help="a scripted run of the five machines", description=RUN,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    r.add_argument("script", metavar="SCRIPT", help="the 11/23's console script")
    r.add_argument("--out", metavar="DIR", help="directory for the outputs (default: the script's)")
    r.add_argument("--disk", metavar="IMAGE", default=str(PRISTINE_DISK),
                   help="disk image every machine starts from, copied (default build/robot.dsk)")
    r.add_argument("--keep-going", action="store_true", help="go on past FORTH errors")
    r.add_argument("--line-limit", type=positive, default=60.0, metavar="SECONDS",
                   help="simulated seconds a line may run (default 60)")
    r.set_defaults(run=run_script)


def run_launch(args):
    disk = working_disk(args.disk)
    if args.trace and not Path(args.trace).resolve().parent.is_dir():
        raise ConsoleError(f"{args.trace}: its directory does not exist")
    if not KERNEL_1103.is_file():
        raise ConsoleError(f"{KERNEL_1103}: no 11/03 kernel (run make)")
    return launch(disk, fast=args.fast, trace=args.trace and Path(args.trace).resolve(),
                  busy_wait=args.busy_wait, boot_lines=False if args.no_boot_lines else None,
                  directory=args.session_dir,
                  page=(lambda d: serve(d / STATUS, d)) if args.lab else None)


def run_console(args):
    if not (args.session_dir / f"{args.axis}.sock").exists():
        raise ConsoleError("no five-machine session is running (make run CONTROLLERS=4)")
    fd = sys.stdin.fileno()
    saved = termios.tcgetattr(fd) if os.isatty(fd) else None
    if saved:
        tty.setraw(fd)
    try:
        said = bridge.join(args.session_dir, args.axis)
    except OSError as e:
        raise ConsoleError(f"cannot reach the console of {args.axis}: {e}") from e
    finally:
        if saved:
            termios.tcsetattr(fd, termios.TCSAFLUSH, saved)
    print(f"\r\n[controllers] {said}")
    return 0


def run_script(args):
    source = Path(args.script)
    out = Path(args.out) if args.out else source.parent
    paths = {m: out / f"{source.stem}.{m}.transcript" for m in MEMBERS}
    trace_path = out / f"{source.stem}.trace.csv"
    with tempfile.TemporaryDirectory(prefix="controllers-run-") as tmp:
        joined = Path(tmp) / "joined.transcript"
        steps, result = run_five_file(source, joined, trace_path, disk=args.disk,
                                      keep_going=args.keep_going, line_limit=args.line_limit)
    for m, text in split_joined(result.transcript).items():
        write_atomic(paths[m], text.encode("latin-1"))
    for failure in result.failures:
        print(failure.where(args.script), file=sys.stderr)
    print(f"{args.script}: five machines, {len(result.failures)} failed; transcripts "
          f"{out}/{source.stem}.{{{','.join(MEMBERS)}}}.transcript, trace {trace_path}")
    return 1 if result.failures else 0
