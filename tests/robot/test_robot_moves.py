"""Moves on x, y, z with the blocks as printed, on the plant of docs/design.md
section 3 (never tuned). Measured first (deterministic runs: harness/machine/robot.py),
then pinned with bounds a little wider than the measurement.

What the measurement showed, and why (blocks 1003-1007):
- 1006 has no ramp: the first tick of every move, however short, commands
  0-Vel +- MaxVel (300 codes, 5860 counts/s); near the target the command is
  the distance left, in codes (W = counts): a proportional gain of 19.5/s.
- An axis inside Range (|error| < 5) gets 0-Vel (State Stop, Velocity 0); once
  it drifts out, Velocity is 0 < distance, so 1006 kicks it at MaxVel again.
  The axes therefore never rest: they hunt around the target with a period of
  four or five ticks (15 or 12 Hz, depending on the axis and the phase) and
  about +-20 counts, every axis, moving or not.
- Command.Status of an axis is cleared the first tick its counter is seen
  inside Range; if the hunting cycle steps over the window (+-4 counts), it is
  never cleared and Move.Complete? never returns (400 -300 600 0 below).
"""
import csv

from harness.machine.robot import numbers

RANGE = 5
# (x, y, z) absolute targets in turn; t stays 0 (MaxVel 0). z moves upward
# first: the counters are zeroed by Set.Up.Robot with z on its lower stop
# (see test_z_sits_on_its_lower_stop).
MOVES = [(1600, 0, 0), (-1600, 0, 0), (200, 0, 0), (40, 0, 0), (0, 800, 0),
         (0, -2400, 0), (0, 80, 0), (0, 0, 400), (0, 0, 2000), (0, 0, 1000),
         (0, 0, 1030), (4000, 3000, 1500), (0, 0, 200)]
# The hunting's phase follows the kernel's instruction counts while the blocks
# load: with the Forth-2012 kernel, (0, 60, 0) stepped over the window and never
# completed, so the short y move is 80 counts.
# measured in this sequence: |counter - target| two seconds after Abs.Move and
# over 3 s of settling up to about 45 (the hunting's amplitude, which depends on
# its phase: other runs gave 26 and 27).
AT_RETURN, SETTLING = 60, 50


def errors(plant, target):
    return [plant[a]["counter"] - g for a, g in zip("XYZ", target)]


def test_moves_arrive_then_hunt(robot):
    """Abs.Move, then two simulated seconds (the longest move, 4000 counts at MaxVel,
    takes 0.7 s): not Move.Complete?, which never returns when an axis's hunting
    steps over the window, and which of these moves does that depends on the
    hunting's phase, i.e. on every instruction the kernel ran before."""
    hunting = 0
    for target in MOVES:
        robot.send("%d %d %d 0 Abs.Move" % target)
        robot.idle(2.0)
        at = errors(robot.plant(), target)
        assert max(map(abs, at)) <= AT_RETURN, (target, at)
        worst = [0, 0, 0]
        for _ in range(12):
            robot.idle(0.25)
            e = errors(robot.plant(), target)
            worst = [max(w, abs(v)) for w, v in zip(worst, e)]
        assert max(worst) <= SETTLING, (target, worst)
        hunting += max(worst) >= RANGE
    # almost no move settles inside Range: after each, some axis leaves it
    # (measured: all 13 on the kernel of issue 4, 12 on issue 8's; which one can
    # settle depends on the hunting's phase)
    assert hunting >= len(MOVES) - 1


def test_show_plant_agrees_with_read_counter(robot):
    """With the servo running the axes hunt at up to 2000 counts/s and .C's
    printing takes milliseconds (measured differences up to 38 counts). So the
    servo is stopped first (clock interrupt off, every DAC at its 0-Vel): the
    axes then creep at a few counts/s and each printed counter must equal the
    plant's counter within what that creep covers while the line runs."""
    robot.send("1200 -700 900 0 Abs.Move Move.Complete?")
    robot.send("0 177546O ! HOLD")
    for _ in range(4):
        robot.idle(1.0)
        printed = numbers(robot.send(".C"))
        plant = robot.plant()
        for axis, value in zip("XYZT", printed):
            slack = 1 + abs(plant[axis]["vel"]) * 0.05
            assert abs(plant[axis]["counter"] - value) <= slack, (axis, value, plant[axis])


