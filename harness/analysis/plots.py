"""Figures from plant traces (matplotlib, Agg backend, no pyplot state).

    fig = moves_figure(trace, "X")            # the paper's Figure 2 from a real run
    fig = time_figure(trace)                  # position and velocity against time
    fig = zero_figure(trace, offsets={"X": 3.0})   # the 0-Vel adaptation
    save(fig, ["out.png", "out.svg"])         # all files whole, or none (plot_files.py)

Each builder returns a matplotlib Figure whose axes carry titles, units and
legends; the definitions behind the marks (D0..D3, idle rows) are in
harness/analysis/moves.py and docs/plots.md.
"""
import textwrap
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
from matplotlib.figure import Figure  # noqa: E402  (after choosing the backend)

from harness.analysis import moves as mv  # noqa: E402
from harness.analysis.plot_errors import PlotError  # noqa: E402,F401  (raised here)
from harness.analysis.plot_files import save, save_all  # noqa: E402,F401  (plots.save)
from harness.analysis.trace import DAC_ZERO  # noqa: E402

WIDTH = 6.4                       # inches per panel
TITLE_CHARS = 64                  # characters of a title line per panel
# A panel's title just above it, fixed: left to matplotlib, its place is worked
# out at every measuring and drawing of the panel, from the y axis's tick labels
# measured again, only to clear an offset text (a corner's "1e4"), which these
# centred titles never meet.
TITLE_Y = 1.0
STYLE = {"commanded": dict(color="tab:blue", lw=1.4, drawstyle="steps-post"),
         "actual": dict(color="tab:orange", lw=1.4),
         "held": dict(color="tab:green", lw=0, marker=".", ms=3),
         "dac": dict(color="lightgrey", lw=0.8, drawstyle="steps-post"),
         "zero": dict(color="tab:red", lw=1.0),
         "given": dict(color="black", lw=1.0, ls="--")}


def _window_text(start, end):
    return f"{start if start is not None else 'start'}-{end if end is not None else 'end'} s"


def pick_moves(series, windows=(), v_idle=mv.V_IDLE, min_travel=mv.MIN_TRAVEL):
    """[(move, label)] to draw: with no windows, the longest move and the short
    one (harness/analysis/moves.py: below MaxVel) when there is one; with windows, the
    longest move starting in each window."""
    found = mv.find_moves(series, v_idle, min_travel)
    if not found:
        raise PlotError(f"no moves on axis {series.axis}: no stretch of motion "
                        f"(|vcmd| or |vel| >= {v_idle:g} counts/s) travels "
                        f"{min_travel:g} counts or more")
    if not windows:
        longest, short = mv.long_and_short(found)
        chosen = [(longest, "long move")]
        if short:
            chosen.append((short, f"short move (peak below the long move's "
                                  f"{longest.peak_code} codes)"))
        return chosen
    chosen = []
    for start, end in windows:
        inside = mv.moves_between(found, start, end)
        if not inside:
            raise PlotError(f"no move on axis {series.axis} starts in "
                            f"{_window_text(start, end)}; moves start at "
                            + ", ".join(f"{m.t0:.3f}" for m in found) + " s")
        chosen.append((max(inside, key=lambda m: m.travel),
                       f"move starting in {_window_text(start, end)}"))
    return chosen


