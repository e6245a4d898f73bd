"""`console`: the interactive FORTH terminal that `make run` starts."""
import argparse
import shutil
from pathlib import Path

from harness.blocks.disk import DiskError, check_image, check_not_held
from harness.commands.argtypes import absolute_path, number_above, positive
from harness.machine.console_session import BUSY_WAIT, HINT, IDLE_SPEED_MAX, RACK_HINT, session
from harness.machine.build import (PDP11, PDP11_TIMED, PRISTINE_DISK as PRISTINE,
                                    WORKING_DISK as WORK_DISK)



class ConsoleError(RuntimeError):
    """The console cannot start."""


ERRORS = (ConsoleError, DiskError)

DESCRIPTION = f"""\
Boot the FORTH on the robot's PDP-11/23 and join your terminal to its console,
ready for `1000 LOAD`. The machine runs at the 11/23's pace (SET CLK
REALTIME) unless --fast: then at full speed while the FORTH works, and at the
11/23's pace while it waits for a key (SET CPU IDLE), which costs the host little;
--idle-speed N makes those waits pass N times faster: a key is read at the next
clock tick, and a line's characters come as on a 9600-baud line (about 1 ms of
waiting each at the 11/23's pace).

{HINT}

{RACK_HINT}

The disk is the working copy local/robot.dsk (created from build/robot.dsk when
missing; make never overwrites it), or --disk IMAGE. One simulator writes an
image at a time: while another (make lab, a second make run) has it, the
console says who and exits 1; --read-only attaches it beside that one, to look
(FLUSH then fails and says so; nothing is written)."""


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--disk", metavar="IMAGE", help="disk image to use and change "
                        "(default: local/robot.dsk)")
    parser.add_argument("--fast", action="store_true",
                        help="full speed instead of the 11/23's real-time pace")
    parser.add_argument("--idle-speed", type=idle_speed, default=1, metavar="N",
                        help="with --fast: the FORTH's waits for keys (at the prompt, and "
                        "between a line's characters) pass at N times the 11/23's pace "
                        f"(SET CLK IDLESPEED, 1-{IDLE_SPEED_MAX}; default 1): a simulated "
                        "second of waiting takes 1/N wall seconds")
    parser.add_argument("--trace", metavar="FILE", help="record the plant trace (CSV)")
    parser.add_argument("--read-only", action="store_true",
                        help="attach the disk read-only (beside a simulator writing it)")
    parser.add_argument("--timed", action="store_true",
                        help="11/23 time: each instruction takes its KDF11-A time (SET CLK "
                        "TIMED, on build/pdp11-timed) instead of 1/300000 s")
    parser.add_argument("--simulator", type=absolute_path, help=argparse.SUPPRESS)
    # wall seconds a running word gets at BYE before ^C stops it (tests shorten it)
    parser.add_argument("--busy-wait", type=positive, default=BUSY_WAIT,
                        help=argparse.SUPPRESS)
    parser.set_defaults(run=run)


# --idle-speed's value: SET CLK IDLESPEED's range (pdp11-devices/bus/kw11l.c)
idle_speed = number_above(int, 0, f"a whole number from 1 to {IDLE_SPEED_MAX}",
                          at_most=IDLE_SPEED_MAX)


def working_disk(requested, read_only=False):
    """The image to attach, checked (harness.blocks.disk.check_image: the console changes
    it, so it must be writable and no other simulator may be writing it, unless
    read_only); the default working copy is made when missing."""
    if requested:
        disk = Path(requested)
        _check(disk, read_only)
        return disk
    if not WORK_DISK.is_file():
        if not PRISTINE.is_file():
            raise ConsoleError(f"neither {WORK_DISK} nor {PRISTINE} exists: run make")
        WORK_DISK.parent.mkdir(parents=True, exist_ok=True)
        tmp = WORK_DISK.with_suffix(".tmp")
        shutil.copyfile(PRISTINE, tmp)
        tmp.replace(WORK_DISK)
        print(f"[console] working disk {WORK_DISK} created from {PRISTINE}")
    _check(WORK_DISK, read_only)
    return WORK_DISK


def _check(disk, read_only):
    check_image(disk, writable=not read_only)
    if not read_only:
        check_not_held(disk)


def run(args):
    if args.idle_speed != 1 and not args.fast:
        raise ConsoleError("--idle-speed paces the waits of --fast (without it every "
                           "instruction runs at the 11/23's pace): give --fast too")
    disk = working_disk(args.disk, args.read_only)
    args.simulator = args.simulator or str(PDP11_TIMED if args.timed else PDP11)
    if not Path(args.simulator).is_file():
        raise ConsoleError(f"{args.simulator}: no simulator (run make)")
    if args.trace and not Path(args.trace).resolve().parent.is_dir():
        raise ConsoleError(f"{args.trace}: its directory does not exist")
    return session(args.simulator, disk, trace=args.trace, fast=args.fast, timed=args.timed,
                   busy_wait=args.busy_wait, read_only=args.read_only,
                   idle_speed=args.idle_speed)
