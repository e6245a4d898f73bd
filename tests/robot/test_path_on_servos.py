"""Blocks 1040-1053 driving the robot through the printed servo (blocks
1000-1012) and through the proposed corrected one (block 1030): a 4-inch
square at 2400 counts/s, traced by the plant, measured against its commanded
segments (harness/analysis/path_metrics.py). Measured in the runs of docs/continuation.md
(these sessions differ from them only in the tick phase):

- printed servo: the path follows the segments with the printed servo's
  15 Hz hunting on it, at most 72 counts from a segment; the speed at the
  corners 2100-2900 counts/s on earlier builds, 391-3224 on issue 16's (the
  hunting's phase); ends within 25 counts of the start.
- corrected servo: no hunting, at most 35 counts from a segment; it slows to
  880-910 counts/s at the corners; ends within 5 counts.
- the corrected servo accelerates only by Increment (3 codes = 59 counts/s)
  a tick: a blend sharper than that leaves it behind. Starting a circle at
  2400 counts/s with Blend 6 it strays 259 counts from the first segments;
  with Blend 24 every segment is within 33 counts (and the segments, shorter
  than two blends, are slowed)."""
from harness.analysis import path_metrics as pm
from harness.analysis import trace as tr

from harness.figures.continuation_runs import run_path

from continuation import PLANE, SQUARE, circle, load


def start(boot, servo_block=None, blend=6):
    r = load(boot, servo_block)
    r.send(f"Path.Servo {blend} Blend !")
    r.send(f"Path.Clear 0 0 {PLANE} 0 Via 1200 Path.Run Path.Wait")
    r.idle(1.0)
    return r


def run(r, origin, points, speed=2400):
    t0, t1 = run_path(r, points, speed)
    r.idle(1.0)
    r.close()                                    # the trace is complete
    return pm.measure(pm.path_samples(tr.read(r.trace_path), t0, t1 + 1.0),
                      [origin] + list(points))


def end_error(m):
    return m.via_miss[-1]


def test_square_on_the_printed_servo(boot):
    r = start(boot)
    m = run(r, SQUARE[0], SQUARE[1:])
    assert max(m.segment_max) <= 90                     # measured 73
    # never stops at a corner; the speed there follows the phase of the printed
    # servo's 15 Hz hunting (its kick can oppose the motion at that instant):
    # 2100-2900 counts/s on earlier builds, 391 at corner 2 on issue 16's kernel
    # (docs/continuation.md), so the bound is "still moving", not a speed
    assert min(m.via_speed[:-1]) >= 300
    assert 40 <= max(m.via_miss[:-1]) <= 100            # corners cut (Paul: 85 set-point)
    assert end_error(m) <= 40


def test_square_on_the_corrected_servo(boot):
    r = start(boot, 1030)
    m = run(r, SQUARE[0], SQUARE[1:])
    assert max(m.segment_max) <= 45                     # measured 35
    assert min(m.via_speed[:-1]) >= 500                 # measured 882
    assert end_error(m) <= 8


def test_corrected_servo_needs_gentle_blends(boot):
    pts = circle()          # block 1060's 16 via points, radius 2 in
    worst = {}
    for blend in (6, 24):
        r = start(boot, 1030, blend)
        r.send(f"Path.Clear {pts[0][0]} {pts[0][1]} {PLANE} 0 Via 1200 Path.Run Path.Wait")
        r.idle(0.5)
        m = run(r, pts[0], pts[1:])
        worst[blend] = max(m.segment_max)
    assert worst[6] >= 150                              # measured 259: left behind
    assert worst[24] <= 45                              # measured 33
