"""The LAB device's live stream (pdp11-devices/lab/lab.c), parsed (pure logic).
Tagged rows: W (watched words at a tick), P (the plant: one axis, the plant
trace's columns), A (watched addresses), S (state), M (memory dump), E (a
refused command), R and I (the front panel: front_panel.py).

P rows are most of the stream (four a tick per axis: 9 600 a wall second at
x10, of some 11 000 lines) and only a page draws them, so the server picks the
other rows out of each block it reads with one regular expression
(other_lines), and finds and decodes the P rows only while a page is connected
(plant_lines, plant_rows).
"""
import re
from dataclasses import dataclass

from harness.machine.plant_rows import AXES, AXIS, COLUMNS


class Lines:
    """Bytes in, whole lines out (as one block, each line ending in a newline); a
    partial last line waits for the rest."""

    def __init__(self):
        self.rest = b""

    def feed(self, data):
        data = self.rest + data
        cut = data.rfind(b"\n") + 1
        self.rest = data[cut:]
        return data[:cut]


# after a newline (a block gets one in front), so that the search skips from one
# newline to the next instead of trying every byte
OTHER_LINE = re.compile(rb"\n((?!P,)[^\n]+)")
PLANT_LINE = re.compile(rb"\n(P,[^\n]*)")


def other_lines(block):
    """The lines of a block of whole lines that are not P rows (empty ones left out)."""
    return OTHER_LINE.findall(b"\n" + block)


def plant_lines(block):
    """The P rows' lines of a block of whole lines, in order."""
    return PLANT_LINE.findall(b"\n" + block)


AXIS_INDEX = {letter.encode(): i for i, letter in enumerate(AXES)}


def plant_numbers(fields):
    """A P row's fields as bytes (the plant's row, plant_rows.COLUMNS) -> its numbers
    in that order, the axis as its index in AXES; columns after these are ignored,
    so the row may grow. None when unreadable (the axis not one of AXES' letters, a
    number float() does not read, fewer columns)."""
    if len(fields) < len(COLUMNS):
        return None
    axis = AXIS_INDEX.get(fields[AXIS])
    if axis is None:
        return None
    try:
        return [*map(float, fields[:AXIS]), axis, *map(float, fields[AXIS + 1:len(COLUMNS)])]
    except ValueError:
        return None


def plant_rows(lines):
    """Whole P lines as the device wrote them (bytes, "P," first) -> the numbers of
    the readable ones, in order."""
    rows = []
    for line in lines:
        numbers = plant_numbers(line.split(b",")[1:])
        if numbers:
            rows.append(numbers)
    return rows


@dataclass
class LabRow:
    kind: str           # W A S M E
    fields: list        # the rest of the row, as text


def lab_row(line):
    """A LAB device line split into its kind and fields (None when empty)."""
    fields = line.decode("ascii", "replace").split(",")
    if not fields[0]:
        return None
    return LabRow(fields[0], fields[1:])


class WordRows:
    """W rows' words, decoded again only when they differ from the previous row's:
    600 rows a wall second at x10, and while the FORTH waits at its prompt the
    words stand still tick after tick (decoding the servo's 29 was most of what an
    idle lab cost)."""

    def __init__(self):
        self.raw, self.words = None, []

    def read(self, line):
        """A W row's whole line (bytes) -> (time_s, tick, [words]); the same list
        (object) while the words repeat."""
        fields = line.split(b",", 3)
        raw = fields[3] if len(fields) > 3 else b""
        if raw != self.raw:
            self.raw, self.words = raw, list(map(int, raw.split(b","))) if raw else []
        return float(fields[1]), int(fields[2]), self.words


def memory_of(row):
    """M row -> (address, [words]) (a W row's words: WordRows)."""
    if row.kind == "M":
        return int(row.fields[0], 8), list(map(int, row.fields[1:]))
    raise ValueError(f"not a row of memory: {row.kind}")


def thin(rows, budget):
    """At most about `budget` rows, keeping every k-th row of each axis, so every
    axis keeps its share when the run goes too fast for the page to draw it all."""
    if len(rows) <= budget:
        return rows
    k = -(-len(rows) // budget)
    seen = [0] * len(AXES)
    kept = []
    for row in rows:
        axis = row[1]
        if seen[axis] % k == 0:
            kept.append(row)
        seen[axis] += 1
    return kept
