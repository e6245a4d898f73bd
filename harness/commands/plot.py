"""`plot TRACE`: figures from a plant trace (see docs/plots.md)."""
import argparse
from pathlib import Path

from harness.analysis import moves as mv
from harness.analysis.plot_errors import PlotError
from harness.analysis.trace import AXES, TraceError, read
from harness.commands.argtypes import positive

ERRORS = (TraceError, PlotError)
FIGURES = ("moves", "time", "zero")              # what "all" draws
ON_REQUEST = ("xy", "gripper")                   # the continuation's, when named

DESCRIPTION = """\
Draw figures from a plant trace (the CSV that SIMH's ATTACH PLANT writes):

  moves  commanded and actual velocity against distance for a move, with the
         paper's D0-D3 marked (its Figure 2); the longest and the shortest move
         side by side, or one panel per --window. One file per axis.
  time   position and velocity against time, one row per axis.
  zero   the 0-Vel adaptation: the DAC code each idle axis is held at, against
         time, beside the plant's true zero (2048 + offset) computed from the
         trace (dac - vcmd/Kv) and, with --offset, the value you give.
  xy     (only when named) the x-y path traced by the counters against the
         straight segments through the --via points (the start point first),
         with each segment's largest deviation and each via point's closest
         approach and the speed there (docs/continuation.md).
  gripper  (only when named) the gripper's opening, contact switch and
         missed steps against time.

Files are named STEM-moves-X.png, STEM-time.svg, ... where STEM is the trace's
path without .csv, or --out. Each file is written whole or not at all; nothing
is written if any figure cannot be drawn."""


def window(text):
    """START:END in simulated seconds; either side may be empty."""
    start, sep, end = text.partition(":")
    if not sep:
        raise argparse.ArgumentTypeError(f"{text!r}: expected START:END in seconds, "
                                         "e.g. 0.5:2 or 3:")
    try:
        bounds = tuple(float(x) if x.strip() else None for x in (start, end))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: START and END must be numbers") from None
    if None not in bounds and bounds[0] > bounds[1]:
        raise argparse.ArgumentTypeError(f"{text!r}: START is after END")
    return bounds


def axis_letters(text):
    letters = text.upper()
    if not letters or any(a not in AXES for a in letters):
        raise argparse.ArgumentTypeError(f"{text!r}: axes are letters from {AXES}")
    return "".join(a for a in AXES if a in letters)


def offset(text):
    """AXIS=CODES, e.g. Z=45."""
    axis, sep, value = text.partition("=")
    try:
        if sep and axis.upper() in AXES and len(axis) == 1:
            return axis.upper(), float(value)
    except ValueError:
        pass
    raise argparse.ArgumentTypeError(f"{text!r}: expected AXIS=CODES, e.g. Z=45")


def point(text):
    """X,Y in counts."""
    try:
        x, y = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected X,Y in counts, "
                                         "e.g. 3200,0") from None
    return x, y


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("trace", metavar="TRACE", help="plant trace CSV")
    parser.add_argument("--figure", choices=FIGURES + ON_REQUEST + ("all",), default="all",
                        help="which figure (default all). moves: one per axis that has "
                        "moves (with --axis, each axis named must have one)")
    parser.add_argument("--axis", type=axis_letters, metavar="AXES",
                        help=f"axes to draw, letters from {AXES} (default: every axis "
                        "in the trace; for moves, every axis that has moves)")
    parser.add_argument("--window", type=window, action="append", default=[],
                        metavar="START:END", help="simulated seconds; repeatable. "
                        "moves: the longest move starting in each window, one panel "
                        "each; time, zero: the span from the first START to the last END")
    parser.add_argument("--out", metavar="STEM",
                        help="output name stem (default: TRACE without .csv)")
    parser.add_argument("--format", choices=("png", "svg", "both"), default="both",
                        help="file formats (default both)")
    parser.add_argument("--offset", type=offset, action="append", default=[],
                        metavar="AXIS=CODES", help="the plant's true zero offset of an "
                        "axis in DAC codes (SHOW PLANT's offset), drawn on the zero "
                        "figure; repeatable")
    parser.add_argument("--kv", type=positive, metavar="KV",
                        help="the plant's Kv, counts/s per code (default: estimated "
                        "per axis from the trace, where the DAC code varies)")
    parser.add_argument("--v-idle", type=positive, default=mv.V_IDLE, metavar="C/S",
                        help=f"an axis is idle below this speed, commanded and actual "
                        f"(default {mv.V_IDLE:g} counts/s)")
    parser.add_argument("--hold", type=positive, default=mv.HOLD, metavar="S",
                        help="zero figure: an idle axis counts as held once its DAC "
                        f"code has not changed for this long (default {mv.HOLD:g} s)")
    parser.add_argument("--min-travel", type=positive, default=mv.MIN_TRAVEL,
                        metavar="COUNTS", help="shortest motion counted as a move "
                        f"(default {mv.MIN_TRAVEL:g} counts)")
    parser.add_argument("--via", type=point, action="append", default=[], metavar="X,Y",
                        help="xy figure: the path's start point, then each via point, "
                        "counts; repeat in order")
    parser.set_defaults(run=run)


def _stem(args):
    stem = Path(args.out) if args.out else Path(args.trace).with_suffix("")
    if not stem.parent.is_dir():
        raise PlotError(f"{stem.parent}: no such directory for the figures")
    return stem


def _paths(stem, name, fmt):
    exts = ("png", "svg") if fmt == "both" else (fmt,)
    return [stem.parent / f"{stem.name}-{name}.{ext}" for ext in exts]


def build_figures(args):
    """[(figure, paths)] for what args ask; raises before anything is written."""
    from harness.analysis import plots        # matplotlib: imported only when plotting
    trace = read(args.trace)
    stem = _stem(args)
    wanted = FIGURES if args.figure == "all" else (args.figure,)
    axes = args.axis or trace.axes
    for letter in axes:
        trace.axis(letter)                      # TraceError when the axis is absent
    out = []
    if "moves" in wanted:
        asked = args.figure == "moves"
        drawn = []
        for letter in axes:
            try:
                fig = plots.moves_figure(trace, letter, args.window, args.v_idle,
                                         args.min_travel, args.kv)
            except PlotError:
                if asked and args.axis:          # an axis named for moves must have one
                    raise
                continue
            drawn.append(letter)
            out.append((fig, _paths(stem, f"moves-{letter}", args.format)))
        if asked and not drawn:
            raise PlotError(f"{args.trace}: no moves to draw on any axis ({axes}): no "
                            f"stretch of motion travels {args.min_travel:g} counts or "
                            "more" + (" and starts in the windows" if args.window else ""))
    if "time" in wanted:
        out.append((plots.time_figure(trace, axes, args.window),
                    _paths(stem, "time", args.format)))
    if "zero" in wanted:
        out.append((plots.zero_figure(trace, axes, args.window, dict(args.offset),
                                      args.kv, args.v_idle, args.hold),
                    _paths(stem, "zero", args.format)))
    if args.figure in ON_REQUEST:
        from harness.analysis import path_plots
        fig = (path_plots.xy_figure(trace, args.via, args.window) if args.figure == "xy"
               else path_plots.gripper_figure(trace, args.window))
        out.append((fig, _paths(stem, args.figure, args.format)))
    return out


def run(args):
    from harness.analysis import plots
    figures = build_figures(args)
    try:
        plots.save_all(figures)
    except OSError as err:
        raise PlotError(f"cannot write the figures: {err}") from err
    for _, paths in figures:
        for path in paths:
            print(path)
    return 0
