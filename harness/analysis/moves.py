"""Moves in a plant trace: segments of motion, the paper's D0..D3, idle rows.

Definitions (docs/plots.md explains them with the figures):

- A row is *idle* when both the commanded and the actual velocity are small:
  |vcmd| < v_idle and |vel| < v_idle (counts/s; default 200, about 10 DAC codes
  at the default Kv of 19.53 counts/s per code). An idle axis is held at one DAC
  code, the servo's zero-velocity code (the paper's 0-Vel).
- A row is *held* when it is idle and its DAC code has not changed for at least
  `hold` seconds (default 0.05, three servo ticks): the code the servo holds an
  idle axis at. (The tail of a deceleration is slow too, but its code changes
  every tick.)
- A *segment* is a maximal run of rows that are not idle. A *stretch* is a
  segment, or a part of one: a segment is cut where its DAC code returns to the
  code held before it (the servo holds 0-Vel: the axis has arrived) and resumes
  where the code leaves it again, so a servo that hunts about its target, never
  letting the axis go idle, still has its move apart from the corrections after.
  A *move* is a stretch the servo commanded (its DAC leaves 0-Vel in the
  direction of travel: z falling onto its stop at power-up, DAC at 2048 and no
  servo, is not one) whose travel (|D3 - D0|) is at least min_travel counts
  (default 50); shorter stretches are corrections (a drifting axis pulled back).
- The servo's *commanded velocity in DAC codes* is dac - 0-Vel, signed in the
  direction of travel. The trace has no 0-Vel column, but an idle axis is held at
  0-Vel and the 1983 servo adapts 0-Vel only while idle, so the move's 0-Vel is
  the DAC code of the idle row just before it (2048 when the move starts the
  trace). The trace's vcmd column is the plant's view of the same command in
  counts/s: Kv * (dac - 2048 - offset), which includes the amplifier's offset.
- D0: the position just before the move (the row before it: idle, or held at 0-Vel).
  D1: the position where the commanded velocity (in codes) first reaches its
      largest value in the move (the paper: "Vel = MaxVel").
  D2: the position where it stops being at that value, the row where the code
      first changes after its last row at the peak: from D2 the command falls
      with the distance left (the paper: "Vel > (D3 - D2)"). A peak held for one
      tick thus has D2 a tick of motion beyond D1, not on top of D0.
  D3: the position where the axis is when the servo next acts: the last row
      before the next stretch starts, or the trace's last row (then `settled`
      is False: the trace ends while the move is still under way).
  MaxVel, as the trace shows it, is the largest commanded velocity of the
  longest move; a *short* move is one whose largest command stays below it (the
  paper's "the maximum velocity is never reached"). The 1983 servo starts every
  move at full speed, so its traces may have no short move at all.
"""
from dataclasses import dataclass

import numpy as np

from harness.analysis.trace import DAC_ZERO

V_IDLE = 200.0        # counts/s
MIN_TRAVEL = 50.0     # counts
HOLD = 0.05           # s: three ticks of the 60 Hz servo


@dataclass(frozen=True)
class Move:
    axis: str
    first: int            # index of the move's first row in the AxisSeries
    last: int             # index of its last row (inclusive) before 0-Vel is held
    rest: int             # index of the row where it came to rest (D3)
    zero_code: int        # the servo's 0-Vel during the move
    direction: int        # +1 or -1
    peak_code: int        # largest commanded velocity, DAC codes above 0-Vel
    t0: float             # s, start of motion
    t1: float             # s, end of the stretch (the servo holds 0-Vel next)
    d0: float             # counts
    d1: float
    d2: float
    d3: float
    settled: bool         # False when the trace ends before the axis rests

    @property
    def travel(self):
        return abs(self.d3 - self.d0)


def idle_mask(series, v_idle=V_IDLE):
    """True for the rows where the axis is idle (see the module's definitions)."""
    return (np.abs(series.vcmd) < v_idle) & (np.abs(series.vel) < v_idle)


def segments(series, v_idle=V_IDLE):
    """(first, last) row indices of each maximal run of rows that are not idle."""
    moving = ~idle_mask(series, v_idle)
    edges = np.diff(np.concatenate(([0], moving.astype(np.int8), [0])))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    return list(zip(starts.tolist(), ends.tolist()))


def servo_velocity_codes(series, move):
    """The commanded velocity of each row, DAC codes above the move's 0-Vel,
    positive in the direction of travel."""
    return (series.dac - move.zero_code) * move.direction


