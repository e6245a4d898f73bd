"""How an axis arrives (docs/controllers.md, "The same moves on both
architectures"): from a trace, when the counter first comes inside the servo's
window (Range 5 in blocks 1000 and 1080: |target - counter| <= 4) after a move
was given, and the band the counter hunts in from then on. Pure logic on
harness/analysis/trace.py's AxisSeries; the instruction counts of a transcript's
`#simh show time` lines (SIMH's "Time:" answers) read as simulated seconds."""
import re
from dataclasses import dataclass

WINDOW = 4            # counts: |d| < Range (5), the blocks' "there"


@dataclass(frozen=True)
class Arrival:
    settle: float     # s from `start` to the first row inside the window; None: never
    low: int          # the band after it: min and max of counter - target
    high: int


def arrival(series, target, start, end, window=WINDOW):
    """The Arrival of `series` (an AxisSeries) at `target` over rows in [start, end)."""
    rows = [(t, c - target) for t, c in zip(series.time, series.counter) if start <= t < end]
    inside = next((i for i, (_, d) in enumerate(rows) if abs(d) <= window), None)
    if inside is None:
        return Arrival(None, None, None)
    after = [d for _, d in rows[inside:]]
    return Arrival(rows[inside][0] - start, int(min(after)), int(max(after)))


def show_times(transcript, rate):
    """The simulated seconds each `show time` in `transcript` answered, in order."""
    return [int(n) / rate for n in re.findall(r"^Time:\s+(\d+)", transcript, re.M)]