def _move_panel(ax, series, move, label, kv):
    first = move.first - 1 if move.first > 0 else move.first
    rows = slice(first, move.rest + 1)
    dist = (series.pos[rows] - move.d0) * move.direction
    ax.plot(dist, series.vcmd[rows] * move.direction, label="commanded velocity (vcmd)",
            **STYLE["commanded"])
    ax.plot(dist, series.vel[rows] * move.direction, label="actual velocity (vel)",
            **STYLE["actual"])
    marks = (("D0", move.d0), ("D1", move.d1), ("D2", move.d2), ("D3", move.d3))
    for k, (name, d) in enumerate(marks):
        x = (d - move.d0) * move.direction
        ax.axvline(x, color="grey", lw=0.8, ls=":")
        # stagger the labels: D0/D1 and D2/D3 can fall close together
        ax.annotate(name, (x, 1.0), xycoords=("data", "axes fraction"),
                    xytext=(2, -12 - 11 * (k % 2)), textcoords="offset points",
                    fontsize=9, color="dimgrey")
    arrow = "+" if move.direction > 0 else "-"
    ax.set_title(f"{label}: {move.d0:.0f} to {move.d3:.0f} counts ({arrow}{move.travel:.0f}),"
                 f"\nt = {move.t0:.2f}-{move.t1:.2f} s, peak {move.peak_code} codes "
                 f"above 0-Vel {move.zero_code}", fontsize=9, y=TITLE_Y)
    ax.set_xlabel("distance travelled from D0, counts")
    ax.set_ylabel("velocity in the direction of travel, counts/s")
    ax.grid(True, alpha=0.3)
    if kv:
        sec = ax.secondary_yaxis("right", functions=(lambda v: v / kv, lambda c: c * kv))
        sec.set_ylabel(f"DAC codes (counts/s / Kv, Kv = {kv:.2f})")
    ax.legend(loc="lower center", fontsize=8)


def moves_figure(trace, axis, windows=(), v_idle=mv.V_IDLE, min_travel=mv.MIN_TRAVEL,
                 kv=None):
    """Commanded and actual velocity against distance for the chosen moves of
    `axis`, D0..D3 marked, one panel per move (long and short side by side)."""
    series = trace.axis(axis)
    chosen = pick_moves(series, windows, v_idle, min_travel)
    kv = kv if kv is not None else mv.estimate_kv(series)
    fig = Figure(figsize=(WIDTH * len(chosen), 4.8), layout="constrained")
    panels = fig.subplots(1, len(chosen), squeeze=False)[0]
    for ax, (move, label) in zip(panels, chosen):
        _move_panel(ax, series, move, label, kv)
    lines = [f"Axis {series.axis}: velocity against position "
             f"(the paper's Figure 2), {Path(trace.name).name}"]
    if not windows and len(chosen) == 1:
        lines.append(f"no short move: every move here peaks at the long move's "
                     f"{chosen[0][0].peak_code} codes above 0-Vel (MaxVel)")
    width = TITLE_CHARS * len(chosen)          # a title fits its panels, wrapped
    fig.suptitle("\n".join(textwrap.fill(line, width) for line in lines))
    return fig


def _span(windows):
    if not windows:
        return None, None
    starts = [s for s, _ in windows]
    ends = [e for _, e in windows]
    return (None if None in starts else min(starts)), (None if None in ends else max(ends))


def _axes_rows(trace, axes, windows):
    start, end = _span(windows)
    rows = []
    for letter in axes or trace.axes:
        series = trace.axis(letter).window(start, end)
        if not len(series):
            raise PlotError(f"axis {letter} has no rows in {_window_text(start, end)}")
        rows.append(series)
    return rows


def time_figure(trace, axes=None, windows=()):
    """Per axis, position (left) and velocity (right) against time."""
    rows = _axes_rows(trace, axes, windows)
    fig = Figure(figsize=(2 * WIDTH, 2.6 * len(rows) + 0.6), layout="constrained")
    grid = fig.subplots(len(rows), 2, squeeze=False)
    for (pos_ax, vel_ax), s in zip(grid, rows):
        pos_ax.plot(s.time, s.pos, color="tab:purple", lw=1.2, label="position (pos)")
        pos_ax.set_title(f"axis {s.axis}: position", fontsize=10, y=TITLE_Y)
        pos_ax.set_ylabel("position, counts")
        vel_ax.plot(s.time, s.vcmd, label="commanded velocity (vcmd)", **STYLE["commanded"])
        vel_ax.plot(s.time, s.vel, label="actual velocity (vel)", **STYLE["actual"])
        vel_ax.set_title(f"axis {s.axis}: velocity", fontsize=10, y=TITLE_Y)
        vel_ax.set_ylabel("velocity, counts/s")
        for ax in (pos_ax, vel_ax):
            ax.set_xlabel("simulated time, s")
            ax.grid(True, alpha=0.3)
            ax.legend(loc="best", fontsize=8)
    fig.suptitle(f"Position and velocity against time, {Path(trace.name).name}")
    return fig


