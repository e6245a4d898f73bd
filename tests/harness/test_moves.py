"""Moves, D0..D3 and held codes, measured on the hand servo's real trace
(tests/harness/servo_program.py: ramp INC=20 codes a tick to MAXVEL=300, then
velocity = distance left; range 5 counts), and the definitions' edge cases on
small made-up series."""
import numpy as np
import pytest

from harness.analysis import moves as mv
from harness.analysis import trace
from harness.analysis.trace import AxisSeries
from servo_program import LONG_TARGET, SETTINGS, SHORT_TARGET


@pytest.fixture(scope="module")
def x(servo_trace):
    return trace.read(servo_trace).axis("X")


@pytest.fixture(scope="module")
def long_short(x):
    found = mv.find_moves(x)
    assert len(found) == 2, found          # the blips that pull x back are not moves
    return mv.long_and_short(found)


def test_long_move_d0_to_d3(x, long_short):
    long_, _ = long_short
    assert long_.direction == 1 and long_.settled
    assert long_.zero_code == SETTINGS["zero"]
    assert long_.peak_code == SETTINGS["maxvel"]        # reaches MaxVel
    assert long_.d0 < long_.d1 < long_.d2 < long_.d3
    assert abs(long_.d3 - LONG_TARGET) <= 2 * SETTINGS["range_"]
    codes = mv.servo_velocity_codes(x, long_)[long_.first:long_.last + 1]
    # the ramp: commanded velocity climbs in steps of INC up to D1
    ramp = np.unique(codes[:np.flatnonzero(codes == long_.peak_code)[0]])
    assert set(np.diff(ramp)) == {SETTINGS["inc"]}
    # after D2 it falls with the distance left: below the peak, never back up to it
    after = codes[np.flatnonzero(codes == long_.peak_code)[-1] + 1:]
    assert len(after) and after.max() < long_.peak_code
    # D2: the row where the code first leaves the peak, after its last peak row
    last_peak = np.flatnonzero(codes == long_.peak_code)[-1]
    first_below = last_peak + 1 + np.flatnonzero(codes[last_peak + 1:] != long_.peak_code)[0]
    assert x.pos[first_below + long_.first] == long_.d2


def test_short_move_never_reaches_maxvel(long_short):
    _, short = long_short
    assert short.direction == -1 and short.settled
    assert 0 < short.peak_code < SETTINGS["maxvel"]
    assert short.peak_code % SETTINGS["inc"] == 0       # the ramp's last step
    assert short.d0 > short.d1 > short.d2 > short.d3    # a one-tick peak: D2 a tick on
    assert abs(short.d3 - SHORT_TARGET) <= 2 * SETTINGS["range_"]
    assert short.t0 > long_short[0].t1


def test_windows_pick_moves(x, long_short):
    found = mv.find_moves(x)
    long_, short = long_short
    assert mv.moves_between(found, short.t0 - 0.01, None) == [short]
    assert mv.moves_between(found, None, long_.t0) == [long_]
    assert mv.moves_between(found, 100, None) == []


def test_held_codes_follow_the_raised_zero(x):
    t, held = mv.held_codes(x)
    zero = SETTINGS["zero"]
    assert set(held) == {zero, zero + 1, zero + 2, zero + 3}   # raised three times
    assert held[-1] == zero + 3 and np.all(np.diff(t) >= 0)
    # every held row is idle and its code has not changed for HOLD seconds
    assert np.all(mv.idle_mask(x)[mv.held_mask(x)])


def test_kv_and_true_zero_from_the_trace(servo_trace, x):
    kv = mv.estimate_kv(x)
    assert kv == pytest.approx(19.53, abs=0.01)        # docs/design.md's default Kv
    assert np.median(mv.true_zero(x, kv)) == pytest.approx(2048 + 3.0, abs=0.1)  # offset +3
    assert mv.estimate_kv(trace.read(servo_trace).axis("Y")) is None   # one code only


def series(pos, dac, vel=None, vcmd=None, dt=1 / 60):
    pos = np.asarray(pos, float)
    n = len(pos)
    vel = np.zeros(n) if vel is None else np.asarray(vel, float)
    return AxisSeries("X", np.arange(n) * dt, np.asarray(dac), np.zeros(n) if vcmd is None
                      else np.asarray(vcmd, float), vel, pos, pos.astype(int))


def test_a_move_at_the_start_and_one_still_running():
    s = series(pos=[0, 100, 300, 300, 300, 400, 700],
               dac=[2148, 2148, 2048, 2048, 2058, 2348, 2348],
               vel=[1000, 1000, 0, 0, 0, 1000, 1000])
    first, second = mv.find_moves(s, min_travel=50)
    assert first.zero_code == 2048 and first.d0 == 0 and first.d3 == 300 and first.settled
    assert second.zero_code == 2058          # the code held just before it
    assert second.peak_code == 290 and not second.settled and second.d3 == 700


def test_short_segments_are_not_moves():
    s = series(pos=[0, 0, 10, 20, 20, 20], dac=[2048, 2048, 2100, 2100, 2048, 2048],
               vel=[0, 0, 900, 900, 0, 0])
    assert mv.segments(s) == [(2, 3)]
    assert mv.find_moves(s, min_travel=50) == []
    assert len(mv.find_moves(s, min_travel=15)) == 1


def test_no_ramp_puts_d1_on_the_first_tick(tmp_path):
    """Like block 1006 as printed: the velocity jumps to MaxVel at once (the hand
    servo with INC = MAXVEL), so D1 is where the move starts."""
    from harness.machine import simh
    from servo_program import servo_program, trace_script
    path = tmp_path / "jump.csv"
    simh.run(trace_script(servo_program(inc=300, adapt_steps=0), path))
    long_, _ = mv.long_and_short(mv.find_moves(trace.read(path).axis("X")))
    x = trace.read(path).axis("X")
    assert long_.peak_code == 300
    assert long_.d1 == x.pos[long_.first] and long_.d1 - long_.d0 < 5


def test_a_one_tick_peak_puts_d2_a_tick_beyond_d1():
    s = series(pos=[0, 0, 40, 140, 220, 260, 270, 270],
               dac=[2048, 2348, 2148, 2128, 2088, 2058, 2048, 2048],
               vel=[0, 900, 6000, 4800, 2400, 900, 0, 0])
    (move,) = mv.find_moves(s)
    assert move.peak_code == 300 and move.d0 == 0 and move.d1 == 0
    assert move.d2 == 40                     # where the command fell, not on D0


def test_drift_with_the_dac_at_zero_is_not_a_move():
    """z falling onto its stop at power-up: DAC 2048 throughout, no servo."""
    s = series(pos=[0, -200, -900, -1800, -2700, -3600, -4000, -4000],
               dac=[2048] * 8, vel=[-880] * 6 + [0, 0], vcmd=[-880] * 8)
    assert mv.find_moves(s) == []


def test_short_means_below_maxvel():
    def move(travel, peak):
        return mv.Move("X", 0, 1, 2, 2048, 1, peak, 0, 1, 0, 0, 0, travel, True)
    long_, big, small = move(4000, 300), move(300, 300), move(100, 120)
    assert mv.long_and_short([long_, big]) == (long_, None)    # no short move
    assert mv.long_and_short([long_, big, small]) == (long_, small)
