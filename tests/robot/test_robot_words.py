"""Every word of blocks 1009-1012, exercised on the machine."""
from harness.machine.robot import numbers


# (line, array printed after it, its four cells)
SETTERS = [
    ("Increment Zero.Array", "Increment", [0, 0, 0, 0]),
    ("Set.Increments", "Increment", [3, 3, 3, 3]),
    ("77 2 Max.Vel.Single", "MaxVel", [300, 300, 77, 0]),
    ("10 20 30 40 Max.Vel", "MaxVel", [10, 20, 30, 40]),
    ("Initialize.Zero.Velocities", "0-Vel", [2049, 2049, 2090, 2048]),
    ("45 Delay ! Set.Delay", "Delay.Left", [45, 45, 45, 45]),
]


def test_array_and_velocity_words(robot):
    robot.send("0 177546O ! HOLD")  # servo off: it adapts 0-Vel, counts Delay.Left
    for line, array, cells in SETTERS:
        robot.send(line)
        assert numbers(robot.send(array + " A.")) == cells, line


def test_move_words(robot):
    robot.send("500 1 Abs.Move.Single")
    assert numbers(robot.send("Desire.Pos A."))[:2] == [0, 500]
    # Move.Complete? itself is exercised by test_moves.py; here the moves are
    # given time instead (the hunting can keep it waiting: test_moves.py)
    robot.idle(3.0)
    assert abs(numbers(robot.send("1 Read.Counter ."))[0] - 500) <= 60
    robot.send("-200 1 Rel.Move.Single")
    assert numbers(robot.send("Desire.Pos A."))[1] == 300
    robot.send("100 50 200 0 Abs.Move")
    robot.idle(3.0)
    robot.send("10 -20 30 0 Rel.Move")
    robot.idle(3.0)
    assert numbers(robot.send("Desire.Pos A.")) == [110, 30, 230, 0]
    c = numbers(robot.send(".C"))
    assert all(abs(a - b) <= 60 for a, b in zip(c[:3], (110, 30, 230)))
    # Read.Counter leaves the processor status as it found it (priority 0)
    assert robot.send("0 Read.Counter DROP Proc.Status @ .") == "0 "


def test_setup_words(robot):
    robot.send("0 177546O ! HOLD Clear.All.Arrays")  # servo off: it would set State
    for name in ("Desire.Pos", "State", "MaxVel", "Velocity", "Command.Status"):
        assert numbers(robot.send(name + " A.")) == [0, 0, 0, 0], name
    # Increment, 0-Vel and Delay.Left are not cleared by Clear.All.Arrays
    assert numbers(robot.send("0-Vel A."))[3] == 2048
    # Initialize.Counter: OUTBUF 0 (all counters held at 0) then 15 (all run)
    # (the DACs at 0-Vel: the axes creep a few counts/s while .C prints)
    c = numbers(robot.send("Initialize.Counter .C"))
    assert robot.examine(0o17767772) == 15
    assert all(abs(v) <= 3 for v in c), c
    robot.send("Set.Up.Robot")
    assert numbers(robot.send("MaxVel A.")) == [300, 300, 300, 0]
    assert robot.examine(0o17777546) & 0o100      # the servo is back on
    # with no move pending Move.Complete? returns at once
    robot.send("Command.Status Zero.Array Move.Complete?")
