"""Block text <-> RL02 disk image.

The image is a plain block file: block n is bytes 1024n..1024n+1023, 16 lines of 64
characters (DESIGN.md section 4). The repository keeps block source as text, one
file per block: blocks/NNNN.fb (NNNN = decimal block number), at most 16 lines of
at most 64 printable ASCII characters; missing lines are blank.

    python -m harness.blocks pack DIR IMAGE        blocks/*.fb -> a fresh RL02 image
    python -m harness.blocks export IMAGE DIR [FIRST [LAST]]
                                                   non-blank blocks -> DIR/NNNN.fb
    python -m harness.blocks working PRISTINE COPY copy PRISTINE to COPY if COPY is missing

Every failure names the file (and line) and exits non-zero; pack writes the image
only when every file is good, so a bad file never leaves half an image behind."""
import re
import shutil
import sys
from pathlib import Path

BLOCK = 1024
LINE = 64
LINES = 16
RL02_BYTES = 10_485_760
BLOCKS = RL02_BYTES // BLOCK
NAME = re.compile(r"^(\d{1,5})\.fb$")


class BlockError(ValueError):
    """Bad block text or a bad block number; the message says where."""


def text_to_block(text, where):
    """1024 bytes from block text (16 lines of 64), or BlockError naming the line."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) > LINES:
        raise BlockError(f"{where}: {len(lines)} lines, a block holds {LINES}")
    out = bytearray()
    for i, line in enumerate(lines, 1):
        line = line.rstrip("\r").rstrip(" ")
        if len(line) > LINE:
            raise BlockError(f"{where}:{i}: {len(line)} characters, a line holds {LINE}")
        bad = [c for c in line if not " " <= c <= "~"]
        if bad:
            raise BlockError(f"{where}:{i}: character {bad[0]!r} is not printable ASCII")
        out += line.ljust(LINE).encode("ascii")
    return bytes(out.ljust(BLOCK, b" "))


def block_to_text(data):
    """Block text from 1024 bytes: 16 lines, trailing blanks and blank lines dropped."""
    lines = []
    for i in range(LINES):
        raw = data[i * LINE:(i + 1) * LINE]
        lines.append("".join(chr(b) if 32 <= b < 127 else " " for b in raw).rstrip())
    while lines and not lines[-1]:
        lines.pop()
    return "".join(line + "\n" for line in lines)


def is_blank(data):
    return all(b in (0, 32) for b in data)


def block_files(folder):
    """{block number: path} of DIR/NNNN.fb; other names are an error. A missing
    folder holds no blocks (git keeps no empty folders)."""
    found = {}
    if not Path(folder).is_dir():
        return found
    for path in sorted(Path(folder).iterdir()):
        if path.suffix != ".fb":
            continue
        m = NAME.match(path.name)
        if not m or int(m.group(1)) >= BLOCKS:
            raise BlockError(f"{path}: name must be NNNN.fb with NNNN in 0..{BLOCKS - 1}")
        found[int(m.group(1))] = path
    return found


def pack(folder, image):
    """Write a fresh RL02 image holding the blocks of folder; blank elsewhere."""
    blocks = {n: text_to_block(p.read_text(encoding="ascii", errors="replace"), p)
              for n, p in block_files(folder).items()}
    image = Path(image)
    tmp = image.with_name(image.name + ".tmp")
    with open(tmp, "wb") as f:
        f.truncate(RL02_BYTES)
        for n, data in sorted(blocks.items()):
            f.seek(n * BLOCK)
            f.write(data)
    tmp.replace(image)
    return sorted(blocks)


def export(image, folder, first=0, last=BLOCKS - 1):
    """Write every non-blank block first..last of image as folder/NNNN.fb; return
    (written, kept): kept are blocks blank on the image whose file is left alone
    (export never deletes: remove such a file by hand if the blank is meant)."""
    if not 0 <= first <= last < BLOCKS:
        raise BlockError(f"block range {first}..{last} is not inside 0..{BLOCKS - 1}")
    folder = Path(folder)
    existing = block_files(folder)
    folder.mkdir(parents=True, exist_ok=True)
    written, kept = [], []
    with open(image, "rb") as f:
        for n in range(first, last + 1):
            f.seek(n * BLOCK)
            data = f.read(BLOCK).ljust(BLOCK, b"\0")
            if not is_blank(data):
                (folder / f"{n:04d}.fb").write_text(block_to_text(data), encoding="ascii")
                written.append(n)
            elif n in existing:
                kept.append(n)
    return written, kept


def working_copy(pristine, copy):
    """Create the user's working disk from the pristine image, never overwriting it."""
    copy = Path(copy)
    if copy.exists():
        return False
    copy.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(pristine, copy)
    return True


def main(argv):
    usage = __doc__.split("\n\n")[2]
    try:
        if len(argv) == 3 and argv[0] == "pack":
            done = pack(argv[1], argv[2])
            print(f"{argv[2]}: {len(done)} blocks packed from {argv[1]}")
        elif 3 <= len(argv) <= 5 and argv[0] == "export":
            span = [int(a) for a in argv[3:]]
            first = span[0] if span else 0
            last = span[1] if len(span) > 1 else (first if span else BLOCKS - 1)
            done, kept = export(argv[1], argv[2], first, last)
            print(f"{argv[2]}: {len(done)} non-blank blocks exported from {argv[1]}")
            for n in kept:
                print(f"{argv[2]}: block {n} is blank on the image; {n:04d}.fb left as it was")
        elif len(argv) == 3 and argv[0] == "working":
            if working_copy(argv[1], argv[2]):
                print(f"{argv[2]}: working disk created from {argv[1]}")
        else:
            print(usage, file=sys.stderr)
            return 2
    except (BlockError, OSError, ValueError) as e:
        print(f"harness.blocks: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
