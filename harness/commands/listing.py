"""`listing`: blocks 1000-1012 line by line beside what each line put into memory."""
import os
import sys
import tempfile
from pathlib import Path

from harness import simh
from harness.listing import ListingError, make_listing

ERRORS = (ListingError, simh.SimhError)

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
  python -m harness listing --blocks 1002-1003 --out stop.lst"""


def block_range(text):
    try:
        first, _, last = text.partition("-")
        first, last = int(first), int(last or first)
    except ValueError:
        raise ListingError(f"--blocks {text!r}: expected N or N-M") from None
    if not 1000 <= first <= last <= 1012:
        raise ListingError(f"--blocks {text}: the listing covers blocks 1000-1012 "
                           "(the paper's appendix), in increasing order")
    return first, last


def configure(parser):
    import argparse
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--blocks", default="1000-1012", metavar="N[-M]",
                        help="which blocks to list (default 1000-1012)")
    parser.add_argument("--out", metavar="FILE", help="write the listing here (default: stdout)")
    parser.set_defaults(run=run)


def run(args):
    first, last = block_range(args.blocks)
    text = make_listing(first, last).format() + "\n"
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
