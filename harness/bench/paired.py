"""Two variants measured round by round, taking turns: on a shared host whose
speed drifts within seconds, the best of each alone can pair a lucky run with an
unlucky one; the ratio of each round's pair, and their median, cannot."""
import statistics


def per_round(a, b):
    """The rounds' ratios a[i] / b[i]: (median, lowest, highest)."""
    each = [x / y for x, y in zip(a, b)]
    return statistics.median(each), min(each), max(each)
