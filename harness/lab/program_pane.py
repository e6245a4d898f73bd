"""The lab's program pane (pure logic but for reading the disk image): a block's
16 lines as the lab's disk holds them, each with the code it laid down, from
`python -m harness listing` (harness/analysis/listing.py, handed in by
harness/commands/lab.py as `lister`, since the lab ranks beside analysis: its own
SIMH run on a copy of the image, never on the lab's running machine).

The text is the disk's: what FLUSH (or a buffer's reuse) last wrote there, not a
changed buffer the FORTH has not written yet. The page never writes the disk: its
editor types the editor's words at the FORTH (docs/lab.md, "Program").
"""
import asyncio
from pathlib import Path

from harness.lab.word_source import definition

BLOCKS = 10240                    # the RL02's blocks (forth/EDITOR.md)
BLOCK_BYTES, LINE_CHARS = 1024, 64
LISTED_FROM = 1000                # python -m harness listing lists blocks from 1000 on


def block_lines(image, block):
    """Block `block` of the image as 16 lines of 64 characters (blanks for NULs)."""
    with open(image, "rb") as disk:
        disk.seek(block * BLOCK_BYTES)
        return lines_of(disk.read(BLOCK_BYTES))


def lines_of(data):
    text = data.ljust(BLOCK_BYTES, b" ").replace(b"\0", b" ").decode("latin-1")
    return [text[i:i + LINE_CHARS] for i in range(0, BLOCK_BYTES, LINE_CHARS)]


def written_blocks(image):
    """(number, 16 lines) of each block of the image that is not blank."""
    data = Path(image).read_bytes()
    for number in range(len(data) // BLOCK_BYTES):
        block = data[number * BLOCK_BYTES:(number + 1) * BLOCK_BYTES]
        if block.strip(b" \0"):
            yield number, lines_of(block)


class ProgramPane:
    """Listings of one disk image's blocks, kept while the image is unchanged."""

    def __init__(self, image, lister=None):
        self.image = Path(image)
        self.lister = lister            # (image, block) -> ({block: 16 lists of rows}, None)
                                        # (the block, and the others the same run listed),
                                        # or (None, why)
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
                for other, other_code in listed.items():   # one run lists the whole chain
                    if other != block:
                        self._cache[other] = (stamp, self._message(other, other_code))
                code = listed[block]
            else:
                why = f"no listing: {failed}"
        message = {"t": "program", "block": block, "lines": lines, "code": code, "why": why}
        self._cache[block] = (stamp, message)
        return message

    def _message(self, block, code):
        return {"t": "program", "block": block, "lines": block_lines(self.image, block),
                "code": code, "why": None}

    def where_defined(self, word, before=(), after=()):
        """{"word", "block", "line"} of the word's definition on the disk, or None;
        `before` and `after` its neighbours in the dictionary (word_source.py)."""
        found = word and definition(word, written_blocks(self.image), before, after)
        return {"word": word, "block": found[0], "line": found[1]} if found else None


class LatestQuestion:
    """The pages' questions for listings, answered one at a time (each listing is a
    SIMH run or two of its own: a dozen at once, asked by the pane following a
    load, left a page's own question waiting behind them, longer than its test
    waited), and a page's question skipped when the same page has asked another
    since (the page shows only the answer to its last)."""

    def __init__(self):
        self.lock = asyncio.Lock()
        self.latest = {}

    async def answer(self, who, question, work):
        """work(question) in a thread, or None when `who` asked another meanwhile."""
        self.latest[who] = question
        async with self.lock:
            if self.latest.get(who) != question:
                return None
            return await asyncio.to_thread(work, question)

    def forget(self, who):
        self.latest.pop(who, None)
