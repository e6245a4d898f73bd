"""`disk`: pack a blocks/ directory into an RL02 image, export blocks back to text,
add to a working disk the blocks a newer version ships."""
import sys

from harness.blocks.disk import (BLOCKS, DiskError, add_missing_blocks, block_ranges,
                                 carry_out_export, pack, plan_export, read_block_dir,
                                 read_image, write_atomic)
from harness.machine.build import PRISTINE_DISK, WORKING_DISK

ERRORS = (DiskError,)


def configure(parser):
    sub = parser.add_subparsers(dest="action", metavar="ACTION", required=True)

    p = sub.add_parser("pack", help="pack NNNN.txt block files into an RL02 image",
                       description="Pack the NNNN.txt block files of SOURCE_DIR into a "
                       "new RL02 image (10,485,760 bytes; unused blocks blank).")
    p.add_argument("source_dir", metavar="SOURCE_DIR", help="directory of NNNN.txt files")
    p.add_argument("image", metavar="IMAGE", help="image file to write (replaced whole)")
    p.set_defaults(run=run_pack)

    e = sub.add_parser("export", help="export blocks of an image to NNNN.txt files",
                       description="Write blocks of IMAGE as NNNN.txt text files into "
                       "OUT_DIR. By default only blocks that are not blank. An existing "
                       "file that differs is an error unless --force; nothing is "
                       "written unless every block can be.")
    e.add_argument("image", metavar="IMAGE", help="RL02 image to read")
    e.add_argument("out_dir", metavar="OUT_DIR", help="directory for the text files")
    e.add_argument("--from", dest="first", type=int, default=0, metavar="N",
                   help="first block (default 0)")
    e.add_argument("--to", dest="last", type=int, default=BLOCKS - 1, metavar="N",
                   help=f"last block (default {BLOCKS - 1})")
    e.add_argument("--all", dest="include_blank", action="store_true",
                   help="also export blank blocks (as 16 empty lines)")
    e.add_argument("--force", action="store_true",
                   help="overwrite existing files that differ")
    e.set_defaults(run=run_export)

    a = sub.add_parser("add-new", help="add to a working disk the blocks it lacks "
                       "(blank there, written on the pristine image)",
                       description="Copy into IMAGE each block that is blank there and "
                       "written on the pristine image: the blocks a newer version of the "
                       "project ships (make never overwrites your working disk). A block "
                       "you wrote is never touched. Refused while a simulator has IMAGE.")
    a.add_argument("image", metavar="IMAGE", nargs="?", default=str(WORKING_DISK),
                   help="the image to complete (default: local/robot.dsk)")
    a.add_argument("--from", dest="pristine", default=str(PRISTINE_DISK), metavar="PRISTINE",
                   help="where the blocks come from (default: build/robot.dsk)")
    a.set_defaults(run=run_add_new)


def run_pack(args):
    blocks, warnings = read_block_dir(args.source_dir)
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
    try:
        write_atomic(args.image, pack(blocks))
    except OSError as err:
        raise DiskError(f"{args.image}: cannot write the image: {err.strerror}") from err
    numbers = sorted(blocks)
    print(f"{args.image}: {len(numbers)} blocks packed from {args.source_dir} "
          f"({block_ranges(numbers)})")
    return 0


def run_export(args):
    image = read_image(args.image)
    plan, skipped = plan_export(image, args.first, args.last, args.include_blank,
                                args.out_dir, args.force)
    try:
        carry_out_export(plan, args.out_dir)
    except OSError as err:
        raise DiskError(f"{args.out_dir}: cannot write: {err.strerror}") from err
    for n, path, _text, action in plan:
        print(f"{action:9} {path}")
    if not plan:
        print(f"no blocks to export: blocks {args.first}-{args.last} of {args.image} "
              "are blank (--all exports blank blocks)")
    elif skipped and args.last - args.first < 100:
        print(f"blank, not exported: {block_ranges(skipped)} (--all exports them)")
    return 0


def run_add_new(args):
    added = add_missing_blocks(args.image, args.pristine)
    if added:
        print(f"{args.image}: {len(added)} blocks added from {args.pristine} "
              f"({block_ranges(added)}); no written block was changed")
    else:
        print(f"{args.image}: nothing to add: every block written on {args.pristine} "
              "is written here too")
    return 0
