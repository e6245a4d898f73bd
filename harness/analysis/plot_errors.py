"""The plot command's error, apart from harness/analysis/plots.py so that the command
line can name it without importing matplotlib (a second or more on start)."""


class PlotError(ValueError):
    """What was asked cannot be drawn from this trace (no moves, bad window)."""
