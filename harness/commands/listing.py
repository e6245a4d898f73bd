"""`listing`: blocks line by line beside what each line put into memory."""
import argparse
import os
import sys
import tempfile
from pathlib import Path

from harness.analysis.listing import (PRISTINE, ListingError, format_ranges, listable_blocks,
                                      make_listing)
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

Machine code names its operands: MOV Desire.Pos(R1),R2, MOV R0,@#CntOut (the
constant the source used; the I/O register follows as a comment). A bad --blocks
is a usage error (exit status 2)."""


def block_range(text):
    """--blocks N or N-M (argparse type): N and M are blocks the disk image holds
    (blank blocks between them are skipped)."""
    try:
        first, _, last = text.partition("-")
        first, last = int(first), int(last or first)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected N or N-M") from None
    try:
        present = listable_blocks(PRISTINE.read_bytes())
    except OSError as err:
        raise argparse.ArgumentTypeError(f"cannot read {PRISTINE}: {err.strerror} "
                                         "(run make)") from None
    if first > last or first not in present or last not in present:
        raise argparse.ArgumentTypeError(
            f"{text}: list blocks that {PRISTINE.name} holds, in increasing order: "
            f"{format_ranges(present)}")
    return first, last


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--blocks", default=(1000, 1012), type=block_range, metavar="N[-M]",
                        help="which blocks to list (default 1000-1012; also 1020, 1030-1031)")
    parser.add_argument("--load", type=int, action="append", default=[], metavar="N",
                        help="a block to LOAD after 1000 and before the listed ones "
                        "(repeatable), e.g. --load 1040 for 1060's demonstrations")
    parser.add_argument("--out", metavar="FILE", help="write the listing here (default: stdout)")
    parser.set_defaults(run=run)


def run(args):
    first, last = args.blocks
    text = make_listing(first, last, first_load=args.load).format() + "\n"
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
