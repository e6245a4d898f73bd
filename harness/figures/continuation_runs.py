"""The runs behind docs/continuation.md: the continuous-path blocks (1040-1053)
and the gripper on the emulated robot, on the printed servo and on the
proposed corrected one (block 1030), in lock-step with simulated time
(harness/machine/robot.py): the same command gives the same traces and figures.

    python -m harness.figures.continuation_runs OUTDIR [--servo printed|ramp]... [--figures DIR]

For each servo, writes OUTDIR/SERVO/square-SPEED.csv (a 4-inch square at
2400 and 4800 counts/s), points.csv (the same corners by Abs.Move
Move.Complete?), circle.csv (16 via points, radius 2 inches, 2400 counts/s),
the square and circle again with blends of BLEND_SLOW ticks (-slow.csv) and
by Spline.Run (-spline.csv), and,
for the printed servo, pick.csv (block 1062's pick and place); prints the
measurements the docs quote (harness/analysis/path_metrics.py). With --figures,
draws the docs' figures from those traces into DIR (continuation-SERVO-NAME-xy.png, continuation-pick-gripper.png).
"""
import argparse
import math
import sys
import tempfile
from pathlib import Path

from harness.analysis import path_metrics as pm
from harness.analysis import trace as tr
from harness.machine.build import fresh_disk
from harness.machine.robot import Robot

PLANE = 400                                  # z of the drawings (block 1060's Plane)
SIDE = 3200                                  # 4 inches
SQUARE = [(0, 0), (SIDE, 0), (SIDE, SIDE), (0, SIDE), (0, 0)]
CENTRE, RADIUS = (1600, 1600), 1600
SPEED = 2400                                 # counts/s: 3 in/s
BLEND, BLEND_SLOW = 6, 24                    # Paul's tau in ticks: block 1040's, and gentler
SERVO_BLOCK = {"printed": None, "ramp": 1030}


def circle():
    """Block 1060's Circle: 16 via points from angle 0, cosines to 4 places."""
    cos = [round(10000 * math.cos(k * math.pi / 8)) for k in range(16)]
    cx, cy = CENTRE
    return [(cx + _scaled(cos[k % 16]), cy + _scaled(cos[(k - 4) % 16])) for k in range(17)]


def _scaled(c):
    """RADIUS c 10000 */ as the FORTH computes it: symmetric division."""
    q = abs(RADIUS * c) // 10000
    return q if c >= 0 else -q


def vias_text(points, z=PLANE):
    """FORTH text giving x-y points as via points at height z."""
    return " ".join(f"{x} {y} {z} 0 Via" for x, y in points)


def session(trace, servo, disk_dir, blend=BLEND, sample=60):
    """1000 LOAD, the servo's block, 1040 LOAD, Set.Up.Robot Path.Servo, the
    blend, and z up to the drawing plane at the origin."""
    disk = fresh_disk(disk_dir, f"{trace.stem}.dsk")
    r = Robot(disk=disk, trace=trace, sample=sample, timeout=30)
    r.send("1000 LOAD")
    if SERVO_BLOCK[servo]:
        r.send(f"{SERVO_BLOCK[servo]} LOAD")
    r.send("1040 LOAD")
    r.send(f"Set.Up.Robot Path.Servo {blend} Blend !")
    r.send(f"Path.Clear 0 0 {PLANE} 0 Via 1200 Path.Run Path.Wait")
    r.idle(1.0)
    return r


def run_path(r, points, speed=SPEED, run="Path.Run"):
    """Give the path (from the current point); (start, end) simulated seconds
    from Path.Run (or `run`: Spline.Run) to Path.Wait's return."""
    r.send("Path.Clear")
    for k in range(0, len(points), 6):           # a console line holds 255 characters
        r.send(vias_text(points[k:k + 6]))
    t0 = r.time()
    r.send(f"{speed} {run} Path.Wait")
    return t0, r.time()


def counters(r):
    return [v["counter"] for v in r.plant().values()]


FIGURES = []          # (trace path, corners, window) of each path run, for --figures


def report_path(name, trace_path, corners, t0, t1, end_counters, round_=False):
    FIGURES.append((trace_path, corners, (t0, t1 + 1.0)))
    xy = pm.path_samples(tr.read(trace_path), t0, t1 + 1.0)
    m = pm.measure(xy, corners)
    print(f"  {name}: Path.Run to Path.Wait {t1 - t0:.3f} s")
    print("    largest deviation per segment, counts: "
          + " ".join(f"{d:.0f}" for d in m.segment_max))
    print("    closest approach to each via point, counts: "
          + " ".join(f"{d:.0f}" for d in m.via_miss))
    print("    speed there, counts/s: " + " ".join(f"{v:.0f}" for v in m.via_speed))
    print(f"    counters 1 s after the end: {end_counters}")
    if round_:
        during = (xy.time >= t0) & (xy.time <= t1)
        radial = abs(pm.radial_error(xy, CENTRE, RADIUS)[during])
        print(f"    distance from the true circle while running: at most {radial.max():.0f} "
              "counts")
    return m


