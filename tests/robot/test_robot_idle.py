"""A simulated minute at rest after a move: the counters and the 0-Vel entries
over time beside the plant's true zeros (2048 + offset, SHOW PLANT).

Block 1005 adapts 0-Vel by Dir (+-1) every Delay (30) ticks, but only on ticks
where the axis is idle (Command.Status 0) and outside Range (State Move). With
the printed 1006 those ticks are mostly the hunting's overshoots (see
test_moves.py), whose sign says little about the drift, so the entries do not
converge to the true zeros. Measured (every 5 s over 65 s; two phases of the
hunting, with and without one more helper line before the move):
0-Vel x 2049 -> 2056 (true 2051.0), y 2049 -> 2052 (true 2046.1),
z 2090 -> 2096..2097 (true 2093.0); x, y, z stay within 25 counts of their
targets. t: Command.Status t stayed 1 in one run (0-Vel 2048, drifting 16
counts/s) and was cleared in the other (0-Vel stepped 2045..2055, t swinging
+-135 counts): with MaxVel 0 nothing but the adaptation acts on it.
"""
from harness.robot import numbers

TARGET = (1600, 800, 400)


def test_zero_velocity_adaptation_at_rest(robot):
    robot.send("%d %d %d 0 Abs.Move Move.Complete?" % TARGET)
    start = numbers(robot.send("0-Vel A."))
    samples = []
    for _ in range(13):
        robot.idle(5.0)
        plant = robot.plant()
        samples.append((numbers(robot.send("0-Vel A.")),
                        [2048 + plant[a]["offset"] for a in "XYZT"],
                        [plant[a]["counter"] for a in "XYZT"]))
    zeros, true, counters = samples[-1]
    # no convergence: x, y and z end at least 2 codes from their true zeros,
    # x and y further than the paper's table started (2049 vs 2051.0 / 2046.1)
    for axis in range(3):
        assert abs(zeros[axis] - true[axis]) >= 2, (axis, zeros, true)
    for axis in range(2):
        assert abs(zeros[axis] - true[axis]) > abs(start[axis] - true[axis])
    # the entries do move: adaptation is running (x moved by 7 codes)
    assert any(s[0][0] != start[0] for s in samples)
    # t (MaxVel 0) is never position-servoed: it wanders by more than 100 counts
    # over the minute (it drifts away if Command.Status t stayed 1, or swings
    # +-135 counts as its 0-Vel is stepped 2045..2055 if it was cleared)
    t = [s[2][3] for s in samples]
    assert max(t) - min(t) > 100, t
    # x, y, z stay near their targets over the minute (measured <= 25 counts)
    for _, _, c in samples:
        assert all(abs(c[k] - TARGET[k]) <= 40 for k in range(3)), c
