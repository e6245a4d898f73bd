"""The lab's program pane (pure logic but for reading the disk image): a block's
16 lines as the lab's disk holds them, each with the code it laid down, from
`python -m harness listing` (harness/analysis/listing.py, handed in by
harness/commands/lab.py as `lister`, since the lab ranks beside analysis: its own
SIMH run on a copy of the image, never on the lab's running machine).

The text is the disk's: what FLUSH (or a buffer's reuse) last wrote there, not a
changed buffer the FORTH has not written yet. The page never writes the disk: its
editor types the editor's words at the FORTH (docs/lab.md, "Program").
"""
from pathlib import Path

BLOCKS = 10240                    # the RL02's blocks (forth/EDITOR.md)
BLOCK_BYTES, LINE_CHARS = 1024, 64
LISTED_FROM = 1000                # python -m harness listing lists blocks from 1000 on


def block_lines(image, block):
    """Block `block` of the image as 16 lines of 64 characters (blanks for NULs)."""
    with open(image, "rb") as disk:
        disk.seek(block * BLOCK_BYTES)
        data = disk.read(BLOCK_BYTES).ljust(BLOCK_BYTES, b" ")
    text = data.replace(b"\0", b" ").decode("latin-1")
    return [text[i:i + LINE_CHARS] for i in range(0, BLOCK_BYTES, LINE_CHARS)]


class ProgramPane:
    """Listings of one disk image's blocks, kept while the image is unchanged."""

    def __init__(self, image, lister=None):
        self.image = Path(image)
        self.lister = lister            # (image, block) -> (16 lists of rows, None) or (None, why)
        self._cache = {}                # block -> (image's stamp, message)

    def _stamp(self):
        info = self.image.stat()
        return info.st_mtime_ns, info.st_size

    def message(self, block):
        """The page's `program` message for `block`: its lines, the code of each
        line (or why there is none)."""
        if not 0 <= block < BLOCKS:
            return {"t": "program", "block": block, "lines": [], "code": [],
                    "why": f"no block {block}: the disk has blocks 0..{BLOCKS - 1}"}
        stamp = self._stamp()
        cached = self._cache.get(block)
        if cached and cached[0] == stamp:
            return cached[1]
        lines = block_lines(self.image, block)
        code, why = [[] for _ in lines], None
        if not "".join(lines).strip():
            why = f"block {block} is blank"
        elif block < LISTED_FROM:
            why = f"no listing: python -m harness listing lists blocks from {LISTED_FROM} on"
        elif self.lister is None:
            why = "no listing in this lab"
        else:
            listed, failed = self.lister(self.image, block)
            if listed:
                code = listed
            else:
                why = f"no listing: {failed}"
        message = {"t": "program", "block": block, "lines": lines, "code": code, "why": why}
        self._cache[block] = (stamp, message)
        return message
