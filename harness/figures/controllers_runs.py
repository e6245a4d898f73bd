"""The runs behind docs/controllers.md's "The same moves on both architectures":
docs/servo.md's moves (make servo-runs) on the 11/23 alone (blocks 1000-1012,
`harness run`) and on the five machines (1200-1206 on the 11/23, 1080-1089 on
each LSI-11/03, `harness controllers run`), from the console scripts in
harness/figures/compare/.

    python -m harness.figures.controllers_runs OUTDIR [--figures STEM]

writes OUTDIR/{moves,rest}-{1123,1103}.* (transcripts and traces), prints per
move and architecture the Abs.Move line's instructions on the 11/23, how long
Move.Complete? took, and per moved axis the settling time into the +-4 window
and the band it hunts in after it (harness/analysis/settling.py); with
--figures, draws STEM-long.png, STEM-short.png and STEM-rest.png: the counter
and the D/A code against simulated time, the 11/23 alone beside the 11/03s.
Each script's `#simh show time` lines give the moments (the 11/23's
instruction count), so the numbers follow the kernels' timing.
"""
import argparse
import sys
from dataclasses import dataclass
from pathlib import Path

from harness.analysis import trace
from harness.analysis.settling import arrival, show_times
from harness.controllers.scripted import run_five_file, split_joined
from harness.machine.build import RATE
from harness.machine.script_run import run_file

SCRIPTS = Path(__file__).resolve().parent / "compare"
ARCHITECTURES = {"1123": "the 11/23 alone (1000-1012)",
                 "1103": "one 11/03 per axis (1200-1206, 1080-1089)"}
# per run: the targets of each move, in the script's order (axis -> counts)
RUNS = {"moves": [{"X": 4000}, {"X": 4150}, {"X": 4190}],
        "rest": [{"X": 1600, "Y": 800, "Z": 400}]}
WATCH = {"moves": 2.0, "rest": 10.0}     # the script's #wait after each move
LINE_LIMIT = 30.0                         # simulated s a line may take


@dataclass
class Move:
    targets: dict
    sent: float           # s: the Abs.Move line typed
    told: float           # its " ok"
    returned: float       # Move.Complete?'s " ok"; None: it did not return
    arrivals: dict        # axis -> settling.Arrival


def run(name, arch, outdir, line_limit=LINE_LIMIT):
    """Run one script (name-arch.script) into outdir; (transcript of the 11/23, trace path)."""
    script = SCRIPTS / f"{name}-{arch}.script"
    stem = outdir / f"{name}-{arch}"
    csv = stem.with_suffix(".trace.csv")
    if arch == "1123":
        transcript = stem.with_suffix(".transcript")
        run_file(script, transcript, csv, line_limit=line_limit)
    else:
        transcript = stem.with_suffix(".main.transcript")
        run_five_file(script, transcript, csv, line_limit=line_limit)
        return split_joined(transcript.read_text("latin-1"))["main"], csv
    return transcript.read_text("latin-1"), csv


def measure(name, text, csv):
    """The Moves of run `name` from its 11/23 transcript and its trace."""
    times, t = show_times(text, RATE), trace.read(csv)
    found = []
    for k, targets in enumerate(RUNS[name]):
        sent, told, *back = times[3 * k:3 * k + 3]
        returned = back[0] if back else None
        end = (returned if returned is not None else t.duration) + WATCH[name]
        found.append(Move(targets, sent, told, returned,
                          {a: arrival(t.axis(a), c, sent, end) for a, c in targets.items()}))
    return found


def _seconds(value):
    return "never" if value is None else f"{value:.3f} s"


def row(name, k, arch, move):
    took = ("did not return" if move.returned is None
            else f"{move.returned - move.sent:.3f} s")
    axes = "; ".join(f"{a} {_seconds(v.settle)}, {v.low:+d}..{v.high:+d}"
                     if v.settle is not None else f"{a} never inside"
                     for a, v in move.arrivals.items())
    line = ", ".join(f"{c}" for c in move.targets.values())
    return (f"| {name} {k + 1} ({line}) | {arch} | {round((move.told - move.sent) * RATE)} "
            f"| {took} | {axes} |")


def figures(stem, results):
    """The three side-by-side figures from results[(name, arch)] = (moves, csv)."""
    from harness.analysis import plots       # matplotlib: imported only when drawing
    traces = {key: trace.read(csv) for key, (_, csv) in results.items()}

    def both(name, k, after):
        """Per architecture: from 0.1 s before its move k's line to `after` s past its return."""
        return [(ARCHITECTURES[a], traces[(name, a)],
                 (moves[k].sent - 0.1, (moves[k].returned or moves[k].sent) + after))
                for a in ARCHITECTURES for moves in [results[(name, a)][0]]]

    chosen = [("long", "moves", 0, ["X"], 0.6, "4000 0 0 0 Abs.Move Move.Complete? on x"),
              ("short", "moves", 1, ["X"], 0.6, "then 4150 0 0 0 (150 counts) on x"),
              ("rest", "rest", 0, ["X", "Y", "Z"], 2.0,
               "1600 800 400 0 Abs.Move Move.Complete?")]
    out = []
    for suffix, name, k, axes, after, what in chosen:
        path = f"{stem}-{suffix}.png"
        fig = plots.architectures_figure(both(name, k, after), axes,
                                         f"{what}: counter and D/A code, 11/23 alone "
                                         f"beside one LSI-11/03 per axis")
        out.append((fig, [path]))
        print(f"figure {path}")
    plots.save_all(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", type=Path)
    ap.add_argument("--figures", metavar="STEM", help="draw STEM-{long,short,rest}.png")
    a = ap.parse_args(argv)
    a.outdir.mkdir(parents=True, exist_ok=True)
    results = {}
    print("| move (targets) | machines | Abs.Move line, 11/23 instructions "
          "| Move.Complete? took | per axis: settled into +-4 after, band after it |")
    for name in RUNS:
        for arch in ARCHITECTURES:
            text, csv = run(name, arch, a.outdir)
            found = measure(name, text, csv)
            results[(name, arch)] = (found, csv)
            for k, move in enumerate(found):
                print(row(name, k, arch, move))
    if a.figures:
        figures(a.figures, results)
    return 0


if __name__ == "__main__":
    sys.exit(main())
