"""Figures for the project's continuation (blocks 1040-1053): the x-y path
against its commanded segments, and the gripper against time.

    fig = xy_figure(trace, corners=[(0, 0), (3200, 0), ...], windows=[(6, 14)])
    fig = gripper_figure(trace)
    plots.save(fig, ["out.png"])

Built like harness/analysis/plots.py (matplotlib Figure, Agg); the numbers on the x-y
figure come from harness/analysis/path_metrics.py.
"""
import math
from pathlib import Path

from matplotlib.figure import Figure

from harness.analysis import path_metrics as pm
from harness.analysis.plot_errors import PlotError
from harness.analysis.plots import STYLE, WIDTH, _span, _window_text


def xy_figure(trace, corners, windows=()):
    """The traced x-y counters against the polyline through `corners` (the
    start point, then each via point), with each segment's largest deviation
    and each via point's closest approach and speed there."""
    if len(corners) < 2:
        raise PlotError("the x-y figure needs the start point and at least one via "
                        "point (--via X,Y, repeated)")
    start, end = _span(windows)
    xy = pm.path_samples(trace, start, end)
    if len(xy.time) < 3:
        raise PlotError(f"too few x-y samples in {_window_text(start, end)} "
                        "(the trace needs SAMPLE rows of all axes)")
    m = pm.measure(xy, corners)
    fig = Figure(figsize=(WIDTH * 1.35, WIDTH), layout="constrained")
    ax = fig.subplots()
    cx, cy = zip(*corners)
    ax.plot(cx, cy, label="commanded segments", **STYLE["given"])
    ax.plot(cx, cy, ls="none", marker="o", color="black", ms=4)
    ax.plot(xy.x, xy.y, label="traced path (counters)", color="tab:orange", lw=1.2)
    # Each via point is numbered just outside the path; its figures stand in a
    # column beside the axes, where no label can hide another or leave the figure.
    mx, my = sum(cx[1:]) / (len(cx) - 1), sum(cy[1:]) / (len(cy) - 1)
    rows = ["via  miss   speed", "     counts counts/s"]
    for k, (c, miss, v) in enumerate(zip(corners[1:], m.via_miss, m.via_speed)):
        dx, dy = c[0] - mx, c[1] - my
        norm = math.hypot(dx, dy) or 1.0
        ax.annotate(str(k + 1), c, fontsize=7, color="dimgrey", ha="center", va="center",
                    xytext=(9 * dx / norm, 9 * dy / norm), textcoords="offset points")
        rows.append(f"{k + 1:3d} {miss:6.0f} {v:8.0f}")
    ax.text(1.03, 1.0, "\n".join(rows), transform=ax.transAxes, va="top", ha="left",
            fontsize=7, family="monospace")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x counter, counts (800 = 1 in)")
    ax.set_ylabel("y counter, counts")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    worst = max(range(len(m.segment_max)), key=lambda k: m.segment_max[k])
    fig.suptitle(f"x-y path, {Path(trace.name).name}: largest deviation from a segment "
                 f"{m.segment_max[worst]:.0f} counts (segment {worst + 1});\nvia points "
                 "numbered; beside them the closest approach to each and the speed there",
                 fontsize=9)
    return fig


def gripper_figure(trace, windows=()):
    """The finger opening, the contact switch and the missed steps against time."""
    if trace.gripper is None:
        raise PlotError(f"{trace.name}: no gripper columns (a trace from an older build)")
    start, end = _span(windows)
    g = trace.gripper
    keep = (g.time >= (start if start is not None else -1)) & \
           (g.time <= (end if end is not None else g.time[-1]))
    if not keep.any():
        raise PlotError(f"no gripper rows in {_window_text(start, end)}")
    fig = Figure(figsize=(2 * WIDTH, 4.2), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=(2, 1))
    top.plot(g.time[keep], g.opening[keep], color="tab:purple", drawstyle="steps-post",
             label="opening between the fingers")
    top.set_ylabel("opening, inches")
    top.set_ylim(-0.05, 2.05)
    bottom.plot(g.time[keep], g.contact[keep], drawstyle="steps-post", color="tab:green",
                label="contact switch (REQ B)")
    bottom.set_ylabel("contact")
    twin = bottom.twinx()
    twin.plot(g.time[keep], g.missed[keep], drawstyle="steps-post", color="tab:red",
              label="step pulses missed, total")
    twin.set_ylabel("missed steps")
    bottom.set_xlabel("simulated time, s")
    for ax in (top, bottom, twin):
        ax.legend(loc="upper left" if ax is not twin else "upper right", fontsize=8)
    top.grid(True, alpha=0.3)
    bottom.grid(True, alpha=0.3)
    fig.suptitle(f"Gripper against time, {Path(trace.name).name}")
    return fig
