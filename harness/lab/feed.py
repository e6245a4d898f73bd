"""The LAB device's live stream (pdp11-devices/lab/lab.c), parsed as it arrives (pure
logic). Tagged rows: W (watched words at a tick), P (the plant: one axis, the
plant trace's columns), A (watched addresses), S (state), M (memory dump),
E (a refused command).
"""
from dataclasses import dataclass

AXES = "XYZT"
PLANT_COLUMNS = ("time_s", "axis", "dac", "vcmd", "vel", "pos", "counter")


class Lines:
    """Bytes in, whole lines out; a partial last line waits for the rest."""

    def __init__(self):
        self.rest = b""

    def feed(self, data):
        lines = (self.rest + data).split(b"\n")
        self.rest = lines.pop()
        return lines


def plant_row(row):
    """A P row -> [time_s, axis index, dac, vcmd, vel, pos, counter], the plant
    trace's columns in its order; columns after these are ignored, so the row
    may grow (a gripper, say). None when unreadable."""
    try:
        t, axis, dac, vcmd, vel, pos, counter = row.fields[:len(PLANT_COLUMNS)]
        return [float(t), AXES.index(axis), int(dac), float(vcmd), float(vel), float(pos),
                int(counter)]
    except ValueError:
        return None


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


def words_of(row):
    """W row -> (time_s, tick, [words]); M row -> (address, [words])."""
    if row.kind == "W":
        return float(row.fields[0]), int(row.fields[1]), [int(w) for w in row.fields[2:]]
    if row.kind == "M":
        return int(row.fields[0], 8), [int(w) for w in row.fields[1:]]
    raise ValueError(f"not a row of words: {row.kind}")


def thin(rows, budget):
    """At most about `budget` rows, keeping every k-th row of each axis, so every
    axis keeps its share when the run goes too fast for the page to draw it all."""
    if len(rows) <= budget:
        return rows
    k = -(-len(rows) // budget)
    seen = [0, 0, 0, 0]
    kept = []
    for row in rows:
        axis = row[1]
        if seen[axis] % k == 0:
            kept.append(row)
        seen[axis] += 1
    return kept
