"""Blocks 1040-1053 (the project's continuation, not 1983 code): the set-point
generator alone. Path.Step is run one tick at a time by a CODE word typed at
the prompt (the servo on vector 100 does not run it), and the x-y set-points it
leaves in Desire.Pos are compared with Paul's continuous trajectory computed
here in exact arithmetic: straight segments at the path speed joined by
constant-acceleration blends of 2 Blend ticks centred on each via point.

Measured: every set-point is within 1 count of the continuous trajectory half
a tick later (the generator adds the velocity after updating it: p_k =
q(k + 1/2) - a/8, and rounds to the nearest count); the path ends exactly on
the last via point; the closest approach to a square's corner is Paul's
|v2 - v1| tau / 4 = 84.9 counts at 2400 counts/s, Blend 6."""
import math

import numpy as np
import pytest

from harness.machine.build import fresh_disk
from harness.machine.robot import Robot

from continuation import SQUARE, circle, paul_phases, paul_position, spline_points, vias

TICK_PATH = ("CODE Path.Tick Path.Step NEXT,",
             ": Trace.Path ( -- ) BEGIN Path.Tick Desire.Pos @ . "
             "Desire.Pos 2+ @ . Path.Done? END ;")


@pytest.fixture(scope="module")
def gen(tmp_path_factory):
    """One robot for the module: 1000 LOAD 1040 LOAD Set.Up.Robot, the clock's
    interrupt off and Interrupt.Path on its vector (Path.Run wants it there;
    here nothing runs it but Path.Tick), Path.Tick and Trace.Path defined;
    each test starts its path at Desire.Pos 0 0 0 0."""
    disk = fresh_disk(tmp_path_factory.mktemp("gen"), "rl0.dsk")
    with Robot(disk=disk, timeout=20) as r:
        r.send("1000 LOAD 1040 LOAD Set.Up.Robot 0 177546O ! Path.Servo")
        for line in TICK_PATH:
            r.send(line)
        yield r


@pytest.fixture
def r(gen):
    gen.send("Path.Clear 6 Blend ! Desire.Pos Zero.Array")
    return gen


def setpoints(r, points, speed, run="Path.Run"):
    r.send("Path.Clear")
    for k in range(0, len(points), 6):
        r.send(vias(points[k:k + 6], 0))
    r.send(f"{speed} {run}")
    out = [int(w) for w in r.send("Trace.Path").split()]
    return np.array(out, float).reshape(-1, 2)


def test_setpoints_follow_pauls_trajectory(r):
    got = setpoints(r, SQUARE[1:], 2400)
    phases = paul_phases(SQUARE[0], SQUARE[1:], 2400, 6)
    assert len(got) == sum(t for t, _ in phases)             # 332 ticks
    want = np.array([paul_position(SQUARE[0], phases, k + 0.5) for k in range(1, len(got) + 1)])
    assert np.abs(got - want).max() <= 1.0
    assert tuple(got[-1]) == SQUARE[-1]                     # snapped to the last via
    corner = 2400 / 60 * math.sqrt(2) * 6 / 4                # Paul: |v2 - v1| tau / 4
    for via in SQUARE[1:-1]:
        closest = np.hypot(*(got - via).T).min()
        assert abs(closest - corner) <= 1.5, (via, closest, corner)


def test_short_segments_are_stretched_to_two_blends(r):
    # 300-count segments at 3000 counts/s would take 6 ticks; a blend takes 12
    points = [(300, 0), (300, 300), (0, 300)]
    got = setpoints(r, points, 3000)
    assert len(got) == 3 * 12 + 12
    phases = paul_phases((0, 0), points, 3000, 6)
    want = np.array([paul_position((0, 0), phases, k + 0.5) for k in range(1, len(got) + 1)])
    assert np.abs(got - want).max() <= 1.0 and tuple(got[-1]) == (0, 300)


def test_spline_setpoints_follow_the_hermite_cubics(r):
    # Spline.Run: the set-points are the cubics' values at whole ticks, and
    # every via point is passed exactly (within rounding)
    for points, speed in ((SQUARE[1:], 2400), (circle()[1:], 2400)):
        start = (0, 0) if points[0] == SQUARE[1] else (3200, 1600)
        if start != (0, 0):
            r.send(f"Path.Clear {start[0]} {start[1]} 0 0 Via 1200 Path.Run")
            r.send("BEGIN Path.Tick Path.Done? END")
        got = setpoints(r, points, speed, "Spline.Run")
        want, n = spline_points(start, points, speed)
        assert len(got) == sum(n)
        assert np.abs(got - want).max() <= 3.0, (points[0], np.abs(got - want).max())
        ends = np.cumsum(n) - 1
        assert np.abs(got[ends] - np.array(points)).max() <= 3.0
        assert tuple(got[-1]) == tuple(points[-1])


def test_bad_paths_are_refused_and_nothing_is_lost(r):
    ok, _, err = r.reply("Path.Clear 1200 Path.Run")
    assert not ok and "Path.Run: no via points" in err
    ok, _, err = r.reply("Path.Clear 100 0 400 0 Via 10 Path.Run")
    assert not ok and "speed 60..5000" in err
    ok, _, err = r.reply("0 Blend ! 1200 Path.Run")          # a blend of no ticks
    assert not ok and "Blend 1..599" in err
    r.send("6 Blend ! Path.Clear")
    ok, _, err = r.reply("33 0 DO I 10 * 0 400 0 Via LOOP")
    assert not ok and "Via: the path is full" in err
    assert r.send("Via.Count ?").split() == ["32"]
    assert r.send("Path.Done? .").split() == ["-1"]
    # the generator not on the clock's vector: Path.Run and the gripper refuse
    r.send("' Interrupt.Servo 100O !")
    for line in ("1200 Path.Run", "10 1 Grip.Move"):
        ok, _, err = r.reply(line)
        assert not ok and "type Path.Servo first" in err
    r.send("Path.Servo")
    assert r.send("Grip.Left ?").split() == ["0"]
