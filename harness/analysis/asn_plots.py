"""Figures of the ASN's learning (blocks 1070-1078, docs/learning.md):

    learning_figure(trials, control)       # steps per trial, learning and rate 0
    paths_figure(trials, [1, 10, 50], p, trace=None)   # x-y paths of those trials
    weights_figure(weights, p)             # the learned weights as a map

Built like harness/analysis/plots.py (matplotlib Figure, Agg); save with
plots.save. `trials` come from harness/analysis/asn_log.py, `p` is the
model's Params (harness/analysis/asn_model.py).
"""
import numpy as np
from matplotlib.figure import Figure

from harness.analysis import asn_model as am
from harness.analysis import path_metrics as pm
from harness.analysis.plot_errors import PlotError
from harness.analysis.plots import WIDTH

ARROW = {0: (1, 0), 1: (-1, 0), 2: (0, 1), 3: (0, -1)}    # +x -x +y -y


def _mean(values):
    return sum(values) / len(values) if values else float("nan")


def learning_figure(trials, control=()):
    """Steps per trial, with the means of the first and last ten."""
    if not trials:
        raise PlotError("no trials to draw")
    fig = Figure(figsize=(WIDTH * 1.3, WIDTH * 0.7), layout="constrained")
    ax = fig.subplots()
    for runs, label, colour in ((trials, "learning", "tab:blue"),
                                (control, "control: Rate 0 (no learning)", "tab:grey")):
        if not runs:
            continue
        n = [t.number for t in runs]
        s = [t.n_steps for t in runs]
        ax.plot(n, s, marker="o", ms=3, lw=1, color=colour,
                label=f"{label}: first 10 {_mean(s[:10]):.1f}, last 10 {_mean(s[-10:]):.1f} "
                      "steps (mean)")
        for part in (slice(0, 10), slice(-10, None)):
            seg = runs[part]
            ax.hlines(_mean([t.n_steps for t in seg]), seg[0].number, seg[-1].number,
                      color=colour, lw=2.5, alpha=0.6)
    ax.axhline(8, color="tab:green", ls=":", lw=1, label="shortest path from a corner: 8 steps")
    ax.set_xlabel("trial")
    ax.set_ylabel("steps to the goal (100: gave up)")
    ax.set_ylim(0, 130)                 # room for the legend above the 100-step cap
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title("ASN on the emulated robot (printed servo): steps per trial")
    return fig


def _arena(ax, p):
    a, g = p.arena, p.goal_size
    ax.add_patch(_rect((0, 0), a, a, fill=False, ec="black", lw=0.8))
    ax.add_patch(_rect((p.goal_x - g, p.goal_y - g), 2 * g, 2 * g, color="tab:green",
                       alpha=0.25, lw=0))
    ax.set_xlim(-300, a + 300)
    ax.set_ylim(-300, a + 300)
    ax.set_aspect("equal")
    ax.set_xlabel("x counter (800 counts = 1 in)")


def _rect(*args, **kw):
    from matplotlib.patches import Rectangle
    return Rectangle(*args, **kw)


def paths_figure(trials, numbers, p, trace=None):
    """Each chosen trial's steps (the counters the FORTH read), over the
    traced counters between its start and end when a plant trace is given."""
    by_number = {t.number: t for t in trials}
    chosen = [by_number[n] for n in numbers if n in by_number]
    if not chosen:
        raise PlotError(f"none of the trials {numbers} is in the run")
    fig = Figure(figsize=(WIDTH * len(chosen) * 0.62, WIDTH * 0.72), layout="constrained")
    axes = np.atleast_1d(fig.subplots(1, len(chosen), sharey=True))
    for ax, t in zip(axes, chosen):
        _arena(ax, p)
        if trace is not None and t.start_time is not None and t.end_time is not None:
            xy = pm.path_samples(trace, t.start_time, t.end_time)
            ax.plot(xy.x, xy.y, color="tab:orange", lw=0.6, alpha=0.8,
                    label="traced counters (from the goal back to the start corner, "
                          "then the trial)")
        x, y = zip(*t.path)
        ax.plot(x, y, color="tab:blue", lw=1, marker="o", ms=2.5, label="counters at each step")
        ax.plot(x[0], y[0], marker="s", color="black", ms=6, label="start")
        ax.set_title(f"trial {t.number}: {t.n_steps} steps, late moves: {t.late}", fontsize=10)
    axes[0].set_ylabel("y counter")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=8, loc="outside lower center", ncols=3)
    return fig


def weights_figure(weights, p, trials=0):
    """Left: the action the weights prefer (no noise) at each point of the
    step lattice, and by how much against the noise after `trials` trials.
    Right: the weights themselves."""
    net = am.Asn(p)
    net.weights = [list(row) for row in weights]
    noise = am.star_slash(p.noise, p.cooling, p.cooling + trials)
    fig = Figure(figsize=(WIDTH * 1.6, WIDTH * 0.72), layout="constrained")
    left, right = fig.subplots(1, 2, width_ratios=[1, 1.25])
    _arena(left, p)
    lattice = range(0, p.arena + 1, p.step_size)
    for gx in lattice:
        for gy in lattice:
            s = [net.activation(j, am.sense(gx, gy)) for j in range(am.N_OUT)]
            best = int(np.argmax(s))
            margin = sorted(s)[-1] - sorted(s)[-2]
            dx, dy = ARROW[best]
            strength = min(1.0, margin / max(1, noise))
            left.arrow(gx, gy, dx * p.step_size * 0.55, dy * p.step_size * 0.55,
                       width=18, head_width=110, head_length=110, length_includes_head=True,
                       color=(0.1, 0.3 + 0.4 * (1 - strength), 0.8, 0.35 + 0.65 * strength))
    left.set_ylabel("y counter")
    left.set_title(f"largest s at each step point (darker: surer against\n"
                   f"the noise after {trials} trials, +-{noise})", fontsize=10)
    w = np.array(weights, dtype=float)
    lim = max(1.0, np.abs(w).max())
    im = right.imshow(w, cmap="RdBu_r", vmin=-lim, vmax=lim, aspect="auto")
    right.set_yticks(range(am.N_OUT), [f"{a} element" for a in am.ACTIONS])
    ticks = [f"x{k * am.FIELD_SPACING}" for k in range(am.FIELDS)] + \
            [f"y{k * am.FIELD_SPACING}" for k in range(am.FIELDS)]
    right.set_xticks(range(am.N_IN), ticks, rotation=90, fontsize=7)
    right.set_xlabel("input: the receptive field centred at x or y (counts)")
    right.set_title(f"weights w[j,i] after {trials} trials (16-bit, from .Net)", fontsize=10)
    fig.colorbar(im, ax=right, shrink=0.8)
    return fig
