"""FORTH blocks as text files and as 1024-byte disk blocks (pure logic, no I/O).

A block is 16 lines of 64 characters, stored without line ends: line n is bytes
64n..64n+63.  The text form (blocks/README.md) is one file per block, at most 16
lines of at most 64 printable ASCII characters; missing lines are blank.  Packing
pads every line with spaces; unpacking strips the trailing spaces again, so a text
file in canonical form survives text -> block -> text unchanged.
"""
import re
from dataclasses import dataclass

LINES = 16
WIDTH = 64
BLOCK_BYTES = LINES * WIDTH          # 1024
BLANK_BLOCK = b" " * BLOCK_BYTES


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a block, located for the user (line numbers from 0,
    as FORTH's LIST shows them; column from 1)."""
    where: str              # file name or "block N"
    line: int               # 0-15, or the count of lines when there are too many
    message: str

    def __str__(self):
        return f"{self.where}: line {self.line}: {self.message}"


class BlockError(ValueError):
    """A block's text cannot be packed or unpacked; carries every Problem found."""

    def __init__(self, problems):
        self.problems = list(problems)
        super().__init__("\n".join(str(p) for p in self.problems))


def _describe(ch):
    if ch == "\t":
        return "a tab (blocks have no tabs: use spaces)"
    if ch == "\r":
        return "a carriage return (save the file with Unix line ends)"
    code = ord(ch)
    if code > 127:
        return f"the non-ASCII character {ch!r} (U+{code:04X})"
    return f"the control character 0x{code:02X}"


def split_lines(text):
    """The lines of a block file's text; a final newline ends the last line."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def problems_in_text(text, where):
    """Every reason why `text` is not a valid block file (empty list: valid)."""
    found = []
    lines = split_lines(text)
    if len(lines) > LINES:
        found.append(Problem(where, len(lines) - 1,
                             f"{len(lines)} lines; a block holds {LINES} (lines 0-15)"))
    for n, line in enumerate(lines):
        for col, ch in enumerate(line, 1):
            if not (" " <= ch <= "~"):
                found.append(Problem(where, n, f"column {col}: {_describe(ch)}"))
                break
        if len(line) > WIDTH:
            found.append(Problem(where, n, f"{len(line)} characters; a block line "
                                           f"holds {WIDTH}: {line[WIDTH:]!r} does not fit"))
    return found


def text_to_block(text, where="block"):
    """The 1024 bytes of a block from its text; BlockError lists every problem."""
    found = problems_in_text(text, where)
    if found:
        raise BlockError(found)
    lines = split_lines(text)
    lines += [""] * (LINES - len(lines))
    return "".join(line.ljust(WIDTH) for line in lines).encode("ascii")


def block_to_text(data, where="block"):
    """The text form of a 1024-byte block: 16 lines, trailing spaces stripped.
    An all-NUL block (never written) reads as blank."""
    if len(data) != BLOCK_BYTES:
        raise BlockError([Problem(where, 0, f"{len(data)} bytes; a block is {BLOCK_BYTES}")])
    if is_blank(data):
        data = BLANK_BLOCK
    found = []
    lines = []
    for n in range(LINES):
        raw = data[n * WIDTH:(n + 1) * WIDTH]
        for col, byte in enumerate(raw, 1):
            if not 32 <= byte <= 126:
                found.append(Problem(where, n, f"column {col}: byte 0x{byte:02X} is not "
                                               "printable ASCII (binary data, not text?)"))
                break
        lines.append(raw.decode("ascii", "replace").rstrip(" "))
    if found:
        raise BlockError(found)
    return "".join(line + "\n" for line in lines)


def is_blank(data):
    """True for a block of spaces only or of NULs only (never written)."""
    return data.strip(b" ") == b"" or data.strip(b"\0") == b""


# a line whose last column is the ) of a ( or .( comment opened on it
_COMMENT_CLOSED_AT_END = re.compile(rb"(?:^|\s)\.?\(\s[^)]*\)$")


def fused_line_ends(data):
    """Line numbers n where line n fills all 64 columns and line n+1 starts with a
    non-blank: LOAD reads the block as one string, so the two words become one.
    Not when line n ends with the ) closing a comment opened on it: the comment
    reads up to its ) and no further, so line n+1's first word is a word of its own."""
    def line(n):
        return data[n * WIDTH:(n + 1) * WIDTH]
    return [n for n in range(LINES - 1)
            if line(n)[-1] != 32 and line(n + 1)[0] != 32
            and not _COMMENT_CLOSED_AT_END.search(line(n))]
