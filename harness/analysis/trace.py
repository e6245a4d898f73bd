"""Read and check a plant trace (the CSV that `ATTACH PLANT file` writes).

Columns: time_s,axis,dac,vcmd,vel,pos,counter: simulated seconds, axis letter
X/Y/Z/T, DAC code (0..4095, 2048 = 0 V), the plant's commanded velocity and its
actual velocity in counts/s, position in counts, and the axis counter as a
signed 16-bit number. Rows are in time order; each sample time gives a row per
axis, and every DAC write adds a row for the axis written. Traces from this
build carry three more columns, the gripper's state on every row whatever its
axis: grip (opening, inches), contact (the finger switch, 0/1), missed (step
pulses missed so far); traces without them are read too.

    trace = read("run.csv")          # TraceError: the file is not a trace
    x = trace.axis("X")              # AxisSeries of numpy arrays
    x.time, x.dac, x.vcmd, x.vel, x.pos, x.counter
    g = trace.gripper                # GripperSeries, or None for older traces

Pure logic apart from opening the file; no plotting here (harness/analysis/plots.py).
"""
import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from harness.machine.plant_rows import AXES, AXIS_COLUMNS as HEADER, COLUMNS, GRIPPER_COLUMNS  # noqa: F401

HEADERS = (COLUMNS, HEADER)     # this build's, and older traces (no gripper)
DAC_ZERO = 2048          # offset binary: the code for 0 V


class TraceError(ValueError):
    """The file is missing, unreadable, or not a well-formed plant trace."""


@dataclass(frozen=True)
class AxisSeries:
    """One axis's rows, in time order, as numpy arrays."""
    axis: str
    time: np.ndarray      # s
    dac: np.ndarray       # code 0..4095
    vcmd: np.ndarray      # counts/s, the plant's commanded velocity
    vel: np.ndarray       # counts/s, actual
    pos: np.ndarray       # counts
    counter: np.ndarray   # signed 16-bit count

    def __len__(self):
        return len(self.time)

    def window(self, start=None, end=None):
        """The rows with start <= time <= end (None: unbounded)."""
        keep = np.ones(len(self), bool)
        if start is not None:
            keep &= self.time >= start
        if end is not None:
            keep &= self.time <= end
        return AxisSeries(self.axis, *(a[keep] for a in self._arrays()))

    def _arrays(self):
        return self.time, self.dac, self.vcmd, self.vel, self.pos, self.counter


@dataclass(frozen=True)
class GripperSeries:
    """The gripper's state, one entry per distinct row time."""
    time: np.ndarray      # s
    opening: np.ndarray   # inches between the fingers
    contact: np.ndarray   # finger contact switch, 0/1
    missed: np.ndarray    # step pulses missed so far


@dataclass(frozen=True)
class Trace:
    name: str
    series: dict          # axis letter -> AxisSeries (axes with rows only)
    gripper: GripperSeries = None   # None: a trace without the gripper columns

    @property
    def axes(self):
        return "".join(a for a in AXES if a in self.series)

    @property
    def duration(self):
        ends = [s.time[-1] for s in self.series.values()]
        starts = [s.time[0] for s in self.series.values()]
        return max(ends) - min(starts)

    def axis(self, letter):
        letter = letter.upper()
        if letter not in self.series:
            raise TraceError(f"{self.name}: no rows for axis {letter} "
                             f"(the trace has {self.axes or 'none'})")
        return self.series[letter]


def _field(kind, text, check):
    """Convert one field; None when it is not a valid value of its column."""
    try:
        value = kind(text)
    except ValueError:
        return None
    if kind is float and not math.isfinite(value):
        return None
    return value if check(value) else None


_CHECKS = {  # column -> (type, range check, what it must be); the checks take a
    # value or a numpy array of a column's values (read's fast way), except axis's
    "time_s": (float, lambda v: v >= 0, "a time in seconds >= 0"),
    "axis": (str, lambda v: v in AXES, "one of " + " ".join(AXES)),
    "dac": (int, lambda v: (0 <= v) & (v <= 4095), "a DAC code 0..4095"),
    "vcmd": (float, lambda v: True, "a number (counts/s)"),
    "vel": (float, lambda v: True, "a number (counts/s)"),
    "pos": (float, lambda v: True, "a number (counts)"),
    "counter": (int, lambda v: (-32768 <= v) & (v <= 32767), "a signed 16-bit count"),
    "grip": (float, lambda v: (0 <= v) & (v <= 2), "an opening in inches, 0..2"),
    "contact": (int, lambda v: (v == 0) | (v == 1), "0 or 1"),
    "missed": (int, lambda v: v >= 0, "a count >= 0"),
}
_COLUMNS = tuple((column,) + _CHECKS[column] for column in COLUMNS)


