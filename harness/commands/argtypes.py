"""argparse types shared by the subcommands: a bad value is a usage error
(exit 2) that names the value and says what was expected."""
import argparse
import math
from pathlib import Path


def number_above(kind, low, what, at_most=None):
    """A converter to `kind` (int or float) accepting values > low (and <= at_most
    when given)."""
    def convert(text):
        try:
            value = kind(text)
        except ValueError:
            value = None
        if value is None or not value > low or not math.isfinite(value) \
                or (at_most is not None and value > at_most):
            raise argparse.ArgumentTypeError(f"{text!r}: expected {what}")
        return value
    return convert


positive = number_above(float, 0, "a positive number")
count = number_above(int, 0, "a whole number >= 1")


def absolute_path(text):
    """A path made absolute against the directory the command was started in: the
    simulator is started in another (a run's own, the project's), where a relative
    name would name nothing."""
    return str(Path(text).absolute())