def test_axes_hunt_instead_of_resting(robot):
    """After a move, x never comes to rest: whenever it drifts out of Range the
    printed 1006 restarts it at MaxVel (no ramp), it overshoots and is braked in
    proportion to the distance left, round and round. Measured over 25 s after
    400 -300 600 0 and 1600 800 400 0: x's counter spans 44 and 84 counts, far
    wider than the +-5 count Range window. On some kernels the cycle steps over
    the window for good and Move.Complete? never returns (docs/servo.md);
    whether it does depends on the tick phase, so only the hunting is asserted."""
    robot.send("400 -300 600 0 Abs.Move")  # not Move.Complete?: it may never return
    settled = robot.time() + 3.0
    robot.idle(28.0)
    rows = [r for r in csv.DictReader(open(robot.trace_path))
            if r["axis"] == "X" and float(r["time_s"]) > settled]
    seen = [int(r["counter"]) for r in rows]
    assert max(seen) - min(seen) > 20, (min(seen), max(seen))
    assert min(seen) < 400 < max(seen)                # around the target, both sides
    assert max(abs(c - 400) for c in seen) < 60


def test_z_sits_on_its_lower_stop(boot):
    """DAC 2048 at power-up and z's gravity offset (+45 codes) drop z at 880
    counts/s: it reaches its lower stop (-4000 from power-up) 4.6 s after
    power-up, before 1000 LOAD (10 simulated s) ends. Set.Up.Robot then zeroes
    the counters there, so a negative z target (the issue's -400) is out of reach."""
    r = boot()
    r.send("1000 LOAD Set.Up.Robot")
    p = r.plant()
    assert p["Z"]["stop"] == "lower" and p["Z"]["pos"] == -4000 and p["Z"]["counter"] == 0
    out = r.begin("1600 800 -400 0 Abs.Move Move.Complete?", 20.0)
    p = r.plant()
    assert "ok" not in out and p["Z"]["stop"] == "lower" and p["Z"]["counter"] == 0


def test_short_moves_never_reach_max_speed(robot):
    """40 counts on x: the first tick still commands 0-Vel+300 (no ramp), but the
    plant's lag and current limit leave it far below MaxVel's 5860 counts/s."""
    zero = numbers(robot.send("0-Vel A."))[0]
    start = robot.time()
    robot.send("40 0 0 0 Abs.Move Move.Complete?")
    rows = [r for r in csv.DictReader(open(robot.trace_path))
            if r["axis"] == "X" and float(r["time_s"]) >= start]
    dacs = [int(r["dac"]) for r in rows]
    assert zero + 300 in dacs[:10]                   # MaxVel on the first write
    peak = max(abs(float(r["vel"])) for r in rows[:40])
    assert peak < 0.6 * 300 * 19.53, peak            # measured ~2700 counts/s


def test_t_wanders(robot):
    """t has MaxVel 0: Change.Speed? outputs its 0-Vel entry and nothing else, so
    t is never position-servoed. If Command.Status t stays 1 (t not seen inside
    Range), 0-Vel t stays 2048 and t drifts with its offset (+0.6 codes, about
    -12 counts/s); if it was cleared, the adaptation steps 0-Vel t by +-1 every
    half second and t swings by tens of counts. Either way it wanders."""
    robot.send("100 100 100 0 Abs.Move Move.Complete?")
    start = robot.time()
    counters = []
    for _ in range(20):
        robot.idle(1.0)
        counters.append(robot.plant()["T"]["counter"])
    assert max(counters) - min(counters) > 40, counters  # measured 71 here, 320 drifting
    rows = [r for r in csv.DictReader(open(robot.trace_path))
            if r["axis"] == "T" and float(r["time_s"]) >= start]
    # never a MaxVel kick on t (x, y, z get +-300 codes): only 0-Vel codes
    assert all(abs(int(r["dac"]) - 2048) <= 12 for r in rows)
