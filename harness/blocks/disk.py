"""RL02 disk images of FORTH blocks: pack a blocks/ directory into an image, export
blocks from an image back to text files.

An RL02 holds 512 cylinders x 2 heads x 40 sectors x 256 bytes = 10,485,760 bytes,
i.e. 10240 blocks of 1024 bytes; block n is bytes 1024n..1024n+1023 (sectors
4n..4n+3), so the image is also a plain FORTH block file.  Unused blocks are spaces:
an empty FORTH screen is blank text, which LISTs as empty lines, LOADs as nothing and
is what the editor expects to insert into (zero bytes would be control characters).

Every write goes to a temporary file in the destination's directory that is renamed
into place only when complete, so a failure never leaves a half-written file.
"""
import fcntl
import os
import re
import stat
import tempfile
from pathlib import Path

from harness.blocks.blockfile import (BLOCK_BYTES, BLANK_BLOCK, BlockError, block_to_text,
                               fused_line_ends, is_blank, text_to_block)

RL02_BYTES = 512 * 2 * 40 * 256
BLOCKS = RL02_BYTES // BLOCK_BYTES    # 10240
_NAME = re.compile(r"^(\d+)\.txt$")


class DiskError(Exception):
    """A disk command failed; the message says what and where, nothing was written."""


def block_file_name(n):
    """The file name of block n in a blocks/ directory: 1000.txt, 0007.txt, 10200.txt."""
    return f"{n:04d}.txt"


def block_ranges(numbers):
    """'1000-1012, 1020' for the block numbers 1000..1012 and 1020."""
    spans = []
    for n in sorted(numbers):
        if spans and n == spans[-1][1] + 1:
            spans[-1][1] = n
        else:
            spans.append([n, n])
    return ", ".join(f"{a}-{b}" if a != b else f"{a}" for a, b in spans)


def check_block_number(n, what="block"):
    if not 0 <= n < BLOCKS:
        raise DiskError(f"{what} {n} is outside the RL02 disk (blocks 0-{BLOCKS - 1})")


def read_block_dir(directory):
    """{block number: 1024 bytes} from the NNNN.txt files of `directory` (other files
    are ignored).  Returns (blocks, warnings); raises DiskError listing every problem."""
    directory = Path(directory)
    if not directory.is_dir():
        raise DiskError(f"{directory}: no such directory of block files")
    blocks, problems, warnings = {}, [], []
    for path in sorted(directory.glob("*.txt")):
        match = _NAME.match(path.name)
        if not match:
            problems.append(f"{path}: not a block file name (block files are NNNN.txt, "
                            "the block number with at least 4 digits)")
            continue
        n = int(match.group(1))
        if path.name != block_file_name(n):
            problems.append(f"{path}: block {n} must be named {block_file_name(n)}")
            continue
        if n >= BLOCKS:
            problems.append(f"{path}: block {n} is outside the RL02 disk "
                            f"(blocks 0-{BLOCKS - 1})")
            continue
        try:
            text = path.read_bytes().decode("utf-8")
        except (OSError, UnicodeDecodeError) as err:
            problems.append(f"{path}: cannot read as text: {err}")
            continue
        try:
            blocks[n] = text_to_block(text, str(path))
        except BlockError as err:
            problems.extend(str(p) for p in err.problems)
            continue
        warnings.extend(f"{path}: lines {line} and {line + 1} run together when loaded "
                        f"(line {line} fills all 64 columns)"
                        for line in fused_line_ends(blocks[n]))
    if problems:
        raise DiskError("\n".join(problems))
    if not blocks:
        raise DiskError(f"{directory}: no block files (NNNN.txt) found")
    return blocks, warnings


def pack(blocks):
    """The bytes of an RL02 image holding `blocks` ({n: 1024 bytes}); the rest blank."""
    image = bytearray(BLANK_BLOCK * BLOCKS)
    for n, data in blocks.items():
        check_block_number(n)
        image[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES] = data
    return bytes(image)


