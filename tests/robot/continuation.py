"""Shared by the continuation's robot tests: load the blocks on a servo, and
Paul's continuous trajectory computed independently of the FORTH."""
import math

import numpy as np

from harness.continuation_runs import PLANE, SQUARE, circle, vias_text as vias  # noqa: F401


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