def stretches(series, v_idle=V_IDLE):
    """(first, last, zero) for each stretch of commanded motion: the segments, each
    cut where the DAC returns to `zero`, the code held before the segment (the servo
    holds 0-Vel: the axis has arrived), and resumed where the code leaves it again.
    A servo that hunts about its target never lets the axis go idle; this keeps the
    move apart from the corrections after it."""
    found = []
    for first, last in segments(series, v_idle):
        zero = int(series.dac[first - 1]) if first > 0 else DAC_ZERO
        start = first
        while True:
            back = np.flatnonzero(series.dac[start + 1:last + 1] == zero)
            end = start + int(back[0]) if len(back) else last
            found.append((start, end, zero))
            gone = np.flatnonzero(series.dac[end + 1:last + 1] != zero)
            if not len(gone):
                break
            start = end + 1 + int(gone[0])
    return found


def find_moves(series, v_idle=V_IDLE, min_travel=MIN_TRAVEL):
    """The moves of one axis (a list of Move, in time order)."""
    parts = stretches(series, v_idle)
    found = []
    for k, (first, last, zero) in enumerate(parts):
        before = first - 1 if first > 0 else first
        rest = parts[k + 1][0] - 1 if k + 1 < len(parts) else len(series) - 1
        d0, d3 = series.pos[before], series.pos[rest]
        if abs(d3 - d0) < min_travel:
            continue
        direction = 1 if d3 > d0 else -1
        codes = (series.dac[first:last + 1] - zero) * direction
        peak = int(codes.max())
        if peak <= 0:
            continue                      # drift: the servo did not command it
        at_peak = np.flatnonzero(codes == peak) + first
        changed = np.flatnonzero(series.dac[at_peak[-1] + 1:rest + 1] != series.dac[at_peak[-1]])
        end_of_peak = at_peak[-1] + 1 + int(changed[0]) if len(changed) else rest
        found.append(Move(series.axis, first, last, rest, zero, direction, peak,
                          float(series.time[first]), float(series.time[last]),
                          float(d0), float(series.pos[at_peak[0]]),
                          float(series.pos[end_of_peak]), float(d3), rest > last))
    return found


def moves_between(moves, start=None, end=None):
    """The moves that start inside [start, end] (None: unbounded)."""
    return [m for m in moves
            if (start is None or m.t0 >= start) and (end is None or m.t0 <= end)]


def long_and_short(moves):
    """(longest, short): the two cases of the paper's Figure 2 (left: normal,
    right: short). `short` is the shortest move whose peak stays below the
    longest's (MaxVel), or None when every move reaches MaxVel."""
    if not moves:
        return None, None
    longest = max(moves, key=lambda m: m.travel)
    below = [m for m in moves if m.peak_code < longest.peak_code]
    return longest, (min(below, key=lambda m: m.travel) if below else None)


def held_mask(series, v_idle=V_IDLE, hold=HOLD):
    """True for the rows where the axis is held: idle, and its DAC code unchanged
    for at least `hold` seconds (the servo writes 0-Vel every tick while the axis
    is in range; the tail of a deceleration is slow too, but its code changes
    every tick)."""
    changed = np.ones(len(series), bool)
    changed[1:] = series.dac[1:] != series.dac[:-1]
    last_change = np.maximum.accumulate(np.where(changed, np.arange(len(series)), 0))
    steady = series.time - series.time[last_change] >= hold
    return idle_mask(series, v_idle) & steady


def held_codes(series, v_idle=V_IDLE, hold=HOLD):
    """(time, dac) of the held rows: the code an idle axis is held at, over time."""
    held = held_mask(series, v_idle, hold)
    return series.time[held], series.dac[held]


def estimate_kv(series):
    """The plant's Kv (counts/s per code) from the rows, by least squares of
    vcmd on dac (vcmd = Kv * (dac - 2048 - offset)); None when every row has
    the same DAC code, so the slope cannot be seen."""
    if len(np.unique(series.dac)) < 2:
        return None
    slope, _ = np.polyfit(series.dac.astype(float), series.vcmd, 1)
    return float(slope)


def true_zero(series, kv):
    """The plant's true zero-velocity code at each row, 2048 + offset(t), from
    vcmd = Kv * (dac - 2048 - offset): dac - vcmd / Kv."""
    return series.dac - series.vcmd / kv