def read_image(path):
    """The bytes of an RL02 image file, checked for size."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as err:
        raise DiskError(f"{path}: cannot read the disk image: {err.strerror}") from err
    if len(data) != RL02_BYTES:
        raise DiskError(f"{path}: {len(data)} bytes is not an RL02 image "
                        f"({RL02_BYTES} bytes = {BLOCKS} blocks of {BLOCK_BYTES})")
    return data


def check_image(path, writable=True):
    """Refuse an image SIMH could not use as the RL02: raise DiskError with one line
    naming the file and what is wrong (missing, not a file, empty, not RL02-sized,
    unreadable, or, when `writable`, write-locked). Reads nothing but the metadata
    and opens the file; SIMH itself would ask "Overwrite last track?" of an empty
    file and boot with no disk, or a read-only one, from a bad one."""
    path = Path(path)
    try:
        st = path.stat()
    except FileNotFoundError:
        raise DiskError(f"{path}: no such disk image") from None
    except OSError as err:
        raise DiskError(f"{path}: cannot reach the disk image: {err.strerror}") from err
    if not stat.S_ISREG(st.st_mode):
        raise DiskError(f"{path}: not a disk image (not a regular file)")
    if st.st_size == 0:
        raise DiskError(f"{path}: empty (0 bytes), not an RL02 image "
                        f"({RL02_BYTES} bytes)")
    if st.st_size != RL02_BYTES:
        raise DiskError(f"{path}: {st.st_size} bytes is not an RL02 image "
                        f"({RL02_BYTES} bytes = {BLOCKS} blocks of {BLOCK_BYTES})")
    # Root opens a file whatever its mode: a mode with no read (write) bit is
    # taken as the owner's intent all the same.
    if st.st_mode & 0o444 == 0:
        raise DiskError(f"{path}: cannot be read (no read permission)")
    _check_opens(path, "rb", "cannot be read")
    if writable:
        locked = "write-locked: blocks could not be saved to it"
        if st.st_mode & 0o222 == 0:
            raise DiskError(f"{path}: {locked} (no write permission)")
        _check_opens(path, "r+b", locked)


def writer_of(path):
    """Who writes the image: a simulator holds an exclusive flock(2) on it while an RL
    unit has it attached read-write (pdp11-devices/simh/rl_one_writer.c). The text of
    PATH.lock ("pid N since DATE UTC") when one does, else None."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return None                          # check_image says why
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        try:
            return Path(f"{path}.lock").read_text().strip() or "another process"
        except OSError:
            return "another process"
    except OSError:
        return None                          # a file system without locks
    finally:
        os.close(fd)                         # our own test lock goes with it
    return None


def check_not_held(path, why="one simulator writes an image at a time: leave that "
                   "one first, or --read-only"):
    """DiskError (one line, naming the holder) when a simulator writes `path`."""
    holder = writer_of(path)
    if holder:
        raise DiskError(f"{path}: in use by {holder} ({why})")


def _check_opens(path, mode, what):
    try:
        with open(path, mode):
            pass
    except OSError as err:
        raise DiskError(f"{path}: {what} ({err.strerror})") from err


def image_block(image, n):
    check_block_number(n)
    return image[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES]


def blocks_missing(work, pristine):
    """Block numbers blank on the image `work` and written on `pristine` (both image
    bytes): the blocks a newer version of the project ships that a working disk made
    by an older one lacks (make never overwrites local/robot.dsk)."""
    return [n for n in range(BLOCKS)
            if is_blank(image_block(work, n)) and not is_blank(image_block(pristine, n))]


def add_missing_blocks(work_path, pristine_path):
    """Copy into the image at `work_path` every block blank there and written on
    `pristine_path`; no written block of `work_path` is touched. Refused (DiskError,
    nothing written) while a simulator writes the image. Returns the block numbers."""
    check_image(work_path)
    check_not_held(work_path, why="leave it first: BYE at its console")
    work, pristine = read_image(work_path), read_image(pristine_path)
    missing = blocks_missing(work, pristine)
    if missing:
        merged = bytearray(work)
        for n in missing:
            merged[n * BLOCK_BYTES:(n + 1) * BLOCK_BYTES] = image_block(pristine, n)
        try:
            write_atomic(work_path, bytes(merged))
        except OSError as err:
            raise DiskError(f"{work_path}: cannot write the image: {err.strerror}") from err
    return missing


def write_atomic(path, data):
    """Write `data` (bytes) to `path` through a temporary file renamed into place."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        os.chmod(tmp, 0o666 & ~_umask())     # mkstemp makes 0600; act like open()
        with os.fdopen(fd, "wb") as out:
            out.write(data)
            out.flush()
            os.fsync(out.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def plan_export(image, first, last, include_blank, out_dir, force):
    """What exporting blocks first..last of `image` into `out_dir` would do: a list of
    (block, path, text, action) with action 'write', 'replace' or 'unchanged', and a
    list of blank blocks skipped.  Raises DiskError (nothing written) on any problem:
    a bad range, a block that is not text, a file that differs and --force not given."""
    check_block_number(first, "first block")
    check_block_number(last, "last block")
    if first > last:
        raise DiskError(f"empty range: first block {first} is after last block {last}")
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise DiskError(f"{out_dir}: exists and is not a directory")
    plan, skipped, problems = [], [], []
    for n in range(first, last + 1):
        data = image_block(image, n)
        if is_blank(data) and not include_blank:
            skipped.append(n)
            continue
        try:
            text = block_to_text(data, f"block {n}")
        except BlockError as err:
            problems.extend(str(p) for p in err.problems)
            continue
        path = out_dir / block_file_name(n)
        action = "write"
        if path.exists():
            if _same_block(path, data):
                action = "unchanged"
            elif force:
                action = "replace"
            else:
                problems.append(f"{path}: exists and differs from block {n} "
                                "(use --force to overwrite, or export to another directory)")
        plan.append((n, path, text, action))
    if problems:
        raise DiskError("\n".join(problems))
    return plan, skipped


def _same_block(path, data):
    """True when the text file at `path` packs to exactly `data` (so a file with
    fewer than 16 lines, or trailing blanks, still counts as the same block)."""
    try:
        return text_to_block(path.read_bytes().decode("utf-8"), str(path)) == data
    except (OSError, UnicodeDecodeError, BlockError):
        return False


def carry_out_export(plan, out_dir):
    Path(out_dir).mkdir(parents=True, exist_ok=True)
    for _n, path, text, action in plan:
        if action != "unchanged":
            write_atomic(path, text.encode("ascii"))
