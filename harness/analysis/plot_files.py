"""Figures written to files: every format of a figure from one layout, and
every file of a set whole or none (harness/analysis/plots.py re-exports these).

    save(fig, ["out.png", "out.svg"])
    save_all([(fig1, ["a.png", "a.svg"]), (fig2, ["b.png"])])

A figure built with layout="constrained" is laid out here once, as its PNG
would be, and drawn as laid out for each format: a savefig of a figure that has
a layout engine lays it out anew and draws it twice (once to measure), and that
layout and measuring, not the few thousand points of a trace, are most of what
saving costs. The PNG is the same as from savefig alone; the SVG has the PNG's
layout, everything in it 3 points at most from where a layout at the SVG's own
72 dpi put it (the servo trace's figures; the same marks, text and look).
The layout measures with the PNG's own renderer, so the PNG's draw finds its
texts measured: the same bytes, cheaper.
"""
import contextlib
import os
import tempfile
from pathlib import Path

import matplotlib
from matplotlib.backend_bases import FigureCanvasBase
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.ticker import NullLocator

DPI = 100                                   # of the PNGs


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _no_minor_dedup(fig):
    """Where an axis has no minor ticks there are none to drop for falling on a
    major one; matplotlib would work out the major ticks a second time for it at
    every measuring and drawing of the axis."""
    for ax in fig.axes + [child for ax in fig.axes for child in ax.child_axes]:
        for axis in (ax.xaxis, ax.yaxis):
            if isinstance(axis.get_minor_locator(), NullLocator):
                axis.remove_overlapping_locs = False


@contextlib.contextmanager
def _laid_out_once(fig):
    """Inside, `fig` laid out as savefig(dpi=DPI) would and without its layout
    engine, so that savefig draws it as it is, once; the engine comes back after."""
    engine = fig.get_layout_engine()
    if engine is None:
        yield
        return
    if type(fig.canvas) is FigureCanvasBase:       # Figure()'s, with no renderer
        # the PNG's own canvas, whose renderer the layout then measures text
        # with and the PNG is drawn by: the texts measured once for both
        FigureCanvasAgg(fig)
    dpi, fig.dpi = fig.dpi, DPI
    try:
        engine.execute(fig)
    except ValueError:              # as Figure.draw: then drawn as it stands
        pass
    finally:
        fig.dpi = dpi
    # None, not "none": savefig would still draw a figure with the placeholder
    # engine that "none" leaves twice; None means the rc default, here no engine
    with matplotlib.rc_context({"figure.autolayout": False,
                                "figure.constrained_layout.use": False}):
        fig.set_layout_engine(None)
    try:
        yield
    finally:
        fig.set_layout_engine(engine)


def save(fig, paths):
    """Write `fig` to each path (format from the suffix: .png or .svg)."""
    save_all([(fig, paths)])


def save_all(figures):
    """Write every (figure, paths) pair; each file is rendered to a temporary
    name beside it and all are renamed only when all rendered, so a failure
    leaves no file half-written and none of the set replaced."""
    done = []
    try:
        for fig, paths in figures:
            _no_minor_dedup(fig)
            with _laid_out_once(fig):
                for path in map(Path, paths):
                    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
                    os.close(fd)
                    os.chmod(tmp, 0o666 & ~_umask())     # as an ordinary new file
                    done.append((tmp, path))
                    svg = path.suffix == ".svg"
                    # a fixed salt and no date: the same trace gives the same SVG
                    with matplotlib.rc_context({"svg.hashsalt": "robot-1983"}):
                        fig.savefig(tmp, format=path.suffix.lstrip("."), dpi=DPI,
                                    metadata={"Date": None} if svg else None)
        for tmp, path in done:
            os.replace(tmp, path)
    finally:
        for tmp, _ in done:
            if os.path.exists(tmp):
                os.unlink(tmp)
