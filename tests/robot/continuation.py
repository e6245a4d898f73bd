"""Shared by the continuation's robot tests: load the blocks on a servo, and
Paul's continuous trajectory computed independently of the FORTH."""
import math

import numpy as np

from harness.figures.continuation_runs import PLANE, SQUARE, circle, vias_text as vias  # noqa: F401


def load(boot, servo_block=None, trace=True):
    """1000 LOAD, the servo's block (e.g. 1030), 1040 LOAD, Set.Up.Robot."""
    r = boot(trace=trace)
    r.send("1000 LOAD")
    if servo_block:
        r.send(f"{servo_block} LOAD")
    r.send("1040 LOAD")
    r.send("Set.Up.Robot")
    return r


def paul_phases(start, points, speed, tau):
    """The phases Plan (blocks 1046-1049) lays down, in exact arithmetic:
    [(ticks, acceleration per tick^2 as an x-y vector)], velocities in counts
    per tick. Segment ticks as the FORTH rounds them."""
    phases, was, here = [], np.zeros(2), np.array(start, float)
    for p in points:
        d = np.array(p, float) - here
        length = math.isqrt(int(d @ d))
        n = max(2 * tau, (length * 60 + speed // 2) // speed)
        v = d / n
        phases.append((2 * tau, (v - was) / (2 * tau)))
        if n > 2 * tau:
            phases.append((n - 2 * tau, np.zeros(2)))
        was, here = v, np.array(p, float)
    phases.append((2 * tau, -was / (2 * tau)))
    return phases


def paul_position(start, phases, t):
    """The continuous trajectory at time t ticks (piecewise constant acceleration)."""
    q, v, left = np.array(start, float), np.zeros(2), t
    for ticks, a in phases:
        dt = min(ticks, left)
        q, v = q + v * dt + a * dt * dt / 2, v + a * dt
        left -= dt
        if left <= 0:
            break
    return q


def spline_points(start, points, speed):
    """The set-points Spline.Plan (blocks 1050-1052) aims at, in exact
    arithmetic: per segment a Hermite cubic over N ticks from P0 to P1 with
    velocities m0, m1 (counts per tick; 0 at both ends of the path, at an
    inner via point (P(i+1) - P(i-1)) / (N(i) + N(i+1))), sampled at ticks
    1..N of each segment."""
    pts = [np.array(start, float)] + [np.array(p, float) for p in points]

    def ticks(a, b):
        d = b - a
        return max(2, (math.isqrt(int(d @ d)) * 60 + speed // 2) // speed)

    n = [ticks(a, b) for a, b in zip(pts[:-1], pts[1:])]
    m = [np.zeros(2)] + [(pts[i + 1] - pts[i - 1]) / (n[i - 1] + n[i])
                         for i in range(1, len(pts) - 1)] + [np.zeros(2)]
    out = []
    for i, N in enumerate(n):
        p0, p1, m0, m1 = pts[i], pts[i + 1], m[i], m[i + 1]
        c = (3 * (p1 - p0) / N - 2 * m0 - m1) / N
        d = (m0 + m1 - 2 * (p1 - p0) / N) / N ** 2
        out += [p0 + m0 * s + c * s * s + d * s ** 3 for s in range(1, N + 1)]
    return np.array(out), n
