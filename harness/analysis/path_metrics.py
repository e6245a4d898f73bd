"""How closely a traced x-y path follows its commanded straight segments
(the continuous-path blocks 1040-1053, docs/continuation.md). Pure geometry on
numpy arrays; no plotting, no simulator.

    xy = path_samples(trace, start, end)      # PathSamples: time, x, y (counts)
    m = measure(xy, corners)                   # corners: [(x, y), ...] start, vias
    m.segment_max      # per segment: the largest distance of a sample whose
                       # nearest segment it is, counts
    m.via_miss         # per via point: closest approach, counts
    m.via_speed        # per via point: speed at that closest approach, counts/s
    radial_error(xy, centre, radius)   # per sample, from a circle, counts

Samples are the trace rows where all four axes were sampled together (SAMPLE
per second), positions are the axis counters (what the FORTH reads), so a
path is measured in the same counts as its via points.
"""
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PathSamples:
    time: np.ndarray
    x: np.ndarray
    y: np.ndarray


@dataclass(frozen=True)
class PathMeasure:
    segment_max: list      # counts, one per segment
    via_miss: list         # counts, one per via point (the end point included)
    via_speed: list        # counts/s at the closest approach
    duration: float        # s, from the first sample that moved to the end's arrival


def path_samples(trace, start=None, end=None):
    """The x-y counter samples of a trace between start and end (s)."""
    xs, ys = trace.axis("X").window(start, end), trace.axis("Y").window(start, end)
    common, ix, iy = np.intersect1d(xs.time, ys.time, return_indices=True)
    return PathSamples(common, xs.counter[ix].astype(float), ys.counter[iy].astype(float))


def radial_error(xy, centre, radius):
    """Per sample: distance from the centre less the radius (counts; + outside)."""
    return np.hypot(xy.x - centre[0], xy.y - centre[1]) - radius


def _distances(px, py, a, b):
    """Distance of the points (px, py) from segment a-b, and the parameter of
    the nearest point (0 at a, 1 at b)."""
    d = np.subtract(b, a, dtype=float)
    length2 = d @ d
    u = np.zeros_like(px) if length2 == 0 else \
        np.clip(((px - a[0]) * d[0] + (py - a[1]) * d[1]) / length2, 0, 1)
    return np.hypot(px - (a[0] + u * d[0]), py - (a[1] + u * d[1])), u


def measure(xy, corners, settle=50.0):
    """Deviation of the samples from the polyline through `corners` (the start
    point then every via point). `settle`: a sample within this distance of
    the last corner counts as arrived (for the duration)."""
    corners = [tuple(map(float, c)) for c in corners]
    segs = list(zip(corners[:-1], corners[1:]))
    dist = np.array([_distances(xy.x, xy.y, a, b)[0] for a, b in segs])
    nearest = dist.argmin(axis=0)
    seg_max = [float(dist[k][nearest == k].max()) if np.any(nearest == k) else float("nan")
               for k in range(len(segs))]
    speed = np.hypot(np.gradient(xy.x, xy.time), np.gradient(xy.y, xy.time))
    miss, at_speed = [], []
    for c in corners[1:]:
        d = np.hypot(xy.x - c[0], xy.y - c[1])
        k = int(d.argmin())
        miss.append(float(d[k]))
        at_speed.append(float(speed[k]))
    moved = np.hypot(xy.x - corners[0][0], xy.y - corners[0][1]) > settle
    first = int(np.argmax(moved))
    last = corners[-1]
    arrived = np.nonzero((np.hypot(xy.x - last[0], xy.y - last[1]) <= settle)
                         & (np.arange(len(xy.time)) > first))[0]
    # arrival: the first sample near the end point after the path's last via left
    end_k = arrived[-1] if len(arrived) else len(xy.time) - 1
    run = np.nonzero(np.hypot(xy.x - last[0], xy.y - last[1]) > settle)[0]
    if len(run):
        after = arrived[arrived > run[-1]]
        end_k = after[0] if len(after) else end_k
    return PathMeasure(seg_max, miss, at_speed, float(xy.time[end_k] - xy.time[first]))
