"""A simulated minute at rest after a move: the counters and the 0-Vel entries
over time beside the plant's true zeros (2048 + offset, SHOW PLANT).

Block 1005 adapts 0-Vel by Dir (+-1) every Delay (30) ticks, but only on ticks
where the axis is idle (Command.Status 0) and outside Range (State Move). With
the printed 1006 those ticks are mostly the hunting's overshoots (see
test_robot_moves.py), whose sign says little about the drift, so the entries
wander instead of converging. Measured (every 5 s over 65 s, two targets):
x 2049 -> 2036..2051 (true 2051.0; it walked 15 codes away in one run),
y 2049 -> 2042 (true 2046.1), z 2090 -> 2096 (true 2093.0, on three kernel
builds; 2093 on a fourth, issue 8's; 2092 on a fifth, issue 16's LEAVE-ENTRY,
whose 32 bytes shift every later instruction count: z climbs towards its true
zero, not always to it or past it); x, y, z stay within 25 counts of their
targets; t (MaxVel 0, never position-servoed) swings -190..+147 counts.
Which entry ends where depends on the hunting's phase (any change of the
kernel's timing moves it), so the bounds below are the phase-independent ones.
"""
from harness.machine.robot import numbers

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
    # the entries do move: adaptation is running
    assert any(s[0][k] != start[k] for s in samples for k in range(3))
    # they wander within about 15 codes of the true zeros: z, whose gravity
    # offset dominates, climbs from 2090 to within 2 codes of its true zero or
    # past it (the tick phase decides how far in the minute: 2092 against
    # 2093.03 on the kernel of issue 23, past it on earlier builds)
    for axis in range(3):
        assert abs(zeros[axis] - true[axis]) <= 20, (axis, zeros, true)
    assert zeros[2] - true[2] >= -2, (zeros, true)
    # t (MaxVel 0) is never position-servoed: it wanders by more than 100 counts
    # over the minute (it drifts away if Command.Status t stayed 1, or swings
    # +-135 counts as its 0-Vel is stepped 2045..2055 if it was cleared)
    t = [s[2][3] for s in samples]
    assert max(t) - min(t) > 100, t
    # x, y, z stay near their targets over the minute (measured <= 25 counts on
    # earlier builds; y once 41 below on issue 19's, its hunting's phase)
    for _, _, c in samples:
        assert all(abs(c[k] - TARGET[k]) <= 50 for k in range(3)), c
