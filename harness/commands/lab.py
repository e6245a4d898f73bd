"""`lab`: the lab bench, the console, the robot, a scope and the servo's words in a
browser page (what make lab starts; docs/lab.md)."""
import argparse
import asyncio
from pathlib import Path

from harness.blocks.disk import DiskError
from harness.commands.argtypes import absolute_path
from harness.commands.console import ConsoleError, working_disk
from harness.lab.server import NODE_MODULES, serve
from harness.machine.build import KERNEL_MAP, PDP11, PDP11_TIMED
from harness.machine.kernel_layout import KernelMapError, read_kernel_map

ERRORS = (ConsoleError, DiskError, KernelMapError)

DESCRIPTION = """\
The lab bench: the FORTH console, the robot, a scope and the servo in a browser page.

Boots the FORTH on the working disk (local/robot.dsk, as make run) and serves
the page on 127.0.0.1 only; open the URL it prints (it holds this session's
token; the server opens no browser). Leave with BYE in the page's terminal (the
FORTH FLUSHes its blocks, the disk is detached) or ^C here. While another
simulator writes the disk (make run), the lab says who and exits 1;
--read-only attaches it beside that one.

Simulated time is the instruction count (300 000 a second) unless --timed: then
the 11/23's own clock, each instruction its KDF11-A time (SET CLK TIMED, on
build/pdp11-timed), and the page's clock button switches between the two."""


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("--disk", metavar="IMAGE", help="disk image to use and change "
                        "(default: local/robot.dsk)")
    parser.add_argument("--port", type=int, default=8023,
                        help="port on 127.0.0.1 (default 8023; 0 = any free port)")
    parser.add_argument("--speed", choices=("real", "x10", "full"), default="real",
                        help="pace at start (default: the 11/23's real pace)")
    parser.add_argument("--read-only", action="store_true",
                        help="attach the disk read-only (beside a simulator writing it)")
    parser.add_argument("--timed", action="store_true",
                        help="11/23 time: each instruction takes its KDF11-A time (SET CLK "
                        "TIMED, on build/pdp11-timed), switchable in the page")
    parser.add_argument("--simulator", type=absolute_path, help=argparse.SUPPRESS)
    parser.set_defaults(run=run)


def announce(url):
    print(f"[lab] the lab bench is at {url}", flush=True)
    print("[lab] open it in a browser on this machine; type in the page or, on a "
          "terminal, here too; leave with BYE or ^D (^C here when no terminal types)",
          flush=True)


def run(args):
    disk = working_disk(args.disk, args.read_only)
    args.simulator = args.simulator or str(PDP11_TIMED if args.timed else PDP11)
    if not Path(args.simulator).is_file():
        raise ConsoleError(f"{args.simulator}: no simulator (run make)")
    if not (NODE_MODULES / "@xterm" / "xterm").is_dir():
        raise ConsoleError(f"{NODE_MODULES}: the page's libraries are missing "
                           "(make lab-assets)")
    symbols = read_kernel_map(KERNEL_MAP)
    try:
        safe = asyncio.run(serve(args.simulator, disk, symbols, args.port, args.speed,
                                    announce, args.read_only, block_listing, args.timed))
    except OSError as err:
        raise ConsoleError(f"cannot serve on 127.0.0.1:{args.port}: {err.strerror}") from err
    if safe is None:
        print("[lab] the simulator exited on its own: blocks UPDATEd since the last "
              f"FLUSH, if any, were not written to {disk}")
    return 0 if safe else 1


APPENDIX = 1000, 1012              # the printed blocks: 1000 LOAD loads them all


def block_listing(image, block):
    """The program pane's listing (harness/lab/program_pane.py): {block: for each of
    its 16 lines the rows of what it laid down}, and None; or None and why. A block
    of the appendix is listed with the others (the listing's runs load them all
    anyway), so following 1000 LOAD takes one listing, not thirteen; when that
    fails (a user's disk whose chain differs), the block alone. Imported here: a lab
    that never shows a listing does not pay for the listing's modules at its start."""
    from harness.analysis.listing import ListingError, make_listing
    ranges = [APPENDIX] if APPENDIX[0] <= block <= APPENDIX[1] else []
    for first, last in ranges + [(block, block)]:
        try:
            listing = make_listing(first, last, image=image)
        except ListingError as err:
            failed = str(err)
            continue
        return {n: [listing.line_code(n, line) for line in range(16)]
                for n in range(first, last + 1)}, None
    return None, failed
