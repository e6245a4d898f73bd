"""The plant's row and SHOW PLANT, read in one place (pure logic but layout()).

The plant's row is what pdp11-devices/plant/plant_dev.c writes (plant_dev_write_row)
into the trace (ATTACH PLANT, after a header naming COLUMNS) and after "P," into
the LAB device's stream: simulated seconds, the axis letter, the DAC code, the
commanded and actual velocity (counts/s), the position (counts), the counter
(signed 16 bits), then the gripper's opening (in), contact (0/1) and step
pulses missed so far, the same on every row whatever its axis.

    AXES, COLUMNS, AXIS_COLUMNS, GRIPPER_COLUMNS
    parse_show_plant(text)       SHOW PLANT's axis table -> {axis: {pos, vel, ...}}
    parse_show_gripper(text)     its gripper line
    parse_layout(text)           SHOW PLANT LAYOUT -> Layout (columns, units, stops)
    layout(simulator)            the layout build/pdp11 powers up with
"""
import functools
from dataclasses import dataclass

from harness.machine import simh

AXES = "XYZT"
AXIS_COLUMNS = ("time_s", "axis", "dac", "vcmd", "vel", "pos", "counter")
GRIPPER_COLUMNS = ("grip", "contact", "missed")
COLUMNS = AXIS_COLUMNS + GRIPPER_COLUMNS
AXIS = COLUMNS.index("axis")


def axis_index(letter):
    return AXES.index(letter)


def parse_show_plant(text):
    """SHOW PLANT's per-axis rows -> {axis: {pos, vel, dac, vcmd, offset, stop, run, counter}}."""
    axes = {}
    for line in text.splitlines():
        f = line.split()
        if len(f) == 11 and f[0] in AXES and f[3] in ("in", "deg"):
            axes[f[0]] = dict(pos=float(f[1]), vel=float(f[4]), dac=int(f[5]),
                              vcmd=float(f[6]), offset=float(f[7]), stop=f[8],
                              run=int(f[9]), counter=int(f[10]))
    if set(axes) != set(AXES):
        raise ValueError(f"SHOW PLANT output not understood: {text!r}")
    return axes


def parse_show_gripper(text):
    """SHOW PLANT's (last) gripper line -> {opening (in), steps, object (in),
    contact, pulses, missed, blocked, part}: part is None, or (x, y, z) in
    counts where a placed part is."""
    lines = text.splitlines()
    starts = [i for i, ln in enumerate(lines) if ln.strip().startswith("gripper ")]
    if not starts:
        raise ValueError(f"no gripper line in SHOW PLANT's output: {text[-200:]!r}")
    first = starts[-1]              # the gripper's lines: its first and those indented under it
    last = next((i for i in range(first + 1, len(lines))
                 if not lines[i].startswith("           ")), len(lines))
    joined = " ".join(ln.strip() for ln in lines[first:last])
    line, _, part = joined.partition(", part at ")
    f = line.replace(",", " ").replace("(", " ").split()
    return dict(opening=float(f[2]), steps=int(f[4]), object=float(f[7]), contact=int(f[10]),
                pulses=int(f[12]), missed=int(f[14]), blocked=int(f[16]),
                part=tuple(float(v) for v in part.split()[:3]) if part else None)


@dataclass(frozen=True)
class Layout:
    columns: tuple        # the row's columns, in order
    units: dict           # axis -> "in" or "deg"
    per_unit: dict        # axis -> counts per unit
    stops: dict           # axis -> (pmin, pmax), counts

    def message(self):
        """What the lab page learns it from (the server's hello)."""
        return {"axes": AXES, "columns": list(self.columns),
                "units": [self.units[a] for a in AXES],
                "per_unit": [self.per_unit[a] for a in AXES]}


def parse_layout(text):
    """SHOW PLANT LAYOUT ("columns a,b,..." then "axis X in 800 PMIN PMAX" per
    axis) -> Layout; ValueError if it is not that or disagrees with COLUMNS."""
    columns, units, per_unit, stops = None, {}, {}, {}
    for line in text.splitlines():
        f = line.split()
        if len(f) == 2 and f[0] == "columns":
            columns = tuple(f[1].split(","))
        elif len(f) == 6 and f[0] == "axis" and f[1] in AXES:
            units[f[1]], per_unit[f[1]] = f[2], float(f[3])
            stops[f[1]] = (float(f[4]), float(f[5]))
    if columns != COLUMNS or set(units) != set(AXES):
        raise ValueError(f"SHOW PLANT LAYOUT not understood (columns {columns}, expected "
                         f"{COLUMNS}; axes {''.join(units)}): {text[-300:]!r}")
    return Layout(columns, units, per_unit, stops)


@functools.lru_cache(maxsize=None)
def layout(simulator=simh.PDP11):
    """The layout the simulator (default build/pdp11) powers up with."""
    return parse_layout(simh.run("show plant layout\n", simulator=simulator, timeout=30))