def square(out, servo, tmp, speed, blend=BLEND, name=None, run="Path.Run"):
    name = name or f"square-{speed}.csv"
    with session(out / name, servo, tmp, blend) as r:
        t0, t1 = run_path(r, SQUARE[1:], speed, run)
        r.idle(1.0)
        how = "by Spline.Run" if run == "Spline.Run" else f"Blend {blend}"
        report_path(f"square 4 in at {speed} counts/s, {how} ({name})", out / name,
                    SQUARE, t0, t1, counters(r))


def circle_run(out, servo, tmp, blend=BLEND, name="circle.csv", run="Path.Run"):
    with session(out / name, servo, tmp, blend) as r:
        r.send(f"Path.Clear {CENTRE[0] + RADIUS} {CENTRE[1]} {PLANE} 0 Via 1200 Path.Run "
               "Path.Wait")
        r.idle(0.5)
        pts = circle()
        t0, t1 = run_path(r, pts[1:], SPEED, run)
        r.idle(1.0)
        how = "by Spline.Run" if run == "Spline.Run" else f"Blend {blend}"
        report_path(f"circle r 2 in, 16 via points, at 2400 counts/s, {how} ({name})",
                    out / name, pts, t0, t1, counters(r), round_=True)


# waits until x and y are within 30 counts of Desire.Pos (the printed servo's
# hunting is about +-25): point to point without Move.Complete?'s +-4 window
NEAR = (": Near ( -- ) BEGIN 0 Read.Counter Desire.Pos @ - ABS 30 < "
        "1 Read.Counter Desire.Pos 2+ @ - ABS 30 < AND END ;")


def point_to_point(out, servo, tmp):
    """The same corners by Abs.Move, waiting with Move.Complete? (a line that
    does not return within 10 simulated seconds is reported: the printed
    servo can hunt round a corner for ever), then again waiting with Near."""
    for wait, name in (("Move.Complete?", "points.csv"), ("Near", "points-near.csv")):
        with session(out / name, servo, tmp) as r:
            r.send(NEAR)
            t0 = r.time()
            for x, y in SQUARE[1:]:
                answer = r.line(f"{x} {y} {PLANE} 0 Abs.Move {wait}", 10.0)
                if answer.stopped:
                    print(f"  point to point, Abs.Move {wait}: at {x} {y} it did not "
                          "return within 10 s")
                    break
            else:
                print(f"  point to point, Abs.Move {wait} at the 4 corners: "
                      f"{r.time() - t0:.3f} s")


def pick_and_place(out, tmp):
    with session(out / "pick.csv", "printed", tmp) as r:
        r.send("1060 LOAD", timeout=60)   # Plane, Go.To (and the shapes demo)
        r.simh("set plant gripper object=1,partx=800,party=800,partz=400")
        t0 = r.time()
        said = r.send("1062 LOAD")
        print(f"  pick and place (1062 LOAD), a 1 in part at 800 800 400: {said.strip()!r}, "
              f"{r.time() - t0:.2f} s, from {t0:.2f} s; the part is now at "
              f"{r.gripper()['part']}")
    return out / "pick.csv"


def draw(figdir, pick):
    from harness.analysis import path_plots, plots
    figdir.mkdir(parents=True, exist_ok=True)
    for path, corners, window in FIGURES:
        name = f"continuation-{path.parent.name}-{path.stem}-xy.png"
        plots.save(path_plots.xy_figure(tr.read(path), corners, [window]), [figdir / name])
        print(figdir / name)
    if pick:
        plots.save(path_plots.gripper_figure(tr.read(pick)),
                   [figdir / "continuation-pick-gripper.png"])
        print(figdir / "continuation-pick-gripper.png")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", type=Path)
    ap.add_argument("--servo", choices=tuple(SERVO_BLOCK), action="append")
    ap.add_argument("--figures", type=Path, metavar="DIR", help="draw the figures there")
    a = ap.parse_args(argv)
    pick = None
    with tempfile.TemporaryDirectory() as tmp:
        for servo in a.servo or tuple(SERVO_BLOCK):
            out = a.outdir / servo
            out.mkdir(parents=True, exist_ok=True)
            print(f"==> {servo} servo" + (f" (block {SERVO_BLOCK[servo]})"
                                          if SERVO_BLOCK[servo] else " (blocks 1000-1012)"))
            for speed in (SPEED, 2 * SPEED):
                square(out, servo, tmp, speed)
            circle_run(out, servo, tmp)
            square(out, servo, tmp, SPEED, BLEND_SLOW, "square-slow.csv")
            circle_run(out, servo, tmp, BLEND_SLOW, "circle-slow.csv")
            square(out, servo, tmp, SPEED, name="square-spline.csv", run="Spline.Run")
            circle_run(out, servo, tmp, name="circle-spline.csv", run="Spline.Run")
            point_to_point(out, servo, tmp)
            if servo == "printed":
                pick = pick_and_place(out, tmp)
    if a.figures:
        draw(a.figures, pick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