def zero_figure(trace, axes=None, windows=(), offsets=None, kv=None, v_idle=mv.V_IDLE,
                hold=mv.HOLD):
    """Per axis: the DAC code the axis is held at while idle (the servo's 0-Vel),
    against time, beside the plant's true zero: 2048 + offset, from the trace
    (dac - vcmd/Kv) and, when given, from `offsets` (axis -> codes)."""
    offsets = offsets or {}
    rows = _axes_rows(trace, axes, windows)
    fig = Figure(figsize=(WIDTH * 1.6, 2.6 * len(rows) + 0.6), layout="constrained")
    panels = fig.subplots(len(rows), 1, squeeze=False)[:, 0]
    for ax, s in zip(panels, rows):
        t, held = mv.held_codes(s, v_idle, hold)
        shown = [held]
        # every row, faint: where the axis is not held the code leaves the plot's scale
        ax.plot(s.time, s.dac, label="DAC code, every row", **STYLE["dac"])
        ax.plot(t, held, label="DAC code while held idle (0-Vel)", **STYLE["held"])
        axis_kv = kv if kv is not None else mv.estimate_kv(s)
        if axis_kv:
            zero = mv.true_zero(s, axis_kv)
            shown.append(zero)
            ax.plot(s.time, zero, label=f"plant's zero from the trace, dac - vcmd/Kv "
                    f"(Kv = {axis_kv:.2f})", **STYLE["zero"])
        if s.axis in offsets:
            shown.append([DAC_ZERO + offsets[s.axis]])
            ax.axhline(DAC_ZERO + offsets[s.axis], label=f"2048 + given offset "
                       f"({offsets[s.axis]:+g})", **STYLE["given"])
        if not len(t):
            ax.text(0.5, 0.75, f"axis {s.axis} is never held idle here", ha="center",
                    transform=ax.transAxes)
        values = [v for group in shown for v in group] or list(s.dac)
        if values:
            ax.set_ylim(min(values) - 2, max(values) + 2)
        ax.set_xlim(s.time[0], s.time[-1])
        ax.set_title(f"axis {s.axis}: zero-velocity code", fontsize=10, y=TITLE_Y)
        ax.set_xlabel("simulated time, s")
        ax.set_ylabel("DAC code (2048 = 0 V)")
        ax.yaxis.get_major_locator().set_params(integer=True)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    fig.suptitle(f"0-Vel adaptation: the code an idle axis is held at, "
                 f"{Path(trace.name).name}")
    return fig


def architectures_figure(columns, axes, title):
    """Side by side, one column per (label, trace, window) and one row per axis:
    the counter (left scale) and the DAC code (right scale) against simulated
    time in each column's window (start, end): the same moves on two machines'
    traces, each from its own moment the move was given."""
    fig = Figure(figsize=(WIDTH * len(columns), 2.4 * len(axes) + 0.8), layout="constrained")
    grid = fig.subplots(len(axes), len(columns), squeeze=False)
    for col, (label, trace, window) in enumerate(columns):
        for row, letter in enumerate(axes):
            s = trace.axis(letter).window(*window)
            if not len(s):
                raise PlotError(f"{label}: axis {letter} has no rows in {_window_text(*window)}")
            ax = grid[row][col]
            ax.plot(s.time, s.counter, color="tab:purple", lw=1.2, label="counter")
            ax.set_ylabel("counter, counts")
            ax.set_xlabel("simulated time, s")
            ax.set_title(f"{label}: axis {letter}", fontsize=10, y=TITLE_Y)
            ax.grid(True, alpha=0.3)
            dac = ax.twinx()
            dac.plot(s.time, s.dac, label="D/A code", **{**STYLE["dac"], "color": "tab:green"})
            dac.set_ylabel("D/A code (2048 = 0 V)")
            lines = ax.get_lines() + dac.get_lines()
            ax.legend(lines, [ln.get_label() for ln in lines], loc="best", fontsize=8)
    fig.suptitle(title)
    return fig
