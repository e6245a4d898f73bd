"""The runs behind docs/servo.md: plant traces of the 1983 servo as printed
(and of the proposed block 1030), made in lock-step with simulated time
(harness/machine/robot.py), so that the same command gives the same traces.

    python -m harness.figures.servo_runs OUTDIR [--block 1030 [--then Ramp.Servo]]
                                        [--figures STEM]

writes OUTDIR/moves.csv (a long and two short moves on x), OUTDIR/rest.csv (a
move, then a simulated minute at rest) and prints what each line answered and
the plant's state (SHOW PLANT) at the points the docs quote. With --figures, it
draws the docs' figures (STEM-moves-X.png, STEM-long-time.png, ...) with
`harness plot`, each time window taken from when this run sent the move's line,
and prints the plot commands, so the windows follow the kernel's timing.
"""
import argparse
import sys
import tempfile
from pathlib import Path

from harness.commands import plot
from harness.machine.build import fresh_disk
from harness.machine.robot import Robot

# x: 4000 counts (5 in) out, then 150 and 40 counts: one long move, two short
MOVES = [(4000, 2.0), (4150, 2.0), (4190, 2.0)]
# the plant's default offsets (docs/design.md section 3), drawn on the zero figure
OFFSETS = ("X=3.0", "Y=-2.0", "Z=45.0", "T=0.6")


def session(trace, block, then, disk_dir):
    disk = fresh_disk(disk_dir, f"{trace.stem}.dsk")
    r = Robot(disk=disk, trace=trace, sample=1000)
    r.send("1000 LOAD")
    if block:
        r.send(f"{block} LOAD")
    r.send("Set.Up.Robot")
    if then:
        r.send(then)
    return r


def report(r, label):
    p = r.plant()
    cells = "  ".join(f"{a}: counter {v['counter']:6d} dac {v['dac']} offset {v['offset']:+.2f}"
                      for a, v in p.items())
    print(f"t={r.time():8.3f} s  {label}\n    {cells}")


def run_moves(r):
    """The moves run's lines (MOVES) on a set-up Robot, reporting each; returns
    [(sent, returned)]: the simulated times each line was sent and answered."""
    report(r, "after Set.Up.Robot")
    lines = []
    for x, settle in MOVES:
        start = r.time()
        r.send(f"{x} 0 0 0 Abs.Move Move.Complete?")
        lines.append((start, r.time()))
        report(r, f"{x} 0 0 0 Abs.Move Move.Complete? returned after "
                  f"{r.time() - start:.3f} s")
        r.idle(settle)
        report(r, f"  {settle} s later")
    return lines


def window(sent, returned, before, after):
    """START:END around a move: from `before` s ahead of the line that started
    it to `after` s past its Move.Complete? (at least `after` s past the line)."""
    return f"{sent - before:.2f}:{max(returned, sent) + after:.2f}"


def figure_commands(outdir, stem, lines):
    """The plot command lines (argument lists) of the docs' figures; `lines` holds
    (sent, returned) times of the moves' lines, the long move first."""
    moves, rest = str(outdir / "moves.csv"), str(outdir / "rest.csv")
    (long_sent, long_back), (short_sent, short_back) = lines[:2]
    png = ["--format", "png"]
    offsets = [w for o in OFFSETS for w in ("--offset", o)]
    return [
        [moves, "--figure", "moves", "--axis", "X", *png, "--out", f"{stem}"],
        [moves, "--figure", "time", "--axis", "X", *png, "--out", f"{stem}-long",
         "--window", window(long_sent, long_back, 0.1, 0.4)],
        [moves, "--figure", "time", "--axis", "X", *png, "--out", f"{stem}-short",
         "--window", window(short_sent, short_back, 0.05, 0.5)],
        [rest, "--figure", "zero", *offsets, *png, "--out", f"{stem}-rest"],
    ]


def draw(commands):
    parser = argparse.ArgumentParser(prog="python -m harness plot")
    plot.configure(parser)
    for argv in commands:
        print("python -m harness plot " + " ".join(argv))
        plot.run(parser.parse_args(argv))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", type=Path)
    ap.add_argument("--block", type=int, help="a block to LOAD after 1000 (e.g. 1030)")
    ap.add_argument("--then", default="", help="a line after Set.Up.Robot (e.g. Ramp.Servo)")
    ap.add_argument("--figures", metavar="STEM", help="draw the docs' figures as STEM-*.png")
    a = ap.parse_args(argv)
    a.outdir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        with session(a.outdir / "moves.csv", a.block, a.then, tmp) as r:
            lines = run_moves(r)
        with session(a.outdir / "rest.csv", a.block, a.then, tmp) as r:
            r.send(": A. ( a -- ) 4 0 DO DUP I 2* + @ . LOOP DROP ;")
            r.send("1600 800 400 0 Abs.Move Move.Complete?")
            for k in range(7):
                report(r, "0-Vel: " + r.send("0-Vel A."))
                r.idle(10.0)
    if a.figures:
        draw(figure_commands(a.outdir, a.figures, lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
