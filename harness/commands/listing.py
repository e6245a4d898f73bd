"""`listing`: blocks line by line beside what each line put into memory."""
import argparse
import os
import sys
import tempfile
from pathlib import Path

from harness.analysis.listing import (PRISTINE, ListingError, format_ranges, listable_blocks,
                                      make_listing)
from harness.commands.invoke import PROG
from harness.machine import simh
from harness.machine.kernel_layout import KernelMapError

ERRORS = (ListingError, simh.SimhError, KernelMapError)

DESCRIPTION = """\
List blocks beside the addresses and words each line compiled or assembled.

Boots the FORTH on a copy of build/robot.dsk, runs `1000 LOAD` with a SIMH
breakpoint on PARSE-NAME that records where each name was read and what the
dictionary held then, and prints each block line followed by the octal words it
laid down: headers ("header of NAME"), threaded code annotated with the names of
the words it calls, and, for CODE words, SIMH's own disassembly.

Examples:
  python -m harness listing                      all of 1000-1012
  python -m harness listing --blocks 1008        the interrupt servo's block
  python -m harness listing --blocks 1002-1003 --out stop.lst
  python -m harness listing --blocks 1030-1031   the proposed ramp (after 1000 LOAD)
  python -m harness listing --disk local/robot.dsk --blocks 1100
                                                 your own block, on your disk

Machine code names its operands: MOV Desire.Pos(R1),R2, MOV R0,@#CntOut (the
constant the source used; the I/O register follows as a comment). A bad --blocks
is a usage error (exit status 2)."""


def block_range(text):
    """--blocks N or N-M (argparse type); whether the disk holds them is checked
    once --disk is known (blocks_refusal)."""
    try:
        first, _, last = text.partition("-")
        return int(first), int(last or first)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected N or N-M") from None


def blocks_refusal(blocks, disk):
    """None, or why --blocks cannot be listed from `disk`: N and M must be blocks
    the image holds (blank blocks between them are skipped)."""
    first, last = blocks
    try:
        present = listable_blocks(Path(disk).read_bytes())
    except OSError as err:
        return f"cannot read {disk}: {err.strerror}" + (" (run make)" if disk == PRISTINE else "")
    if first > last or first not in present or last not in present:
        return (f"{first}-{last}: list blocks that {Path(disk).name} holds, in increasing "
                f"order: {format_ranges(present)}")
    return None


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--blocks", default=(1000, 1012), type=block_range, metavar="N[-M]",
                        help="which blocks to list (default 1000-1012; also 1020, 1030-1031)")
    parser.add_argument("--load", type=int, action="append", default=[], metavar="N",
                        help="a block to LOAD after 1000 and before the listed ones "
                        "(repeatable), e.g. --load 1040 for 1060's demonstrations")
    parser.add_argument("--disk", default=PRISTINE, type=Path, metavar="IMAGE",
                        help="list the blocks of this RL02 image, e.g. your own local/robot.dsk "
                        "(default: build/robot.dsk, the pristine disk); a copy is loaded, the "
                        "image is only read")
    parser.add_argument("--out", metavar="FILE", help="write the listing here (default: stdout)")
    parser.set_defaults(run=run, usage=parser.format_usage)


def run(args):
    why = blocks_refusal(args.blocks, args.disk)
    if why:                                   # a usage error, as argparse reports one
        print(args.usage(), end="", file=sys.stderr)
        print(f"{PROG} listing: error: argument --blocks: {why}", file=sys.stderr)
        return 2
    first, last = args.blocks
    text = make_listing(first, last, image=args.disk, first_load=args.load).format() + "\n"
    if not args.out:
        sys.stdout.write(text)
        return 0
    out = Path(args.out)
    if not out.parent.is_dir():
        raise ListingError(f"--out {out}: no directory {out.parent}")
    fd, tmp = tempfile.mkstemp(dir=out.parent, prefix=f".{out.name}.")
    with os.fdopen(fd, "w") as f:               # written whole, then renamed
        f.write(text)
    os.replace(tmp, out)
    return 0
