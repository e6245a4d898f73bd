"""Features of a plant trace that a regression scenario pins down, with tolerances.

    features(trace) -> {("final_counter", "X"): 800.0, ...}
    read_expected(text) / check(measured, expected) / update_expected(text, measured)

Features, per axis: final_pos, final_counter (the last row's), min_pos, max_pos,
peak_speed (largest |vel|, counts/s), end_stop_rows (rows at or beyond PMIN or
PMAX, the plant's power-up end stops unless given: SHOW PLANT LAYOUT); and
duration (axis "-", simulated seconds of the last row).

Expected-features file: one feature a line, "NAME AXIS VALUE TOLERANCE", the
check being |measured - VALUE| <= TOLERANCE; '#' starts a comment.
Pure logic, but for asking build/pdp11 its end stops (plant_rows.layout).
"""
from dataclasses import dataclass

from harness.machine import plant_rows
from harness.machine.plant_rows import AXES

NAMES = ("final_pos", "final_counter", "min_pos", "max_pos", "peak_speed", "end_stop_rows")


class FeatureError(ValueError):
    """An expected-features file is malformed or names an unknown feature."""


@dataclass(frozen=True)
class Expected:
    name: str
    axis: str
    value: float
    tolerance: float
    lineno: int


def features(trace, limits=None):
    limits = limits or plant_rows.layout().stops
    found = {}
    last = 0.0
    for axis in AXES:
        s = trace.axis(axis)
        if not len(s):
            continue
        low, high = limits[axis]
        found.update({
            ("final_pos", axis): float(s.pos[-1]),
            ("final_counter", axis): float(s.counter[-1]),
            ("min_pos", axis): float(s.pos.min()),
            ("max_pos", axis): float(s.pos.max()),
            ("peak_speed", axis): float(abs(s.vel).max()),
            ("end_stop_rows", axis): float(((s.pos <= low) | (s.pos >= high)).sum()),
        })
        last = max(last, float(s.time[-1]))
    found[("duration", "-")] = last
    return found


def read_expected(text, name="features"):
    expected = []
    for lineno, line in enumerate(text.splitlines(), 1):
        body = line.split("#", 1)[0].split()
        if not body:
            continue
        if len(body) != 4:
            raise FeatureError(f"{name}:{lineno}: expected NAME AXIS VALUE TOLERANCE")
        feature, axis, value, tol = body
        if feature not in NAMES + ("duration",) or axis not in tuple(AXES) + ("-",):
            raise FeatureError(f"{name}:{lineno}: unknown feature {feature} {axis}")
        try:
            expected.append(Expected(feature, axis, float(value), float(tol), lineno))
        except ValueError:
            raise FeatureError(f"{name}:{lineno}: VALUE and TOLERANCE must be numbers") from None
    return expected


def check(measured, expected):
    """The mismatches, one readable line each (empty if all agree)."""
    problems = []
    for e in expected:
        got = measured.get((e.name, e.axis))
        if got is None:
            problems.append(f"{e.name} {e.axis}: not in the trace")
        elif abs(got - e.value) > e.tolerance:
            problems.append(f"{e.name} {e.axis}: measured {got:.3f}, expected "
                            f"{e.value:g} +- {e.tolerance:g}")
    return problems


def update_expected(text, measured):
    """The file with every VALUE replaced by the measured one (tolerances and
    comments kept)."""
    out = []
    for line in text.splitlines():
        body, hash_, comment = line.partition("#")
        fields = body.split()
        if len(fields) == 4 and (fields[0], fields[1]) in measured:
            value = measured[(fields[0], fields[1])]
            new = f"{fields[0]:<14} {fields[1]:<2} {_number(value):>12} {fields[3]:>8}"
            line = new + (f"  #{comment}" if hash_ else "")
        out.append(line.rstrip())
    return "\n".join(out) + "\n"


def _number(value):
    return str(int(value)) if value == int(value) else f"{value:.3f}"