def parse_rows(lines, name="trace"):
    """Check the header and every row of `lines` (an iterable of text lines);
    returns a list of tuples (time, axis, dac, vcmd, vel, pos, counter[, grip,
    contact, missed])."""
    reader = csv.reader(lines)
    try:
        header = next(reader, None)
    except (csv.Error, UnicodeDecodeError) as err:
        raise TraceError(f"{name}: not a plant trace: {err}") from err
    if header is None:
        raise TraceError(f"{name}: empty file, not a plant trace")
    header = tuple(h.strip() for h in header)
    if header not in HEADERS:
        raise TraceError(f"{name}: not a plant trace: the first line is "
                         f"{','.join(header)[:80]!r}, expected {','.join(HEADERS[0])!r}")
    rows, last_time = [], 0.0
    try:
        for fields in reader:
            line = reader.line_num
            if not fields:
                continue
            if len(fields) != len(header):
                raise TraceError(f"{name} line {line}: {len(fields)} fields, "
                                 f"expected {len(header)}")
            row = []
            for (column, kind, check, what), text in zip(_COLUMNS, fields):
                value = _field(kind, text.strip(), check)
                if value is None:
                    raise TraceError(f"{name} line {line}: {column} is {text!r}, "
                                     f"expected {what}")
                row.append(value)
            if row[0] < last_time:
                raise TraceError(f"{name} line {line}: time {row[0]} goes back "
                                 f"(previous row {last_time})")
            last_time = row[0]
            rows.append(tuple(row))
    except (csv.Error, UnicodeDecodeError) as err:
        raise TraceError(f"{name}: not a plant trace: {err}") from err
    if not rows:
        raise TraceError(f"{name}: the header only, no rows: an empty trace")
    return rows


def from_rows(rows, name="trace"):
    """A Trace from parsed rows (see parse_rows)."""
    if not rows:
        return Trace(name, {})
    cols = list(zip(*rows))
    return _from_columns([np.array(c, dtype=int if kind is int else None)
                          for c, (_, kind, _, _) in zip(cols, _COLUMNS)], name)


def _from_columns(cols, name):
    """A Trace from the columns as arrays (time, axis, dac, ..., in file order)."""
    time, axis = cols[0], cols[1]
    series = {}
    for letter in AXES:
        mine = axis == letter
        if mine.any():
            series[letter] = AxisSeries(letter, *(c[mine] for c in (time, *cols[2:7])))
    gripper = None
    if len(cols) > len(HEADER):         # one row per distinct time (times never go back)
        first = np.ones(len(time), bool)
        first[1:] = time[1:] != time[:-1]
        gripper = GripperSeries(*(c[first] for c in (time, *cols[7:])))
    return Trace(name, series, gripper)


def _columns(text):
    """read's fast way through a well-formed trace: each column converted whole
    (the same float() and int() as parse_rows) and checked at once; None when
    anything is out of the ordinary, for parse_rows to say what and where."""
    if '"' in text or "\r" in text:
        return None
    lines = text.split("\n")
    header = tuple(h.strip() for h in lines[0].split(","))
    body = lines[1:-1] if lines[-1] == "" else lines[1:]
    n = len(header)
    if header not in HEADERS or not body or "" in body \
            or any(line.count(",") != n - 1 for line in body):
        return None
    fields = ",".join(body).split(",")
    cols = []
    try:
        for k, (_, kind, check, _) in enumerate(_COLUMNS[:n]):
            texts = fields[k::n]
            if kind is str:
                if not set(texts) <= set(AXES):
                    return None
                cols.append(np.array(texts))
                continue
            values = np.array(list(map(kind, texts)))
            if not (np.all(check(values)) and (kind is int or np.isfinite(values).all())):
                return None
            cols.append(values)
    except (ValueError, OverflowError):
        return None
    if np.any(np.diff(cols[0]) < 0):
        return None
    return cols


def read(path):
    """Read and check the trace at `path`; TraceError says what is wrong."""
    path = Path(path)
    try:
        with open(path, newline="", encoding="ascii") as f:
            try:
                cols = _columns(f.read())
            except UnicodeDecodeError:
                cols = None
            if cols is not None:
                return _from_columns(cols, str(path))
            f.seek(0)
            rows = parse_rows(f, str(path))
    except FileNotFoundError as err:
        raise TraceError(f"{path}: no such file") from err
    except IsADirectoryError as err:
        raise TraceError(f"{path}: a directory, not a trace file") from err
    except OSError as err:
        raise TraceError(f"{path}: cannot read: {err.strerror}") from err
    return from_rows(rows, str(path))
