"""Blocks 1030-1031: the project's proposed correction (not 1983 code), the
servo with one ELSE, restored in 1006 so that the speed ramps up by Increment
until MaxVel. Measured with it (harness/figures/servo_runs.py --block 1030): moves
return and the axes stay within 9 counts of their targets while settling;
after a minute at rest 0-Vel sits within one code of the plant's true zeros
(x 2051/2051.0, y 2046/2046.1, z 2093/2093.0), where the printed code ends
3-6 codes away (test_robot_idle.py)."""
from harness.machine.robot import numbers

TARGETS = [(4000, 0, 0), (4150, 0, 0), (4190, 0, 0), (1600, 800, 400)]


def test_ramp_servo_settles_and_adapts(robot):
    assert robot.send("1030 LOAD Ramp.Servo") == ""
    servo = numbers(robot.send("' Interrupt.Servo ."))[0] & 0xFFFF
    assert robot.examine(0o100) == servo
    for target in TARGETS:
        robot.send("%d %d %d 0 Abs.Move Move.Complete?" % target)
        for _ in range(4):
            robot.idle(0.5)
            p = robot.plant()
            errs = [abs(p[a]["counter"] - g) for a, g in zip("XYZ", target)]
            assert max(errs) <= 12, (target, errs)      # measured <= 9
    robot.idle(60.0)
    p = robot.plant()
    zeros = numbers(robot.send("0-Vel A."))
    for k, axis in enumerate("XYZ"):
        assert abs(zeros[k] - (2048 + p[axis]["offset"])) <= 1.0, (axis, zeros)
